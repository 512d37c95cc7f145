// Section index: the panel section · the overlay.
#include "ui/check_panel.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <imgui.h>
#include <imgui_internal.h>  // ImGui::ScrollToItem
#include <imgui_stdlib.h>

#include "check/check_texts.h"
#include "ui/panels.h"
#include "session/shown_files.h"
#include "ui/words.h"
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

// ---- the panel section -----------------------------------------------------------------------------------
namespace {
// A verdict that has just arrived is brought into sight: the first one opens the section (a program given on
// the command line), and each is scrolled into the panel's view once, its first lines and the next step with
// it (what the diagnosis says, else the clear button: the last section is below the fold at lecture sizes);
// the panel is the instructor's to scroll after that. A verdict the student asked for (Check now, the page's
// answer file: the page grades nothing by itself) is scrolled at once; one that came by itself (automatic
// checks) never while the mouse is over the panel: a panel that moves under the mouse turns the next click
// into a click on another control (with automatic checks on, every Open brings a verdict); that scroll waits
// until the mouse leaves it.
struct VerdictInView {
  std::weak_ptr<const KeyedVerdict> shown;  // keeps its control block: a new verdict never matches it
  bool any = false;
  ImVec4 drawn_at{0, 0, 0, 0};       // where the verdict was last drawn
  ImVec4 next_step_at{0, 0, 0, 0};   // the verdict down to the next step, as last drawn
  bool scroll_pending = false;        // arrived, not yet scrolled into view
  bool asked = false;                 // the student asked for it: scrolled even under the mouse
  bool check_now_clicked = false;     // Check now was clicked: the next verdict is asked for
  std::vector<std::string> lines;     // what the verdict's part of the section said, for the tests
  bool arrived(const CheckProgress& progress) const {
    return progress.latest && !progress.running &&
           (shown.owner_before(progress.latest) || progress.latest.owner_before(shown));
  }
};
VerdictInView& verdict_in_view() {
  static VerdictInView in_view;
  return in_view;
}
}  // namespace

void check_section(CameraCheck& check, const HostCapabilities& host, double now, Language language,
                   const std::string& mistakes) {
  const CheckProgress progress = check.progress();
  VerdictInView& in_view = verdict_in_view();
  const bool arrived = in_view.arrived(progress);
  if (arrived && !in_view.any) ImGui::SetNextItemOpen(true);
  if (arrived) {
    const bool asked = !host.runs_programs || in_view.check_now_clicked;
    in_view = VerdictInView{};
    in_view.shown = progress.latest;
    in_view.any = true;
    in_view.scroll_pending = true;
    in_view.asked = asked;
  }
  if (!ui::section(tr(language, "Check my camera###check"), tr(language, "Check###check"))) return;
  CheckRequest& request = check.request();
  ImGui::PushStyleColor(ImGuiCol_Text, current_theme().hint);
  if (host.runs_programs)
    wrapped_between_words(tr(language, "Your program reads this camera and scene as JSON on stdin and prints {\"ids\": …}; "
                             "it is checked whenever they change: every pixel must equal raycam's, except those where a ray "
                             "grazes an object."));
  else  // a page runs no program: the student's route, step by step
    for (const char* step : {tr_later("Your program reads a case (a camera and its scene) as JSON on stdin and "
                                      "prints {\"ids\": …}; a page cannot run it, so:"),
                             tr_later("1. download this camera's case;"),
                             tr_later("2. run your program on it: python3 my_camera.py < raycam-case.json > "
                                      "answer.json;"),
                             tr_later("3. give the answer file: it is graded for the camera of that case, every pixel "
                                      "against raycam's.")})
      wrapped_between_words(tr(language, step));
  ImGui::PopStyleColor();
  if (!host.runs_programs) {  // a page: the case goes out as a download, the answer file comes back
    if (button(tr(language, "Download this camera's case###check_case"))) request.download_case = true;
    if (button(tr(language, "Give the answer file…###check_answer"))) request.pick_answer = true;
    if (!request.command.empty())
      wrapped_between_words(trf(language, "answer file: %s", shown_file_name(host, request.command).c_str()));
  } else {
    const std::string label = tr(language, "program###check_command");  // above its box, which takes the whole width
    wrapped_between_words(label.substr(0, label.find("##")));
    ImGui::SetNextItemWidth(-FLT_MIN);
    ImGui::InputText("###check_command", &request.command);
    checkbox(tr(language, "an answer file, not a program###check_is_file"), &request.is_file);
    checkbox(tr(language, "check when the camera changes###check_auto"), &request.automatic);
    if (button(tr(language, "Check now###check_now"))) request.check_now = in_view.check_now_clicked = true;
  }

  if (progress.running) wrapped_between_words(trf(language, "running… (%.1f s)", now - progress.started_at));
  if (!progress.running && !progress.latest && !host.runs_programs) wrapped_between_words(tr(language, "no answer yet"));
  if (progress.running || !progress.latest) return;  // a re-run: the old verdict is no longer this camera's
  const check::CaseVerdict& v = progress.latest->verdict;
  const check::CaseResult& r = v.result;
  // A verdict for an earlier camera is greyed, whatever it says: never a red fail for a camera it was not for.
  const ImVec4 colour = !progress.current                       ? current_theme().hint
                        : r.status == check::CaseStatus::pass ? current_theme().confirmation
                                                              : current_theme().error;
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::BeginGroup();  // one item: the verdict
  if (r.status == check::CaseStatus::pass)
    wrapped_between_words(tr(language, "pass: every pixel agrees"));
  else if (r.status == check::CaseStatus::fail) {
    wrapped_between_words(trf(language, "fail: %lld of %lld {{pixel|pixels}} wrong (in red on the image)", r.wrong_pixels, r.pixels));
    // Found on the image by their frames, and in the answer file by their place: row, column of the ids.
    wrapped_between_words(trf(language, "wrong pixels (row, column), framed on the image: %s", wrong_pixels_named(v).c_str()));
  }
  else
    wrapped_between_words(trf(language, "%s: %s", check::text(language, check::status_name(r.status)),
                              with_file_shown(host, tr_reason(language, r.detail), request.command).c_str()));
  ImGui::EndGroup();
  const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();  // the verdict
  if (host.runs_programs) {
    if (!progress.current) wrapped_between_words(tr(language, "(for the camera before your last change)"));
  } else {
    wrapped_between_words(!progress.current ? tr(language, "answer for an earlier camera: download the new case")
                          : mistakes.empty()
                              ? tr(language, "graded for the camera shown")
                              : trf(language, "graded for the downloaded case: the image shown shows the mistake « %s »",
                                    mistakes.c_str()));
  }
  in_view.drawn_at = {low.x, low.y, high.x, high.y};
  ImGui::PopStyleColor();
  if (button(tr(language, "Clear the verdict###check_clear"))) {
    check.clear();
    return;
  }
  float next_step_bottom = ImGui::GetItemRectMax().y;  // the clear button, unless a diagnosis says more
  if (!v.sandboxed && !request.is_file) wrapped_between_words(tr(language, "no sandbox: bubblewrap is not available here"));
  in_view.lines.clear();
  // Only an image of the right size is an image a classic mistake could make (a bad-size answer is not).
  if (v.diagnosed && v.diagnosis.empty() && r.status == check::CaseStatus::fail) {
    in_view.lines.push_back(tr(language, "no classic mistake reproduces this image"));
    ImGui::TextWrapped("%s", in_view.lines.back().c_str());
    next_step_bottom = ImGui::GetItemRectMax().y;
  }
  if (!v.diagnosis.empty()) {  // the bullets' heading: what they are
    in_view.lines.push_back(tr(language, "Classic mistakes that make this same image:"));
    wrapped_between_words(in_view.lines.back());
  }
  for (const check::Explanation& e : v.diagnosis) {
    ImGui::Bullet();
    // The mistakes' names in the window's language, not their ids ("mirrored + rows from the bottom").
    std::string names;
    for (const MistakeInfo* m : e.mistakes) names += (names.empty() ? "" : " + ") + std::string(m->label[language]);
    in_view.lines.push_back(trf(language, "%s: %s", names.c_str(), e.text(language).c_str()));
    wrapped_between_words(in_view.lines.back());
    if (&e == &v.diagnosis.front()) next_step_bottom = ImGui::GetItemRectMax().y;
  }
  in_view.next_step_at = {low.x, low.y, high.x, next_step_bottom};
  // ImGui counts a window as not hovered while one of its controls is held (a click on a box, a slider, a
  // header): an automatic verdict's scroll waits for the mouse itself to be elsewhere, with no button down.
  const bool mouse_on_panel =
      ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows | ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
  if (in_view.scroll_pending && (in_view.asked || (!mouse_on_panel && !ImGui::IsAnyMouseDown()))) {
    // The least scroll that shows the verdict and the next step; the verdict's top first when both do not fit.
    ImGui::ScrollToRect(ImGui::GetCurrentWindow(), ImRect(low, {high.x, next_step_bottom}));
    in_view.scroll_pending = in_view.asked = in_view.check_now_clicked = false;
  }
  if (!r.stderr_text.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, current_theme().hint);
    ImGui::TextWrapped("%s", r.stderr_text.substr(0, 600).c_str());
    ImGui::PopStyleColor();
  }
}

ImVec4 drawn_verdict_rect() { return verdict_in_view().drawn_at; }
ImVec4 drawn_next_step_rect() { return verdict_in_view().next_step_at; }
std::vector<std::string> drawn_diagnosis_lines() { return verdict_in_view().lines; }

// ---- the overlay -----------------------------------------------------------------------------------------
void check_overlay(const CameraCheck& check, const Lesson& state, const CastCache& cast, ImDrawList* list, float x0, float y0,
                   float x1, float y1) {
  const CheckProgress progress = check.progress();
  if (!progress.latest || !progress.current) return;  // only over the image it was made for
  const check::CaseVerdict& v = progress.latest->verdict;
  if (v.dimension != dimension(state) || v.columns != cast.map.width || v.rows != cast.map.height) return;
  const float cw = (x1 - x0) / float(v.columns), ch = (y1 - y0) / float(v.rows);
  // The image's column of the answer's column, and back: a 2D bar shows pixel k = n-1-column (its own inverse).
  const auto image_column = [&](int c) { return v.dimension == 2 ? v.columns - 1 - c : c; };
  const ImU32 red = IM_COL32(255, 0, 0, 120);  // translucent: the student's mistake stays visible underneath
  // One rectangle per run of wrong pixels along a row: few rectangles even when most of the image is wrong.
  for (int row = 0; row < v.rows; ++row)
    for (int column = 0; column < v.columns;) {
      // The image's column `column`; a 2D bar shows pixel k = n-1-column there.
      auto wrong_at = [&](int c) {
        return v.wrong[std::size_t(row) * std::size_t(v.columns) + std::size_t(image_column(c))] != 0;
      };
      if (!wrong_at(column)) {
        ++column;
        continue;
      }
      int end = column;
      while (end < v.columns && wrong_at(end)) ++end;
      list->AddRectFilled({x0 + column * cw, y0 + row * ch}, {x0 + end * cw, y0 + (row + 1) * ch}, red);
      column = end;
    }
  // The pixels the verdict names, each in a black and a white frame: one of the two stands out on any colour
  // (a red tint alone vanished on a red sphere), and a frame at least a few screen pixels wide around a pixel
  // that is smaller on screen.
  const float thick = std::max(1.0f, std::round(ImGui::GetFontSize() / 8.0f));
  for (const WrongPixel& p : first_wrong_pixels(v, kNamedWrongPixels)) {
    const int column = image_column(p.column);
    const ImVec2 centre{x0 + (column + 0.5f) * cw, y0 + (p.row + 0.5f) * ch};
    const ImVec2 half{std::max(cw / 2, 2 * thick) + thick, std::max(ch / 2, 2 * thick) + thick};
    list->AddRect({centre.x - half.x, centre.y - half.y}, {centre.x + half.x, centre.y + half.y}, IM_COL32(255, 255, 255, 255), 0, 0, thick);
    list->AddRect({centre.x - half.x - thick, centre.y - half.y - thick}, {centre.x + half.x + thick, centre.y + half.y + thick},
                  IM_COL32(0, 0, 0, 255), 0, 0, thick);
  }
}

}  // namespace raycam::ui
