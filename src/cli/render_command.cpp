// `raycam-cli render`: the handout's exercise 2 from the command line.
#include <cstdio>
#include <stdexcept>

#include "commands.h"
#include "raycam/accuracy_options.h"
#include "raycam/ray_caster.h"
#include "raycam/view_setup.h"

namespace raycam::cli {

namespace {
constexpr int kBarHeight = 32;  // a 2D colour bar is written n × 32 so that it can be seen

void print_help() {
  std::printf(
      "usage: raycam-cli render [--scene FILE] [--mode 2d|3d] [--target x,y[,z]] [--d D] [--theta DEG]\n"
      "                         [--phi DEG] [--df F] [--res R] [--size N | --size WxH]\n"
      "                         [--method M] [--threads T] [accuracy knobs] [--out image.png] [--ids ids.txt]\n\n"
      "Casts one primary ray per pixel (nearest object wins, ties to the lower index) and writes the colour\n"
      "map. Flags override the scene file's camera preset. Angles in degrees.\n\n%s"
      "  --method M          automatic (default) | plain | culled | footprint | binned: the caster (README,\n"
      "                      \"Speed\"); every method gives the plain loop's ids\n"
      "  --threads T         worker threads in [1, 256] (default: every hardware thread)\n%s"
      "  --out FILE          PNG of the colour map (2D: the bar as an n x %d image; column 0 = the eye's\n"
      "                      left). Default: render.png, unless only --ids is given\n"
      "  --ids FILE          object ids as text: one image row per line, space-separated, -1 = background\n"
      "  --help              this text\n",
      view_flags_help(), accuracy_flags_help(), kBarHeight);
}
}  // namespace

int run_render(const Args& args) {
  ViewFlags flags;
  AccuracyFlags accuracy;
  CastOptions cast_options;
  std::string out_path, ids_path;
  for (std::size_t i = 0; i < args.size();) {
    if (args[i] == "--help" || args[i] == "-h") {
      print_help();
      return 0;
    }
    if (parse_view_flag(args, i, flags) || parse_accuracy_flag(args, i, accuracy)) continue;
    if ((args[i] == "--method" || args[i] == "--threads") && i + 1 < args.size()) {
      if (args[i] == "--method") cast_options.method = parse_cast_method(args[i + 1], args[i]);
      else cast_options.threads = parse_integer_flag(args[i + 1], args[i], 1, 256);
      i += 2;
      continue;
    }
    if (args[i] == "--out" || args[i] == "--ids") {
      if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + ": missing file name");
      (args[i] == "--out" ? out_path : ids_path) = args[i + 1];
      i += 2;
      continue;
    }
    throw std::invalid_argument("unknown option '" + args[i] + "' (see raycam-cli render --help)");
  }
  if (out_path.empty() && ids_path.empty()) out_path = "render.png";

  const ViewSetup setup = make_view_setup(flags);
  ColourMap map;
  if (accuracy.given) {
    map = render_with_accuracy(setup, accuracy);
  } else if (setup.dimension == 2) {
    validate(setup.file.scene2d);
    map = cast_primary_rays(setup.camera2d, setup.file.scene2d, cast_options);
  } else {
    validate(setup.file.scene3d);
    map = cast_primary_rays(setup.camera3d, setup.file.scene3d, cast_options);
  }
  long long background = 0;
  for (int id : map.ids) background += id < 0;
  if (!out_path.empty()) write_png(map, out_path, 1, setup.dimension == 2 ? kBarHeight : 1);
  if (!ids_path.empty()) write_ids(map, ids_path);
  std::printf("%dD %dx%d, %zu objects, %.1f%% background%s%s%s%s\n", setup.dimension, map.width, map.height,
              setup.dimension == 2 ? setup.file.scene2d.circles.size() : setup.file.scene3d.spheres.size(),
              100.0 * double(background) / double(map.ids.size()), out_path.empty() ? "" : "; wrote ",
              out_path.c_str(), ids_path.empty() ? "" : "; wrote ", ids_path.c_str());
  return 0;
}

}  // namespace raycam::cli
