#include "ui/local_numbers.h"

#include <imgui_internal.h>  // TempInputIsActive, RenderTextClipped

#include <cstdio>
#include <cstdlib>
#include <string>

namespace raycam::ui {

LocalNumber::LocalNumber(Language language, const char* label, const char* format)
    : language_(language), label_(label), format_(format),
      own_(language != Language::en && !ImGui::TempInputIsActive(ImGui::GetID(label))) {}

double LocalNumber::shown(double value) const {
  if (!own_) return value;
  char c_text[64];
  std::snprintf(c_text, sizeof c_text, format_, value);
  const double rounded = std::strtod(c_text, nullptr);  // what ImGui would keep with the format
  const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
  const float label_width = ImGui::CalcTextSize(label_, nullptr, true).x;
  const float frame_right = label_width > 0 ? high.x - label_width - ImGui::GetStyle().ItemInnerSpacing.x : high.x;
  const ImVec2 frame_high{frame_right, low.y + ImGui::GetFrameHeight()};
  const std::string text = formatted(language_, format_, rounded);
  ImGui::RenderTextClipped(low, frame_high, text.c_str(), nullptr, nullptr, {0.5f, 0.5f});
  return rounded;
}

}  // namespace raycam::ui
