#include "figure/tikz_file.h"

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>

namespace raycam::figure {

namespace {

constexpr double kCmPerPoint = 2.54 / 72.0;

// A page point as TikZ coordinates: cm, y up from the page's lower left.
struct Coordinates {
  double page_height;
  std::string operator()(glm::dvec2 p) const {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4f,%.4f)", p.x * kCmPerPoint, (page_height - p.y) * kCmPerPoint);
    return text;
  }
};

std::string number(double value) {
  char text[48];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string font(double size, bool bold = false) {
  return "font=\\fontsize{" + number(size) + "}{" + number(1.2 * size) + "}\\selectfont" + (bold ? "\\bfseries" : "");
}

const char* style_of(Stroke stroke) {
  switch (stroke) {
    case Stroke::camera:
      return "camera";
    case Stroke::arrow:
      return "vector";
    case Stroke::construction:
      return "construction";
    case Stroke::ray:
      return "ray";
    case Stroke::tick:
      return "tick";
    case Stroke::pointer:
      return "pointer";
  }
  return "";
}

// The styles, the same strokes as cairo's drawing (figure_files.cpp).
std::string styles() {
  return std::string(
    "  camera/.style={line width=1.2pt},\n"
    "  tick/.style={line width=0.5pt},\n"
    "  vector/.style={line width=0.8pt, -{Stealth[length=5pt]}},\n"
    "  construction/.style={line width=0.5pt, gray, dash pattern=on 3pt off 2pt},\n"
    "  pointer/.style={line width=0.8pt, gray, dash pattern=on 3pt off 2pt, -{Stealth[length=5pt]}},\n"
    "  ray/.style={line width=0.6pt, color={rgb,255:red,204;green,77;blue,13}},\n"
    "  cross/.style={line width=0.8pt},\n"
    "  leader/.style={line width=0.4pt, darkgray},\n"
    "  name leader/.style={line width=") + number(kNameLeaderWidth) + "pt, black!90},\n"
    "  name dot/.style={fill=black!90, draw=white, line width=0.4pt},\n"
    "  point label/.style={anchor=base west, inner sep=0pt, outer sep=0pt, fill=white, fill opacity=0.8, "
    "text opacity=1},\n"
    "  plain text/.style={anchor=base west, inner sep=0pt, outer sep=0pt},\n";
}

std::string colour(const Rgb8& c) {
  return "{rgb,255:red," + std::to_string(c.r) + ";green," + std::to_string(c.g) + ";blue," + std::to_string(c.b) + "}";
}

std::string rectangle(const Box& b, const Coordinates& at) {
  return at({b.left, b.bottom}) + " rectangle " + at({b.right, b.top});
}

// The overview of the whole scene, as the cairo painter draws it (figure_files.cpp's draw_inset).
std::string inset_commands(const PageInset& inset, const Coordinates& at) {
  if (!inset.shown()) return "";
  char background[96];
  std::snprintf(background, sizeof background, "{rgb,255:red,%d;green,%d;blue,%d}", int(255 * kInsetBackground[0] + 0.5),
                int(255 * kInsetBackground[1] + 0.5), int(255 * kInsetBackground[2] + 0.5));
  std::string t = "\\filldraw[fill=" + std::string(background) + ", draw=gray, line width=0.6pt] " + rectangle(inset.box, at) +
                  ";\n\\begin{scope}\n\\clip " + rectangle(inset.box, at) + ";\n";
  for (const PageDisc& disc : inset.discs)
    t += "\\fill[fill=" + colour(disc.colour) + ", fill opacity=0.8] " + at(disc.centre) + " circle[radius=" +
         number(disc.radius * kCmPerPoint) + "cm];\n";
  for (const Segment& s : inset.screen) t += "\\draw[line width=1pt] " + at(s.from) + " -- " + at(s.to) + ";\n";
  const std::string arm = number(kInsetArm) + "pt";
  for (const glm::dvec2& p : inset.crosses)
    t += "\\draw[line width=0.6pt, color={rgb,255:red,140;green,0;blue,0}] " + at(p) + " +(-" + arm + ",0) -- +(" + arm +
         ",0) " + at(p) + " +(0,-" + arm + ") -- +(0," + arm + ");\n";
  t += "\\draw[line width=0.6pt, color={rgb,255:red,217;green,26;blue,26}] " + rectangle(inset.zoom, at) + ";\n";
  return t + "\\end{scope}\n";
}

// One frame's drawing commands.
std::string frame_commands(const Figure& figure, int index, const FigureOutput& output) {
  const PageFrame page = lay_out_frame(figure, index, output);
  const Frame& frame = figure.frames[std::size_t(index)];
  const Coordinates at{output.page.height_pt};
  std::string t;
  if (!page.title.markup.empty())
    t += "\\node[plain text, " + font(page.title.size, true) + "] at " + at(page.title.at) + " {" + latex_of(page.title.markup) + "};\n";
  if (!page.caption.empty())  // LaTeX wraps it within the drawing's width, in the document's font
    t += "\\node[anchor=base west, inner sep=0pt, align=left, text width=" + number(page.area.width() * kCmPerPoint) +
         "cm, " + font(page.font_size) + "] at " + at(page.caption.front().at) + " {" + latex_of(frame.caption) + "};\n";
  t += "\\begin{scope}\n\\clip " + at({page.area.left, page.area.bottom}) + " rectangle " +
       at({page.area.right, page.area.top}) + ";\n";
  for (const PageDisc& disc : page.discs) {
    t += "\\filldraw[line width=0.5pt, " +
         std::string(page.objects_faded ? "fill=gray, fill opacity=0.12, draw opacity=0.3"
                                        : "fill=" + colour(disc.colour) + ", fill opacity=0.8") +
         "] ";
    if (disc.outline.empty()) {
      t += at(disc.centre) + " circle[radius=" + number(disc.radius * kCmPerPoint) + "cm];\n";
    } else {
      for (const glm::dvec2& p : disc.outline) t += at(p) + " -- ";
      t += "cycle;\n";
    }
  }
  for (const Segment& s : page.segments)
    t += "\\draw[" + std::string(style_of(s.stroke)) + "] " + at(s.from) + " -- " + at(s.to) + ";\n";
  for (const PageMarker& m : page.markers) {
    const std::string name = coordinate_name(m.point);
    t += "\\coordinate (" + name + ") at " + at(m.at) + ";\n";
    const std::string arm = number(page.arm) + "pt";
    t += "\\draw[cross] ([xshift=-" + arm + "]" + name + ") -- ([xshift=" + arm + "]" + name + ") ([yshift=-" + arm +
         "]" + name + ") -- ([yshift=" + arm + "]" + name + ");\n";
  }
  t += inset_commands(page.inset, at);
  for (const PlacedText& label : page.labels)
    if (label.leader) {
      t += "\\draw[" + std::string(label.dot ? "name leader" : "leader") + "] " + at(label.anchor) + " -- " +
           at({std::clamp(label.anchor.x, label.box.left, label.box.right),
               std::clamp(label.anchor.y, label.box.top, label.box.bottom)}) + ";\n";
      if (label.dot)
        t += "\\filldraw[name dot] " + at(label.anchor) + " circle[radius=" + number(kNameDotRadius) + "pt];\n";
    }
  for (const PlacedText& label : page.labels)
    t += "\\node[point label, " + font(label.size, label.bold) + "] at " + at(label.at) + " {" + latex_of(label.markup) + "};\n";
  t += "\\end{scope}\n";
  for (const KeyEntry& entry : page.key)  // the names that found no place in the drawing, beside it
    t += "\\filldraw[line width=0.5pt, fill=" + colour(entry.colour) + ", fill opacity=0.8] " + at(entry.swatch) +
         " circle[radius=" + number(entry.swatch_radius) + "pt];\n\\node[plain text, " + font(entry.text.size) + "] at " +
         at(entry.text.at) + " {" + latex_of(entry.text.markup) + "};\n";
  if (!page.cells.empty()) {  // the matrix: pmatrix (amsmath), centred on the rows' band
    std::string rows;
    const int n = frame.matrix_size;
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const std::string cell = latex_of("$" + matrix_entry(frame.matrix[std::size_t(r)][std::size_t(c)], figure.language) + "$");
        rows += cell.substr(1, cell.size() - 2) + (c + 1 < n ? " & " : "");
      }
      rows += r + 1 < n ? " \\\\ " : "";
    }
    const glm::dvec2 left(page.matrix_name.box.left, 0.5 * (page.matrix_brackets.top + page.matrix_brackets.bottom));
    t += "\\node[anchor=west, inner sep=0pt, " + font(page.font_size) + "] at " + at(left) + " {$M_d = \\begin{pmatrix} " +
         rows + " \\end{pmatrix}$};\n";
  }
  return t;
}

std::string picture(const std::string& body, const FigureOutput& output) {
  return "\\begin{tikzpicture}[scale=1,\n" + styles() + "]\n\\useasboundingbox (0,0) rectangle " +
         Coordinates{0.0}({output.page.width_pt, -output.page.height_pt}) + ";\n" + body + "\\end{tikzpicture}\n";
}

}  // namespace

const char* coordinate_name(Point point) {
  switch (point) {
    case Point::eye:
      return "eye";
    case Point::screen_first_end:
      return "screen first end";
    case Point::screen_last_end:
      return "screen last end";
    case Point::screen_centre:
      return "screen centre";
    case Point::target:
      return "target";
    case Point::origin:
      return "origin";
  }
  return "";
}

namespace {

// standalone's Beamer mode does not crop: its page is a 128 × 96 mm slide with 1 cm margins, which cut the
// default 160 × 120 mm picture's right and bottom (the matrix) off. The slide takes the picture's size.
std::string slide_of_the_picture(const PageSize& page) {
  char text[200];
  std::snprintf(text, sizeof text,
                "\\geometry{paperwidth=%.4fbp, paperheight=%.4fbp}\n"
                "\\setbeamersize{text margin left=0pt, text margin right=0pt}\n",
                page.width_pt, page.height_pt);
  return text;
}

}  // namespace

std::string tikz_document(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output) {
  const bool fr = figure.language == Language::fr;
  std::string t =
      "% raycam-cli figure: the construction of M_d (docs/figures.md).\n"
      "% Needs: \\usepackage{tikz} \\usetikzlibrary{arrows.meta} \\usepackage{amsmath}" +
      std::string(fr ? " \\usepackage[french]{babel}" : "") +
      "\n% Coordinates in cm; change the size with the tikzpicture's scale key (the text keeps its size).\n";
  if (output.pages) t += "% Beamer: \\only<1> ... \\only<" + std::to_string(frames.size()) + "> build the frames one slide after the other.\n";
  if (output.standalone)
    t += "\\documentclass" + std::string(output.pages ? "[beamer]" : "[tikz]") +
         "{standalone}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n\\usepackage{amsmath}\n" +
         (fr ? "\\usepackage[french]{babel}\n" : "") + "\\usepackage{tikz}\n\\usetikzlibrary{arrows.meta}\n" +
         (output.pages ? slide_of_the_picture(output.page) : "") + "\\begin{document}\n";
  if (output.pages) {
    std::string body;
    for (std::size_t i = 0; i < frames.size(); ++i)
      body += "\\only<" + std::to_string(i + 1) + ">{\n" + frame_commands(figure, frames[i], output) + "}\n";
    t += output.standalone ? "\\begin{standaloneframe}[plain]\n" + picture(body, output) + "\\end{standaloneframe}\n"
                           : picture(body, output);
  } else {
    for (int index : frames) t += picture(frame_commands(figure, index, output), output);
  }
  if (output.standalone) t += "\\end{document}\n";
  return t;
}

}  // namespace raycam::figure
