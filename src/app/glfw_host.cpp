// The GLFW host and the window's loop. With main.cpp, the only files that include GLFW.
#include "app/glfw_host.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>
#include <csignal>
#include <ctime>
#include <cstdio>
#include <string>

#include "gl/gl.h"
#include "ui/renderer_backend.h"
#include "session/shown_files.h"
#include "session/text.h"

namespace raycam::app {

namespace {
volatile std::sig_atomic_t quit_signal = 0;  // SIGINT / SIGTERM: leave the loop cleanly
extern "C" void on_quit_signal(int) { quit_signal = 1; }

void toggle_fullscreen(GLFWwindow* window, int saved[4]) {
  if (glfwGetWindowMonitor(window)) {
    glfwSetWindowMonitor(window, nullptr, saved[0], saved[1], saved[2], saved[3], 0);
    return;
  }
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (!monitor) return;
  glfwGetWindowPos(window, &saved[0], &saved[1]);
  glfwGetWindowSize(window, &saved[2], &saved[3]);
  const GLFWvidmode* mode = glfwGetVideoMode(monitor);
  glfwSetWindowMonitor(window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}
}  // namespace

bool GlfwHost::should_close() const { return quit_signal || glfwWindowShouldClose(window_); }

void GlfwHost::key_pressed(int key) {
  if (key == GLFW_KEY_Q && (glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS))
    state_.requests.ask(session::HostRequestKind::quit);
}

void GlfwHost::install_own_callbacks() {
  glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { glfw_host::host_of(w).note_event(); });
  glfwSetWindowIconifyCallback(window_, [](GLFWwindow* w, int) { glfw_host::host_of(w).note_event(); });
}

void GlfwHost::wait_for_frame(const session::AppState& state, const ui::PanelState& panels) {
  forward_held_keys();  // a key's changes held since the last frame, before this frame's events
  if (scripted_) {
    glfwPollEvents();
    return;
  }
  // Sleep until there is something to draw: input (the callbacks set the settle frames), pending work, or
  // a reason to leave. A timeout only re-checks the quit signal; it draws nothing. Minimised: sleep.
  // Recording, the window also draws when the video's next frame is due (a still window is a still video,
  // and the status line's clock moves).
  for (;;) {
    const bool minimised = glfwGetWindowAttrib(window_, GLFW_ICONIFIED);
    const bool frame_due = recording_ && recording_->frame_due(recording_seconds());
    const bool busy = !minimised && (has_work(state, panels) || frame_due);
    if (busy || should_close()) break;
    const double wait = recording_ ? std::min(kIdleWaitSeconds, recording_->seconds_to_next_frame(recording_seconds()))
                                   : kIdleWaitSeconds;
    glfwWaitEventsTimeout(std::max(wait, 0.001));
  }
  spend_settle_frame();
  glfwPollEvents();
}

void GlfwHost::frame_started() {
  if (scripted_) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);  // scripted: no stray hover
}

void GlfwHost::present() { glfwSwapBuffers(window_); }

void GlfwHost::save_recording() {
  if (recording_) stop_recording();  // quitting while recording keeps the video
}

double GlfwHost::recording_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - recording_start_).count();
}

void GlfwHost::toggle_recording() {
  if (recording_) {
    stop_recording();
    return;
  }
  const std::string path = session::next_recording_path(state_);
  const int width = video::LiveRecording::even(size_.width), height = video::LiveRecording::even(size_.height);
  try {
    if (width < 2 || height < 2) throw std::runtime_error("the window has no pixels to record");
    recording_ = std::make_unique<video::LiveRecording>(path, video::VideoFormat::mp4, width, height, 30);
    recording_start_ = std::chrono::steady_clock::now();
    state_.recording = true;
    state_.recording_seconds = 0.0;
    session::set_message(state_, session::MessageSource::files, false,
                         session::trf(state_.language, "recording the window to %s (F9 stops)", path.c_str()));
  } catch (const std::exception& error) {
    session::set_message(state_, session::MessageSource::files, true,
                         session::trf(state_.language, "cannot record: %s", session::tr_reason(state_.language, error.what()).c_str()));
  }
}

void GlfwHost::stop_recording() {
  const double seconds = recording_seconds();
  std::unique_ptr<video::LiveRecording> recording = std::move(recording_);
  state_.recording = false;
  try {
    const int frames = recording->finish();
    const std::string saved = session::trf(state_.language, "wrote %s (%d:%02d, %d {{frame|frames}})", recording->path().c_str(),
                                      int(seconds) / 60, int(seconds) % 60, frames);
    session::set_message(state_, session::MessageSource::files, false, saved);
    std::printf("raycam: %s\n", saved.c_str());
  } catch (const std::exception& error) {
    session::set_message(state_, session::MessageSource::files, true,
                         session::trf(state_.language, "cannot record: %s", session::tr_reason(state_.language, error.what()).c_str()));
  }
}

void GlfwHost::frame_drawn(session::AppState& state) {
  if (state.requests.take(session::HostRequestKind::toggle_recording)) toggle_recording();
  if (!recording_) return;
  if (const std::string error = recording_->error(); !error.empty()) {  // a full disk: the encoder stopped
    stop_recording();
    return;
  }
  const double now = recording_seconds();
  state.recording_seconds = now;
  // Drawn between two video frames (a drag draws at the screen's rate): nothing to read back.
  if (!recording_->frame_due(now)) return;
  const gl::RgbaImage frame = read_back();
  recording_->add(frame.pixels.data(), frame.width, frame.height, now);
}

int run_window(const session::AppOptions& options, const ScriptedRun& run, session::AppState& state) {
  glfwSetErrorCallback([](int, const char* message) { std::fprintf(stderr, "raycam: GLFW: %s\n", message); });
  if (!glfwInit()) {
    std::fprintf(stderr,
                 "raycam: cannot open a window (no display?). For a headless render use: raycam-cli shot\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // A window larger than the screen is cut at its edge (the default 1280×720 on a 1024×768 projector): the
  // size asked for is fitted into the primary monitor's work area, and the layout follows the window's size.
  int width = options.width, height = options.height;
  int area_x = 0, area_y = 0, area_width = 0, area_height = 0;
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor())
    glfwGetMonitorWorkarea(monitor, &area_x, &area_y, &area_width, &area_height);
  if (area_width > 0 && area_height > 0) {
    width = std::min(width, area_width);
    height = std::min(height, area_height);
  }
  GLFWwindow* window = glfwCreateWindow(width, height, "raycam", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    std::fprintf(stderr, "raycam: cannot create a GL 3.3 core window\n");
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(run.frames > 0 ? 0 : 1);
  GlfwHost host(window, state, run.frames > 0);
  std::signal(SIGINT, on_quit_signal);
  std::signal(SIGTERM, on_quit_signal);
  host.start_imgui();
  int exit_code = 0;
  {
    ui::FrameRenderer frame;
    frame.panels() = ui::panel_state_for(options, state);  // --check CMD, the Open box's file
    int saved[4] = {0, 0, options.width, options.height};
    for (int drawn = 0; !host.should_close() && !state.requests.pending(session::HostRequestKind::quit);) {
      const bool last = run.frames > 0 && drawn + 1 >= run.frames;
      if (last && !run.screenshot.empty()) state.requests.ask(session::HostRequestKind::screenshot, run.screenshot);
      state.in_fullscreen = glfwGetWindowMonitor(window) != nullptr;  // the panel's button says Leave there
      const ui::FrameResult result = ui::run_frame(host, frame, state);
      if (!result.drawn) continue;
      host.apply_title();
      ++drawn;
      if (result.screenshot_failed && last) exit_code = 1;
      if (state.requests.take(session::HostRequestKind::toggle_fullscreen)) toggle_fullscreen(window, saved);
      state.requests.take(session::HostRequestKind::pick_scene_file);  // a window has no picker: typed paths
      if (last) break;
    }
  }
  host.save_recording();
  host.stop_imgui();
  glfwDestroyWindow(window);
  glfwTerminate();
  // The process's CPU time too: an idle loop that polls instead of waiting draws no frame but burns a core.
  std::printf("raycam: %lld frames drawn, %lld casts, %.0f ms of CPU\n", state.frame_count, state.cast_count,
              1000.0 * double(std::clock()) / CLOCKS_PER_SEC);
  if (exit_code != 0) std::fprintf(stderr, "raycam: error: %s\n", state.message.c_str());
  return exit_code;
}

}  // namespace raycam::app
