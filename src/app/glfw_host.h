// The GLFW window as a FrameHost (frame_host.h): the interactive raycam window. Idle costs nothing: with no
// input and nothing pending, begin() sleeps in glfwWaitEventsTimeout until an event (input, a dropped file,
// a resize, a signal to quit) arrives; minimised, it sleeps until restored. It keeps drawing, without
// waiting, while the state has work pending (ui::frame_needs_redraw) and for a few frames after each event,
// so that ImGui's hover and click states settle.
#pragma once

#include <string>

#include "app_options.h"
#include "frame_host.h"
#include "key_queue.h"

struct GLFWwindow;

namespace raycam::app {

// What an unattended run does: 0 frames = interactive; N = draw N frames without waiting, then exit.
struct ScriptedRun {
  int frames = 0;
  std::string screenshot;  // with frames: the last frame's PNG
};

// Opens the window, runs the loop until the user quits (window closed, Ctrl+Q, SIGINT or SIGTERM), and
// returns the process's exit code. Prints one line at exit: frames drawn, casts and the CPU time used.
int run_window(const session::AppOptions& options, const ScriptedRun& run, session::AppState& state);

class GlfwHost : public ui::FrameHost {
 public:
  // After each event, this many frames are drawn without waiting (press, release, hover settle).
  static constexpr int kSettleFrames = 3;
  // The longest sleep between two checks of the quit signal; a timeout draws nothing.
  static constexpr double kIdleWaitSeconds = 0.25;

  GlfwHost(GLFWwindow* window, bool scripted) : window_(window), scripted_(scripted) {}
  ui::FramebufferSize begin(const session::AppState& state) override;
  void present() override;
  gl::RgbaImage read_back() const override;

  void note_event() { settle_frames_ = kSettleFrames; }  // called by every GLFW callback
  bool should_close() const;
  ui::KeyEventQueue& keys() { return keys_; }  // key events spread over frames (key_queue.h)

 private:
  GLFWwindow* window_;
  bool scripted_;
  int settle_frames_ = kSettleFrames;  // the first frames draw at once
  ui::FramebufferSize size_;
  ui::KeyEventQueue keys_;
};

}  // namespace raycam::app
