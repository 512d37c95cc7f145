// The accuracy flags: parsing, errors that name the flag, and that the default knobs reproduce the plain
// caster while --exact reproduces the exact bar.
#include <catch2/catch.hpp>

#include "raycam/accuracy_options.h"
#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"

using namespace raycam;

namespace {
AccuracyFlags parse(std::vector<std::string> args) {
  AccuracyFlags flags;
  for (std::size_t i = 0; i < args.size();) REQUIRE(parse_accuracy_flag(args, i, flags));
  return flags;
}

ViewSetup demo(int dimension) {
  ViewFlags view;
  view.dimension = dimension;
  return make_view_setup(view);
}
}  // namespace

TEST_CASE("accuracy flags parse into the caster's options", "[accuracy][flags]") {
  const AccuracyFlags flags = parse({"--precision", "float", "--intersect", "naive", "--spp", "16", "--frame",
                                     "relative", "--placement", "arccos", "--exact"});
  CHECK(flags.options.scalar == Scalar::float32);
  CHECK(flags.options.formula == IntersectFormula::naive);
  CHECK(flags.options.samples_per_pixel == 16);
  CHECK(flags.options.camera_relative);
  CHECK(flags.placement == PlacementRoute::arccos);
  CHECK(flags.exact);
  CHECK(flags.given);

  std::vector<std::string> other = {"--d", "3"};
  std::size_t i = 0;
  AccuracyFlags untouched;
  CHECK_FALSE(parse_accuracy_flag(other, i, untouched));
  CHECK(i == 0);
  CHECK_FALSE(untouched.given);
}

TEST_CASE("bad accuracy flags name the flag and the accepted values", "[accuracy][flags]") {
  AccuracyFlags flags;
  auto fails = [&](std::vector<std::string> args) {
    std::size_t i = 0;
    parse_accuracy_flag(args, i, flags);
  };
  CHECK_THROWS_WITH(fails({"--precision", "half"}),
                    Catch::Contains("--precision") && Catch::Contains("float"));
  CHECK_THROWS_WITH(fails({"--intersect", "quick"}), Catch::Contains("--intersect"));
  CHECK_THROWS_WITH(fails({"--spp", "0"}), Catch::Contains("--spp"));
  CHECK_THROWS_WITH(fails({"--spp", "4x"}), Catch::Contains("--spp"));
  CHECK_THROWS_WITH(fails({"--frame", "camera"}), Catch::Contains("--frame"));
  CHECK_THROWS_WITH(fails({"--placement", "euler"}), Catch::Contains("--placement"));
  CHECK_THROWS_WITH(fails({"--spp"}), Catch::Contains("missing value"));
}

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
  CHECK_THROWS_WITH(render_with_accuracy(setup3d, exact), Catch::Contains("--exact"));

  AccuracyFlags stable_placement = defaults;
  stable_placement.placement = PlacementRoute::stable;
  CHECK(render_with_accuracy(setup3d, stable_placement).ids == plain3d.ids);  // same camera, other route
}
