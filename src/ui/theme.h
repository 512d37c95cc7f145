// The two themes (dark, and high contrast for a lit lecture hall) and their text colours. Every text colour
// has a contrast ratio of at least 4.5:1 (WCAG AA) against every background it is drawn on: tests/ui/
// test_theme.cpp computes it from these colours.
#pragma once

#include <imgui.h>

namespace raycam::ui {

struct ThemeColours {
  ImVec4 hint;          // explanations under the widgets
  ImVec4 error;         // messages that say something went wrong (red)
  ImVec4 confirmation;  // messages that say something was done
  ImVec4 look_at;       // after a mistake's "show me": what to look at
  ImVec4 clear;         // what the host clears the window to (behind the windows' alpha)
};

// The style at a font scale (sizes scaled; the font itself is rasterised at that scale: fonts.h).
ImGuiStyle make_style(bool high_contrast, float scale);
ThemeColours theme_colours(bool high_contrast);
// The theme apply_theme() last applied.
const ThemeColours& current_theme();
void set_current_theme(bool high_contrast);

// WCAG 2 contrast ratio of two opaque colours (alpha ignored), from 1 to 21.
double contrast_ratio(const ImVec4& a, const ImVec4& b);
// `top` drawn with its alpha over an opaque `bottom`.
ImVec4 composite(const ImVec4& top, const ImVec4& bottom);

}  // namespace raycam::ui
