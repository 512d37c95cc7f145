// The app's frame rendered with no display: an OSMesa GL 3.3 core context (llvmpipe) instead of a window.
// A FrameHost (frame_host.h), like the GLFW window: the frame and the loop body are the very code the app
// runs (ui::run_frame).
#pragma once

#include <memory>

#include "session/app_state.h"
#include "ui/frame.h"
#include "ui/frame_host.h"
#include "gl/framebuffer_image.h"

namespace raycam::headless {

class HeadlessRenderer : public ui::FrameHost {
 public:
  // Throws std::runtime_error if no OSMesa context can be created.
  HeadlessRenderer(int width, int height);
  ~HeadlessRenderer() override;
  HeadlessRenderer(const HeadlessRenderer&) = delete;
  HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

  // Runs one frame (ImGui needs two to settle its layout: see render_settled).
  void run_frame(session::AppState& state);
  // Runs `frames` frames (at least 2) and reads the last one back.
  gl::RgbaImage render_settled(session::AppState& state, int frames = 3);

  // FrameHost: no events to wait for, no mouse (nothing hovered), a fixed 60 Hz clock for ImGui.
  ui::FramebufferSize begin(const session::AppState& state, const ui::PanelState& panels) override;
  void present() override;
  gl::RgbaImage read_back() const override;

  // Input, as a window system would send it, through ImGui's IO: the next run_frame sees it. The mouse
  // stays where it was put (outside the window until then); a pressed key is released after one frame.
  void move_mouse(float x, float y);
  void set_mouse_button(int button, bool down);
  void scroll(float wheel);
  void press_key(int imgui_key);  // ImGuiKey_Tab, ImGuiKey_LeftArrow, ...
  void type_text(const char* utf8);

  const ui::FrameLayout& layout() const { return layout_; }
  // The frame's panel state (its widgets' own, beside the session's AppState): the start-up options' values
  // (ui::panel_state_for), the tests' widget_rects hook.
  ui::PanelState& panels() { return frame_->panels(); }
  session::CameraCheck& check() { return frame_->check(); }  // the page's route: its case and answer files
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Context;
  std::unique_ptr<Context> context_;
  std::unique_ptr<ui::FrameRenderer> frame_;
  ui::FrameLayout layout_;
  float mouse_x_, mouse_y_;
  bool mouse_down_[3] = {false, false, false};
  float wheel_ = 0.0f;
  int pressed_key_ = -1;
  int width_, height_;
};

}  // namespace raycam::headless
