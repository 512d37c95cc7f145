#include "figure_export.h"

#include <stdexcept>

#include "figure_files.h"
#include "text.h"

namespace raycam::session {

std::vector<std::string> export_construction_figure(const Lesson& state, const std::string& path,
                                                    bool all_steps) {
  figure::FigureOutput output;
  bool known = false;
  for (figure::Format format : {figure::Format::svg, figure::Format::pdf, figure::Format::png}) {
    const std::string ext = std::string(".") + figure::extension(format);
    if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0) {
      output.format = format;
      known = true;
    }
  }
  if (!known) throw std::invalid_argument(trf("%s: expected a name ending in .svg, .pdf or .png", path.c_str()));
  output.pages = all_steps && output.format == figure::Format::pdf;
  const figure::FigureOptions options{current_language() == Language::fr ? figure::Language::fr
                                                                         : figure::Language::en};
  const figure::Figure drawn = std::visit(
      overloaded{[&](const View2D& view) { return figure::construction_figure_2d(view.scene, view.camera, options); },
                 [&](const View3D& view) { return figure::construction_figure_3d(view.scene, view.camera, options); }},
      state.view);
  // The app's steps are the figures' frames: 2D steps 0 … 3 are the handout's frames (a) … (d).
  const int count = int(drawn.frames.size());
  std::vector<int> frames;
  if (all_steps)
    for (int i = 0; i < count; ++i) frames.push_back(i);
  else
    frames.push_back(state.construction_step < 0 ? count - 1 : std::min(state.construction_step, count - 1));
  return figure::write_figure(drawn, frames, output, path).files;
}

}  // namespace raycam::session
