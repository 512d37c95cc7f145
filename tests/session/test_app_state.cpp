// The app's state, without any window: input hygiene (a bad file keeps the scene, options are checked),
// presets round-trip, and the coarse preview while dragging is refined to the full image afterwards.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

#include "../scratch_dir.h"
#include "session/app_options.h"
#include "app_state_for.h"
#include "raycam/exact_bar.h"

using namespace raycam;
using raycam::test::state_for;

TEST_CASE("a bad scene file shows an error naming it and keeps the current scene", "[ui][input]") {
  session::AppState state = state_for({});
  session::recast_if_needed(state);
  const std::size_t spheres = view3d(state).scene.spheres.size();
  const test::ScratchDir scratch("app-state");
  const std::string bad_scene = scratch.path("bad_scene.json");
  {
    std::ofstream bad(bad_scene);
    bad << R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -2}]})";
  }
  CHECK_FALSE(session::open_scene(state, bad_scene));
  CHECK(state.message_is_error);
  CHECK_THAT(state.message, Catch::Contains("bad_scene.json") && Catch::Contains("objects[0].radius"));
  CHECK(view3d(state).scene.spheres.size() == spheres);
  CHECK_FALSE(session::open_scene(state, scratch.path("no_such_file.json")));
  CHECK(view3d(state).scene.spheres.size() == spheres);
}

TEST_CASE("a saved preset opens with the same camera", "[ui][files]") {
  session::AppState state = state_for({"--view", "3d", "--theta", "-70", "--phi", "100", "--d", "5.5", "--df", "0.8"});
  const test::ScratchDir scratch("app-state");
  REQUIRE(session::save_preset(state, scratch.path("preset.json")));
  session::AppState reopened = state_for({});
  REQUIRE(session::open_scene(reopened, scratch.path("preset.json")));
  CHECK(view3d(reopened).orbit.theta == Approx(view3d(state).orbit.theta));
  CHECK(view3d(reopened).orbit.phi == Approx(view3d(state).orbit.phi));
  CHECK(view3d(reopened).orbit.d == Approx(5.5));
  CHECK(view3d(reopened).orbit.df == Approx(0.8));
  CHECK(view3d(reopened).scene.spheres.size() == view3d(state).scene.spheres.size());
}

TEST_CASE("options outside their range are refused before any window opens", "[ui][input]") {
  CHECK_THROWS_WITH(state_for({"--view", "2d", "--inspect", "10,3"}), Catch::Contains("--inspect"));
  CHECK_THROWS_WITH(state_for({"--view", "2d", "--step", "4"}), Catch::Contains("--step"));
  CHECK_THROWS_WITH(state_for({"--font-scale", "9"}), Catch::Contains("--font-scale"));
  CHECK_THROWS_WITH(state_for({"--width", "100000"}), Catch::Contains("--width"));
}

TEST_CASE("while dragging, an expensive cast is a coarse preview, refined when the drag ends", "[ui][preview]") {
  session::AppState state = state_for({"--size", "512x512"});
  state.ns_per_ray = 250.0;  // pretend a slow machine: 512² rays × 250 ns ≈ 66 ms > the budget
  state.cameras_dirty = true;
  REQUIRE(session::recast_if_needed(state, true));
  CHECK(state.refine_pending);
  CHECK(state.map.width < 512);
  CHECK(double(state.map.width) * state.map.height * 250e-6 <= session::kInteractiveBudgetMs * 1.1);
  CHECK_FALSE(session::recast_if_needed(state, true));  // nothing changed and still dragging: no work
  REQUIRE(session::recast_if_needed(state, false));      // released: the full image
  CHECK_FALSE(state.refine_pending);
  CHECK(state.map.width == 512);
  CHECK(state.map.height == 512);
  CHECK_FALSE(session::recast_if_needed(state, false));  // and then nothing more to do
}

TEST_CASE("the accuracy knobs switch the app to the reference caster, and back", "[ui][accuracy]") {
  session::AppState state = state_for({"--view", "2d", "--exact"});
  REQUIRE(session::uses_reference_caster(state));
  REQUIRE(session::recast_if_needed(state));
  const ExactBar bar = exact_bar(view2d(state).camera, view2d(state).scene);
  const ColourMap exact = to_colour_map(exact_bar_image(bar, view2d(state).scene));
  CHECK(state.map.colours == exact.colours);
  CHECK(state.map.ids == exact.ids);
  // Back to the defaults: the fast caster, which equals the plain loop.
  state.accuracy = AccuracyFlags{};
  state.cameras_dirty = true;
  REQUIRE_FALSE(session::uses_reference_caster(state));
  REQUIRE(session::recast_if_needed(state));
  CastOptions plain;
  plain.method = CastMethod::plain;
  CHECK(state.map.ids == cast_primary_rays(view2d(state).camera, view2d(state).scene, plain).ids);
  // The exact bar is 2D only: in 3D the knob is ignored rather than failing every frame.
  session::switch_dimension(state, 3);
  state.accuracy.exact = true;
  CHECK_FALSE(session::uses_reference_caster(state));
}

TEST_CASE("every caster method shows the same image in the app", "[ui][accuracy]") {
  session::AppState plain = state_for({"--method", "plain", "--size", "96x80"});
  session::AppState binned = state_for({"--method", "binned", "--size", "96x80"});
  REQUIRE(session::recast_if_needed(plain));
  REQUIRE(session::recast_if_needed(binned));
  CHECK(plain.map.ids == binned.map.ids);
  CHECK(binned.stats.intersection_tests < plain.stats.intersection_tests);
  CHECK_THROWS_WITH(state_for({"--placement", "arccos"}), Catch::Contains("--mistake arccos"));
  CHECK_THROWS_WITH(state_for({"--method", "quick"}), Catch::Contains("--method"));
}

TEST_CASE("a knob the scene cannot take shows an error and the fast image, never a crash", "[ui][accuracy]") {
  session::AppState state = state_for({"--view", "2d", "--exact"});
  view2d(state).scene.circles.assign(kMaxExactBarCircles + 1, Circle{{0, 0}, 0.5, {9, 9, 9}, ""});
  state.cameras_dirty = true;
  REQUIRE(session::recast_if_needed(state));
  CHECK(state.message_is_error);
  CHECK_THAT(state.message, Catch::Contains("circles"));
  CastOptions plain;
  plain.method = CastMethod::plain;
  CHECK(state.map.ids == cast_primary_rays(view2d(state).camera, view2d(state).scene, plain).ids);
}

TEST_CASE("placing the app's camera composes M_d once per change, with or without a mistake", "[ui][cache]") {
  session::AppState state = state_for({});
  for (bool printed : {false, true})
    for (bool arccos : {false, true})
      for (int wanted : {2, 3}) {
        session::switch_dimension(state, wanted);
        state.mistakes.printed_rotation_sign = printed;
        state.arccos_route = arccos;
        const long long before = placements_built_on_this_thread();
        session::place_cameras(state);
        CHECK(placements_built_on_this_thread() - before == 1);
      }
}

TEST_CASE("the 3D scene is packed for the caster once per scene: a newly opened file is cast, not the old one",
          "[ui][cache]") {
  session::AppState state = state_for({"--size", "64x48"});
  REQUIRE(session::recast_if_needed(state));
  const std::uint64_t packed = state.packed_version;
  CastOptions plain;
  plain.method = CastMethod::plain;
  // A camera change re-casts from the same packed copy.
  view3d(state).orbit.theta += 0.3;
  state.cameras_dirty = true;
  REQUIRE(session::recast_if_needed(state));
  CHECK(state.packed_version == packed);
  CHECK(state.map.ids == cast_primary_rays(view3d(state).camera, view3d(state).scene, plain).ids);
  // A new file: one big sphere on the target, so nearly every pixel changes from the demo's.
  const test::ScratchDir scratch("app-state");
  {
    std::ofstream file(scratch.path("one_sphere.json"));
    file << R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 3,
               "color": [1, 2, 3]}], "camera": {"d": 8, "size": [64, 48]}})";
  }
  REQUIRE(session::open_scene(state, scratch.path("one_sphere.json")));
  REQUIRE(session::recast_if_needed(state));
  CHECK(state.packed_version != packed);
  CHECK(state.packed3d.size() == 1);
  CHECK(state.map.ids == cast_primary_rays(view3d(state).camera, view3d(state).scene, plain).ids);
  CHECK(state.map.colour_at(24, 32) == Rgb8{1, 2, 3});
}

TEST_CASE("switching 2D/3D away from a file and back shows and names that file again", "[ui][files]") {
  session::AppState state = state_for({"--scene", RAYCAM_SOURCE_DIR "/scenes/many3d.json"});
  const std::size_t spheres = view3d(state).scene.spheres.size();
  REQUIRE(spheres == 2000);
  CHECK_THAT(session::window_title(state), Catch::Contains("3D") && Catch::Contains("many3d.json"));
  session::switch_dimension(state, 2);
  CHECK_THAT(session::window_title(state), Catch::Contains("2D") && Catch::Contains("demo scene"));
  CHECK(view2d(state).scene.circles.size() == demo_scene_2d().circles.size());
  session::switch_dimension(state, 3);
  CHECK_THAT(session::window_title(state), Catch::Contains("3D") && Catch::Contains("many3d.json"));
  CHECK(view3d(state).scene.spheres.size() == spheres);
  // A 2D file opened now: the 3D side is the demo again, and is named so.
  REQUIRE(session::open_scene(state, RAYCAM_SOURCE_DIR "/scenes/classic2d.json"));
  session::switch_dimension(state, 3);
  CHECK_THAT(session::window_title(state), Catch::Contains("demo scene"));
  session::switch_dimension(state, 2);
  CHECK_THAT(session::window_title(state), Catch::Contains("classic2d.json"));
}

TEST_CASE("the note that the other dimension is the demo goes when the switch comes back to the file",
          "[ui][files]") {
  session::AppState state = state_for({"--scene", RAYCAM_SOURCE_DIR "/scenes/classic2d.json"});
  session::switch_dimension(state, 3);  // leaving the file for the 3D demo: said so
  CHECK_THAT(state.message, Catch::Contains("3D demo"));
  session::switch_dimension(state, 2);  // back on classic2d.json: the note would now say the wrong thing
  CHECK_THAT(session::window_title(state), Catch::Contains("classic2d.json"));
  CHECK_THAT(state.message, !Catch::Contains("demo"));
}

TEST_CASE("a pinned ray follows res: the same canonical point, not dropped, no drift", "[ui][state]") {
  session::AppState state = state_for({"--view", "3d", "--size", "200x100"});
  session::recast_if_needed(state, false);
  REQUIRE(state.map.width == 200);
  state.pinned_pixel = session::PixelIndex{30, 150};  // the pixel centred at (150.5 / 200, 30.5 / 100)
  for (double res : {0.5, 0.37, 1.0}) {
    state.res = res;
    state.cameras_dirty = true;
    session::recast_if_needed(state, false);
    INFO("res " << res << ": " << state.map.width << " x " << state.map.height);
    REQUIRE(state.pinned_pixel);
    // The pinned pixel covers the point pinned first.
    CHECK(state.pinned_pixel->column <= 150.5 / 200 * state.map.width);
    CHECK(state.pinned_pixel->column + 1 > 150.5 / 200 * state.map.width);
    CHECK(state.pinned_pixel->row <= 30.5 / 100 * state.map.height);
    CHECK(state.pinned_pixel->row + 1 > 30.5 / 100 * state.map.height);
  }
  CHECK(state.pinned_pixel->column == 150);  // back at res 1: the very pixel, no drift through the others
  CHECK(state.pinned_pixel->row == 30);
}

// A confirmation ("wrote …") is read and goes by itself; an error stays until the user dismisses it. The
// clock starts when the message is first drawn (the frame passes its own clock), not when it was set.
TEST_CASE("a confirmation goes by itself after a few seconds, an error stays until read", "[ui][messages]") {
  session::Messages messages;
  session::set_message(messages, session::MessageSource::files, false, "wrote /tmp/lecture/map.png");
  CHECK(session::age_message(messages, 100.0));  // first drawn at t = 100 s: counting down
  CHECK(session::age_message(messages, 100.0 + 3.0));
  CHECK(messages.message == "wrote /tmp/lecture/map.png");  // 3 s: still there, long enough to read a path
  CHECK_FALSE(session::age_message(messages, 100.0 + 10.0));
  CHECK(messages.message.empty());  // 10 s: gone
  // A new message starts its own clock, even when it says the same thing again.
  session::set_message(messages, session::MessageSource::files, false, "wrote /tmp/lecture/map.png");
  session::age_message(messages, 200.0);
  session::set_message(messages, session::MessageSource::files, false, "wrote /tmp/lecture/map.png");
  CHECK(session::age_message(messages, 207.0));
  CHECK_FALSE(messages.message.empty());
  // An error is never timed out.
  session::set_message(messages, session::MessageSource::files, true, "cannot open /tmp/lecture/typo.json");
  CHECK_FALSE(session::age_message(messages, 300.0));
  CHECK_FALSE(session::age_message(messages, 300.0 + 3600.0));
  CHECK(messages.message == "cannot open /tmp/lecture/typo.json");
}
