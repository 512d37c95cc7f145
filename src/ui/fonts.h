// Lecture mode's text: DejaVu Sans (Debian's fonts-dejavu-core, found through fontconfig or its known path)
// rasterised at the chosen size, so text stays crisp at 1×, 1.5×, 2× and 3× instead of a 13-px bitmap font
// stretched. Falls back to ImGui's built-in font (ASCII only) when no TrueType font is found.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

namespace raycam::ui {

// The base pixel size of the text at font scale 1.
inline constexpr float kBaseFontPixels = 15.0f;

// Path of the TrueType font to use, or "" for the built-in font.
std::string find_ui_font();

// Rebuilds the font atlas when the scale changed (or at the first call). Call it before the renderer
// backend's NewFrame (ImGui_ImplOpenGL3_NewFrame), outside a frame: it re-creates the backend's font
// texture. Returns true if it rebuilt. `pixel_density` is the screen's device pixels per UI pixel (a page on
// a screen of pixel ratio 2): the glyphs are rasterised at that many pixels and drawn at the size they have
// at density 1, so text stays crisp and the same size to the eye.
bool update_fonts(float font_scale, float pixel_density = 1.0f);

// Every text the window may show from a table, in every language: the window's table, the checker's, the
// error reasons', the classic mistakes' labels and explanations, the shipped scenes' object names.
std::vector<const char*> shown_table_texts();

// The glyph ranges the font is loaded with: Latin, Greek, and every character of shown_table_texts().
const ImWchar* ui_glyph_ranges();

// True when the TrueType font is in use (false: built-in fallback).
bool using_truetype_font();

}  // namespace raycam::ui
