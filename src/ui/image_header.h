// The image window's header: one line, whatever it has to say, so that the picture under it keeps its whole
// height (a mistake turned on changes the picture, never its size). In order: the check's verdict (never
// cut: its shortest form fits), a classic mistake that is on (cut with an ellipsis when the line is full,
// named whole in the header's tooltip), the picture's size (dropped first).
#pragma once

#include <string>
#include <vector>

namespace raycam::ui {

struct ImageHeaderParts {
  std::vector<std::string> verdict;  // longest first; empty: no verdict to show
  std::string mistake;               // "MISTAKE ON: …", empty when none is on
  std::string mistake_brief;         // "MISTAKE ON"
  std::vector<std::string> size;     // longest first
};

struct ImageHeader {
  std::string title;    // what the header shows (no ImGui id)
  std::string tooltip;  // every part in its longest form, when the title left something out; else empty
};

// The room a title bar `width` pixels wide has for its text (ImGui's title padding).
float title_room(float width);
// `text` cut at a character boundary with "…" so that it is at most `width` pixels wide ("…" alone if even
// one character does not fit); `text` itself when it fits. Measured with the current ImGui font.
std::string ellipsized(const std::string& text, float width);
// The header line for a title bar `width` pixels wide.
ImageHeader fit_image_header(const ImageHeaderParts& parts, float width);

}  // namespace raycam::ui
