#include "session/figure_export.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "figure/figure_files.h"
#include "session/text.h"

namespace raycam::session {

namespace {

struct Export {
  figure::Figure drawn;
  std::vector<int> frames;
  figure::FigureOutput output;
  std::string path;  // absolute
};

// The figure of the camera on screen, the frames asked for and the output the path's extension says.
Export prepare(const Lesson& state, const FigureContent& content, const std::string& path, bool all_steps) {
  const int format = figure_format_of(path);
  if (format < 0)
    throw std::invalid_argument(trf(state.language, "%s: expected a name ending in .svg, .pdf, .png or .tex", path.c_str()));
  Export e;
  e.path = std::filesystem::absolute(path).lexically_normal().string();
  e.output.format = figure::Format(format);  // kFigureExtensions is figure::Format's order
  e.output.pages = all_steps && e.output.format == figure::Format::pdf;
  e.output.matrix = content.matrix;
  const figure::FigureOptions options{state.language, content.rays};
  e.drawn = std::visit(
      overloaded{[&](const View2D& view) { return figure::construction_figure_2d(scene_as_shown(state.language, view), view.camera, options); },
                 [&](const View3D& view) { return figure::construction_figure_3d(scene_as_shown(state.language, view), view.camera, options); }},
      state.view);
  // The app's steps are the figures' frames: 2D steps 0 … 3 are the handout's frames (a) … (d).
  const int count = int(e.drawn.frames.size());
  if (all_steps)
    for (int i = 0; i < count; ++i) e.frames.push_back(i);
  else
    e.frames.push_back(state.construction_step < 0 ? count - 1 : std::min(state.construction_step, count - 1));
  return e;
}

}  // namespace

std::vector<std::string> export_construction_figure(const Lesson& lesson, const FigureContent& content,
                                                    const std::string& path, bool all_steps) {
  const Export e = prepare(lesson, content, path, all_steps);
  // Names that find no place by their object, on a leader or in the key: refused, as raycam-cli figure
  // refuses them, with the size that names them all (a figure without some names would pass for complete).
  if (!figure::names_fit(e.drawn, e.frames, e.output)) {
    constexpr double kPointsPerMm = 72.0 / 25.4;
    const figure::PageSize least = figure::smallest_page_for_names(e.drawn, e.frames, e.output, kPointsPerMm, 1000.0 * kPointsPerMm);
    const auto mm = [](double pt) { return int(std::lround(pt / kPointsPerMm)); };
    throw std::runtime_error(trf(lesson.language,
                                 "not every object's name fits on the figure's %d × %d mm page: raycam-cli figure --size %dx%dmm names them all",
                                 mm(e.output.page.width_pt), mm(e.output.page.height_pt), mm(least.width_pt), mm(least.height_pt)));
  }
  return figure::write_figure(e.drawn, e.frames, e.output, e.path).files;
}

std::vector<std::string> existing_figure_files(const Lesson& lesson, const FigureContent& content,
                                               const std::string& path, bool all_steps) {
  const Export e = prepare(lesson, content, path, all_steps);
  std::vector<std::string> existing;
  for (const std::string& file : figure::figure_files(e.drawn, e.frames, e.output, e.path))
    if (std::filesystem::exists(file)) existing.push_back(file);
  return existing;
}

}  // namespace raycam::session
