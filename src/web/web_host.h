// The browser page as a FrameHost (ui/frame_host.h): emscripten's GLFW on a WebGL 2 canvas. The browser
// owns the loop: each animation frame calls tick(), which draws only while something changed (an event,
// then a few settle frames, or the state's pending work) and otherwise pauses the loop until the next event,
// so an idle page casts and draws nothing, like the desktop window asleep in glfwWaitEvents.
#pragma once

#include "frame.h"
#include "frame_host.h"

struct GLFWwindow;

namespace raycam::web {

class WebHost : public ui::FrameHost {
 public:
  static constexpr int kSettleFrames = 3;  // as the desktop's: press, release, hover settle

  explicit WebHost(GLFWwindow* window) : window_(window) {}
  ui::FramebufferSize begin(const session::AppState& state) override;
  void present() override {}  // the browser shows the canvas when the animation frame returns
  gl::RgbaImage read_back() const override;

  // Called by every input callback: draw the next frames, waking the loop if it sleeps.
  void note_event();
  // True when this animation frame has something to draw; false puts the loop to sleep.
  bool wants_frame(const session::AppState& state);

 private:
  GLFWwindow* window_;
  int settle_frames_ = kSettleFrames;
  bool sleeping_ = false;
  ui::FramebufferSize size_;
};

// Creates the canvas's context and ImGui, then hands the loop to the browser (never returns to main's
// caller in the usual sense: emscripten keeps the runtime alive).
void run_page(session::AppState& state);

// The page's state, for the functions JavaScript calls (web_main.cpp).
session::AppState& page_state();
const ui::FrameLayout& page_layout();  // the last frame drawn: where things were, what the tables showed
session::CameraCheck& page_check();
// Check my camera: a case was downloaded, and the camera or scene on screen is no longer that case's.
bool camera_changed_since_case_download();         // Check my camera's, for the answer file the page is given
void wake_page();

}  // namespace raycam::web
