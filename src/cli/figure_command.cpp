// `raycam-cli figure`: the handout's construction of M_d as figures for course notes and slides: the 2D
// frames (a) → (d) or the 3D steps 0 → 5, for a scene file or the demo and the camera flags `render` takes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "figure/figure_files.h"
#include "flags/flag_values.h"
#include "raycam/demo_names.h"
#include "flags/view_options.h"

namespace raycam::cli {

namespace {

// --size: the figure's size with its unit (160x120mm, 1200x900px), or, without a unit, the camera's N|WxH
// as `render` takes it.
struct SizeValue {
  std::optional<figure::PageSize> page;
  std::vector<int> camera;
};

constexpr double kMinMm = 20.0, kMaxMm = 2000.0;
constexpr int kMinPx = 64, kMaxPx = 8192;

flags::ValueRule<SizeValue> size_rule() {
  const flags::ValueRule<std::vector<int>> camera = flags::size_rule();
  return {"a figure size W[xH]mm in [20, 2000] or W[xH]px in [64, 8192] (H = 3/4 W when left out), or the "
          "camera's " + camera.expected,
          [camera](const std::string& text) -> std::optional<SizeValue> {
            const bool mm = text.size() > 2 && text.compare(text.size() - 2, 2, "mm") == 0;
            const bool px = text.size() > 2 && text.compare(text.size() - 2, 2, "px") == 0;
            if (!mm && !px) {
              const auto size = camera.parse(text);
              if (!size) return std::nullopt;
              return SizeValue{std::nullopt, *size};
            }
            const std::string number = text.substr(0, text.size() - 2);
            const std::size_t x = number.find('x');
            const flags::ValueRule<double> side =
                flags::number_in(mm ? flags::Interval{kMinMm, kMaxMm} : flags::Interval{kMinPx, kMaxPx});
            const auto width = side.parse(number.substr(0, x));
            const auto height = x == std::string::npos ? std::optional<double>(0.75 * width.value_or(0.0))
                                                       : side.parse(number.substr(x + 1));
            if (!width || !height || *height < (mm ? kMinMm : kMinPx)) return std::nullopt;
            if (px && (*width != std::floor(*width) || *height != std::floor(*height)) && x != std::string::npos)
              return std::nullopt;
            return SizeValue{mm ? figure::page_in_mm(*width, *height)
                                : figure::page_in_px(int(*width), int(std::lround(*height))),
                             {}};
          }};
}

struct FigureOptions {
  ViewFlags view;
  std::vector<std::string> frames;  // empty: every frame
  std::optional<figure::Format> format;
  std::string out_path;
  figure::PageSize page = figure::page_in_mm(160.0, 120.0);
  bool page_in_px = false;
  std::optional<double> dpi;
  double font_size = 9.0;
  bool pages = false, standalone = false, no_matrix = false, no_title = false, no_caption = false;
  Language language = Language::en;
  int rays = 5;
};

const std::vector<std::string> kFormats = {"svg", "pdf", "png", "tikz"};  // figure::Format's order
constexpr int kMaxPngSide = 20000;  // px: beyond, the image alone would take gigabytes

// How each dimension names its frames: the handout's letters a … d (2D), the steps 0 … 5 (3D).
struct FrameNames {
  char first;
  int count;
  const char* expected;  // for --frames' message
};
FrameNames frame_names(int dimension) {
  return dimension == 2 ? FrameNames{'a', figure::kFrames2D, "frames among a, b, c, d (a 2D scene), or a range such as a..d"}
                        : FrameNames{'0', figure::kSteps3D, "steps among 0 … 5 (a 3D scene), or a range such as 0..5"};
}

// The frames asked for, as indices: "a,b" or "a..d" (2D), "0,3" or "0..5" (3D).
std::vector<int> frame_indices(const std::vector<std::string>& asked, int dimension) {
  const FrameNames names = frame_names(dimension);
  const char first = names.first;
  const int count = names.count;
  auto index_of = [&](const std::string& name) -> int {
    if (name.size() != 1 || name[0] < first || name[0] >= first + count) return -1;
    return name[0] - first;
  };
  std::vector<int> indices;
  for (const std::string& item : asked) {
    const std::size_t dots = item.find("..");
    const int from = index_of(dots == std::string::npos ? item : item.substr(0, dots));
    const int to = dots == std::string::npos ? from : index_of(item.substr(dots + 2));
    if (from < 0 || to < from)
      throw std::invalid_argument(flags::bad_value_message("--frames", names.expected, item));
    for (int i = from; i <= to; ++i) indices.push_back(i);
  }
  if (indices.empty())
    for (int i = 0; i < count; ++i) indices.push_back(i);
  return indices;
}

std::optional<figure::Format> format_of_name(const std::string& path) {
  for (std::size_t i = 0; i < kFormats.size(); ++i) {
    const std::string ext = std::string(".") + figure::extension(figure::Format(i));
    if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
      return figure::Format(i);
  }
  return std::nullopt;
}

int run_figure(FigureOptions options) {
  const std::optional<figure::Format> named = format_of_name(options.out_path);
  if (options.format && named && *named != *options.format)
    throw std::invalid_argument(flags::bad_value_message(
        "--out", std::string("a file name ending in .") + figure::extension(*options.format) + " (--format)",
        options.out_path));
  figure::FigureOutput output;
  output.format = options.format.value_or(named.value_or(figure::Format::svg));
  const std::string format_name = kFormats[std::size_t(output.format)];
  if (options.pages && output.format != figure::Format::pdf && output.format != figure::Format::tikz)
    throw std::invalid_argument("--pages: expected --format pdf (one PDF with a page per frame) or tikz (Beamer "
                                "overlays), got --format " + format_name);
  if (options.standalone && output.format != figure::Format::tikz)
    throw std::invalid_argument("--standalone: expected --format tikz, got --format " + format_name);
  if (options.out_path.empty()) options.out_path = std::string("figure.") + figure::extension(output.format);
  output.page = options.page;
  if (options.dpi) {
    if (options.page_in_px)
      throw std::invalid_argument("--dpi: expected a --size in mm (a size in px is 96 dpi), got --dpi " +
                                  std::to_string(int(*options.dpi)) + " with a size in px");
    output.page.pixels_per_point = *options.dpi / 72.0;
  }
  if (output.format == figure::Format::png &&
      std::max(output.page.width_px(), output.page.height_px()) > kMaxPngSide)
    throw std::invalid_argument("--size: expected a PNG of at most " + std::to_string(kMaxPngSide) +
                                " px a side (--size × --dpi), got " + std::to_string(output.page.width_px()) + "x" +
                                std::to_string(output.page.height_px()) + " px");
  output.matrix = !options.no_matrix;
  output.title = !options.no_title;
  output.caption = !options.no_caption;
  output.pages = options.pages;
  output.standalone = options.standalone;
  output.font_size_pt = options.font_size;

  ViewSetup setup = make_view_setup(options.view);
  name_demo_objects(setup, options.language);  // a shipped scene's "yellow" is "jaune" in a French figure
  const std::vector<int> frames = frame_indices(options.frames, setup.dimension);
  const figure::FigureOptions drawing{options.language, options.rays};
  const figure::Figure drawn = visit_view_setup(
      setup, [&](const auto& camera, const auto& scene) { return figure::construction_figure(scene, camera, drawing); });
  // A page whose title, caption and matrix leave the drawing less than a fifth of its height: the text would
  // run over the drawing and the labels over the matrix (80x60mm at --font-size 12 left it nothing).
  const double room = figure::room_for_drawing_pt(drawn, output);
  if (room < figure::kLeastDrawingShare * output.page.height_pt) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "--size: expected a page with room for the drawing (a fifth of its height, %.0f pt), got %.0f pt "
                  "left by the title, the caption and the matrix at --font-size %g: a bigger --size, a smaller "
                  "--font-size, or --no-title, --no-caption, --no-matrix",
                  figure::kLeastDrawingShare * output.page.height_pt, std::max(room, 0.0), output.font_size_pt);
    throw std::invalid_argument(text);
  }
  // Names that find no place by their object, on a leader or in the key: the smallest page that names them.
  if (!figure::names_fit(drawn, frames, output)) {
    const double per_unit = options.page_in_px ? 0.75 : 72.0 / 25.4;  // points per px, per mm
    const char* unit = options.page_in_px ? "px" : "mm";
    const figure::PageSize least = figure::smallest_page_for_names(
        drawn, frames, output, per_unit, (options.page_in_px ? kMaxPx : kMaxMm) * per_unit);
    auto size = [&](const figure::PageSize& page) {
      char text[64];
      std::snprintf(text, sizeof text, "%gx%g%s", std::round(10.0 * page.width_pt / per_unit) / 10.0,
                    std::round(10.0 * page.height_pt / per_unit) / 10.0, unit);
      return std::string(text);
    };
    char font[32];
    std::snprintf(font, sizeof font, "%g", output.font_size_pt);
    const std::string works = least.width_pt > output.page.width_pt
                                  ? "the smallest that works is " + size(least)
                                  : std::string("no size of this shape works");
    throw std::invalid_argument("--size: expected a page with room for every object's name (by its object, on a "
                                "leader or in a key), got " + size(output.page) + " at --font-size " + font +
                                ": " + works + ", or a smaller --font-size");
  }
  const figure::WrittenFigure written = figure::write_figure(drawn, frames, output, options.out_path);
  for (std::size_t i = 0; i < written.files.size(); ++i)
    std::printf("wrote %s\n", written.files[i].c_str());
  return 0;
}

}  // namespace

void add_figure_command(CLI::App& cli, int& exit_code) {
  CLI::App* command = add_described_subcommand(
      cli, "figure", "draw the construction of M_d as course figures (SVG, PDF, PNG, TikZ)",
      "Draws the handout's frames (a) identity, (b) H(1, d_f), (c) the rotations R(phi_v)·R(psi0) onto "
      "v = PC/|PC|, (d) the translation, for a 2D scene; the steps 0 (identity) … 5 (M_d) for a 3D scene. Each "
      "frame shows the objects, the target C, the eye, the screen and its pixels, a few primary rays and the "
      "frame's matrix. Text keeps its size in points whatever --size. Without --scene: the demo scene. See "
      "docs/figures.md.\n");
  auto options = std::make_shared<FigureOptions>();
  CLI::Option_group* camera = flags::add_view_options(*command, options->view);
  camera->remove_option(camera->get_option("--size"));  // --size below also takes the figure's size
  flags::add_checked_option<SizeValue>(
      *command, "--size", "SIZE",
      "the figure's size: W[xH]mm (default 160x120mm; PNG at --dpi) or W[xH]px; without a unit, the "
      "camera's N (2D) or WxH (3D) as for render",
      size_rule(), [options](SizeValue size) {
        if (size.page) {
          options->page = *size.page;
          options->page_in_px = size.page->pixels_per_point == figure::page_in_px(1, 1).pixels_per_point;
        } else
          options->view.camera.size = size.camera;
      });
  const flags::ValueRule<std::string> name = flags::file_name();
  command
      ->add_option_function<std::vector<std::string>>(
          "--frames", [options](const std::vector<std::string>& items) { options->frames = items; },
          "which frames: a,b,c,d or a..d (2D), 0..5 (3D); default: all")
      ->type_name("LIST")
      ->delimiter(',');
  flags::add_checked_option<int>(*command, "--format", "svg|pdf|png|tikz",
                                 "default: from --out's extension, else svg", flags::one_of(kFormats),
                                 [options](int i) { options->format = figure::Format(i); });
  flags::add_checked_option<std::string>(
      *command, "--out", "FILE",
      "the figure's file (.svg, .pdf, .png, .tex); with several frames, one file each: FILE-a.svg, "
      "FILE-b.svg… (default figure.svg)",
      name, [options](std::string path) { options->out_path = path; });
  command->add_flag("--pages", options->pages,
                    "with --format pdf: one PDF, a page per frame; with tikz: one picture, the frames as Beamer "
                    "overlays \\only<1>, \\only<2>…");
  command->add_flag("--standalone", options->standalone,
                    "with --format tikz: a standalone LaTeX document (pdflatex compiles it on its own)");
  flags::add_checked_option<double>(*command, "--font-size", "PT",
                                    "the text's size in points, whatever --size (default 9; the title 1.3×); a page "
                                    "whose title, caption and matrix leave the drawing under a fifth of it is refused",
                                    flags::number_in({4.0, 72.0}), [options](double pt) { options->font_size = pt; });
  flags::add_checked_option<double>(*command, "--dpi", "DPI",
                                    "a PNG's resolution for a --size in mm, recorded in the file (default 300)",
                                    flags::number_in({36.0, 2400.0}), [options](double dpi) { options->dpi = dpi; });
  command->add_flag("--no-title", options->no_title, "leave out each frame's title");
  command->add_flag("--no-caption", options->no_caption, "leave out each frame's caption");
  flags::add_checked_option<Language>(*command, "--lang", flags::language_metavar(),
                                      "the figures' language (default en)", flags::language_rule(),
                                      [options](Language language) { options->language = language; });
  flags::add_checked_option<int>(*command, "--rays", "N", "primary rays drawn per 2D frame, 0 … 64 (default 5)",
                                 flags::integer_in(0, 64), [options](int n) { options->rays = n; });
  command->add_flag("--no-matrix", options->no_matrix, "leave out each frame's matrix");
  command->callback([options, &exit_code] { exit_code = run_figure(*options); });
}

}  // namespace raycam::cli
