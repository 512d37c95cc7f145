// `raycam-cli render`: the handout's exercise 2 from the command line.
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "raycam/image_files.h"
#include "commands.h"
#include "flag_values.h"
#include "raycam/accuracy_options.h"
#include "raycam/ray_caster.h"
#include "raycam/view_setup.h"
#include "view.h"
#include "view_options.h"

namespace raycam::cli {

namespace {
constexpr int kBarHeight = 32;  // a 2D colour bar is written n × 32 so that it can be seen

struct RenderOptions {
  ViewFlags view;
  CastOptions cast;
  AccuracyFlags accuracy;
  std::string out_path, ids_path;
};

int run_render(RenderOptions options) {
  if (options.out_path.empty() && options.ids_path.empty()) options.out_path = "render.png";
  const ViewSetup setup = make_view_setup(options.view);
  const session::View view = session::views_from_setup(setup).on_screen;  // the app's view of the scene
  if (options.accuracy.exact && !session::exact_bar_applies(view))
    throw std::invalid_argument("--exact: only for a 2D scene (3D: use --spp)");
  ColourMap map;
  const AccuracyFlags& knobs = options.accuracy;
  options.cast.formula = knobs.options.formula;  // the fast casters take either formula
  if (needs_reference_caster(knobs.options, knobs.exact) || knobs.placement != PlacementRoute::orbit) {
    map = render_with_accuracy(setup, knobs);
  } else {
    session::validate(view);
    map = std::visit([&](const auto& v) { return cast_primary_rays(v.camera, v.scene, options.cast); }, view);
  }
  long long background = 0;
  for (int id : map.ids) background += id < 0;
  const std::string& out = options.out_path;
  const std::string& ids = options.ids_path;
  if (!out.empty()) write_png(map, out, 1, session::image_is_bar(view) ? kBarHeight : 1);
  if (!ids.empty()) write_ids(map, ids);
  const std::size_t objects = std::visit([](const auto& v) { return objects_of(v.scene).size(); }, view);
  std::printf("%dD %dx%d, %zu objects, %.1f%% background%s%s%s%s\n", session::dimension_of(view), map.width,
              map.height, objects,
              100.0 * double(background) / double(map.ids.size()), out.empty() ? "" : "; wrote ", out.c_str(),
              ids.empty() ? "" : "; wrote ", ids.c_str());
  return 0;
}
}  // namespace

void add_render_command(CLI::App& cli, int& exit_code) {
  CLI::App* render = add_described_subcommand(
      cli, "render", "cast the primary rays and write the colour map (PNG) and object ids (text)",
      "Casts one primary ray per pixel (nearest object wins, ties to the lower index) and writes the colour "
      "map.\n");
  auto options = std::make_shared<RenderOptions>();
  flags::add_view_options(*render, options->view);
  flags::add_caster_options(*render, options->cast, options->accuracy);
  const flags::ValueRule<std::string> path = flags::file_name();
  flags::add_checked_option<std::string>(*render, "--out", "FILE",
                                         "PNG of the colour map (2D: the bar as an n x 32 image; column 0 = "
                                         "the eye's left). Default: render.png, "
                                         "unless only --ids is given",
                                         path, [options](std::string p) { options->out_path = p; });
  flags::add_checked_option<std::string>(
      *render, "--ids", "FILE",
      "object ids as text: one image row per line, space-separated, -1 = background", path,
      [options](std::string p) { options->ids_path = p; });
  render->callback([options, &exit_code] { exit_code = run_render(*options); });
}

}  // namespace raycam::cli
