// The browser page as a FrameHost (the shared GLFW host, src/glfw_host/glfw_host_base.h): emscripten's GLFW on a
// WebGL 2 canvas; the page overrides only its loop and its file routes. The browser
// owns the loop: each animation frame calls tick(), which draws only while something changed (an event,
// then a few settle frames, or the state's pending work) and otherwise pauses the loop until the next event,
// so an idle page casts and draws nothing, like the desktop window asleep in glfwWaitEvents.
// The canvas's drawing buffer follows its CSS size × the screen's pixel ratio (resizes, zoom, another
// screen); the UI is laid out in CSS pixels, drawn at the ratio (text rasterised at it, so it stays crisp and
// the same size to the eye). Full screen is the browser's Fullscreen API (F11 or the panel's button).
#pragma once

#include "ui/frame.h"
#include "glfw_host/glfw_host_base.h"

struct GLFWwindow;

namespace raycam::web {

class WebHost : public glfw_host::GlfwHostBase {
 public:
  WebHost(GLFWwindow* window, session::AppState& state) : GlfwHostBase(window, state) {}
  void present() override {}  // the browser shows the canvas when the animation frame returns

  // True when this animation frame has something to draw; false puts the loop to sleep until an event.
  bool wants_frame(const session::AppState& state, const ui::PanelState& panels);
  // After a frame drawn: ImGui read the keys; the changes held since go to it for the next frame.
  void frame_drawn(session::AppState&) override { forward_held_keys(); }

  float pixel_density() const override { return pixel_ratio_; }
  // The canvas's new drawing buffer (already sized by the page's script) and the screen's pixel ratio.
  void resized(double pixel_ratio);

 private:
  void woken() override;  // a paused loop resumes
  void frame_started() override;  // ImGui's sizes and mouse from device pixels to CSS pixels
  void after_imgui_backend() override;  // the page's own wheel, canvas size and key listeners

  bool sleeping_ = false;
  float pixel_ratio_ = 1.0f;
};

// Creates the canvas's context and ImGui, then hands the loop to the browser (never returns to main's
// caller in the usual sense: emscripten keeps the runtime alive). The frame starts with `panels`.
void run_page(session::AppState& state, const ui::PanelState& panels);

// The page's state, for the functions JavaScript calls (web_main.cpp).
session::AppState& page_state();
const ui::FrameLayout& page_layout();  // the last frame drawn: where things were, what the tables showed
session::CameraCheck& page_check();
const ui::PanelState& page_panels();  // the frame's panel state (the tests' widget_rects hook)
void wake_page();

}  // namespace raycam::web
