// The window's two resolution variables (the handout's "une (ou deux) variables de résolution"): with the
// non-square toggle on, the columns and the rows each have their own res, and the camera, Reset, Save and a
// coarse preview while dragging all keep them. Counts are the handout's nbc = round(res_c·W), nbl = round(res_l·H).
#include <catch2/catch.hpp>
#include <cmath>

#include "../scratch_dir.h"
#include "app_state.h"
#include "app_state_for.h"
#include "raycam/scene_file.h"

using namespace raycam;

TEST_CASE("the window's two resolutions reach the camera, Reset, Save and the coarse preview", "[ui][res]") {
  ui::AppState state = test::state_for({"--size", "40x40", "--res", "0.5,0.25"});
  REQUIRE(state.res_rows);  // the toggle is on when the command line gives two
  ui::place_cameras(state);
  CHECK(state.camera3d.columns() == 20);  // round(0.5·40)
  CHECK(state.camera3d.rows() == 10);     // round(0.25·40)

  // Toggle off: one res for both sides again.
  state.res_rows.reset();
  ui::place_cameras(state);
  CHECK(state.camera3d.rows() == 20);
  // Reset brings the command line's pair back.
  ui::reset_camera(state);
  REQUIRE(state.res_rows);
  CHECK(*state.res_rows == 0.25);

  // Saved and opened again: the pair is in the file.
  const test::ScratchDir scratch("two-res-window");
  const std::string path = scratch.path("two.json");
  ui::place_cameras(state);
  REQUIRE(ui::save_preset_as(state, path, false));
  const SceneFile saved = load_scene_file(path);
  CHECK(saved.camera.res == 0.5);
  CHECK(saved.camera.res_rows == 0.25);
  ui::AppState opened = test::state_for({});
  REQUIRE(ui::open_scene(opened, path));
  ui::place_cameras(opened);
  CHECK(opened.camera3d.columns() == 20);
  CHECK(opened.camera3d.rows() == 10);

  // A coarse preview while dragging scales both sides alike: the columns stay about twice the rows.
  ui::AppState dragging = test::state_for({"--size", "400x400", "--res", "1,0.5"});
  dragging.ns_per_ray = 1e4;  // a slow machine: the full image is far over the interactive budget
  REQUIRE(ui::recast_if_needed(dragging, true));
  REQUIRE(dragging.refine_pending);
  const int columns = dragging.camera3d.columns(), rows = dragging.camera3d.rows();
  CHECK(columns < 400);
  CHECK(std::abs(columns - 2 * rows) <= 2);
}
