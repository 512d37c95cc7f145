// Layouts that fit a lecture hall's projector: at 1×, 2× and 3× fonts on 1024×768, 1280×800 and 1920×1080, in
// both languages and both views, with every section of the panel open, a mistake shown and a ray pinned, no
// window of the frame has content wider than what it shows without a horizontal scroll bar (a text, a button
// or a box that extends past its window's clip rectangle is cut) and no window title is wider than its
// window. ImGui measures every item it lays out into its window's content size, so this reads what the frame
// itself measured, item by item.
#include <imgui.h>
#include <imgui_internal.h>

#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app_flags.h"
#include "app_options.h"
#include "headless_renderer.h"
#include "mistake_lessons.h"
#include "overhead_view.h"
#include "panels.h"

using namespace raycam;

namespace {
session::AppState lecture_state(const char* view, const char* language) {
  session::AppOptions options;
  return session::make_app_state(
      flags::parse_app_options({"--view", view, "--lang", language, "--inspect", "3,0"}, options));
}

// Opens every section of the panel, as an instructor preparing a lecture would (ImGui keeps a header's
// open state in its window's storage, under the header's id).
void open_every_section() {
  ImGuiWindow* panel = ImGui::FindWindowByName("raycam###panel");
  REQUIRE(panel);
  for (const char* id : {"###camera", "###mistakes", "###caster", "###files", "###lecture", "###construction",
                         "###inspector", "###check"})
    panel->StateStorage.SetInt(panel->GetID(id), 1);
}

// Window titles cut: a title wider than its window's title bar.
std::vector<std::string> cut_titles() {
  std::vector<std::string> cut;
  for (ImGuiWindow* window : GImGui->Windows) {
    if (!window->WasActive || window->Hidden || (window->Flags & ImGuiWindowFlags_NoTitleBar)) continue;
    const char* end = ImGui::FindRenderedTextEnd(window->Name);
    const float title = ImGui::CalcTextSize(window->Name, end).x + 2 * GImGui->Style.FramePadding.x;
    if (title > window->Size.x + 1.0f) cut.push_back("title '" + std::string(window->Name, std::size_t(end - window->Name)) + "'");
  }
  return cut;
}

// Every visible window whose laid-out content is wider than its inner width while it has no horizontal
// scroll bar, with by how much.
std::vector<std::string> cut_windows() {
  std::vector<std::string> cut;
  for (ImGuiWindow* window : GImGui->Windows) {
    if (!window->WasActive || window->Hidden || window->ScrollbarX) continue;
    const float shown = window->InnerRect.GetWidth(), content = window->ContentSize.x + window->WindowPadding.x;
    if (content > shown + 1.0f) {
      std::ostringstream out;
      out << "'" << window->Name << "' content " << content << " px in " << shown << " px";
      cut.push_back(out.str());
    }
  }
  return cut;
}

}  // namespace

TEST_CASE("at 1x to 3x on 1024x768 to 1920x1080, in both languages, no window's content is cut",
          "[render][lecture][layout]") {
  struct Screen {
    int width, height;
  };
  int checked = 0;
  for (const Screen screen : {Screen{1024, 768}, Screen{1280, 800}, Screen{1920, 1080}})
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* language : {"fr", "en"})
        for (const char* view : {"2d", "3d"}) {
          session::AppState state = lecture_state(view, language);
          state.font_scale = scale;
          session::show_mistake(state, *session::find_lesson("pixel_edges"));
          if (std::string(view) == "3d") state.res_rows = 0.5;  // non-square: the res_c and res_l sliders
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          renderer.run_frame(state);
          open_every_section();
          renderer.render_settled(state, 4);
          std::vector<std::string> cut = cut_windows();
          for (const std::string& title : cut_titles()) cut.push_back(title);
          std::string all;
          for (const std::string& c : cut) all += "\n  " + c;
          INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << language << ", " << view << ":"
                            << all);
          CHECK(cut.empty());
          ++checked;
        }
  CHECK(checked == 36);
}

// The overhead view's landmark labels never print over each other, however big the font and however close
// their anchors ("k = 0" over "eye's left (column 0)" at 3× in a narrow view), and stay inside the view.
TEST_CASE("a label placed beside others moves off them and stays in the view", "[render][lecture][layout]") {
  const ImVec2 low{0, 0}, high{400, 300}, size{180, 45};
  std::vector<std::pair<ImVec2, ImVec2>> placed = {{{100, 100}, {200, 45}}};
  for (const ImVec2 wanted : {ImVec2{110, 100}, ImVec2{250, 120}, ImVec2{390, 290}, ImVec2{-50, -50}}) {
    const ImVec2 at = ui::place_label(wanted, size, low, high, placed);
    INFO(wanted.x << "," << wanted.y << " -> " << at.x << "," << at.y);
    for (const auto& [q, s] : placed)
      CHECK_FALSE((at.x < q.x + s.x && q.x < at.x + size.x && at.y < q.y + s.y && q.y < at.y + size.y));
    CHECK((at.x >= low.x && at.y >= low.y && at.x + size.x <= high.x && at.y + size.y <= high.y));
    placed.push_back({at, size});
  }
}
