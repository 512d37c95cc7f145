#include "figure_files.h"

#include <algorithm>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <cmath>
#include <glm/geometric.hpp>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <png.h>
#include <stdexcept>

namespace raycam::figure {

namespace {

constexpr double kPointsPerMm = 72.0 / 25.4;
constexpr double kObjectNamesUpTo = 40;  // beyond, names would cover the drawing (the objects are all drawn)
const char* const kFont = "DejaVu Sans";  // the app's font: it has θ, φ, ψ, Ω, ‖ and the arrow above u⃗
const char* const kMonoFont = "DejaVu Sans Mono";

// The page's bands: title and caption above the drawing, note and matrix below. Fixed per page size, so
// every frame of a figure has the same drawing area and the same scale.
struct Layout {
  double unit;    // one point at the reference page height (340 pt ≈ 120 mm)
  double margin;
  double title, text, small;  // font sizes
  double top, bottom;         // the drawing area's page y range
  double left, right;
};

Layout layout_of(const PageSize& page, bool with_matrix) {
  Layout l;
  l.unit = std::min(page.width_pt, page.height_pt) / 340.0;
  l.margin = 12.0 * l.unit;
  l.title = 14.0 * l.unit;
  l.text = 9.0 * l.unit;
  l.small = 8.0 * l.unit;
  l.left = l.margin;
  l.right = page.width_pt - l.margin;
  l.top = l.margin + 1.4 * l.title + 2.0 * 1.3 * l.text + 0.5 * l.margin;
  const double matrix_rows = with_matrix ? 4.0 : 0.0;
  l.bottom = page.height_pt - l.margin - 2.0 * 1.3 * l.small - matrix_rows * 1.3 * l.small;
  return l;
}

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

void set_font(cairo_t* cr, const char* face, double size, bool bold = false, bool italic = false) {
  cairo_select_font_face(cr, face, italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

void text_at(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

// A label near a point, kept inside the drawing area: moved left when it would run past its right side.
void label_at(cairo_t* cr, double x, double y, const std::string& text, const Layout& l) {
  text_at(cr, std::max(l.left, std::min(x, l.right - text_width(cr, text))), y, text);
}

// Wraps between words within `width`; at most `max_lines` lines (the last one takes the rest).
std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double width, int max_lines) {
  std::vector<std::string> lines(1);
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const std::string candidate = lines.back().empty() ? word : lines.back() + " " + word;
    if (!lines.back().empty() && text_width(cr, candidate) > width && int(lines.size()) < max_lines)
      lines.push_back(word);
    else
      lines.back() = candidate;
    start = end + 1;
  }
  return lines;
}

void arrow_head(cairo_t* cr, double x0, double y0, double x1, double y1, double size) {
  const glm::dvec2 tip(x1, y1), along = glm::normalize(glm::dvec2(x1 - x0, y1 - y0) + 1e-300);
  const glm::dvec2 side(-along.y, along.x);
  const glm::dvec2 a = tip - size * along + 0.4 * size * side, b = tip - size * along - 0.4 * size * side;
  cairo_move_to(cr, tip.x, tip.y);
  cairo_line_to(cr, a.x, a.y);
  cairo_line_to(cr, b.x, b.y);
  cairo_close_path(cr);
  cairo_fill(cr);
}

void draw_segments(cairo_t* cr, const Frame& frame, const PageTransform& to_page, const Layout& l) {
  for (const Segment& s : frame.segments) {
    const double x0 = to_page.x(s.from.x), y0 = to_page.y(s.from.y);
    const double x1 = to_page.x(s.to.x), y1 = to_page.y(s.to.y);
    cairo_save(cr);
    switch (s.stroke) {
      case Stroke::camera:
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 1.5 * l.unit);
        break;
      case Stroke::arrow:
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 1.0 * l.unit);
        break;
      case Stroke::construction: {
        const double dashes[] = {3.0 * l.unit, 2.0 * l.unit};
        cairo_set_dash(cr, dashes, 2, 0.0);
        cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
        cairo_set_line_width(cr, 0.6 * l.unit);
        break;
      }
      case Stroke::ray:  // solid and coloured: grey but not dashed once printed in black and white
        cairo_set_source_rgb(cr, 0.80, 0.30, 0.05);
        cairo_set_line_width(cr, 0.7 * l.unit);
        break;
    }
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    cairo_stroke(cr);
    if (s.stroke == Stroke::arrow) arrow_head(cr, x0, y0, x1, y1, 6.0 * l.unit);
    cairo_restore(cr);
  }
}

int draw_objects(cairo_t* cr, const Frame& frame, const PageTransform& to_page, const Layout& l) {
  for (const Disc& disc : frame.objects) {
    cairo_new_path(cr);
    cairo_arc(cr, to_page.x(disc.centre.x), to_page.y(disc.centre.y), to_page.scale * disc.radius, 0.0,
              2.0 * M_PI);
    if (frame.objects_faded)
      cairo_set_source_rgba(cr, 0.5, 0.5, 0.5, 0.12);
    else
      cairo_set_source_rgba(cr, disc.colour.r / 255.0, disc.colour.g / 255.0, disc.colour.b / 255.0, 0.8);
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0, 0, 0, frame.objects_faded ? 0.3 : 1.0);
    cairo_set_line_width(cr, 0.6 * l.unit);
    cairo_stroke(cr);
  }
  if (frame.objects.size() <= kObjectNamesUpTo && !frame.objects_faded) {  // names: black and white prints keep them apart
    set_font(cr, kFont, l.small);
    for (const Disc& disc : frame.objects) {
      if (disc.name.empty()) continue;
      const double r = to_page.scale * disc.radius;
      label_at(cr, to_page.x(disc.centre.x) + 0.75 * r + 2.0 * l.unit, to_page.y(disc.centre.y) - 0.75 * r,
               disc.name, l);
    }
  }
  return int(frame.objects.size());
}

void draw_markers(cairo_t* cr, const Frame& frame, const PageTransform& to_page, const Layout& l) {
  const double arm = 3.0 * l.unit;
  for (const Marker& marker : frame.markers) {
    const double x = to_page.x(marker.at.x), y = to_page.y(marker.at.y);
    cairo_new_path(cr);
    cairo_move_to(cr, x - arm, y);
    cairo_line_to(cr, x + arm, y);
    cairo_move_to(cr, x, y - arm);
    cairo_line_to(cr, x, y + arm);
    cairo_set_source_rgb(cr, 0, 0, (int(marker.point) + 1) / 255.0);  // see the header
    cairo_set_line_width(cr, 1.0 * l.unit);
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  set_font(cr, kFont, l.text, true);
  for (const Marker& marker : frame.markers)
    if (!marker.label.empty())
      label_at(cr, to_page.x(marker.at.x) + 1.5 * arm, to_page.y(marker.at.y) - 1.5 * arm, marker.label, l);
  set_font(cr, kFont, l.small);
  for (const Label& label : frame.labels)
    label_at(cr, to_page.x(label.at.x) + 2.0 * l.unit, to_page.y(label.at.y) + 0.4 * l.small, label.text, l);
}

void draw_matrix(cairo_t* cr, const Frame& frame, const Layout& l, double y, Language language) {
  set_font(cr, kMonoFont, l.small);
  const std::string name = "M = ";
  const double row_height = 1.3 * l.small;
  text_at(cr, l.left, y + row_height * (frame.matrix_size - 1) / 2.0, name);
  const double x = l.left + text_width(cr, name);
  for (int r = 0; r < frame.matrix_size; ++r) {
    std::string row = "[";
    for (int c = 0; c < frame.matrix_size; ++c) {
      std::string number = decimal(frame.matrix[r][c], 3, language);
      row += std::string(std::max<std::size_t>(1, 9 - number.size()), ' ') + number;
    }
    text_at(cr, x, y + r * row_height, row + " ]");
  }
}

// Paints one frame on `cr` in page points; returns the number of objects drawn.
int paint_frame(cairo_t* cr, const Figure& figure, int index, const PageSize& page, const FigureOutput& output) {
  const Frame& frame = figure.frames[std::size_t(index)];
  const Layout l = layout_of(page, output.matrix);
  const PageTransform to_page = page_transform(frame, page, output.matrix);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  set_font(cr, kFont, l.title, true);
  text_at(cr, l.left, l.margin + l.title, frame.title);
  set_font(cr, kFont, l.text);
  double y = l.margin + 1.4 * l.title + 1.1 * l.text;
  for (const std::string& line : wrap(cr, frame.caption, l.right - l.left, 2)) {
    text_at(cr, l.left, y, line);
    y += 1.3 * l.text;
  }

  cairo_save(cr);
  cairo_rectangle(cr, l.left, l.top, l.right - l.left, l.bottom - l.top);
  cairo_clip(cr);
  const int drawn = draw_objects(cr, frame, to_page, l);
  draw_segments(cr, frame, to_page, l);
  draw_markers(cr, frame, to_page, l);
  cairo_restore(cr);

  cairo_set_source_rgb(cr, 0, 0, 0);
  y = l.bottom + 1.1 * l.small;
  if (!frame.note.empty()) {
    set_font(cr, kFont, l.small, false, true);
    for (const std::string& line : wrap(cr, frame.note, l.right - l.left, 2)) {
      text_at(cr, l.left, y, line);
      y += 1.3 * l.small;
    }
  } else {
    y += 2.0 * 1.3 * l.small;
  }
  if (output.matrix) draw_matrix(cr, frame, l, y, figure.language);
  return drawn;
}

// cairo_surface_write_to_png spends ~85 % of a 300 dpi frame in libpng's adaptive filters and zlib's
// default level; a line drawing on white compresses as well with the "up" filter at a low level, ~5× faster.
void write_png(cairo_surface_t* surface, const std::string& path) {
  cairo_surface_flush(surface);
  const int width = cairo_image_surface_get_width(surface), height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  std::vector<unsigned char> row(std::size_t(width) * 3);  // before setjmp: nothing to unwind after it
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
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

std::string file_for(const std::string& path, const std::string& id, Format format, bool one_file) {
  if (one_file) return path;
  const std::string ext = std::string(".") + extension(format);
  const bool has_ext = path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  const std::string stem = has_ext ? path.substr(0, path.size() - ext.size()) : path;
  return stem + "-" + id + ext;
}

}  // namespace

int PageSize::width_px() const { return std::max(1, int(std::lround(width_pt * pixels_per_point))); }
int PageSize::height_px() const { return std::max(1, int(std::lround(height_pt * pixels_per_point))); }

PageSize page_in_mm(double width, double height) {
  return {width * kPointsPerMm, height * kPointsPerMm, 300.0 / 72.0};
}

PageSize page_in_px(int width, int height) { return {0.75 * width, 0.75 * height, 1.0 / 0.75}; }

const char* extension(Format format) {
  switch (format) {
    case Format::svg:
      return "svg";
    case Format::pdf:
      return "pdf";
    case Format::png:
      return "png";
  }
  return "";
}

PageTransform page_transform(const Frame& frame, const PageSize& page, bool with_matrix) {
  const Layout l = layout_of(page, with_matrix);
  const glm::dvec2 extent = frame.plane_max - frame.plane_min;
  PageTransform t;
  t.scale = std::min((l.right - l.left) / extent.x, (l.bottom - l.top) / extent.y);
  const glm::dvec2 middle = 0.5 * (frame.plane_min + frame.plane_max);
  t.x0 = 0.5 * (l.left + l.right) - t.scale * middle.x;
  t.y0 = 0.5 * (l.top + l.bottom) + t.scale * middle.y;
  return t;
}

WrittenFigure write_figure(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                           const std::string& path) {
  WrittenFigure written;
  const PageSize& page = output.page;
  const bool one_file = frames.size() == 1 || (output.pages && output.format == Format::pdf);
  if (one_file && output.format == Format::pdf) {
    Surface surface(cairo_pdf_surface_create(path.c_str(), page.width_pt, page.height_pt));
    Context cr(cairo_create(surface.get()));
    for (int index : frames) {
      written.objects_drawn.push_back(paint_frame(cr.get(), figure, index, page, output));
      cairo_show_page(cr.get());
    }
    check(cairo_status(cr.get()), path);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), path);
    written.files.push_back(path);
    return written;
  }
  for (int index : frames) {
    const std::string file = file_for(path, figure.frames[std::size_t(index)].id, output.format, one_file);
    Surface surface;
    if (output.format == Format::svg)
      surface.reset(cairo_svg_surface_create(file.c_str(), page.width_pt, page.height_pt));
    else if (output.format == Format::pdf)
      surface.reset(cairo_pdf_surface_create(file.c_str(), page.width_pt, page.height_pt));
    else
      surface.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, page.width_px(), page.height_px()));
    check(cairo_surface_status(surface.get()), file);
    Context cr(cairo_create(surface.get()));
    if (output.format == Format::png)
      cairo_scale(cr.get(), page.width_px() / page.width_pt, page.height_px() / page.height_pt);
    written.objects_drawn.push_back(paint_frame(cr.get(), figure, index, page, output));
    check(cairo_status(cr.get()), file);
    if (output.format == Format::png) write_png(surface.get(), file);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), file);
    written.files.push_back(file);
  }
  return written;
}

}  // namespace raycam::figure
