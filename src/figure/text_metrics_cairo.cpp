#include <cairo.h>

#include <memory>

#include "figure/figure_layout.h"
#include "figure/text_metrics.h"

namespace raycam::figure {

namespace {
// One cairo context for measuring text (a 1×1 image: only the font metrics are used).
cairo_t* measuring_context() {
  struct Deleter {
    void operator()(cairo_t* cr) const {
      cairo_surface_destroy(cairo_get_target(cr));
      cairo_destroy(cr);
    }
  };
  thread_local std::unique_ptr<cairo_t, Deleter> cr(cairo_create(cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1)));
  return cr.get();
}
}  // namespace

RunMetrics measure_run(const std::string& text, double size, bool bold) {
  cairo_t* cr = measuring_context();
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t x;
  cairo_text_extents(cr, text.c_str(), &x);
  cairo_font_extents_t f;  // the font's ascent and descent, as a PDF reader boxes a word
  cairo_font_extents(cr, &f);
  return {x.x_advance, x.y_bearing, x.height, f.ascent, f.descent};
}

}  // namespace raycam::figure
