// The camera on screen picked in one place: in 2D the shared orbit parameters, the target, the size limit,
// the objects and the preset are the 2D camera's, in 3D the 3D camera's, and writing through the accessor
// moves only the camera on screen.
#include <catch2/catch.hpp>

#include "app_state_for.h"

using namespace raycam;

TEST_CASE("the active camera is the 2D one in 2D and the 3D one in 3D", "[ui][active]") {
  for (const char* view : {"2d", "3d"}) {
    session::AppState state = test::state_for({"--view", view, "--size", "64"});
    const bool is_2d = std::string(view) == "2d";
    INFO(view);
    REQUIRE(dimension(state) == (is_2d ? 2 : 3));
    const double other_d = is_2d ? view3d(state).orbit.d : view2d(state).orbit.d;
    session::active_orbit(state).d = 7.25;
    session::active_orbit(state).df = 0.75;
    session::active_orbit(state).theta = 0.5;
    CHECK((is_2d ? view2d(state).orbit.d : view3d(state).orbit.d) == 7.25);
    CHECK((is_2d ? view2d(state).orbit.df : view3d(state).orbit.df) == 0.75);
    CHECK((is_2d ? view2d(state).orbit.theta : view3d(state).orbit.theta) == 0.5);
    CHECK((is_2d ? view3d(state).orbit.d : view2d(state).orbit.d) == other_d);  // the other camera stays
    const session::AppState& read = state;
    CHECK(session::active_orbit(read).d == 7.25);

    const glm::dvec2 target = session::active_target_xy(state);
    CHECK(target.x == (is_2d ? view2d(state).orbit.target.x : view3d(state).orbit.target.x));
    CHECK(target.y == (is_2d ? view2d(state).orbit.target.y : view3d(state).orbit.target.y));
    CHECK(session::active_max_side(state) ==
          (is_2d ? view2d(state).max_pixels : std::max(view3d(state).max_columns, view3d(state).max_rows)));
    CHECK(session::active_object_count(state) ==
          (is_2d ? view2d(state).scene.circles.size() : view3d(state).scene.spheres.size()));

    session::place_cameras(state);
    const CameraPreset preset = session::active_preset(state);
    REQUIRE(preset.d);
    CHECK(*preset.d == 7.25);
    CHECK(preset.phi_deg.has_value() == !is_2d);
    CHECK(preset.size->size() == (is_2d ? 1u : 2u));
  }
}
