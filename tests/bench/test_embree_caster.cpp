// The Embree reference caster against raycam's plain caster: Embree rounds the rays and spheres to float,
// so grazing pixels may differ; anything beyond a handful of pixels would be a wrong ray or id mapping.
#include <embree3/rtcore_config.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <glm/gtc/constants.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/embree_caster.h"
#include "raycam/ray_caster.h"

using namespace raycam;
using raycam::bench::EmbreeCaster;

namespace {
constexpr double kPi = glm::pi<double>();

double uniform(std::mt19937_64& engine, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(engine);
}

Scene3D random_scene(std::mt19937_64& engine, int count) {
  Scene3D scene;
  scene.background = {7, 8, 9};
  for (int i = 0; i < count; ++i)
    scene.spheres.push_back({{uniform(engine, -4, 4), uniform(engine, -4, 4), uniform(engine, -4, 4)},
                             uniform(engine, 0.3, 1.2),
                             {std::uint8_t(i), std::uint8_t(255 - i), 100},
                             ""});
  return scene;
}

// Looks at the spheres from outside them all (no sphere reaches 8.2 from the centre, the screen is ≥ 9 away);
// sizes that are not multiples of 4 leave partial packets.
Camera3D random_camera(std::mt19937_64& engine, int columns, int rows) {
  Camera3D camera(columns, rows);
  camera.set_orbit({{0, 0, 0},
                    uniform(engine, 9, 13),
                    uniform(engine, -kPi, kPi),
                    uniform(engine, 0.2, 3.0),
                    uniform(engine, 1.5, 3.0)});
  return camera;
}

// The handout's plain loop, pixel by pixel: the reference whatever method cast_primary_rays defaults to.
std::vector<int> plain_ids(const Camera3D& camera, const Scene3D& scene) {
  std::vector<int> ids;
  for (int row = 0; row < camera.rows(); ++row)
    for (int column = 0; column < camera.columns(); ++column)
      ids.push_back(nearest_hit(scene.spheres, camera.primary_ray(row, column), IntersectFormula::stable).id);
  return ids;
}
}  // namespace

TEST_CASE("Embree's ids agree with the plain caster's on random scenes", "[embree]") {
  std::mt19937_64 engine(2024);
  for (int trial = 0; trial < 8; ++trial) {
    const Scene3D scene = random_scene(engine, 50);
    const bool odd_size = trial % 2 == 1;
    const Camera3D camera = random_camera(engine, odd_size ? 63 : 64, odd_size ? 61 : 64);
    const std::vector<int> expected = plain_ids(camera, scene);
    const EmbreeCaster caster(scene);
    ColourMap single;
    caster.cast(camera, 1, 1, single);
    for (int packet : {1, 16})
      for (int threads : {1, 2}) {
        ColourMap map;
        caster.cast(camera, packet, threads, map);
        REQUIRE(map.width == camera.columns());
        REQUIRE(map.height == camera.rows());
        REQUIRE(map.ids.size() == expected.size());
        std::size_t differing = 0, hits = 0;
        for (std::size_t i = 0; i < map.ids.size(); ++i) {
          differing += map.ids[i] != expected[i];
          hits += expected[i] >= 0;
          // Colours follow the ids, whichever caster is right about a grazing pixel.
          CHECK(map.colours[i] == (map.ids[i] < 0 ? scene.background : scene.spheres[map.ids[i]].colour));
        }
        INFO("trial " << trial << ", packet " << packet << ", threads " << threads << ": " << differing
                      << " of " << map.ids.size() << " pixels differ (" << hits << " hits)");
        CHECK(hits > 0);
        CHECK(differing <= map.ids.size() / 200);  // ≥ 99.5 % agree
        // Same float rays, same BVH: packets and threads must not change a single id.
        CHECK(map.ids == single.ids);
      }
    // Rays made beforehand (the benchmark's "ray table" variant) are the camera's rays: the same ids.
    std::vector<Ray3D> table;
    for (int row = 0; row < camera.rows(); ++row)
      for (int column = 0; column < camera.columns(); ++column) table.push_back(camera.primary_ray(row, column));
    ColourMap from_table;
    caster.cast(camera, 16, 2, from_table, &table);
    CHECK(from_table.ids == single.ids);
  }
}

TEST_CASE("an empty scene gives the background everywhere", "[embree]") {
  Scene3D scene;
  scene.background = {1, 2, 3};
  const EmbreeCaster caster(scene);
  std::mt19937_64 engine(7);
  const Camera3D camera = random_camera(engine, 30, 18);
  for (int packet : {1, 16}) {
    ColourMap map;
    caster.cast(camera, packet, 2, map);
    REQUIRE(map.ids.size() == 30u * 18u);
    CHECK(std::all_of(map.ids.begin(), map.ids.end(), [](int id) { return id == -1; }));
    CHECK(std::all_of(map.colours.begin(), map.colours.end(), [](Rgb8 c) { return c == Rgb8{1, 2, 3}; }));
  }
}

TEST_CASE("the map is reused when its size is unchanged, and bad arguments throw", "[embree]") {
  std::mt19937_64 engine(11);
  const Scene3D scene = random_scene(engine, 10);
  const Camera3D camera = random_camera(engine, 20, 20);
  const auto before = std::chrono::steady_clock::now();
  const EmbreeCaster caster(scene);
  const double construct_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - before).count();
  ColourMap map;
  caster.cast(camera, 16, 2, map);
  const int* ids = map.ids.data();
  const Rgb8* colours = map.colours.data();
  caster.cast(camera, 1, 1, map);
  CHECK(map.ids.data() == ids);
  CHECK(map.colours.data() == colours);
  // The BVH build is timed inside the constructor: a positive time no longer than the whole construction.
  CHECK(caster.build_ms() > 0.0);
  CHECK(caster.build_ms() <= construct_ms);
  // The note reads the library's version at run time: it must be the version of the headers we built with,
  // and it lists 16-wide packets exactly when the device says they are native.
  const std::string note = caster.isa_note();
  CHECK(note.rfind(std::string("Embree ") + RTC_VERSION_STRING + ", native packets:", 0) == 0);
  CHECK((note.find(" 16") != std::string::npos) == caster.native_packet16());
  CHECK_THROWS_AS(caster.cast(camera, 8, 1, map), std::invalid_argument);
  CHECK_THROWS_AS(caster.cast(camera, 1, 0, map), std::invalid_argument);
}
