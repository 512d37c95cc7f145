#include "ui/renderer_backend.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace raycam::ui {

namespace {
#ifdef __EMSCRIPTEN__
constexpr const char* kGlslVersion = "#version 300 es";
#else
constexpr const char* kGlslVersion = "#version 330 core";
#endif
}  // namespace

void start_renderer_backend() { ImGui_ImplOpenGL3_Init(kGlslVersion); }

void restart_renderer_backend() {
  // Not ImGui_ImplOpenGL3_DestroyDeviceObjects alone: in Dear ImGui 1.86 it deletes the vertex and index
  // buffers but keeps their sizes, so the new buffers would never be given storage (WebGL: "bufferSubData:
  // buffer overflow", a blank page). A new backend starts with sizes of zero.
  // No backend (the null host draws nothing): the font atlas stays on the CPU, nothing to restart.
  if (!ImGui::GetIO().BackendRendererUserData) return;
  ImGui_ImplOpenGL3_Shutdown();
  start_renderer_backend();
}

}  // namespace raycam::ui
