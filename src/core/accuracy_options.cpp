#include "raycam/accuracy_options.h"

#include <cmath>
#include <stdexcept>

#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"

namespace raycam {

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
  if (flags.exact)
    throw std::invalid_argument("exact: the exact bar is 2D only (3D: use more samples per pixel)");
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
