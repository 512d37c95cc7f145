// Scene files: round trip, and every kind of bad input refused with the file, the field and the expectation.
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <glm/gtc/constants.hpp>

#include "raycam/scene_file.h"
#include "raycam/view_setup.h"
#include "test_support.h"

using namespace raycam;
using raycam::test::error_of;

namespace {
const char* kValid3D = R"({ "dimension": 3, "background": [20, 20, 30],
  "objects": [ {"type": "sphere", "center": [0, 0, 0], "radius": 1, "color": [230, 60, 50], "name": "red"},
               {"type": "sphere", "center": [1.5, -2, 0.25], "radius": 0.5} ],
  "camera": {"target": [0, 0, 0], "d": 8, "theta": 30, "phi": 60, "df": 2, "res": 1, "size": [256, 128]} })";

}  // namespace

TEST_CASE("a valid 3D scene file is read field by field", "[scene_file]") {
  const SceneFile file = parse_scene_json(kValid3D, "scene.json");
  CHECK(file.dimension == 3);
  REQUIRE(file.scene3d.spheres.size() == 2);
  CHECK(file.scene3d.spheres[0].name == "red");
  CHECK(file.scene3d.spheres[0].colour == Rgb8{230, 60, 50});
  CHECK(file.scene3d.spheres[1].centre == glm::dvec3(1.5, -2, 0.25));
  CHECK(file.scene3d.background == Rgb8{20, 20, 30});
  CHECK(*file.camera.phi_deg == 60.0);
  CHECK(*file.camera.size == std::vector<int>{256, 128});
}

TEST_CASE("scene files round-trip through scene_to_json", "[scene_file]") {
  const SceneFile file = parse_scene_json(kValid3D, "scene.json");
  const SceneFile again = parse_scene_json(scene_to_json(file), "again.json");
  REQUIRE(again.scene3d.spheres.size() == file.scene3d.spheres.size());
  for (std::size_t i = 0; i < file.scene3d.spheres.size(); ++i) {
    CHECK(again.scene3d.spheres[i].centre == file.scene3d.spheres[i].centre);
    CHECK(again.scene3d.spheres[i].radius == file.scene3d.spheres[i].radius);
    CHECK(again.scene3d.spheres[i].colour == file.scene3d.spheres[i].colour);
    CHECK(again.scene3d.spheres[i].name == file.scene3d.spheres[i].name);
  }
  CHECK(*again.camera.theta_deg == 30.0);
  CHECK(*again.camera.size == *file.camera.size);

  const std::string twod = R"({"dimension": 2, "objects": [{"type": "circle", "center": [1, 2], "radius": 3}],
                               "camera": {"size": 64, "theta": 45}})";
  const SceneFile file2 = parse_scene_json(twod, "2d.json");
  const SceneFile again2 = parse_scene_json(scene_to_json(file2), "again.json");
  CHECK(again2.dimension == 2);
  CHECK(again2.scene2d.circles.at(0).centre == glm::dvec2(1, 2));
  CHECK(again2.camera.size->at(0) == 64);
}

TEST_CASE("a case file's check protocol is read, written back, and checked", "[scene_file]") {
  // raycam-cli check writes "protocol" in its case files (docs/check.md); they stay scene files.
  const std::string text = R"({"dimension": 2, "objects": [], "protocol": 2})";
  const SceneFile file = parse_scene_json(text, "case.json");
  REQUIRE(file.protocol);
  CHECK(*file.protocol == 2);
  CHECK(parse_scene_json(scene_to_json(file), "again.json").protocol == 2);
  const SceneFile plain = parse_scene_json(R"({"dimension": 2, "objects": []})", "scene.json");
  CHECK_FALSE(plain.protocol);
  CHECK(scene_to_json(plain).find("protocol") == std::string::npos);  // a scene file without it stays so
  CHECK_THAT(error_of(R"({"dimension": 2, "objects": [], "protocol": "2"})"), Catch::Contains("protocol"));
  CHECK_THAT(error_of(R"({"dimension": 2, "objects": [], "protocol": 0})"), Catch::Contains("protocol"));
}

TEST_CASE("bad scene files name the file, the field and what was expected", "[scene_file][input]") {
  CHECK_THAT(error_of("{ \"dimension\": 3, \"objects\": [ }"),
             Catch::Contains("scene.json") && Catch::Contains("line 1"));
  CHECK_THAT(error_of("{\n  \"dimension\": 3,\n  \"objects\": [,]\n}"), Catch::Contains("line 3"));
  CHECK_THAT(error_of("[]"), Catch::Contains("JSON object"));
  CHECK_THAT(error_of("{\"objects\": []}"), Catch::Contains("dimension") && Catch::Contains("required"));
  CHECK_THAT(error_of("{\"dimension\": 4, \"objects\": []}"),
             Catch::Contains("dimension") && Catch::Contains("[2, 3]"));
  CHECK_THAT(error_of("{\"dimension\": \"3\", \"objects\": []}"), Catch::Contains("dimension"));
  CHECK_THAT(error_of("{\"dimension\": 3}"), Catch::Contains("objects"));
  CHECK_THAT(error_of("{\"dimension\": 3, \"objects\": {}}"), Catch::Contains("objects: expected an array"));
  CHECK_THAT(
      error_of(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,0], "radius": -1}]})"),
      Catch::Contains("objects[0].radius") && Catch::Contains("]0, 1e12]"));
  CHECK_THAT(error_of(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0], "radius": 1}]})"),
             Catch::Contains("objects[0].center") && Catch::Contains("3 numbers"));
  CHECK_THAT(error_of(R"({"dimension": 2, "objects": [{"type": "sphere", "center": [0,0], "radius": 1}]})"),
             Catch::Contains("objects[0].type") && Catch::Contains("circle"));
  CHECK_THAT(
      error_of(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,"x",0], "radius": 1}]})"),
      Catch::Contains("objects[0].center[1]"));
  CHECK_THAT(
      error_of(
          R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1, "color": [0, 300, 0]}]})"),
      Catch::Contains("objects[0].color[1]") && Catch::Contains("[0, 255]"));
  CHECK_THAT(
      error_of(
          R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1, "colour": [0, 0, 0]}]})"),
      Catch::Contains("objects[0].colour") && Catch::Contains("no such field"));
  CHECK_THAT(
      error_of(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,1e999], "radius": 1}]})"),
      Catch::Contains("scene.json"));
  CHECK_THAT(error_of(R"({"dimension": 3, "objects": [], "camera": {"df": 0}})"),
             Catch::Contains("camera.df"));
  CHECK_THAT(error_of(R"({"dimension": 3, "objects": [], "camera": {"res": 1.5}})"),
             Catch::Contains("camera.res"));
  CHECK_THAT(error_of(R"({"dimension": 3, "objects": [], "camera": {"size": [0, 10]}})"),
             Catch::Contains("camera.size[0]"));
  CHECK_THAT(error_of(R"({"dimension": 2, "objects": [], "camera": {"phi": 10}})"),
             Catch::Contains("camera.phi"));
  CHECK_THAT(error_of(R"({"dimension": 3, "objects": [], "camera": {"target": [0, 0]}})"),
             Catch::Contains("camera.target"));
  CHECK_THAT(error_of(""), Catch::Contains("scene.json"));
}

TEST_CASE("loading names a missing file, saving replaces atomically", "[scene_file][input]") {
  CHECK_THROWS_WITH(load_scene_file("/nonexistent/dir/scene.json"),
                    Catch::Contains("/nonexistent/dir/scene.json"));
  const std::string path = "raycam_test_scene.json";
  SceneFile file = parse_scene_json(kValid3D, "scene.json");
  save_scene_file(file, path);
  file.scene3d.spheres.pop_back();
  save_scene_file(file, path);
  CHECK(load_scene_file(path).scene3d.spheres.size() == 1);
  CHECK_THROWS(save_scene_file(file, "/nonexistent/dir/scene.json"));
  CHECK(load_scene_file(path).scene3d.spheres.size() == 1);  // a failed save elsewhere changes nothing here
  std::remove(path.c_str());
}
