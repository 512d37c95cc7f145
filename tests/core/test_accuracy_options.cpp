// The accuracy knobs: the default knobs reproduce the plain caster, exact reproduces the exact bar (their
// flags are tested in tests/flags).
#include <catch2/catch.hpp>

#include "raycam/accuracy_options.h"
#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"

using namespace raycam;

namespace {
ViewSetup demo(int dimension) {
  ViewFlags view;
  view.dimension = dimension;
  return make_view_setup(view);
}
}  // namespace

TEST_CASE("default knobs reproduce the plain caster; --exact reproduces the exact bar", "[accuracy][flags]") {
  AccuracyFlags defaults;
  defaults.given = true;
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
