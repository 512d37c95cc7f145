// The widgets the control panel's sections share: labels beside or above their widget, text wrapped between
// words, checkboxes and buttons whose labels are never cut, section headers, hints, the "Replace it?" question.
#include "ui/panel_widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "session/figure_export.h"
#include "ui/image_header.h"  // ellipsized
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
// `text` in lines no wider than `width`, broken between words only (at spaces and newlines): ImGui's own
// wrapping also breaks after '.' and ',', inside numbers ("67." / "4°"). A word wider than a whole line
// keeps a line of its own.
std::vector<std::string> lines_between_words(const std::string& text, float width) {
  std::vector<std::string> lines;
  std::string line;
  bool open = false;  // a line has started (it may be empty: a blank line)
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = std::min(text.find_first_of(" \n", at), text.size());
    const std::string word = text.substr(at, end - at);
    const std::string longer = open ? line + " " + word : word;
    if (open && !line.empty() && ImGui::CalcTextSize(longer.c_str()).x > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    open = true;
    if (end < text.size() && text[end] == '\n') {
      lines.push_back(line);
      line.clear();
      open = false;
    }
    at = end + 1;
  }
  if (open) lines.push_back(line);
  return lines;
}

// The widest label of the LabelGroup alive now (0 when none).
float g_group_label_width = 0.0f;
}  // namespace

LabelParts label_parts(const char* label) {
  const std::string text = label;
  const std::size_t hidden = text.find("##"), id = text.find("###");
  return {text.substr(0, hidden), id != std::string::npos ? text.substr(id) : "###" + text.substr(0, hidden)};
}

void record_item_rect(const PanelState& panels, const std::string& id) {
  if (!panels.widget_rects) return;
  const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
  (*panels.widget_rects)[id] = {low.x, low.y, high.x, high.y};
}

LabelGroup::LabelGroup(std::initializer_list<const char*> labels) {
  for (const char* label : labels)
    g_group_label_width = std::max(g_group_label_width, ImGui::CalcTextSize(label_parts(label).shown.c_str()).x +
                                                            ImGui::GetStyle().ItemInnerSpacing.x);
}
LabelGroup::~LabelGroup() { g_group_label_width = 0.0f; }

bool labelled(const PanelState& panels, const char* label, const std::function<bool(const char*)>& widget,
              float widget_min_width) {
  const LabelParts parts = label_parts(label);
  const std::string& shown = parts.shown;
  const std::string& id = parts.id;
  const float avail = ImGui::GetContentRegionAvail().x;
  const float label_width = ImGui::CalcTextSize(shown.c_str()).x + ImGui::GetStyle().ItemInnerSpacing.x;
  const float deciding_width = std::max(g_group_label_width, label_width);  // its group's widest
  bool changed = false;
  if (deciding_width <= avail * 0.45f && avail - deciding_width >= widget_min_width) {
    ImGui::SetNextItemWidth(avail - label_width);
    changed = widget((shown + id).c_str());  // the same id as above its widget
  } else {
    wrapped_between_words(shown);
    ImGui::SetNextItemWidth(avail);
    changed = widget(id.c_str());
  }
  record_item_rect(panels, id);
  return changed;
}

void same_line_if_fits(float width) {
  const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

double without_negative_zero(double value, int decimals) {
  return std::abs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value;
}

void explain(const char* text) {
  // French typography (the core's texts, e.g. the mistakes', are written with plain spaces).
  const std::string shown = with_no_break_spaces(text);
  ImGui::PushStyleColor(ImGuiCol_Text, current_theme().hint);
  wrapped_between_words(shown);
  ImGui::PopStyleColor();
}

ReplaceAnswer replace_question(Language language, const PanelState& panels, const std::vector<std::string>& files,
                               const std::string& id, bool just_asked) {
  ImGui::PushStyleColor(ImGuiCol_Text, current_theme().error);
  ImGui::TextWrapped("%s", figure_replace_question(language, files).c_str());
  ImGui::PopStyleColor();
  ReplaceAnswer answer = ReplaceAnswer::waiting;
  if (button((tr(language, "Replace") + ("###" + id + "_replace")).c_str())) answer = ReplaceAnswer::replace;
  record_item_rect(panels, "###" + id + "_replace");
  same_line_if_fits(ImGui::CalcTextSize(tr(language, "Cancel")).x + 2 * ImGui::GetStyle().FramePadding.x);
  if (button((tr(language, "Cancel") + ("###" + id + "_cancel")).c_str())) answer = ReplaceAnswer::cancel;
  record_item_rect(panels, "###" + id + "_cancel");
  if (just_asked) ImGui::SetScrollHereY(1.0f);
  return answer;
}

std::string combo_preview(const PanelState& panels, const std::string& id, const char* name) {
  const float room = ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 2 * ImGui::GetStyle().FramePadding.x;
  const std::string whole = name;
  const std::string shown = ImGui::CalcTextSize(name).x <= room ? whole : ellipsized(whole.substr(0, whole.find(" (")), room);
  if (panels.widget_rects) (*panels.widget_rects)[id + "/preview"] = {0, 0, ImGui::CalcTextSize(shown.c_str()).x, 0};
  return shown;
}

// Text wrapped at the panel's edge between words; a word wider than the whole line wraps inside (rather
// than be cut).
void wrapped_between_words(const std::string& text) {
  const float width = ImGui::GetContentRegionAvail().x;
  for (const std::string& line : lines_between_words(text, width)) {
    if (ImGui::CalcTextSize(line.c_str()).x <= width) ImGui::TextUnformatted(line.c_str());
    else ImGui::TextWrapped("%s", line.c_str());
  }
}

// A checkbox whose label wraps under itself when the line is too short for it (lecture sizes): the label
// is never cut. Clicking the label toggles too, as with ImGui's own checkbox.
bool checkbox(const char* label, bool* value) {
  const float box = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x;
  if (box + ImGui::CalcTextSize(label, nullptr, true).x <= ImGui::GetContentRegionAvail().x)
    return ImGui::Checkbox(label, value);
  ImGui::PushID(label);
  bool changed = ImGui::Checkbox("##box", value);
  ImGui::PopID();
  ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::BeginGroup();  // the label's lines start beside the box, not under it
  wrapped_between_words(label_parts(label).shown);
  ImGui::EndGroup();
  if (ImGui::IsItemClicked()) {
    *value = !*value;
    changed = true;
  }
  return changed;
}

// A button whose label goes over several lines when it does not fit the panel's width (lecture sizes): a
// button's text is never cut. Its id stays the one of the label as given.
bool button(const char* label) {
  const LabelParts parts = label_parts(label);
  const float room = ImGui::GetContentRegionAvail().x - 2 * ImGui::GetStyle().FramePadding.x;
  std::string lines;
  for (const std::string& line : lines_between_words(parts.shown, room)) lines += (lines.empty() ? "" : "\n") + line;
  return ImGui::Button((lines + parts.id).c_str());
}


// A section header: the full title if it fits the panel's width, else the brief one (a header never wraps).
bool section(const char* full, const char* brief, int flags) {
  const std::string shown = label_parts(full).shown;
  const float room = ImGui::GetContentRegionAvail().x - ImGui::GetTreeNodeToLabelSpacing() -
                     ImGui::GetStyle().FramePadding.x;
  return ImGui::CollapsingHeader(ImGui::CalcTextSize(shown.c_str()).x <= room ? full : brief, flags);
}

}  // namespace raycam::ui
