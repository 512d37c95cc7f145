#include "ui/theme.h"

#include <algorithm>
#include <cmath>

namespace raycam::ui {

namespace {
ThemeColours g_current;
bool g_current_set = false;

double linear(double channel) {  // sRGB to linear light (WCAG 2 relative luminance)
  return channel <= 0.04045 ? channel / 12.92 : std::pow((channel + 0.055) / 1.055, 2.4);
}
double luminance(const ImVec4& c) {
  return 0.2126 * linear(c.x) + 0.7152 * linear(c.y) + 0.0722 * linear(c.z);
}
}  // namespace

ImGuiStyle make_style(bool high_contrast, float scale) {
  ImGuiStyle style;
  ImVec4* c = style.Colors;
  if (high_contrast) {
    ImGui::StyleColorsLight(&style);
    c[ImGuiCol_Text] = {0, 0, 0, 1};
    c[ImGuiCol_TextDisabled] = {0.30f, 0.30f, 0.33f, 1};  // the light theme's 0.6 grey is 2.8:1 on white
    c[ImGuiCol_WindowBg] = {1, 1, 1, 1};
    c[ImGuiCol_ButtonActive] = {0.45f, 0.70f, 1.00f, 1};
    c[ImGuiCol_HeaderActive] = {0.45f, 0.70f, 1.00f, 1};
    style.FrameBorderSize = 1.0f;
  } else {
    ImGui::StyleColorsDark(&style);
    // ImGui's bright blue (0.26, 0.59, 0.98) under white text is 3.5:1: a deeper blue for opaque states.
    const ImVec4 blue{0.16f, 0.38f, 0.72f, 1.0f};
    c[ImGuiCol_ButtonHovered] = blue;
    c[ImGuiCol_ButtonActive] = {0.12f, 0.30f, 0.60f, 1};
    c[ImGuiCol_HeaderHovered] = blue;
    c[ImGuiCol_HeaderActive] = {0.12f, 0.30f, 0.60f, 1};
    c[ImGuiCol_TextDisabled] = {0.62f, 0.62f, 0.66f, 1};
    style.FrameBorderSize = 0.0f;
  }
  // Opaque: the help window and the drop-down lists lie over the panel, whose text showed through them.
  c[ImGuiCol_WindowBg].w = 1.0f;
  c[ImGuiCol_PopupBg].w = 1.0f;
  // A slider's grab a few pixels wide, under its value's digits: ImGui's 10 px (30 at 3×) covered one.
  style.GrabMinSize = 4.0f;
  // Paddings grow slower than the text: at 3× the text needs the room, not the margins around it.
  style.ScaleAllSizes(1.0f + 0.5f * (scale - 1.0f));
  return style;
}

ThemeColours theme_colours(bool high_contrast) {
  if (high_contrast)
    return {{0.25f, 0.27f, 0.33f, 1},
            {0.72f, 0.0f, 0.0f, 1},
            {0.0f, 0.42f, 0.0f, 1},
            {0.60f, 0.30f, 0.0f, 1},
            {1, 1, 1, 1}};
  return {{0.68f, 0.71f, 0.78f, 1},
          {1.0f, 0.42f, 0.38f, 1},
          {0.45f, 0.85f, 0.45f, 1},
          {1.0f, 0.75f, 0.3f, 1},
          {0.08f, 0.08f, 0.10f, 1}};
}

const ThemeColours& current_theme() {
  if (!g_current_set) set_current_theme(false);
  return g_current;
}

void set_current_theme(bool high_contrast) {
  g_current = theme_colours(high_contrast);
  g_current_set = true;
}

double contrast_ratio(const ImVec4& a, const ImVec4& b) {
  const double la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

ImVec4 composite(const ImVec4& top, const ImVec4& bottom) {
  const float a = top.w;
  return {top.x * a + bottom.x * (1 - a), top.y * a + bottom.y * (1 - a), top.z * a + bottom.z * (1 - a),
          1.0f};
}

}  // namespace raycam::ui
