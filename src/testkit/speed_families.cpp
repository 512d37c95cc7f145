#include "raycam/speed_families.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/trigonometric.hpp>
#include <random>
#include <stdexcept>

#include "raycam/standard_scenes.h"

namespace raycam::testkit {

namespace {
// d_f for a full field of view: the canonical screen's half side is 1 at the eye's distance d_f.
double focal_for_view(double degrees) { return 1.0 / std::tan(glm::radians(degrees) / 2.0); }

// A sphere's radius when K of them fill [-10, 10]³ as the cube family does.
double cube_radius(int count) { return 2.0 * std::pow(double(std::max(count, 1)), -1.0 / 3.0); }

Rgb8 colour_of(int i) { return {std::uint8_t(40 + i % 200), std::uint8_t(i * 7), 200}; }

using Engine = std::mt19937_64;

Scene3D generated(int count, unsigned seed, const std::function<Sphere(Engine&, int)>& make) {
  Engine engine(seed + unsigned(count));
  Scene3D scene;
  scene.spheres.reserve(std::size_t(std::max(count, 0)));
  for (int i = 0; i < count; ++i) scene.spheres.push_back(make(engine, i));
  return scene;
}

// Radii log-uniform from a quarter to five times the cube family's: small and large mixed, 14 times its
// volume, so that each pixel sees several spheres behind each other.
Scene3D spread_radii(int count) {
  const double smallest = cube_radius(count) / 4.0;
  return generated(count, 71u, [&](Engine& engine, int i) {
    std::uniform_real_distribution<double> coordinate(-10.0, 10.0), exponent(0.0, 1.0);
    const glm::dvec3 centre{coordinate(engine), coordinate(engine), coordinate(engine)};
    return Sphere{centre, smallest * std::pow(20.0, exponent(engine)), colour_of(i), ""};
  });
}

// Eight dense clumps (normal, σ = 1.2) at random places in the cube: most of the scene is empty, the
// clumps are far denser than the cube family.
Scene3D clumps(int count) {
  Engine placement(97u);
  std::uniform_real_distribution<double> where(-7.0, 7.0);
  std::vector<glm::dvec3> centres(8);
  for (glm::dvec3& c : centres) c = {where(placement), where(placement), where(placement)};
  const double radius = 0.5 * cube_radius(count);
  return generated(count, 83u, [&](Engine& engine, int i) {
    std::normal_distribution<double> offset(0.0, 1.2);
    const glm::dvec3 centre = centres[std::size_t(i) % centres.size()] +
                              glm::dvec3{offset(engine), offset(engine), offset(engine)};
    return Sphere{centre, radius, colour_of(i), ""};
  });
}

// A flat layer: x, y in [-20, 20], z in [-0.5, 0.5], spheres about a third of their spacing wide.
Scene3D layer(int count) {
  const double spacing = 40.0 / std::sqrt(double(std::max(count, 1)));
  return generated(count, 89u, [&](Engine& engine, int i) {
    std::uniform_real_distribution<double> across(-20.0, 20.0), height(-0.5, 0.5);
    const glm::dvec3 centre{across(engine), across(engine), height(engine)};
    return Sphere{centre, 0.35 * spacing, colour_of(i), ""};
  });
}

struct FamilyRecipe {
  const char* name;
  const char* description;
  Scene3D (*scene)(int count);
  Orbit3D orbit;
};

const FamilyRecipe* recipes(std::size_t& count) {
  static const FamilyRecipe kRecipes[] = {
      {"cube", "uniform in [-10,10]³, r = 2K^(−1/3); d = 35, 53° view (d_f = 2)", random_spheres,
       {{0, 0, 0}, 35.0, glm::radians(30.0), glm::radians(60.0), 2.0}},
      {"narrow 20°", "the cube; d = 35, 20° view", random_spheres,
       {{0, 0, 0}, 35.0, glm::radians(30.0), glm::radians(60.0), focal_for_view(20.0)}},
      {"wide 70°", "the cube; d = 22, 70° view", random_spheres,
       {{0, 0, 0}, 22.0, glm::radians(30.0), glm::radians(60.0), focal_for_view(70.0)}},
      {"radii ×20", "uniform in the cube, radii log-uniform from r/4 to 5r (r: the cube's); d = 18, 40° view", spread_radii,
       {{0, 0, 0}, 18.0, glm::radians(30.0), glm::radians(60.0), focal_for_view(40.0)}},
      {"clumps", "8 normal clumps (σ 1.2) in the cube; d = 35, 53° view", clumps,
       {{0, 0, 0}, 35.0, glm::radians(30.0), glm::radians(60.0), 2.0}},
      {"eye inside", "the cube; eye inside it (d = 4), 53° view", random_spheres,
       {{0, 0, 0}, 4.0, glm::radians(30.0), glm::radians(60.0), 2.0}},
      {"grazing layer", "a 1-thick layer 40 wide; d = 30, 5° above it, 53° view", layer,
       {{0, 0, 0}, 30.0, glm::radians(30.0), glm::radians(85.0), 2.0}},
  };
  count = std::size(kRecipes);
  return kRecipes;
}
}  // namespace

std::vector<std::string> speed_family_names() {
  std::size_t count = 0;
  const FamilyRecipe* all = recipes(count);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < count; ++i) names.push_back(all[i].name);
  return names;
}

SpeedFamily speed_family(const std::string& name, int count) {
  std::size_t known = 0;
  const FamilyRecipe* all = recipes(known);
  std::string list;
  for (std::size_t i = 0; i < known; ++i) {
    if (name == all[i].name) return {all[i].name, all[i].description, all[i].scene(count), all[i].orbit};
    list += (list.empty() ? "" : ", ") + std::string(all[i].name);
  }
  throw std::invalid_argument("family: unknown scene family '" + name + "' (known: " + list + ")");
}

}  // namespace raycam::testkit
