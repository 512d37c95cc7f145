// Scenes: flat-coloured circles (2D) and spheres (3D), as in the handout's exercise 2.
// Coordinates are world units; colours are 8-bit sRGB triples. An object's id is its index in the vector.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace raycam {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(Rgb8 a, Rgb8 b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
  friend bool operator!=(Rgb8 a, Rgb8 b) { return !(a == b); }
};

inline constexpr Rgb8 kDefaultBackground{20, 20, 30};

struct Circle {
  glm::dvec2 centre{0.0};
  double radius = 1.0;
  Rgb8 colour{255, 255, 255};
  std::string name;
};

struct Sphere {
  glm::dvec3 centre{0.0};
  double radius = 1.0;
  Rgb8 colour{255, 255, 255};
  std::string name;
};

struct Scene2D {
  Rgb8 background = kDefaultBackground;
  std::vector<Circle> circles;
};

struct Scene3D {
  Rgb8 background = kDefaultBackground;
  std::vector<Sphere> spheres;
};

// A 3D scene packed for casting: the spheres' centres and radii as columns (32 bytes a sphere, where the
// scene's Sphere is 72 with its name) and their colours. The fast caster reads every sphere once a frame to
// project it; from columns that loop vectorises, and 10⁵ spheres fit in less cache. A copy: build it when
// the scene changes and keep it between frames (the app keys it on its scene_version); cast_primary_rays on
// a Scene3D packs a fresh one every call. Sphere i here is object i of the scene (its id).
struct PackedScene3D {
  std::vector<double> x, y, z, radius;
  std::vector<Rgb8> colour;
  Rgb8 background = kDefaultBackground;

  PackedScene3D() = default;
  explicit PackedScene3D(const Scene3D& scene) { pack(scene); }
  void pack(const Scene3D& scene);  // reuses the columns' memory
  int size() const { return int(radius.size()); }
  glm::dvec3 centre(int i) const { return {x[std::size_t(i)], y[std::size_t(i)], z[std::size_t(i)]}; }
};

// Throws std::invalid_argument naming the object index and field if a centre or radius is not finite,
// a radius is not > 0, or there are more than kMaxObjects objects.
void validate(const Scene2D& scene);
void validate(const Scene3D& scene);

// Built-in demo scenes used when no scene file is given.
Scene2D demo_scene_2d();
Scene3D demo_scene_3d();

}  // namespace raycam
