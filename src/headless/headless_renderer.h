// The app's frame rendered with no display: an OSMesa GL 3.3 core context (llvmpipe) instead of a window.
// The frame itself is the very code the GLFW app runs (raycam_ui's FrameRenderer).
#pragma once

#include <memory>

#include "app_state.h"
#include "frame.h"
#include "framebuffer_image.h"

namespace raycam::headless {

class HeadlessRenderer {
 public:
  // Throws std::runtime_error if no OSMesa context can be created.
  HeadlessRenderer(int width, int height);
  ~HeadlessRenderer();
  HeadlessRenderer(const HeadlessRenderer&) = delete;
  HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

  // Runs one frame (ImGui needs two to settle its layout: see render_settled).
  void run_frame(ui::AppState& state);
  // Runs `frames` frames (at least 2) and reads the last one back.
  gl::RgbaImage render_settled(ui::AppState& state, int frames = 3);
  gl::RgbaImage read_back() const;

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
