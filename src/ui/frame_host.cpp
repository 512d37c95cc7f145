#include "ui/frame_host.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cmath>
#include <exception>

#include "gl/gl.h"
#include "session/shown_files.h"
#include "ui/words.h"
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

FrameResult run_frame(FrameHost& host, FrameRenderer& frame, AppState& state) {
  FrameResult result;
  prepare_frame(state, host.pixel_density());  // fonts at the current scale, before the backend's frame
  const FramebufferSize size = host.begin(state, frame.panels());
  if (size.empty()) return result;
  const auto start = std::chrono::steady_clock::now();
  ImGui::NewFrame();
  // Laid out in UI pixels: the framebuffer's size over the host's pixel density (ImGui's DisplaySize).
  const ImVec2 ui_size = ImGui::GetIO().DisplaySize;
  result.layout = frame.build(state, int(std::lround(ui_size.x)), int(std::lround(ui_size.y)));
  ImGui::Render();
  host.draw(size);
  if (const auto shot = state.requests.take(HostRequestKind::screenshot)) {
    const std::string path = shot->path.empty() ? "raycam-screenshot.png" : shot->path;
    try {
      gl::write_png(host.read_back(), path);
      set_message(state, MessageSource::files, false, written_message(state.host, state.language, path));
    } catch (const std::exception& error) {
      set_message(state, MessageSource::files, true, with_file_shown(state.host, tr_reason(state.language, error.what()), path));
      result.screenshot_failed = true;
    }
  }
  host.frame_drawn(state);
  host.present();
  state.frame_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.drawn = true;
  return result;
}

void FrameHost::draw(const FramebufferSize& size) {
  glViewport(0, 0, size.width, size.height);
  const ImVec4 clear = current_theme().clear;  // the colour the theme's contrast was computed against
  glClearColor(clear.x, clear.y, clear.z, clear.w);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

FramebufferSize NullHost::begin(const session::AppState&, const PanelState&) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(float(size_.width), float(size_.height));
  io.DeltaTime = 1.0f / 60.0f;
  if (!io.Fonts->IsBuilt()) {  // what a renderer backend's first frame does, without a texture
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsAlpha8(&pixels, &width, &height);
  }
  return size_;
}

bool frame_needs_redraw(const AppState& state, const PanelState& panels) {
  const HostRequests& asked = state.requests;
  return state.cameras_dirty || state.refine_pending || asked.pending(HostRequestKind::screenshot) ||
         asked.pending(HostRequestKind::toggle_fullscreen) || asked.pending(HostRequestKind::quit) ||
         panels.check_waiting || (!state.message.empty() && !state.message_is_error);  // a confirmation goes by itself
}

}  // namespace raycam::ui
