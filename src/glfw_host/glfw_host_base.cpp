#include "glfw_host/glfw_host_base.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>

#include "gl/gl.h"
#include "ui/renderer_backend.h"

namespace raycam::glfw_host {

GlfwHostBase& host_of(GLFWwindow* window) { return *static_cast<GlfwHostBase*>(glfwGetWindowUserPointer(window)); }

namespace {
void note(GLFWwindow* window) { host_of(window).note_event(); }
}  // namespace

GlfwHostBase::GlfwHostBase(GLFWwindow* window, session::AppState& state) : window_(window), state_(state) {
  glfwSetWindowUserPointer(window_, this);
}

void GlfwHostBase::key_callback(GLFWwindow* window, int key, int, int action, int) {
  GlfwHostBase& host = host_of(window);
  host.note_event();
  if (action != GLFW_PRESS) return;
  session::AppState& state = host.state_;
  if (key == GLFW_KEY_F1) state.show_help = !state.show_help;
  if (key == GLFW_KEY_F11 && state.host.fullscreen) state.requests.ask(session::HostRequestKind::toggle_fullscreen);
  if (key == GLFW_KEY_F12) session::request_screenshot(state, state.language);  // as the Screenshot button (the page: a download)
  if (key == GLFW_KEY_F9) state.requests.ask(session::HostRequestKind::toggle_recording);  // as the Record button
  host.key_pressed(key);
}

// Installed over ImGui's backend's key, character and mouse button callbacks (which chain to ours): a key's
// changes reach ImGui one per frame, characters in order with them, and what follows a click in the next
// frame (KeyEventQueue).
void GlfwHostBase::queued_key_callback(GLFWwindow* window, int key, int scancode, int action, int mods) {
  GlfwHostBase& host = host_of(window);
  host.note_event();
  const bool modifier = key >= GLFW_KEY_LEFT_SHIFT && key <= GLFW_KEY_RIGHT_SUPER;  // GLFW's eight modifiers
  if (action == GLFW_REPEAT || host.keys_.arrive(key, action == GLFW_PRESS, modifier))
    ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
}
void GlfwHostBase::queued_button_callback(GLFWwindow* window, int button, int action, int mods) {
  GlfwHostBase& host = host_of(window);
  host.note_event();
  if (host.keys_.arrive_button(button, action == GLFW_PRESS))
    ImGui_ImplGlfw_MouseButtonCallback(window, button, action, mods);
}
void GlfwHostBase::queued_char_callback(GLFWwindow* window, unsigned int character) {
  GlfwHostBase& host = host_of(window);
  host.note_event();
  if (host.keys_.arrive_character(character)) ImGui_ImplGlfw_CharCallback(window, character);
}

void GlfwHostBase::forward_held_keys() {
  for (const ui::KeyEventQueue::Event& e : keys_.start_frame()) {
    const int action = e.press ? GLFW_PRESS : GLFW_RELEASE;
    if (e.key >= 0) ImGui_ImplGlfw_KeyCallback(window_, e.key, 0, action, 0);
    else if (e.button >= 0) ImGui_ImplGlfw_MouseButtonCallback(window_, e.button, action, 0);
    else ImGui_ImplGlfw_CharCallback(window_, e.character);
  }
}

// A dropped file (the page's GLFW writes it into the page's file system first) opens as Open does, with the
// same checks and messages: a bad file shows its error and keeps the current scene.
void GlfwHostBase::drop_callback(GLFWwindow* window, int count, const char** paths) {
  GlfwHostBase& host = host_of(window);
  host.note_event();
  if (count > 0) session::open_scene(host.state_, paths[0]);
}

void GlfwHostBase::start_imgui() {
  // Every other event only wakes the loop (ImGui's backend installs its own after these and chains to them).
  glfwSetKeyCallback(window_, key_callback);
  glfwSetDropCallback(window_, drop_callback);
  glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned int) { note(w); });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int, int) { note(w); });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double) { note(w); });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { note(w); });
  glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { note(w); });
  glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { note(w); });
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { note(w); });
  install_own_callbacks();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  glfwSetKeyCallback(window_, queued_key_callback);  // over the backend's, which they call
  glfwSetCharCallback(window_, queued_char_callback);
  glfwSetMouseButtonCallback(window_, queued_button_callback);
  after_imgui_backend();
  ui::start_renderer_backend();
}

void GlfwHostBase::stop_imgui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void GlfwHostBase::note_event() {
  settle_frames_ = kSettleFrames;
  woken();
}

bool GlfwHostBase::has_work(const session::AppState& state, const ui::PanelState& panels) const {
  return settle_frames_ > 0 || keys_.holding() || ui::frame_needs_redraw(state, panels);
}

void GlfwHostBase::spend_settle_frame() { settle_frames_ = std::max(0, settle_frames_ - 1); }

ui::FramebufferSize GlfwHostBase::begin(const session::AppState& state, const ui::PanelState& panels) {
  wait_for_frame(state, panels);
  glfwGetFramebufferSize(window_, &size_.width, &size_.height);
  if (size_.empty() || !keeps_running()) return {};  // minimised (or leaving): no frame
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  frame_started();
  return size_;
}

gl::RgbaImage GlfwHostBase::read_back() const {
  glFinish();
  return gl::read_framebuffer(size_.width, size_.height);
}

void GlfwHostBase::apply_title() {
  if (state_.window_title == applied_title_) return;  // the UI names the mode and the scene; the host shows it
  glfwSetWindowTitle(window_, state_.window_title.c_str());
  applied_title_ = state_.window_title;
}

}  // namespace raycam::glfw_host
