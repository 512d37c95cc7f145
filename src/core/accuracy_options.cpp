#include "raycam/accuracy_options.h"

#include <cmath>
#include <stdexcept>

#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"

namespace raycam {

bool parse_accuracy_flag(const std::vector<std::string>& args, std::size_t& i, AccuracyFlags& flags) {
  const std::string& flag = args[i];
  if (flag == "--exact") {
    flags.exact = flags.given = true;
    ++i;
    return true;
  }
  if (flag != "--precision" && flag != "--intersect" && flag != "--spp" && flag != "--frame" &&
      flag != "--placement")
    return false;
  if (i + 1 >= args.size()) throw std::invalid_argument(flag + ": missing value (see --help)");
  const std::string& value = args[i + 1];
  if (flag == "--precision") {
    flags.options.scalar = parse_scalar(value, flag);
  } else if (flag == "--intersect") {
    flags.options.formula = parse_formula(value, flag);
  } else if (flag == "--spp") {
    std::size_t used = 0;
    int spp = 0;
    try {
      spp = std::stoi(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != value.size() || spp < 1 || spp > kMaxSamplesPerPixel)
      throw std::invalid_argument("--spp must be an integer in [1, " + std::to_string(kMaxSamplesPerPixel) +
                                  "], got '" + value + "'");
    flags.options.samples_per_pixel = spp;
  } else if (flag == "--frame") {
    if (value != "world" && value != "relative")
      throw std::invalid_argument("--frame must be world or relative, got '" + value + "'");
    flags.options.camera_relative = value == "relative";
  } else {
    if (value == "orbit")
      flags.placement = PlacementRoute::orbit;
    else if (value == "arccos")
      flags.placement = PlacementRoute::arccos;
    else if (value == "stable")
      flags.placement = PlacementRoute::stable;
    else
      throw std::invalid_argument("--placement must be orbit, arccos or stable, got '" + value + "'");
  }
  flags.given = true;
  i += 2;
  return true;
}

const char* accuracy_flags_help() {
  return "accuracy knobs (README, \"Accuracy\"):\n"
         "  --precision P       float | double | long-double arithmetic per ray (default double)\n"
         "  --intersect F       naive (textbook b^2 - c) | stable (Ray Tracing Gems 2019; default)\n"
         "  --spp N             stratified samples per pixel, colours averaged (3D: a square, 1, 4, 9, "
         "16...)\n"
         "  --frame F           world (default) | relative: coordinates relative to the eye\n"
         "  --placement R       orbit (default) | arccos (handout) | stable (atan2): free placement from P, "
         "C\n"
         "  --exact             2D: the exact bar, each pixel's colour weighted by exact coverage\n";
}

namespace {
AngleRoute route_of(PlacementRoute placement) {
  return placement == PlacementRoute::arccos ? AngleRoute::handout_arccos : AngleRoute::stable;
}
}  // namespace

// The one rule (needs_reference_caster) picks the caster, as in the app: knobs the fast caster takes (the
// formula) keep it, and it gives the reference's image for them.
ColourMap render_with_accuracy(const Camera2D& camera, const Scene2D& scene, const AccuracyFlags& flags) {
  validate(scene);
  if (!needs_reference_caster(flags.options, flags.exact))
    return cast_primary_rays(camera, scene, CastOptions{flags.options.formula});
  if (flags.exact) return to_colour_map(exact_bar_image(exact_bar(camera, scene), scene));
  return to_colour_map(reference_cast(camera, scene, flags.options));
}

ColourMap render_with_accuracy(const Camera3D& camera, const Scene3D& scene, const AccuracyFlags& flags) {
  if (flags.exact) throw std::invalid_argument("--exact is for the 2D bar only (3D: use --spp)");
  validate(scene);
  if (!needs_reference_caster(flags.options, false))
    return cast_primary_rays(camera, scene, CastOptions{flags.options.formula});
  return to_colour_map(reference_cast(camera, scene, flags.options));
}

ColourMap render_with_accuracy(const ViewSetup& setup, const AccuracyFlags& flags) {
  if (setup.dimension == 2) {
    Camera2D camera = setup.camera2d;
    if (flags.placement != PlacementRoute::orbit) {
      const Orbit2D orbit = camera.orbit();
      camera.set_free(camera.screen_centre(), orbit.target, orbit.df, route_of(flags.placement));
    }
    return render_with_accuracy(camera, setup.file.scene2d, flags);
  }
  Camera3D camera = setup.camera3d;
  if (flags.placement != PlacementRoute::orbit) {
    const Orbit3D orbit = camera.orbit();
    camera.set_free(camera.screen_centre(), orbit.target, orbit.df, route_of(flags.placement));
  }
  return render_with_accuracy(camera, setup.file.scene3d, flags);
}

}  // namespace raycam
