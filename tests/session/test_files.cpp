// Files are safe: replacing a file needs a yes, a failed open changes nothing but the message (the panels'
// own boxes and questions: tests/ui/test_panel_state.cpp), saved scenes stay readable, screenshots never overwrite each other, and
// a scene that cannot be opened at startup gives the demo scene and an error naming it.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "../scratch_dir.h"
#include "flags/app/app_flags.h"
#include "session/app_options.h"

using namespace raycam;
namespace fs = std::filesystem;

namespace {
session::AppState state_for(const std::vector<std::string>& args, bool demo_on_bad_scene = false) {
  session::AppOptions options;
  options.language = raycam::Language::en;
  options.demo_on_bad_scene = demo_on_bad_scene;
  return session::make_app_state(flags::parse_app_options(args, options));
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Scratch : test::ScratchDir {
  Scratch() : ScratchDir("files") {}
};
}  // namespace

TEST_CASE("Open with an empty box says what to type, and changes nothing else", "[ui][files]") {
  session::AppState state = state_for({"--theta", "40"});
  const double theta = view3d(state).orbit.theta;
  const std::string title = state.window_title;
  CHECK_FALSE(session::open_scene(state, ""));
  CHECK(state.message_is_error);
  CHECK(state.message.find("path") != std::string::npos);
  CHECK(state.message.find(": :") == std::string::npos);
  CHECK(view3d(state).orbit.theta == theta);
  CHECK(state.window_title == title);
}

TEST_CASE("a failed open leaves the scene and the camera as they were, and says why", "[ui][files]") {
  Scratch scratch;
  const std::string good = (scratch.dir / "good.json").string();
  session::AppState state = state_for({"--theta", "40"});
  REQUIRE(session::save_preset(state, good));
  const std::uint64_t opens = state.scene_opens;
  REQUIRE(session::open_scene(state, good));
  CHECK(state.scene_opens == opens + 1);  // the panels follow it (the Open box shows the file)
  view3d(state).orbit.theta = 1.25;  // the student moved the camera since
  const auto spheres = view3d(state).scene.spheres.size();
  const std::string missing = (scratch.dir / "typo.json").string();
  CHECK_FALSE(session::open_scene(state, missing));
  CHECK(state.scene_opens == opens + 1);  // not counted: the Open box keeps what was typed
  CHECK(state.message_is_error);
  CHECK(state.message_source == session::MessageSource::files);
  CHECK_THAT(state.message, Catch::Contains("typo.json"));
  CHECK(view3d(state).scene.spheres.size() == spheres);
  CHECK(view3d(state).orbit.theta == 1.25);
  CHECK(scene_path(state) == good);
}

TEST_CASE("Save as never writes over a file without a yes", "[ui][files]") {
  Scratch scratch;
  const std::string opened = (scratch.dir / "lesson.json").string();
  session::AppState state = state_for({});
  REQUIRE(session::save_preset(state, opened));
  REQUIRE(session::open_scene(state, opened));
  const std::string before = read(opened);
  view3d(state).orbit.d = 3.5;
  using session::SaveAsOutcome;
  CHECK(session::save_preset_as(state, opened, false) == SaveAsOutcome::needs_yes);  // exists: the panel asks
  CHECK(read(opened) == before);                   // nothing written yet
  CHECK(session::save_preset_as(state, opened, true) == SaveAsOutcome::saved);  // the user said yes
  CHECK(read(opened) != before);
  CHECK_THAT(state.message, Catch::Contains(opened));
  CHECK_FALSE(state.message_is_error);
  const std::string fresh = (scratch.dir / "new.json").string();
  CHECK(session::save_preset_as(state, fresh, false) == SaveAsOutcome::saved);  // a new file needs no question
  CHECK(fs::exists(fresh));
  CHECK(session::save_preset_as(state, "", false) == SaveAsOutcome::failed);
  CHECK(state.message_is_error);
}

TEST_CASE("Open resets every field that belonged to the scene on screen before", "[ui][files]") {
  Scratch scratch;
  const std::string first = (scratch.dir / "first.json").string(), second = (scratch.dir / "second.json").string();
  session::AppState state = state_for({"--theta", "40", "--phi", "70"});
  REQUIRE(session::save_preset(state, second));  // the camera the second file holds
  const Orbit3D saved = session::view3d(state).orbit;
  REQUIRE(session::save_preset(state, first));
  REQUIRE(session::open_scene(state, first));
  // Everything a user can have left behind on the first scene (the panels' boxes: tests/ui).
  state.pinned_pixel = session::PixelIndex{3, 4};
  state.construction_step = 2;
  state.mistake_look_at = "the colour bar";  // a "show me" on the first scene
  // The other kind's view named a file too.
  std::visit([&](auto& other) { other.scene_path = first; }, state.other_view);
  session::view3d(state).orbit.theta = 0.25;
  session::view3d(state).orbit.d = 2.5;
  state.res = 0.5;
  state.overhead_fit_pending = false;
  state.cameras_dirty = false;
  session::set_message(state, session::MessageSource::camera, true, "an old error");
  const std::uint64_t version = state.scene_version;

  REQUIRE(session::open_scene(state, second));
  CHECK(session::scene_path(state) == second);
  CHECK(std::visit([](const auto& other) { return other.scene_path.empty(); }, state.other_view));  // the other kind's scene is the demo again
  CHECK_FALSE(state.pinned_pixel);
  CHECK(state.construction_step == -1);
  CHECK(state.mistake_look_at.empty());
  CHECK(session::view3d(state).orbit.theta == Approx(saved.theta));  // the file's camera, not the one moved
  CHECK(session::view3d(state).orbit.d == Approx(saved.d));
  CHECK(session::view3d(state).preset.theta == session::view3d(state).orbit.theta);  // Reset camera returns to the file's camera
  CHECK(state.res == 1.0);
  CHECK(state.preset_res == 1.0);
  CHECK(state.overhead_fit_pending);
  CHECK(state.cameras_dirty);
  CHECK(state.scene_version > version);
  CHECK_FALSE(state.message_is_error);
  CHECK(state.message_source == session::MessageSource::files);
  session::recast_if_needed(state);
  CHECK_FALSE(state.pinned_pixel);  // no pin comes back on the new image
}

TEST_CASE("a save that fails leaves the old file as it was and names the path typed", "[ui][files]") {
  Scratch scratch;
  const std::string path = (scratch.dir / "lesson.json").string();
  session::AppState state = state_for({});
  REQUIRE(session::save_preset(state, path));
  const std::string before = read(path);
  fs::create_directory(path + ".tmp");  // the temporary file cannot be made: the write fails
  view3d(state).orbit.d = 3.5;
  CHECK_FALSE(session::save_preset(state, path));
  CHECK(state.message_is_error);
  CHECK_THAT(state.message, Catch::Contains(path + ":"));
  CHECK_THAT(state.message, !Catch::Contains(".tmp"));
  CHECK(read(path) == before);  // intact
  fs::remove(path + ".tmp");
  for (const auto& entry : fs::directory_iterator(scratch.dir)) CHECK(entry.path().extension() != ".tmp");
}

TEST_CASE("saved angles are the degrees the user set", "[ui][files]") {
  Scratch scratch;
  const std::string path = (scratch.dir / "angles.json").string();
  session::AppState state = state_for({"--view", "3d", "--theta", "30", "--phi", "60"});
  REQUIRE(session::save_preset(state, path));
  const std::string text = read(path);
  CHECK_THAT(text, Catch::Contains("\"theta\": 30.0}") || Catch::Contains("\"theta\": 30.0,"));
  CHECK_THAT(text, Catch::Contains("\"phi\": 60.0,") || Catch::Contains("\"phi\": 60.0}"));
  CHECK_THAT(text, !Catch::Contains("29.99") && !Catch::Contains("59.99"));
}

TEST_CASE("a saved scene keeps short arrays and each object on one line", "[ui][files]") {
  Scratch scratch;
  const std::string path = (scratch.dir / "scene.json").string();
  session::AppState state = state_for({SCENES_DIR "/classic3d.json"});
  const std::size_t objects = view3d(state).scene.spheres.size();
  REQUIRE(session::save_preset(state, path));
  const std::string text = read(path);
  std::istringstream lines(text);
  std::string line;
  int count = 0, centres = 0;
  while (std::getline(lines, line)) {
    ++count;
    if (line.find("\"center\": [") != std::string::npos) {
      ++centres;
      CHECK(line.find(']', line.find("\"center\"")) != std::string::npos);  // the array closes on its line
      CHECK(line.find("\"radius\"") != std::string::npos);                  // the whole object is on it
    }
  }
  CHECK(centres == int(objects));
  CHECK(count <= int(objects) + 16);     // a few header lines, one line per object, the camera (dump(2): 60)
  REQUIRE(session::open_scene(state, path));  // and it still reads back
  CHECK(view3d(state).scene.spheres.size() == objects);
}

TEST_CASE("screenshots are numbered, never overwritten, and named in the window's language", "[ui][files]") {
  Scratch scratch;
  const std::string first = session::next_screenshot_path(Language::en, scratch.dir.string());
  CHECK(fs::path(first).filename() == "raycam-screenshot-001.png");
  std::ofstream(first) << "x";
  CHECK(fs::path(session::next_screenshot_path(Language::en, scratch.dir.string())).filename() == "raycam-screenshot-002.png");
  // QA: F12 wrote raycam-screenshot-001.png in front of a French class.
  CHECK(fs::path(session::next_screenshot_path(Language::fr, scratch.dir.string())).filename() == "raycam-capture-001.png");
  session::AppState state = state_for({});
  session::request_screenshot(state, state.language);
  const session::HostRequest* shot = state.requests.find(session::HostRequestKind::screenshot);
  REQUIRE(shot);
  CHECK(fs::path(shot->path).is_absolute());  // the message can say exactly where
}

TEST_CASE("started with a scene that cannot be opened, the app shows the demo and the error naming the file",
          "[ui][files]") {
  const session::AppState state = state_for({"no_such_dir/lesson3.json"}, true);
  CHECK(scene_path(state).empty());
  CHECK(view3d(state).scene.spheres.size() == demo_scene_3d().spheres.size());
  CHECK(state.message_is_error);
  CHECK_THAT(state.message, Catch::Contains("no_such_dir/lesson3.json"));
  CHECK(session::window_title(state) == "raycam — 3D — demo scene");
  // A bad flag still stops it; and raycam-cli shot (no fallback) refuses the file.
  CHECK_THROWS_WITH(state_for({"no_such_dir/lesson3.json", "--d", "-1"}, true), Catch::Contains("--d"));
  CHECK_THROWS(state_for({"no_such_dir/lesson3.json"}, false));
}

TEST_CASE("the window title names the mode and the scene file", "[ui][title]") {
  const session::AppState state = state_for({SCENES_DIR "/many3d.json"});
  CHECK(session::window_title(state) == "raycam — 3D — many3d.json");
  CHECK(session::window_title(state_for({"--view", "2d", "--lang", "fr"})) == "raycam — 2D — scène de démonstration");
}
