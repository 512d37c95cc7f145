#include "frame_host.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <exception>

#include "gl.h"
#include "text.h"
#include "theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

FrameResult run_frame(FrameHost& host, FrameRenderer& frame, AppState& state) {
  FrameResult result;
  prepare_frame(state);  // fonts at the current scale, before the backend's frame
  const FramebufferSize size = host.begin(state);
  if (size.empty()) return result;
  const auto start = std::chrono::steady_clock::now();
  ImGui::NewFrame();
  result.layout = frame.build(state, size.width, size.height);
  ImGui::Render();
  glViewport(0, 0, size.width, size.height);
  const ImVec4 clear = current_theme().clear;  // the colour the theme's contrast was computed against
  glClearColor(clear.x, clear.y, clear.z, clear.w);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (state.request_screenshot) {
    const std::string path = state.screenshot_path.empty() ? "raycam-screenshot.png" : state.screenshot_path;
    try {
      glFinish();
      gl::write_png(host.read_back(), path);
      set_message(state, MessageSource::files, false, trf("wrote %s", path.c_str()));
    } catch (const std::exception& error) {
      set_message(state, MessageSource::files, true, tr_reason(error.what()));
      result.screenshot_failed = true;
    }
    state.request_screenshot = false;
  }
  host.present();
  state.frame_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.drawn = true;
  return result;
}

bool frame_needs_redraw(const AppState& state) {
  return state.cameras_dirty || state.refine_pending || state.request_screenshot ||
         state.request_fullscreen || state.request_quit || state.check_waiting;
}

}  // namespace raycam::ui
