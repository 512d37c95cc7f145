// Lecture mode's themes: every text colour has a contrast ratio of at least 4.5:1 (WCAG AA) against every
// background it is drawn on, computed from the themes' own colours (with their alpha over the window).
#include <catch2/catch.hpp>

#include "ui/theme.h"

using namespace raycam::ui;

TEST_CASE("the contrast ratio is WCAG's", "[ui][theme]") {
  CHECK(contrast_ratio({0, 0, 0, 1}, {1, 1, 1, 1}) == Approx(21.0));
  CHECK(contrast_ratio({1, 1, 1, 1}, {1, 1, 1, 1}) == Approx(1.0));
  CHECK(contrast_ratio({0.4627f, 0.4627f, 0.4627f, 1}, {1, 1, 1, 1}) ==
        Approx(4.54).epsilon(0.01));  // #767676
}

TEST_CASE("every text colour of both themes has a contrast of at least 4.5:1 on its backgrounds",
          "[ui][theme]") {
  for (const bool high_contrast : {false, true}) {
    const ImGuiStyle style = make_style(high_contrast, 1.0f);
    const ThemeColours theme = theme_colours(high_contrast);
    const ImVec4* c = style.Colors;
    const ImVec4 window = composite(c[ImGuiCol_WindowBg], theme.clear);
    const auto over_window = [&](ImGuiCol col) { return composite(c[col], window); };
    // Plain text sits on windows, popups, fields, buttons, headers, title bars, table headers, selections.
    const ImVec4 backgrounds[] = {window,
                                  composite(c[ImGuiCol_PopupBg], theme.clear),
                                  over_window(ImGuiCol_ChildBg),
                                  over_window(ImGuiCol_FrameBg),
                                  over_window(ImGuiCol_FrameBgHovered),
                                  over_window(ImGuiCol_FrameBgActive),
                                  over_window(ImGuiCol_Button),
                                  over_window(ImGuiCol_ButtonHovered),
                                  over_window(ImGuiCol_ButtonActive),
                                  over_window(ImGuiCol_Header),
                                  over_window(ImGuiCol_HeaderHovered),
                                  over_window(ImGuiCol_HeaderActive),
                                  composite(c[ImGuiCol_TitleBg], theme.clear),
                                  composite(c[ImGuiCol_TitleBgActive], theme.clear),
                                  over_window(ImGuiCol_TableHeaderBg),
                                  over_window(ImGuiCol_TableRowBgAlt),
                                  composite(c[ImGuiCol_TextSelectedBg], over_window(ImGuiCol_FrameBg))};
    for (const ImVec4& background : backgrounds) {
      INFO((high_contrast ? "high contrast" : "dark")
           << ": text on (" << background.x << ", " << background.y << ", " << background.z << ")");
      CHECK(contrast_ratio(c[ImGuiCol_Text], background) >= 4.5);
    }
    // Hints, disabled text, errors and confirmations sit on windows, fields and popups.
    for (const ImVec4& text :
         {c[ImGuiCol_TextDisabled], theme.hint, theme.error, theme.confirmation, theme.look_at})
      for (const ImVec4& background :
           {window, over_window(ImGuiCol_FrameBg), composite(c[ImGuiCol_PopupBg], theme.clear)}) {
        INFO((high_contrast ? "high contrast" : "dark")
             << ": (" << text.x << ", " << text.y << ", " << text.z << ") on (" << background.x << ", "
             << background.y << ", " << background.z << ")");
        CHECK(contrast_ratio(text, background) >= 4.5);
      }
  }
}

TEST_CASE("windows and popups are opaque: what lies under the help window or a drop-down list never shows through",
          "[ui][theme]") {
  for (const bool high_contrast : {false, true}) {
    const ImGuiStyle style = make_style(high_contrast, 1.0f);
    INFO((high_contrast ? "high contrast" : "dark"));
    CHECK(style.Colors[ImGuiCol_WindowBg].w == 1.0f);
    CHECK(style.Colors[ImGuiCol_PopupBg].w == 1.0f);
  }
}
