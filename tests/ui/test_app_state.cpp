// The app's state, without any window: input hygiene (a bad file keeps the scene, options are checked),
// presets round-trip, and the coarse preview while dragging is refined to the full image afterwards.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

#include "app_options.h"

using namespace raycam;

namespace {
ui::AppState state_for(const std::vector<std::string>& args) {
  ui::AppOptions options;
  for (std::size_t i = 0; i < args.size();)
    if (!ui::parse_app_option(args, i, options)) throw std::logic_error("not an app option: " + args[i]);
  return ui::make_app_state(options);
}
}  // namespace

TEST_CASE("a bad scene file shows an error naming it and keeps the current scene", "[ui][input]") {
  ui::AppState state = state_for({});
  ui::recast_if_needed(state);
  const std::size_t spheres = state.file.scene3d.spheres.size();
  {
    std::ofstream bad("bad_scene.json");
    bad << R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -2}]})";
  }
  CHECK_FALSE(ui::open_scene(state, "bad_scene.json"));
  CHECK(state.message_is_error);
  CHECK_THAT(state.message, Catch::Contains("bad_scene.json") && Catch::Contains("objects[0].radius"));
  CHECK(state.file.scene3d.spheres.size() == spheres);
  CHECK_FALSE(ui::open_scene(state, "no_such_file.json"));
  CHECK(state.file.scene3d.spheres.size() == spheres);
  std::remove("bad_scene.json");
}

TEST_CASE("a saved preset opens with the same camera", "[ui][files]") {
  ui::AppState state = state_for({"--view", "3d", "--theta", "-70", "--phi", "100", "--d", "5.5", "--df", "0.8"});
  REQUIRE(ui::save_preset(state, "preset.json"));
  ui::AppState reopened = state_for({});
  REQUIRE(ui::open_scene(reopened, "preset.json"));
  CHECK(reopened.orbit3d.theta == Approx(state.orbit3d.theta));
  CHECK(reopened.orbit3d.phi == Approx(state.orbit3d.phi));
  CHECK(reopened.orbit3d.d == Approx(5.5));
  CHECK(reopened.orbit3d.df == Approx(0.8));
  CHECK(reopened.file.scene3d.spheres.size() == state.file.scene3d.spheres.size());
  std::remove("preset.json");
}

TEST_CASE("options outside their range are refused before any window opens", "[ui][input]") {
  CHECK_THROWS_WITH(state_for({"--view", "2d", "--inspect", "10,3"}), Catch::Contains("--inspect"));
  CHECK_THROWS_WITH(state_for({"--view", "2d", "--step", "4"}), Catch::Contains("--step"));
  CHECK_THROWS_WITH(state_for({"--font-scale", "9"}), Catch::Contains("--font-scale"));
  CHECK_THROWS_WITH(state_for({"--width", "100000"}), Catch::Contains("--width"));
}

TEST_CASE("while dragging, an expensive cast is a coarse preview, refined when the drag ends", "[ui][preview]") {
  ui::AppState state = state_for({"--size", "512x512"});
  state.ns_per_ray = 250.0;  // pretend a slow machine: 512² rays × 250 ns ≈ 66 ms > the budget
  state.cameras_dirty = true;
  REQUIRE(ui::recast_if_needed(state, true));
  CHECK(state.refine_pending);
  CHECK(state.map.width < 512);
  CHECK(double(state.map.width) * state.map.height * 250e-6 <= ui::kInteractiveBudgetMs * 1.1);
  CHECK_FALSE(ui::recast_if_needed(state, true));  // nothing changed and still dragging: no work
  REQUIRE(ui::recast_if_needed(state, false));      // released: the full image
  CHECK_FALSE(state.refine_pending);
  CHECK(state.map.width == 512);
  CHECK(state.map.height == 512);
  CHECK_FALSE(ui::recast_if_needed(state, false));  // and then nothing more to do
}
