// The handout's "une (ou deux) variables de résolution (selon qu'on souhaite une image carrée ou non)": in 3D
// the columns and the rows may each have their own res, from the command line (--res RC,RL) or a scene file
// ("res": [RC, RL]). The image then has nbc = round(RC·W) columns and nbl = round(RL·H) rows, the handout's
// counts, computed here from that formula and never read back from the program.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "flags/view_options.h"

using namespace raycam;

namespace {
// The handout's useful size: res·N rounded, at least 1, at most N.
int handout_count(double res, int max_size) {
  return int(std::clamp(std::floor(res * max_size + 0.5), 1.0, double(max_size)));
}

// Parses like a command that renders; returns "" or the error message the user would see.
std::string parse(std::vector<std::string> args, ViewFlags& view) {
  CLI::App command("test", "render");
  flags::add_view_options(command, view);
  try {
    command.parse(std::vector<std::string>(args.rbegin(), args.rend()));
  } catch (const CLI::Error& error) {
    return flags::usage_error_message(command, error);
  }
  return "";
}

std::string setup_error(const ViewFlags& view) {
  try {
    make_view_setup(view);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

std::string scene_error(const std::string& text) {
  try {
    parse_scene_json(text, "two.json");
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}
}  // namespace

TEST_CASE("the flag --res RC,RL gives the handout's nbc columns and nbl rows", "[flags][res]") {
  // Fractional parts near .7 and .3, so that a swapped pair, one res for both or a floor all miss.
  for (const auto& [columns, rows, res_c, res_l] :
       {std::tuple{40, 40, 0.5, 0.25}, {64, 48, 0.3671, 0.8125}, {37, 53, 0.9, 0.111}, {20, 10, 1.0, 0.05}}) {
    ViewFlags view;
    REQUIRE(parse({"--size", std::to_string(columns) + "x" + std::to_string(rows), "--res",
                   std::to_string(res_c) + "," + std::to_string(res_l)},
                  view) == "");
    const Camera3D camera = make_view_setup(view).camera3d;
    INFO(columns << "x" << rows << " at res " << res_c << "," << res_l);
    CHECK(camera.columns() == handout_count(res_c, columns));  // nbc
    CHECK(camera.rows() == handout_count(res_l, rows));        // nbl
    CHECK(camera.res_columns() == res_c);
    CHECK(camera.res_rows() == res_l);
  }
  ViewFlags one;
  REQUIRE(parse({"--size", "40x30", "--res", "0.5"}, one) == "");
  const Camera3D square = make_view_setup(one).camera3d;
  CHECK(square.columns() == 20);
  CHECK(square.rows() == 15);  // one res: both sides
}

TEST_CASE("a scene file's res is one number or [columns, rows], and a flag's res replaces the pair",
          "[flags][res]") {
  const std::string scene =
      R"({"dimension": 3, "objects": [], "camera": {"res": [0.375, 0.6875], "size": [64, 32]}})";
  const SceneFile file = parse_scene_json(scene, "two.json");
  REQUIRE(file.camera.res == 0.375);
  REQUIRE(file.camera.res_rows == 0.6875);
  const Camera3D camera = camera3d_from_preset(file.camera);
  CHECK(camera.columns() == handout_count(0.375, 64));
  CHECK(camera.rows() == handout_count(0.6875, 32));

  // Saved and read again, the pair stays a pair (and is written as one).
  const std::string saved = scene_to_json(file);
  CHECK(saved.find("\"res\": [0.375, 0.6875]") != std::string::npos);
  const SceneFile again = parse_scene_json(saved, "again.json");
  CHECK(again.camera.res == 0.375);
  CHECK(again.camera.res_rows == 0.6875);
  // The preset of a camera with two resolutions has both; a square camera's has one.
  CHECK(preset_of(camera).res_rows == 0.6875);
  CHECK_FALSE(preset_of(Camera3D(64, 32)).res_rows);

  // The command line's --res over a file with two: one res, the image square again.
  const test::ScratchDir scratch("two-res");
  ViewFlags over;
  over.scene_path = scratch.path("two.json");
  save_scene_file(file, *over.scene_path);
  CHECK(make_view_setup(over).camera3d.rows() == handout_count(0.6875, 32));  // the file's pair
  REQUIRE(parse({"--res", "0.5"}, over) == "");
  const Camera3D square = make_view_setup(over).camera3d;
  CHECK(square.columns() == handout_count(0.5, 64));
  CHECK(square.rows() == handout_count(0.5, 32));
}

TEST_CASE("two resolutions out of range or out of place name the field and the range", "[flags][res]") {
  ViewFlags view;
  CHECK(parse({"--res", "0"}, view) == "--res: expected a number in ]0, 1], got '0'");
  CHECK(parse({"--res", "0.5,0"}, view) ==
        "--res: expected RC,RL (columns, rows) with each in ]0, 1], got '0.5,0'");
  CHECK(parse({"--res", "1.5,0.5"}, view) ==
        "--res: expected RC,RL (columns, rows) with each in ]0, 1], got '1.5,0.5'");
  CHECK(parse({"--res", "0.5,0.5,0.5"}, view) ==
        "--res: expected RC,RL (columns, rows) with each in ]0, 1], got '0.5,0.5,0.5'");
  CHECK(parse({"--res"}, view) ==
        "--res: expected R or RC,RL (columns, rows) with each in ]0, 1], got nothing");

  ViewFlags two_d;
  REQUIRE(parse({"--mode", "2d", "--res", "0.5,0.25"}, two_d) == "");
  CHECK(setup_error(two_d) == "--res: expected one number R for a 2D scene (RC,RL is for 3D)");
  ViewFlags two_d_one;
  REQUIRE(parse({"--mode", "2d", "--res", "0.5"}, two_d_one) == "");
  CHECK(setup_error(two_d_one).empty());

  CHECK_THAT(scene_error(R"({"dimension": 3, "objects": [], "camera": {"res": [0.5, 0]}})"),
             Catch::StartsWith("two.json: camera.res[1]: expected a number in ]0, 1]"));
  CHECK_THAT(scene_error(R"({"dimension": 3, "objects": [], "camera": {"res": [1.5, 0.5]}})"),
             Catch::StartsWith("two.json: camera.res[0]: expected a number in ]0, 1]"));
  CHECK_THAT(scene_error(R"({"dimension": 3, "objects": [], "camera": {"res": [0.5, 0.5, 0.5]}})"),
             Catch::StartsWith("two.json: camera.res: expected a number in ]0, 1] or [columns, rows]"));
  CHECK_THAT(scene_error(R"({"dimension": 2, "objects": [], "camera": {"res": [0.5, 0.5]}})"),
             Catch::StartsWith("two.json: camera.res: expected a number in ]0, 1]"));
}
