// How big a run of text (one font size, no markup) is set in DejaVu Sans, in points, as cairo's toy text API
// reports it on an image surface (hinted metrics: each glyph's advance and the font's ascent and descent in
// whole points). The page layout (figure_layout.cpp) places labels with it. Natively cairo measures
// (text_metrics_cairo.cpp); the web page has no cairo and reads the same font files (text_metrics_font.cpp).
#pragma once

#include <string>

namespace raycam::figure {

struct RunMetrics {
  double x_advance = 0.0;
  double y_bearing = 0.0, height = 0.0;  // the ink: top (negative: above the baseline) and height
  double ascent = 0.0, descent = 0.0;    // the font's, at this size
};

RunMetrics measure_run(const std::string& text, double size, bool bold);

// The same from DejaVu Sans's font files, without cairo (the web page's measure_run; natively, the test that
// compares the two). Throws std::runtime_error when a font file cannot be read.
RunMetrics measure_run_in_font_files(const std::string& text, double size, bool bold);

}  // namespace raycam::figure
