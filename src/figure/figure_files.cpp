#include "figure/figure_files.h"

#include <algorithm>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <memory>
#include <png.h>
#include <stdexcept>
#include <unistd.h>

#include "figure/cairo_files.h"

namespace raycam::figure {

namespace {

struct CairoDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
using Context = std::unique_ptr<cairo_t, CairoDeleter>;
using Surface = std::unique_ptr<cairo_surface_t, CairoDeleter>;

void check(cairo_status_t status, const std::string& path) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(path + ": cannot write the figure (" + cairo_status_to_string(status) + ")");
}

// ---- drawing ----------------------------------------------------------------------------------------------

void set_font(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

void arrow_head(cairo_t* cr, glm::dvec2 from, glm::dvec2 tip, double size) {
  const glm::dvec2 along = glm::normalize(tip - from + 1e-300);
  const glm::dvec2 side(-along.y, along.x);
  const glm::dvec2 a = tip - size * along + 0.4 * size * side, b = tip - size * along - 0.4 * size * side;
  cairo_move_to(cr, tip.x, tip.y);
  cairo_line_to(cr, a.x, a.y);
  cairo_line_to(cr, b.x, b.y);
  cairo_close_path(cr);
  cairo_fill(cr);
}

void line(cairo_t* cr, glm::dvec2 a, glm::dvec2 b) {
  cairo_move_to(cr, a.x, a.y);
  cairo_line_to(cr, b.x, b.y);
}

// Markup text (math_text.h) with its baseline's left end at `at`: scripts smaller and shifted, an arrow over
// a vector. With `halo`, a white outline first, so that the text stays readable over lines.
// An object's fill wherever it is shown (the drawing, the inset, the key's swatch): its colour, the lines
// under it showing through.
void set_object_fill(cairo_t* cr, const Rgb8& colour) {
  cairo_set_source_rgba(cr, colour.r / 255.0, colour.g / 255.0, colour.b / 255.0, 0.8);
}

void draw_text(cairo_t* cr, const std::string& markup, glm::dvec2 at, double size, bool bold, bool halo) {
  for (int pass = halo ? 0 : 1; pass < 2; ++pass) {
    double x = at.x;
    cairo_save(cr);
    if (pass == 0) {
      cairo_set_source_rgb(cr, 1, 1, 1);
      cairo_set_line_width(cr, 0.25 * size);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    } else {
      cairo_set_source_rgb(cr, 0, 0, 0);
    }
    for (const TextRun& run : parse_math_text(markup)) {
      const double run_size = run.level == 0 ? size : kScriptScale * size;
      const double y = at.y + (run.level < 0 ? kSubscriptDrop * size : run.level > 0 ? -kSuperscriptRise * size : 0.0);
      set_font(cr, run_size, bold);
      cairo_text_extents_t e;
      cairo_text_extents(cr, run.text.c_str(), &e);
      cairo_move_to(cr, x, y);
      if (pass == 0) {
        cairo_text_path(cr, run.text.c_str());
        cairo_stroke(cr);
      } else {
        cairo_show_text(cr, run.text.c_str());
      }
      if (run.vector) {  // the arrow over the vector, from its ink's left to its right
        const double over = y - std::max(-e.y_bearing, 0.72 * size) - 0.15 * size;
        const glm::dvec2 a(x + e.x_bearing, over), b(x + e.x_bearing + std::max(e.width, 0.5 * size), over);
        cairo_set_line_width(cr, pass == 0 ? 0.25 * size : 0.06 * size);
        line(cr, a, b);
        cairo_stroke(cr);
        if (pass == 1) arrow_head(cr, a, b + glm::dvec2(0.12 * size, 0.0), 0.3 * size);
      }
      x += e.x_advance;
    }
    cairo_restore(cr);
  }
}

void draw_segments(cairo_t* cr, const PageFrame& page) {
  for (const Segment& s : page.segments) {
    cairo_save(cr);
    const glm::dvec2 from = s.from, to = s.to;
    switch (s.stroke) {
      case Stroke::camera:
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 1.2);
        break;
      case Stroke::tick:  // thin: thinned ticks never merge into a bar
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 0.5);
        break;
      case Stroke::arrow:
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 0.8);
        break;
      case Stroke::construction:
      case Stroke::pointer: {
        const double dashes[] = {3.0, 2.0};
        cairo_set_dash(cr, dashes, 2, 0.0);
        cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
        cairo_set_line_width(cr, s.stroke == Stroke::pointer ? 0.8 : 0.5);
        break;
      }
      case Stroke::ray:  // solid and coloured: grey but not dashed once printed in black and white
        cairo_set_source_rgb(cr, 0.80, 0.30, 0.05);
        cairo_set_line_width(cr, 0.6);
        break;
    }
    line(cr, from, to);
    cairo_stroke(cr);
    if (s.stroke == Stroke::arrow || s.stroke == Stroke::pointer) arrow_head(cr, from, to, 5.0);
    cairo_restore(cr);
  }
}

void draw_discs(cairo_t* cr, const PageFrame& page) {
  for (const PageDisc& disc : page.discs) {
    cairo_new_path(cr);
    if (disc.outline.empty()) {
      cairo_arc(cr, disc.centre.x, disc.centre.y, disc.radius, 0.0, 2.0 * M_PI);
    } else {
      for (const glm::dvec2& p : disc.outline) cairo_line_to(cr, p.x, p.y);
      cairo_close_path(cr);
    }
    if (page.objects_faded)
      cairo_set_source_rgba(cr, 0.5, 0.5, 0.5, 0.12);
    else
      set_object_fill(cr, disc.colour);
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0, 0, 0, page.objects_faded ? 0.3 : 1.0);
    cairo_set_line_width(cr, 0.5);
    cairo_stroke(cr);
  }
}

void draw_markers(cairo_t* cr, const PageFrame& page) {
  for (const PageMarker& marker : page.markers) {
    cairo_new_path(cr);
    line(cr, marker.at - glm::dvec2(page.arm, 0.0), marker.at + glm::dvec2(page.arm, 0.0));
    line(cr, marker.at - glm::dvec2(0.0, page.arm), marker.at + glm::dvec2(0.0, page.arm));
    cairo_set_source_rgb(cr, 0, 0, (int(marker.point) + 1) / 255.0);  // see the header
    cairo_set_line_width(cr, 0.8);
    cairo_stroke(cr);
  }
}

// The overview of the whole scene: a light framed box (opaque, over the drawing), the objects, the screen,
// the eye and C as dark red crosses (not the markers' coded blues), the zoomed region as a red rectangle.
void draw_inset(cairo_t* cr, const PageFrame& page) {
  const PageInset& inset = page.inset;
  if (!inset.shown()) return;
  const Box& b = inset.box;
  cairo_save(cr);
  cairo_rectangle(cr, b.left, b.top, b.width(), b.height());
  cairo_set_source_rgb(cr, kInsetBackground[0], kInsetBackground[1], kInsetBackground[2]);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
  cairo_set_line_width(cr, 0.6);
  cairo_stroke_preserve(cr);
  cairo_clip(cr);
  for (const PageDisc& disc : inset.discs) {
    cairo_new_path(cr);
    cairo_arc(cr, disc.centre.x, disc.centre.y, disc.radius, 0.0, 2.0 * M_PI);
    set_object_fill(cr, disc.colour);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  for (const Segment& s : inset.screen) line(cr, s.from, s.to);
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0.55, 0, 0);
  cairo_set_line_width(cr, 0.6);
  for (const glm::dvec2& p : inset.crosses) {
    line(cr, p - glm::dvec2(kInsetArm, 0.0), p + glm::dvec2(kInsetArm, 0.0));
    line(cr, p - glm::dvec2(0.0, kInsetArm), p + glm::dvec2(0.0, kInsetArm));
  }
  cairo_stroke(cr);
  cairo_rectangle(cr, inset.zoom.left, inset.zoom.top, inset.zoom.width(), inset.zoom.height());
  cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
  cairo_set_line_width(cr, 0.6);
  cairo_stroke(cr);
  cairo_restore(cr);
}

void draw_labels(cairo_t* cr, const PageFrame& page) {
  for (const PlacedText& label : page.labels)
    if (label.leader) {
      // A name's leader darker and thicker, so that an eye follows it to the dot on its object.
      const double grey = label.dot ? 0.1 : 0.3;
      cairo_set_source_rgb(cr, grey, grey, grey);
      cairo_set_line_width(cr, label.dot ? kNameLeaderWidth : 0.4);
      line(cr, label.anchor, glm::dvec2(std::clamp(label.anchor.x, label.box.left, label.box.right),
                                        std::clamp(label.anchor.y, label.box.top, label.box.bottom)));
      cairo_stroke(cr);
      if (label.dot) {  // white-ringed, to show on any colour
        cairo_new_path(cr);
        cairo_arc(cr, label.anchor.x, label.anchor.y, kNameDotRadius, 0.0, 2.0 * M_PI);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_set_line_width(cr, 0.4);
        cairo_stroke(cr);
      }
    }
  for (const PlacedText& label : page.labels) draw_text(cr, label.markup, label.at, label.size, label.bold, true);
}

// The names that found no place in the drawing: a swatch of the object's colour and its name, beside it.
void draw_key(cairo_t* cr, const PageFrame& page) {
  for (const KeyEntry& entry : page.key) {
    cairo_new_path(cr);
    cairo_arc(cr, entry.swatch.x, entry.swatch.y, entry.swatch_radius, 0.0, 2.0 * M_PI);
    set_object_fill(cr, entry.colour);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 0.5);
    cairo_stroke(cr);
    draw_text(cr, entry.text.markup, entry.text.at, entry.text.size, false, false);
  }
}

void draw_matrix(cairo_t* cr, const PageFrame& page) {
  if (page.cells.empty()) return;
  draw_text(cr, page.matrix_name.markup, page.matrix_name.at, page.matrix_name.size, false, false);
  for (const MatrixCell& cell : page.cells) {
    const double width = measure_text(cell.markup, page.font_size).width;
    draw_text(cr, cell.markup, {cell.right - width, cell.baseline}, page.font_size, false, false);
  }
  const Box& b = page.matrix_brackets;  // brackets spanning the rows
  const double serif = 0.3 * page.font_size;
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 0.6);
  cairo_move_to(cr, b.left + serif, b.top);
  cairo_line_to(cr, b.left, b.top);
  cairo_line_to(cr, b.left, b.bottom);
  cairo_line_to(cr, b.left + serif, b.bottom);
  cairo_move_to(cr, b.right - serif, b.top);
  cairo_line_to(cr, b.right, b.top);
  cairo_line_to(cr, b.right, b.bottom);
  cairo_line_to(cr, b.right - serif, b.bottom);
  cairo_stroke(cr);
}

// Paints one frame on `cr` in page points; returns the number of objects drawn.
int paint_frame(cairo_t* cr, const Figure& figure, int index, const FigureOutput& output) {
  const PageFrame page = lay_out_frame(figure, index, output);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  if (!page.title.markup.empty())
    draw_text(cr, page.title.markup, page.title.at, page.title.size, true, false);
  for (const PlacedText& line : page.caption) draw_text(cr, line.markup, line.at, line.size, false, false);
  cairo_save(cr);
  cairo_rectangle(cr, page.area.left, page.area.top, page.area.width(), page.area.height());
  cairo_clip(cr);
  draw_discs(cr, page);
  draw_segments(cr, page);
  draw_markers(cr, page);
  draw_inset(cr, page);
  draw_labels(cr, page);
  cairo_restore(cr);
  draw_key(cr, page);
  draw_matrix(cr, page);
  return int(page.discs.size());
}

// cairo_surface_write_to_png spends ~85 % of a 300 dpi frame in libpng's adaptive filters and zlib's
// default level; a line drawing on white compresses as well with the "up" filter at a low level, ~5× faster.
// The pHYs chunk carries the dpi, so that a word processor places the figure at its size.
void write_png(cairo_surface_t* surface, const std::string& temporary, const std::string& path, double dpi) {
  cairo_surface_flush(surface);
  const int width = cairo_image_surface_get_width(surface), height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  std::vector<unsigned char> row(std::size_t(width) * 3);  // before setjmp: nothing to unwind after it
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(temporary.c_str(), "wb"), &std::fclose);
  if (!file) throw std::runtime_error(path + ": cannot open for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(path + ": cannot write the PNG");
  }
  png_init_io(png, file.get());
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  const auto per_metre = png_uint_32(std::lround(dpi / 0.0254));
  png_set_pHYs(png, info, per_metre, per_metre, PNG_RESOLUTION_METER);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_compression_level(png, 3);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) {
    const auto* pixel = reinterpret_cast<const std::uint32_t*>(data + std::ptrdiff_t(y) * stride);
    for (int x = 0; x < width; ++x) {  // CAIRO_FORMAT_RGB24: 0xXXRRGGBB in native order
      row[std::size_t(x) * 3 + 0] = (pixel[x] >> 16) & 0xff;
      row[std::size_t(x) * 3 + 1] = (pixel[x] >> 8) & 0xff;
      row[std::size_t(x) * 3 + 2] = pixel[x] & 0xff;
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fflush(file.get()) != 0) throw std::runtime_error(path + ": cannot write the PNG");
}

}  // namespace

// One cairo file: SVG, PDF (all `frames` as pages) or PNG.
void write_cairo_file(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                      const std::string& file, const std::string& shown_name, WrittenFigure& written) {
  const PageSize& page = output.page;
  Surface surface;
  if (output.format == Format::svg)
    surface.reset(cairo_svg_surface_create(file.c_str(), page.width_pt, page.height_pt));
  else if (output.format == Format::pdf)
    surface.reset(cairo_pdf_surface_create(file.c_str(), page.width_pt, page.height_pt));
  else
    surface.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, page.width_px(), page.height_px()));
  check(cairo_surface_status(surface.get()), shown_name);
  Context cr(cairo_create(surface.get()));
  if (output.format == Format::png)
    cairo_scale(cr.get(), page.width_px() / page.width_pt, page.height_px() / page.height_pt);
  for (int index : frames) {
    written.objects_drawn.push_back(paint_frame(cr.get(), figure, index, output));
    if (output.format == Format::pdf) cairo_show_page(cr.get());
  }
  check(cairo_status(cr.get()), shown_name);
  if (output.format == Format::png) write_png(surface.get(), file, shown_name, page.dpi());
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()), shown_name);
}


}  // namespace raycam::figure
