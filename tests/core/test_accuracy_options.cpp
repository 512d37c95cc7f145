// The accuracy knobs: the default knobs reproduce the plain caster, exact reproduces the exact bar (their
// flags are tested in tests/flags).
#include <catch2/catch.hpp>

#include "raycam/accuracy_options.h"
#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"
#include "raycam/view_setup.h"

using namespace raycam;

namespace {
ViewSetup demo(int dimension) {
  ViewFlags view;
  view.dimension = dimension;
  return make_view_setup(view);
}
}  // namespace

TEST_CASE("default knobs reproduce the plain caster, --exact reproduces the exact bar", "[accuracy][flags]") {
  AccuracyFlags defaults;
  const ViewSetup setup2d = demo(2);
  const ColourMap plain2d = cast_primary_rays(setup2d.camera2d, setup2d.file.scene2d);
  const ColourMap knobs2d = render_with_accuracy(setup2d, defaults);
  CHECK(knobs2d.ids == plain2d.ids);
  CHECK(knobs2d.colours == plain2d.colours);

  const ViewSetup setup3d = demo(3);
  const ColourMap plain3d = cast_primary_rays(setup3d.camera3d, setup3d.file.scene3d);
  CHECK(render_with_accuracy(setup3d, defaults).ids == plain3d.ids);

  AccuracyFlags exact = defaults;
  exact.exact = true;
  const ExactBar bar = exact_bar(setup2d.camera2d, setup2d.file.scene2d);
  CHECK(render_with_accuracy(setup2d, exact).ids == bar.centre_ids);
  CHECK_THROWS_WITH(render_with_accuracy(setup3d, exact), Catch::Contains("2D"));

  AccuracyFlags stable_placement = defaults;
  stable_placement.placement = PlacementRoute::stable;
  CHECK(render_with_accuracy(setup3d, stable_placement).ids == plain3d.ids);  // same camera, other route
}

TEST_CASE("the placement knob changes the camera: arccos loses θ at the pole, atan2 keeps it",
          "[accuracy][flags][placement]") {
  // φ = 1e-9: cos φ rounds to 1 (φ < 1.05e-8), so the handout's route finds φ = 0 and, with sin φ = 0, no θ
  // (it keeps θ = 0). At the pole θ is the image's roll (image up = (−cos θ cos φ, −sin θ cos φ, sin φ)), so
  // the arccos image is the θ = 0 image, turned by θ against the orbit's; atan2 recovers θ and the orbit's
  // image.
  ViewSetup setup = demo(3);
  setup.file.scene3d.spheres = {{{2.5, 0, 0}, 1.0, {200, 0, 0}, "on +x"},
                                {{0, 1.5, 0.5}, 0.7, {0, 200, 0}, "on +y"},
                                {{-1, -1, -1}, 1.0, {0, 0, 200}, "low"}};
  setup.camera3d = Camera3D(48, 48);
  setup.camera3d.set_orbit({{0, 0, 0}, 8.0, 1.2, 1e-9, 1.5});
  AccuracyFlags orbit;
  AccuracyFlags arccos = orbit, stable = orbit;
  arccos.placement = PlacementRoute::arccos;
  stable.placement = PlacementRoute::stable;
  const ColourMap from_orbit = render_with_accuracy(setup, orbit);
  const ColourMap from_arccos = render_with_accuracy(setup, arccos);
  CHECK(render_with_accuracy(setup, stable).ids == from_orbit.ids);
  CHECK(from_arccos.ids != from_orbit.ids);  // the knob is not ignored
  ViewSetup theta_zero = setup;
  theta_zero.camera3d.set_orbit({{0, 0, 0}, 8.0, 0.0, 0.0, 1.5});
  CHECK(from_arccos.ids == render_with_accuracy(theta_zero, orbit).ids);
}
