// The window's two resolution variables (the handout's "une (ou deux) variables de résolution"): with the
// non-square toggle on, the columns and the rows each have their own res, and the camera, Reset, Save and a
// coarse preview while dragging all keep them. Counts are the handout's nbc = round(res_c·W), nbl = round(res_l·H).
#include <catch2/catch.hpp>
#include <cmath>

#include "../scratch_dir.h"
#include "session/app_state.h"
#include "app_state_for.h"
#include "raycam/scene_file.h"

using namespace raycam;

TEST_CASE("the window's two resolutions reach the camera, Reset, Save and the coarse preview", "[ui][res]") {
  session::AppState state = test::state_for({"--size", "40x40", "--res", "0.5,0.25"});
  REQUIRE(state.res_rows);  // the toggle is on when the command line gives two
  session::place_cameras(state);
  CHECK(session::view3d(state).camera.columns() == 20);  // round(0.5·40)
  CHECK(session::view3d(state).camera.rows() == 10);     // round(0.25·40)

  // Toggle off: one res for both sides again.
  state.res_rows.reset();
  session::place_cameras(state);
  CHECK(session::view3d(state).camera.rows() == 20);
  // Reset brings the command line's pair back.
  session::reset_camera(state, state);
  REQUIRE(state.res_rows);
  CHECK(*state.res_rows == 0.25);

  // Saved and opened again: the pair is in the file.
  const test::ScratchDir scratch("two-res-window");
  const std::string path = scratch.path("two.json");
  session::place_cameras(state);
  REQUIRE(session::save_preset_as(state, path, false) == session::SaveAsOutcome::saved);
  const SceneFile saved = load_scene_file(path);
  CHECK(saved.camera.res == 0.5);
  CHECK(saved.camera.res_rows == 0.25);
  session::AppState opened = test::state_for({});
  REQUIRE(session::open_scene(opened, path));
  session::place_cameras(opened);
  CHECK(session::view3d(opened).camera.columns() == 20);
  CHECK(session::view3d(opened).camera.rows() == 10);

  // A coarse preview while dragging scales both sides alike: the columns stay about twice the rows.
  session::AppState dragging = test::state_for({"--size", "400x400", "--res", "1,0.5"});
  dragging.ns_per_ray = 1e4;  // a slow machine: the full image is far over the interactive budget
  REQUIRE(session::recast_if_needed(dragging, true));
  REQUIRE(dragging.refine_pending);
  const int columns = session::view3d(dragging).camera.columns(), rows = session::view3d(dragging).camera.rows();
  CHECK(columns < 400);
  CHECK(std::abs(columns - 2 * rows) <= 2);
}
