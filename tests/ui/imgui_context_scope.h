// What a host sets up around its frames, for the ui tests that run frames on the null host: an ImGui context
// for the scope, writing no imgui.ini.
#pragma once

#include <imgui.h>

namespace raycam::test {
struct ImGuiContextScope {
  ImGuiContextScope() {
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
  }
  ~ImGuiContextScope() { ImGui::DestroyContext(); }
  ImGuiContextScope(const ImGuiContextScope&) = delete;
  ImGuiContextScope& operator=(const ImGuiContextScope&) = delete;
};
}  // namespace raycam::test
