// The web page has no cairo: its figures' text is measured from DejaVu Sans's font files instead
// (text_metrics_font.cpp), so that its TikZ places the labels where raycam-cli figure's does. Both are
// measured here on every word the figures set (labels, titles, captions, matrices; 2D and 3D; English and
// French), at the sizes the layout sets them.
#include <catch2/catch.hpp>
#include <cmath>

#include "figure/construction_figure.h"
#include "figure/figure_layout.h"
#include "figure_test_support.h"
#include "figure/math_text.h"
#include "figure/text_metrics.h"

using namespace raycam;
using namespace raycam::figure;
using namespace raycam::figure_tests;

namespace {
struct Tally {
  int runs = 0, same_advance = 0, glyphs = 0;
  double worst_gap_per_glyph = 0.0;  // |cairo − font files| over the run's glyphs
  int same_font_extent = 0;
};

int glyph_count(const std::string& text) {
  int count = 0;
  for (unsigned char c : text) count += (c & 0xC0) != 0x80;
  return count;
}

void compare(const std::string& markup, double size, bool bold, Tally& tally) {
  for (const TextRun& run : parse_math_text(markup)) {
    if (run.text.empty()) continue;
    const double run_size = run.level == 0 ? size : kScriptScale * size;
    const RunMetrics cairo = measure_run(run.text, run_size, bold);
    const RunMetrics files = measure_run_in_font_files(run.text, run_size, bold);
    ++tally.runs;
    tally.glyphs += glyph_count(run.text);
    // cairo's whole points come back through its font matrix: 4 is 3.9999999999999996 at some sizes.
    const auto same = [](double a, double b) { return std::abs(a - b) < 1e-9; };
    tally.same_advance += same(cairo.x_advance, files.x_advance);
    tally.worst_gap_per_glyph = std::max(tally.worst_gap_per_glyph,
                                         std::abs(cairo.x_advance - files.x_advance) / glyph_count(run.text));
    tally.same_font_extent += same(cairo.ascent, files.ascent) && same(cairo.descent, files.descent);
  }
}

void compare_figure(const Figure& figure, Tally& tally) {
  FigureOutput output;
  for (int i = 0; i < int(figure.frames.size()); ++i) {
    const PageFrame page = lay_out_frame(figure, i, output);
    for (const PlacedText& t : page.labels) compare(t.markup, t.size, t.bold, tally);
    for (const PlacedText& t : page.caption) compare(t.markup, t.size, t.bold, tally);
    compare(page.title.markup, page.title.size, page.title.bold, tally);
    compare(page.matrix_name.markup, page.matrix_name.size, page.matrix_name.bold, tally);
    for (const MatrixCell& cell : page.cells) compare(cell.markup, page.font_size, false, tally);
  }
}
}  // namespace

TEST_CASE("the page's text metrics (font files, no cairo) are cairo's on the figures' words", "[figure][web]") {
  Tally tally;
  for (const Language language : {Language::en, Language::fr}) {
    const FigureOptions options{language, 5};
    for (const Camera2D& camera : cameras_2d()) compare_figure(construction_figure_2d(scene_2d(), camera, options), tally);
    Camera3D camera(32, 32);
    compare_figure(construction_figure_3d(scene_3d(), camera, options), tally);
  }
  INFO(tally.runs << " runs, " << tally.glyphs << " glyphs, " << tally.same_advance << " advances equal, worst gap "
                  << tally.worst_gap_per_glyph << " pt a glyph");
  REQUIRE(tally.runs > 200);
  // The font's ascent and descent, rounded up to whole points as cairo's hinted metrics are: always equal.
  CHECK(tally.same_font_extent == tally.runs);
  // Each glyph's advance rounded to a whole point as cairo's are; the hinting of a few glyphs at a few sizes
  // rounds the other way: never by more than a point a glyph, and rarely.
  CHECK(tally.worst_gap_per_glyph <= 1.0);
  CHECK(tally.same_advance >= 0.95 * tally.runs);
}
