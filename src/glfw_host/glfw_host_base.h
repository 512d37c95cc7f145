// The GLFW host that the desktop window (glfw_host.h) and the browser page (src/web/web_host.h) both are:
// the input callbacks (each wakes the loop for a few settle frames, so that ImGui's press, release and hover
// settle), the keys every host understands (F1 help, F11 full screen where the host can, F12 screenshot, a
// dropped scene file), Dear ImGui's set-up on the window, the frame's start, the read-back and the title.
// Key changes reach ImGui one per frame (key_queue.h): a tap, down and up between two frames, is seen.
// A host overrides only its loop (how it waits for the next frame) and its routes for files and keys.
#pragma once

#include "ui/frame_host.h"
#include "ui/key_queue.h"

struct GLFWwindow;

namespace raycam::glfw_host {

class GlfwHostBase : public ui::FrameHost {
 public:
  // After each event, this many frames are drawn without waiting (press, release, hover settle).
  static constexpr int kSettleFrames = 3;

  GlfwHostBase(GLFWwindow* window, session::AppState& state);
  GlfwHostBase(const GlfwHostBase&) = delete;
  GlfwHostBase& operator=(const GlfwHostBase&) = delete;

  // The window's callbacks, then Dear ImGui with its GLFW and GL backends (which chain to the callbacks).
  // Needs the window's GL context current.
  void start_imgui();
  void stop_imgui();

  ui::FramebufferSize begin(const session::AppState& state, const ui::PanelState& panels) override;
  gl::RgbaImage read_back() const override;

  // Called by every callback: draw the next frames.
  void note_event();
  // The title the frame names (mode and scene), applied when it changed.
  void apply_title();

 protected:
  // True while the loop must draw without waiting: settle frames left, or the state's or the panels'
  // pending work.
  bool has_work(const session::AppState& state, const ui::PanelState& panels) const;
  void spend_settle_frame();
  // The key changes held since ImGui last read the keys, to ImGui now: call right after a frame read them and
  // before new events arrive (the window: before it polls; the page: after each frame it draws).
  void forward_held_keys();

  // ---- what a host overrides ----
  // Before the frame: a desktop window sleeps here until there is something to draw.
  virtual void wait_for_frame(const session::AppState&, const ui::PanelState&) {}
  // False: no frame (the window is closing).
  virtual bool keeps_running() const { return true; }
  // After ImGui's frame started (a scripted run hides the mouse).
  virtual void frame_started() {}
  // After note_event() (a paused page resumes its loop).
  virtual void woken() {}
  // A key pressed that only this host knows (the desktop's Ctrl+Q).
  virtual void key_pressed(int) {}
  // Callbacks only this host installs, and what it adds over ImGui's backend (before start_renderer_backend).
  virtual void install_own_callbacks() {}
  virtual void after_imgui_backend() {}

  GLFWwindow* window_;
  session::AppState& state_;
  int settle_frames_ = kSettleFrames;  // the first frames draw at once
  ui::FramebufferSize size_;

 private:
  static void key_callback(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void drop_callback(GLFWwindow* window, int count, const char** paths);
  static void queued_key_callback(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void queued_char_callback(GLFWwindow* window, unsigned int character);
  static void queued_button_callback(GLFWwindow* window, int button, int action, int mods);
  ui::KeyEventQueue keys_;
  std::string applied_title_ = "raycam";
};

// The host a GLFW callback belongs to (the window's user pointer).
GlfwHostBase& host_of(GLFWwindow* window);

}  // namespace raycam::glfw_host
