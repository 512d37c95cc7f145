// The figures' notation: every label, caption and matrix entry is UTF-8 with a few TeX-like marks, so that
// one string gives both cairo's drawing (a subscript set smaller and lower, an arrow drawn over a vector) and
// the TikZ output's LaTeX. `$…$` delimits mathematics; inside it `_x` or `_{xy}` is a subscript, `^x` or
// `^{xy}` a superscript and `\vec{PC}` a vector. `\$` and `\\` are a literal dollar and backslash.
#pragma once

#include <string>
#include <vector>

namespace raycam::figure {

struct TextRun {
  std::string text;     // UTF-8, marks removed
  int level = 0;        // -1 subscript, 0 on the line, +1 superscript
  bool vector = false;  // an arrow over the run
  bool math = false;    // inside $…$ (LaTeX sets it as mathematics)
};

std::vector<TextRun> parse_math_text(const std::string& markup);

// The LaTeX for a markup string: text escaped, mathematics in $…$ with θ → \theta, − → -, 1,5 → 1{,}5….
std::string latex_of(const std::string& markup);

// The text without its marks ("$\vec{u}_0$" → "u0"): what a PDF's text extraction reads.
std::string plain_text_of(const std::string& markup);

// Free text (an object's name from a scene file) as markup that prints it as is.
std::string escape_markup(const std::string& text);

}  // namespace raycam::figure
