// Every shipped scene (scenes/*.json) through `raycam-cli render`: the ids equal the plain loop on the camera
// built here from the file's preset (degrees converted in the test), the PNG holds each id's colour, and the
// symmetric scenes give mirror-symmetric images (invariant 5, docs/testing.md). Exit code 0 alone proves nothing.
#include <stb_image.h>  // implementation provided by Debian's libstb

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "raycam/view_setup.h"

using namespace raycam;

namespace {

std::vector<std::vector<int>> read_ids(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<int>> rows;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    rows.emplace_back();
    for (int id; fields >> id;) rows.back().push_back(id);
  }
  return rows;
}

// The camera of the preset, built from the file's numbers with this test's own degree conversion.
ColourMap expected_map(const SceneFile& file) {
  const CameraPreset& p = file.camera;
  CastOptions plain;
  plain.method = CastMethod::plain;
  if (file.dimension == 2) {
    Camera2D camera(p.size ? (*p.size)[0] : 256);
    camera.set_res(p.res.value_or(1.0));
    camera.set_orbit({{(*p.target)[0], (*p.target)[1]}, *p.d, glm::radians(*p.theta_deg), *p.df});
    return cast_primary_rays(camera, file.scene2d, plain);
  }
  Camera3D camera(p.size ? (*p.size)[0] : 256, p.size ? (*p.size)[1] : 256);
  camera.set_res(p.res.value_or(1.0));
  camera.set_orbit({{(*p.target)[0], (*p.target)[1], (*p.target)[2]},
                    *p.d,
                    glm::radians(*p.theta_deg),
                    glm::radians(*p.phi_deg),
                    *p.df});
  // 2000 spheres: the plain loop would take seconds; the fast casters equal it (test_accelerated_caster).
  if (file.scene3d.spheres.size() > 100) plain.method = CastMethod::automatic;
  return cast_primary_rays(camera, file.scene3d, plain);
}

Rgb8 colour_of(const SceneFile& file, int id) {
  if (id < 0) return file.dimension == 2 ? file.scene2d.background : file.scene3d.background;
  return file.dimension == 2 ? file.scene2d.circles[std::size_t(id)].colour
                             : file.scene3d.spheres[std::size_t(id)].colour;
}
}  // namespace

TEST_CASE("every shipped scene renders the core's ids and their colours", "[cli][scenes]") {
  const test::ScratchDir scratch("shipped");
  for (const char* name : {"classic2d", "classic3d", "symmetric2d", "symmetric3d", "many3d"}) {
    INFO(name);
    const std::string path = std::string(RAYCAM_SCENES) + "/" + name + ".json";
    const std::string ids_path = scratch.path(std::string(name) + ".txt"),
                      png_path = scratch.path(std::string(name) + ".png");
    const std::string command = std::string(RAYCAM_CLI) + " render --scene " + path + " --ids " + ids_path +
                                " --out " + png_path + " > /dev/null 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    const SceneFile file = load_scene_file(path);
    REQUIRE(file.camera.target);  // every shipped scene has a full preset
    const ColourMap map = expected_map(file);
    const std::vector<std::vector<int>> rows = read_ids(ids_path);
    REQUIRE(int(rows.size()) == map.height);
    int wrong_ids = 0, visible = 0;
    for (int r = 0; r < map.height; ++r) {
      REQUIRE(int(rows[std::size_t(r)].size()) == map.width);
      for (int c = 0; c < map.width; ++c) {
        wrong_ids += rows[std::size_t(r)][std::size_t(c)] != map.id_at(r, c);
        visible += map.id_at(r, c) >= 0;
      }
    }
    CHECK(wrong_ids == 0);
    CHECK(visible > 0);  // a shipped scene shows something
    // The PNG: a 2D bar is n wide and drawn 32 high, a 3D image is the map itself.
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(png_path.c_str(), &width, &height, &channels, 3);
    REQUIRE(pixels != nullptr);
    CHECK(width == map.width);
    CHECK(height == (file.dimension == 2 ? 32 : map.height));
    int wrong_colours = 0;
    for (int y = 0; y < height && width == map.width; ++y)
      for (int x = 0; x < width; ++x) {
        const Rgb8 want = colour_of(file, map.id_at(file.dimension == 2 ? 0 : y, x));
        const unsigned char* got = pixels + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
        wrong_colours += got[0] != want.r || got[1] != want.g || got[2] != want.b;
      }
    stbi_image_free(pixels);
    CHECK(wrong_colours == 0);
    // The symmetric scenes are symmetric about the view axis: column c and its mirror see the same object's
    // colour (the twins share a colour), up to a pixel whose ray grazes (none in these presets).
    if (std::string(name).rfind("symmetric", 0) == 0) {
      int asymmetric = 0;
      for (int r = 0; r < map.height; ++r)
        for (int c = 0; c < map.width; ++c)
          asymmetric += !(colour_of(file, rows[std::size_t(r)][std::size_t(c)]) ==
                          colour_of(file, rows[std::size_t(r)][std::size_t(map.width - 1 - c)]));
      CHECK(asymmetric == 0);
    }
  }
}

TEST_CASE("the built-in demo scenes are scenes/classic2d.json and classic3d.json, object for object",
          "[cli][scenes]") {
  // One definition: the built-in scenes are generated from these files at build time.
  const SceneFile file2d = load_scene_file(std::string(RAYCAM_SCENES) + "/classic2d.json");
  const Scene2D demo2d = demo_scene_2d();
  REQUIRE(file2d.scene2d.circles.size() == demo2d.circles.size());
  CHECK(file2d.scene2d.background == demo2d.background);
  for (std::size_t i = 0; i < demo2d.circles.size(); ++i) {
    CHECK(file2d.scene2d.circles[i].centre == demo2d.circles[i].centre);
    CHECK(file2d.scene2d.circles[i].radius == demo2d.circles[i].radius);
    CHECK(file2d.scene2d.circles[i].colour == demo2d.circles[i].colour);
    CHECK(file2d.scene2d.circles[i].name == demo2d.circles[i].name);
  }
  // Its camera too: the 2D demo opens at θ = 70°, where every construction step moves the camera.
  REQUIRE(file2d.camera.theta_deg);
  CHECK(*file2d.camera.theta_deg == kDemoTheta2DDegrees);
  CHECK(demo_camera_2d().orbit().theta == Approx(glm::radians(*file2d.camera.theta_deg)));
  const SceneFile file3d = load_scene_file(std::string(RAYCAM_SCENES) + "/classic3d.json");
  const Scene3D demo3d = demo_scene_3d();
  REQUIRE(file3d.scene3d.spheres.size() == demo3d.spheres.size());
  for (std::size_t i = 0; i < demo3d.spheres.size(); ++i) {
    CHECK(file3d.scene3d.spheres[i].centre == demo3d.spheres[i].centre);
    CHECK(file3d.scene3d.spheres[i].radius == demo3d.spheres[i].radius);
    CHECK(file3d.scene3d.spheres[i].colour == demo3d.spheres[i].colour);
  }
}
