// `raycam-cli render` end to end: the ids it writes equal the core's colour map for the same camera (set
// here directly in radians, so the CLI's degree conversion and flag handling are checked too).
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "raycam/ray_caster.h"

using namespace raycam;

namespace {

// Where this process's files go: the system's temporary folder.
std::string scratch(const std::string& file) {
  static const test::ScratchDir dir("cli-render");
  return dir.path(file);
}

int run(const std::string& arguments) {
  const std::string command = std::string(RAYCAM_CLI) + " " + arguments + " > /dev/null 2>&1";
  return std::system(command.c_str());
}

std::vector<std::vector<int>> read_ids(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<int>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    rows.emplace_back();
    for (int id; fields >> id;) rows.back().push_back(id);
  }
  return rows;
}

void check_same(const std::vector<std::vector<int>>& rows, const ColourMap& map) {
  REQUIRE(int(rows.size()) == map.height);
  for (int r = 0; r < map.height; ++r) {
    REQUIRE(int(rows[r].size()) == map.width);
    for (int c = 0; c < map.width; ++c) CHECK(rows[r][c] == map.id_at(r, c));
  }
}
}  // namespace

TEST_CASE("render --ids matches the core in 3D", "[cli]") {
  REQUIRE(run("render --mode 3d --size 40x30 --theta 120 --phi 70 --d 7 --df 1.7 --target 0.5,0,0.2 --ids " +
              scratch("cli3d.txt")) == 0);
  Camera3D camera(40, 30);
  camera.set_orbit({{0.5, 0, 0.2}, 7.0, glm::radians(120.0), glm::radians(70.0), 1.7});
  check_same(read_ids(scratch("cli3d.txt")), cast_primary_rays(camera, demo_scene_3d()));
}

TEST_CASE("render --ids matches the core in 2D, with res", "[cli]") {
  REQUIRE(
      run("render --mode 2d --size 200 --res 0.5 --theta -30 --d 5 --df 1 --ids " + scratch("cli2d.txt") +
          " --out " + scratch("cli2d.png")) ==
      0);
  Camera2D camera(200);
  camera.set_res(0.5);
  camera.set_orbit({{0, 0}, 5.0, -glm::radians(30.0), 1.0});
  const ColourMap map = cast_primary_rays(camera, demo_scene_2d());
  CHECK(map.width == 100);
  check_same(read_ids(scratch("cli2d.txt")), map);
  CHECK(std::ifstream(scratch("cli2d.png")).good());
}

TEST_CASE("render with a scene file uses its preset, flags override it", "[cli]") {
  {
    std::ofstream scene(scratch("cli_scene.json"));
    scene
        << R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "color": [255, 0, 0]}],
                 "camera": {"d": 5, "theta": 0, "phi": 90, "df": 1, "size": [16, 16]}})";
  }
  REQUIRE(run("render --scene " + scratch("cli_scene.json") + " --theta 45 --ids " + scratch("cli_scene.txt")) == 0);
  Camera3D camera(16, 16);
  camera.set_orbit({{0, 0, 0}, 5.0, glm::radians(45.0), glm::radians(90.0), 1.0});
  Scene3D scene;
  scene.spheres = {{{0, 0, 0}, 1.0, {255, 0, 0}, ""}};
  check_same(read_ids(scratch("cli_scene.txt")), cast_primary_rays(camera, scene));
}

TEST_CASE("render --method and --threads give the plain loop's ids, accuracy knobs reach the caster", "[cli]") {
  Camera3D camera(96, 64);
  camera.set_orbit({{0, 0, 0}, 8.0, glm::radians(30.0), glm::radians(60.0), 2.0});
  CastOptions plain;
  plain.method = CastMethod::plain;
  const ColourMap expected = cast_primary_rays(camera, demo_scene_3d(), plain);
  for (const char* method : {"plain", "culled", "footprint", "binned", "automatic"}) {
    INFO(method);
    REQUIRE(run(std::string("render --size 96x64 --method ") + method + " --threads 2 --ids " + scratch("method_ids.txt")) == 0);
    check_same(read_ids(scratch("method_ids.txt")), expected);
  }
  // Long double, 1 sample, stable: the pixel-centre ids equal double's here (no grazing pixel in this view).
  REQUIRE(run("render --size 96x64 --precision long-double --ids " + scratch("knob_ids.txt")) == 0);
  check_same(read_ids(scratch("knob_ids.txt")), expected);
  CHECK(run("render --exact") != 0);  // --exact is for the 2D bar
}
