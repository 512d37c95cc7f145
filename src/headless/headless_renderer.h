// The app's frame rendered with no display: an OSMesa GL 3.3 core context (llvmpipe) instead of a window.
// A FrameHost (frame_host.h), like the GLFW window: the frame and the loop body are the very code the app
// runs (ui::run_frame).
#pragma once

#include <memory>

#include "app_state.h"
#include "frame.h"
#include "frame_host.h"
#include "framebuffer_image.h"

namespace raycam::headless {

class HeadlessRenderer : public ui::FrameHost {
 public:
  // Throws std::runtime_error if no OSMesa context can be created.
  HeadlessRenderer(int width, int height);
  ~HeadlessRenderer() override;
  HeadlessRenderer(const HeadlessRenderer&) = delete;
  HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

  // Runs one frame (ImGui needs two to settle its layout: see render_settled).
  void run_frame(ui::AppState& state);
  // Runs `frames` frames (at least 2) and reads the last one back.
  gl::RgbaImage render_settled(ui::AppState& state, int frames = 3);

  // FrameHost: no events to wait for, no mouse (nothing hovered), a fixed 60 Hz clock for ImGui.
  ui::FramebufferSize begin(const ui::AppState& state) override;
  void present() override;
  gl::RgbaImage read_back() const override;

  const ui::FrameLayout& layout() const { return layout_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Context;
  std::unique_ptr<Context> context_;
  std::unique_ptr<ui::FrameRenderer> frame_;
  ui::FrameLayout layout_;
  int width_, height_;
};

}  // namespace raycam::headless
