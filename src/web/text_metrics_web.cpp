// The page's figures measure their text from the font files (no cairo in the page): the same numbers as
// cairo's on 99 % of the figures' words (tests/figure/test_text_metrics.cpp).
#include "figure/text_metrics.h"

namespace raycam::figure {

RunMetrics measure_run(const std::string& text, double size, bool bold) {
  return measure_run_in_font_files(text, size, bold);
}

}  // namespace raycam::figure
