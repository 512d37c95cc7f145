// `raycam-cli render`: the handout's exercise 2 from the command line.
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "raycam/image_files.h"
#include "cli/commands.h"
#include "flags/flag_values.h"
#include "raycam/accuracy_options.h"
#include "raycam/ray_caster.h"
#include "raycam/view_setup.h"
#include "session/view.h"
#include "flags/view_options.h"

namespace raycam::cli {

namespace {
constexpr int kBarHeight = 32;  // a 2D colour bar is written n × 32 so that it can be seen

struct RenderOptions {
  ViewFlags view;
  CastOptions cast;
  AccuracyFlags accuracy;
  std::string out_path, ids_path;
  bool ids_in_k_order = false;  // --ids-order k: a 2D line in the answer's order k, not the image's
};

// The ids as a student's answer lists them. In 3D that is the image's order (row 0 the top, column 0 the left,
// canonical x near -1). In 2D column 0 is the eye's left, which is pixel k = n-1 (docs/conventions.md): the
// line is turned around so that entry k is pixel k, the handout's centre x = -1 + (2k+1)/n.
ColourMap in_answer_order(const ColourMap& map, const session::View& view) {
  const auto* view2d = std::get_if<session::View2D>(&view);
  if (!view2d) return map;
  if (view2d->camera.pixel_count() != map.width || map.height != 1)
    throw std::logic_error("--ids-order k: the bar has not the camera's n pixels");
  ColourMap out = map;
  for (int column = 0; column < map.width; ++column)
    out.ids[out.index(0, view2d->camera.pixel_of_column(column))] = map.id_at(0, column);
  return out;
}

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
  if (options.ids_in_k_order && ids.empty()) throw std::invalid_argument("--ids-order: only with --ids FILE");
  if (!ids.empty()) write_ids(options.ids_in_k_order ? in_answer_order(map, view) : map, ids);
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
      "object ids as text: one image row per line, space-separated, -1 = background; in the image's order "
      "(2D: column 0 = the eye's left = pixel k = n-1) unless --ids-order k",
      path, [options](std::string p) { options->ids_path = p; });
  const std::vector<std::string> orders = {"image", "k"};
  flags::add_checked_option<int>(
      *render, "--ids-order", "image|k",
      "the order of --ids: image (default) or k, an answer's order (2D: entry k is pixel k, centre "
      "x = -1 + (2k+1)/n, the image's line reversed; 3D: the same as image)",
      flags::one_of(orders), [options](int i) { options->ids_in_k_order = i == 1; });
  render->callback([options, &exit_code] { exit_code = run_render(*options); });
}

}  // namespace raycam::cli
