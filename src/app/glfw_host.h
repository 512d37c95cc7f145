// The GLFW window as a FrameHost (frame_host.h, over glfw_host_base.h): the interactive raycam window. Idle
// costs nothing: with no input and nothing pending, begin() sleeps in glfwWaitEventsTimeout until an event
// (input, a dropped file, a resize, a signal to quit) arrives; minimised, it sleeps until restored. It keeps
// drawing, without waiting, while the state has work pending (ui::frame_needs_redraw) and for a few frames
// after each event, so that ImGui's hover and click states settle.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "session/app_options.h"
#include "glfw_host/glfw_host_base.h"
#include "video/live_recording.h"

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

// The desktop's loop over the shared GLFW host: it sleeps until there is something to draw, toggles full
// screen and quits on Ctrl+Q.
class GlfwHost : public glfw_host::GlfwHostBase {
 public:
  // The longest sleep between two checks of the quit signal; a timeout draws nothing.
  static constexpr double kIdleWaitSeconds = 0.25;

  GlfwHost(GLFWwindow* window, session::AppState& state, bool scripted)
      : glfw_host::GlfwHostBase(window, state), scripted_(scripted) {}
  void present() override;
  void frame_drawn(session::AppState& state) override;

  bool should_close() const;
  // F9 or the Record button: starts a recording of the window (an MP4 named after the scene, numbered, in
  // the working folder) or stops it and says where it went. At exit a recording under way is saved.
  void toggle_recording();
  // Stops a recording under way and saves it (the loop's end: quitting while recording keeps the video).
  void save_recording();

 private:
  void wait_for_frame(const session::AppState& state, const ui::PanelState& panels) override;
  bool keeps_running() const override { return !should_close(); }
  void frame_started() override;
  void key_pressed(int key) override;
  void install_own_callbacks() override;

  void stop_recording();
  double recording_seconds() const;

  bool scripted_;
  std::unique_ptr<video::LiveRecording> recording_;
  std::chrono::steady_clock::time_point recording_start_;
};

}  // namespace raycam::app
