// The construction figures' words (frame titles, captions, the "up" vector's name) in English or French: the
// English text is the key, the French in figure_texts.cpp's own table, as the window's tr() and the checker's
// check::text() do. The figure sits beside io in the layers (raycam_figure_tikz links only the core), so the
// table has its own small lookup rather than io's TranslationTable. The symbols ($M_d$, $E_0$, $k = 0$) and
// the numbers are written where they are drawn: they read the same in both languages.
#pragma once

#include <vector>

#include "raycam/languages.h"

namespace raycam::figure {

// `english` in `language` (english itself if the table lacks it: tests/session/test_text.cpp fails on any
// figure_text("...") whose key is missing).
const char* figure_text(Language language, const char* english);

// The whole table (for the tests that every text has every language and every call has its key).
const std::vector<LocalText>& figure_translations();

}  // namespace raycam::figure
