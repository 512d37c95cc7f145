// The panels' own state (ui/panel_state.h), kept by the frame beside the session's AppState: the Open and
// Save as boxes, the Replace question, the start-up options that reach the panels. The session only says
// what happened (a scene opened, Save as needs a yes); the panels keep their boxes from that.
#include <catch2/catch.hpp>
#include <imgui.h>

#include <fstream>
#include <iterator>

#include "../scratch_dir.h"
#include "../session/app_state_for.h"
#include "ui/frame_host.h"
#include "imgui_context_scope.h"
#include "ui/panel_state.h"

using namespace raycam;

namespace {
std::string read(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST_CASE("the start-up options reach the panels: --check's program, the Open box, the export's name",
          "[ui][panel-state]") {
  session::AppOptions options = flags::parse_app_options(
      {"--scene", std::string(SCENES_DIR) + "/many3d.json", "--check", "./my_camera", "--lang", "fr"});
  const session::AppState state = session::make_app_state(options);
  const ui::PanelState panels = ui::panel_state_for(options, state);
  CHECK(panels.check_command == "./my_camera");
  CHECK(panels.path_input == std::string(SCENES_DIR) + "/many3d.json");
  CHECK(panels.save_path.empty());  // never the opened file
  CHECK(panels.export_path == "many3d-carte-des-couleurs.png");  // after the scene, in French
  // The demo scene: no file to show.
  CHECK(ui::panel_state_for(session::AppOptions{}, test::state_for({})).path_input.empty());
  // A file that does not open: the app shows the demo and the error; the box keeps the path, to be fixed (QA:
  // it was empty).
  session::AppOptions typo = flags::parse_app_options({"--scene", std::string(SCENES_DIR) + "/many3d.jsn"});
  typo.demo_on_bad_scene = true;
  const session::AppState on_demo = session::make_app_state(typo);
  REQUIRE(session::scene_path(on_demo).empty());
  CHECK(ui::panel_state_for(typo, on_demo).path_input == std::string(SCENES_DIR) + "/many3d.jsn");
}

TEST_CASE("the panels follow an opened scene: the Open box shows it, Save as starts empty, no question left",
          "[ui][panel-state][files]") {
  const test::ScratchDir scratch("panel-state-open");
  const std::string first = scratch.path("first.json"), second = scratch.path("second.json");
  session::AppState state = test::state_for({});
  REQUIRE(session::save_preset(state, first));
  REQUIRE(session::save_preset(state, second));
  ui::PanelState panels;
  REQUIRE(session::open_scene(state, first));
  ui::follow_scene_shown(state, panels);
  CHECK(panels.path_input == first);
  // Everything a user can have left in the boxes on the first scene.
  panels.save_path = scratch.path("typed-for-first.json");  // typed in Save as, not saved yet
  panels.overwrite_pending = first;                          // a Replace question not answered
  panels.path_input = scratch.path("half-typed");
  ui::follow_scene_shown(state, panels);  // nothing opened since: the boxes stay
  CHECK(panels.path_input == scratch.path("half-typed"));
  CHECK(panels.overwrite_pending == first);

  REQUIRE(session::open_scene(state, second));
  ui::follow_scene_shown(state, panels);
  CHECK(panels.save_path.empty());          // Save as never offers the old scene's path
  CHECK(panels.overwrite_pending.empty());  // nor its pending Replace
  CHECK(panels.path_input == second);

  // A failed open: the box keeps the typo, to be fixed in place.
  const std::string typo = scratch.path("typo.json");
  panels.path_input = typo;
  CHECK_FALSE(session::open_scene(state, typo));
  ui::follow_scene_shown(state, panels);
  CHECK(panels.path_input == typo);
}

TEST_CASE("a scene opened outside the panel (dropped, the page's picker) shows in the Open box at the next frame",
          "[ui][panel-state][files][null-host]") {
  const test::ScratchDir scratch("panel-state-drop");
  const std::string dropped = scratch.path("dropped.json");
  session::AppState state = test::state_for({"--size", "32x24"});
  REQUIRE(session::save_preset(state, dropped));
  const test::ImGuiContextScope imgui;
  ui::NullHost host(1280, 720);
  ui::FrameRenderer frame(ui::FrameRenderer::Graphics::none);
  ui::run_frame(host, frame, state);
  frame.panels().save_path = scratch.path("typed.json");
  REQUIRE(session::open_scene(state, dropped));  // what the host's drop callback does
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().path_input == dropped);
  CHECK(frame.panels().save_path.empty());
}

TEST_CASE("Save as from the panel asks before replacing, and Replace writes the file the question names",
          "[ui][panel-state][files]") {
  const test::ScratchDir scratch("panel-state-save");
  const std::string path = scratch.path("lesson.json");
  session::AppState state = test::state_for({});
  REQUIRE(session::save_preset(state, path));
  const std::string before = read(path);
  session::view3d(state).orbit.d = 3.5;
  ui::PanelState panels;
  REQUIRE(ui::save_as(state, panels, scratch.path("other.json"), false));  // "saved the camera preset to …"
  REQUIRE_FALSE(state.message.empty());
  panels.save_path = path;
  CHECK_FALSE(ui::save_as(state, panels, panels.save_path, false));  // "… already exists. Replace it?"
  REQUIRE(panels.overwrite_pending == path);
  CHECK(state.message.empty());  // no "saved" left beside the question (it read as done, and after Cancel)
  CHECK(read(path) == before);  // nothing written yet
  // The Replace button hands the pending path itself (a reference to the panels' own string).
  CHECK(ui::save_as(state, panels, panels.overwrite_pending, true));
  CHECK(panels.overwrite_pending.empty());
  CHECK_FALSE(state.message_is_error);
  CHECK(read(path) != before);
  CHECK(session::open_scene(state, path));
  CHECK(session::view3d(state).orbit.d == 3.5);
  // An empty box: no question, an error that says what to type.
  CHECK_FALSE(ui::save_as(state, panels, "", false));
  CHECK(panels.overwrite_pending.empty());
  CHECK(state.message_is_error);
}

// QA: with Export figure's question up in 3D (steps-0 … 5), Tab to 2D and Replace wrote steps-a … d, which it
// never named; the other way round it replaced six files nobody was asked about. Save as's question the same:
// Replace wrote the 2D demo over the file asked about for the 3D scene.
TEST_CASE("a Replace question is withdrawn when the other dimension comes on screen or a scene opens",
          "[ui][panel-state][files]") {
  const test::ScratchDir scratch("panel-state-switch");
  const std::string file = scratch.path("lesson3d.json");
  session::AppState state = test::state_for({});
  REQUIRE(session::save_preset(state, file));
  REQUIRE(session::open_scene(state, file));
  ui::PanelState panels;
  ui::follow_scene_shown(state, panels);
  auto ask_both = [&] {
    panels.overwrite_pending = file;
    panels.figure_replace_pending = 2;
    panels.figure_replace_files = {scratch.path("steps-0.svg"), scratch.path("steps-5.svg")};
  };
  ask_both();
  ui::follow_scene_shown(state, panels);  // nothing changed: the questions stay
  CHECK(panels.overwrite_pending == file);
  CHECK(panels.figure_replace_pending == 2);

  session::switch_dimension(state, 2);  // Tab
  ui::follow_scene_shown(state, panels);
  CHECK(panels.overwrite_pending.empty());
  CHECK(panels.figure_replace_pending == 0);
  CHECK(panels.figure_replace_files.empty());
  CHECK(panels.path_input.empty());  // the 2D demo is on screen: no file, not the 3D scene's path

  ask_both();
  session::switch_dimension(state, 3);  // and back: the 3D scene's file again
  ui::follow_scene_shown(state, panels);
  CHECK(panels.overwrite_pending.empty());
  CHECK(panels.figure_replace_pending == 0);
  CHECK(panels.path_input == file);

  ask_both();
  REQUIRE(session::open_scene(state, file));  // an open: the same
  ui::follow_scene_shown(state, panels);
  CHECK(panels.overwrite_pending.empty());
  CHECK(panels.figure_replace_pending == 0);
}

TEST_CASE("the colour map's default file name follows the scene, the dimension and the language, a typed one stays",
          "[ui][panel-state][files][null-host]") {
  // Named as the page names its downloads (the demo is raycam-demo-3d), the suffix in the window's language.
  session::AppState state = test::state_for({"--size", "32x24"});
  REQUIRE(state.language == Language::en);
  const test::ImGuiContextScope imgui;
  ui::NullHost host(1280, 720);
  ui::FrameRenderer frame(ui::FrameRenderer::Graphics::none);
  frame.panels() = ui::panel_state_for(session::AppOptions{}, state);
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().export_path == "raycam-demo-3d-colour-map.png");
  CHECK(frame.panels().figure_path == "raycam-demo-3d-figure.svg");
  state.language = Language::fr;  // what the Language control does
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().export_path == "raycam-demo-3d-carte-des-couleurs.png");  // QA: it stayed in English
  session::switch_dimension(state, 2);  // Tab: QA, the 2D bar was written over the 3D map's file
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().export_path == "raycam-demo-2d-carte-des-couleurs.png");
  CHECK(frame.panels().figure_path == "raycam-demo-2d-figure.svg");
  state.language = Language::en;
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().export_path == "raycam-demo-2d-colour-map.png");
  // A scene file: its name, and the dimension where the name does not say it.
  const test::ScratchDir scratch("panel-state-names");
  session::switch_dimension(state, 3);
  REQUIRE(session::save_preset(state, scratch.path("lesson.json")));
  REQUIRE(session::open_scene(state, scratch.path("lesson.json")));
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().export_path == "lesson-3d-colour-map.png");
  REQUIRE(session::open_scene(state, std::string(SCENES_DIR) + "/many3d.json"));
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().export_path == "many3d-colour-map.png");
  // Typed by the user: kept whatever changes.
  frame.panels().export_path = "lecture-3.png";
  frame.panels().figure_path = "steps.pdf";
  state.language = Language::fr;
  session::switch_dimension(state, 2);
  ui::run_frame(host, frame, state);
  CHECK(frame.panels().export_path == "lecture-3.png");
  CHECK(frame.panels().figure_path == "steps.pdf");
}
