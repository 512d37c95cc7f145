// The browser page as a FrameHost (the shared GLFW host, src/app/glfw_host_base.h): emscripten's GLFW on a
// WebGL 2 canvas; the page overrides only its loop and its file routes. The browser
// owns the loop: each animation frame calls tick(), which draws only while something changed (an event,
// then a few settle frames, or the state's pending work) and otherwise pauses the loop until the next event,
// so an idle page casts and draws nothing, like the desktop window asleep in glfwWaitEvents.
#pragma once

#include "frame.h"
#include "glfw_host_base.h"

struct GLFWwindow;

namespace raycam::web {

class WebHost : public app::GlfwHostBase {
 public:
  WebHost(GLFWwindow* window, session::AppState& state) : GlfwHostBase(window, state) {}
  void present() override {}  // the browser shows the canvas when the animation frame returns

  // True when this animation frame has something to draw; false puts the loop to sleep until an event.
  bool wants_frame(const session::AppState& state);

 private:
  void woken() override;  // a paused loop resumes
  void after_imgui_backend() override;  // the page's own wheel listener

  bool sleeping_ = false;
};

// Creates the canvas's context and ImGui, then hands the loop to the browser (never returns to main's
// caller in the usual sense: emscripten keeps the runtime alive).
void run_page(session::AppState& state);

// The page's state, for the functions JavaScript calls (web_main.cpp).
session::AppState& page_state();
const ui::FrameLayout& page_layout();  // the last frame drawn: where things were, what the tables showed
session::CameraCheck& page_check();
void wake_page();

}  // namespace raycam::web
