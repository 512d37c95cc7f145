// Scenes: flat-coloured circles (2D) and spheres (3D), as in the handout's exercise 2 ("pour l'instant, de
// simples cercles"), and in 3D the seam for other kinds of object (Shape3D, below).
// Coordinates are world units; colours are 8-bit sRGB triples. An object's id is its index in the vector; in
// 3D, the spheres come first and the other kinds after them (ids spheres.size(), spheres.size() + 1, …).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <variant>
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

// A plane: the points p with dot(p - point, normal) = 0, one flat colour on both sides; `normal` need not be
// of unit length. The second kind of 3D object, there so that the seam between kinds stays open and tested:
// the fast casters know spheres only, and a scene holding any other kind is cast by the plain loop, with the
// same nearest-hit rule (t ≥ 0, ties to the lower id). docs/architecture.md, "Adding a kind of object",
// lists what else a kind touches.
struct Plane {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};
  Rgb8 colour{255, 255, 255};
  std::string name;
};

// The kinds of 3D object besides spheres, tagged (as pbrt-v4's Shape): one alternative per kind. Spheres
// keep a vector of their own (the fast casters' packed columns are built from it).
using Shape3D = std::variant<Plane>;

struct Scene2D {
  Rgb8 background = kDefaultBackground;
  std::vector<Circle> circles;
};

struct Scene3D {
  Rgb8 background = kDefaultBackground;
  std::vector<Sphere> spheres;
  std::vector<Shape3D> shapes;  // ids spheres.size() onwards; cast by the plain loop (ray_caster.h)
};

// The scene's objects (circles or spheres), in id order: what code written once for both dimensions calls.
inline std::vector<Circle>& objects_of(Scene2D& scene) { return scene.circles; }
inline std::vector<Sphere>& objects_of(Scene3D& scene) { return scene.spheres; }
inline const std::vector<Circle>& objects_of(const Scene2D& scene) { return scene.circles; }
inline const std::vector<Sphere>& objects_of(const Scene3D& scene) { return scene.spheres; }

// The spheres of a 3D scene in clusters of neighbours, each with a sphere that holds it: what the fast caster
// projects, so that a cluster out of view is culled in one test, not kSize (a third of 10⁵ spheres can lie
// outside a view). Neighbours: the spheres split in halves along the longest side of their centres' bounds,
// again and again, down to kSize.
struct SphereClusters {
  static constexpr int kSize = 64;
  std::vector<double> x, y, z, radius;  // the spheres, cluster after cluster
  std::vector<int> object;              // each one's index in the scene (its id)
  // The same spheres rounded to float, for a cheap first culling pass (four a WebAssembly vector, not two).
  std::vector<float> float_x, float_y, float_z, float_radius;
  // Cluster k holds spheres k·kSize … min(size, (k+1)·kSize) - 1, all inside this sphere.
  std::vector<double> bound_x, bound_y, bound_z, bound_radius;

  // The splits that made the clusters: spheres with a centre up to `at` along the axis went to `first`,
  // those from `at` on to `second`; a child ≥ 0 is a split, -1 - k is cluster k. splits[0] is the first one.
  struct Split {
    int axis;
    double at;
    int first, second;
  };
  std::vector<Split> splits;

  void build(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
             const std::vector<double>& radius);
  // The clusters in a near-to-far order from the eye (the eye's side of each split first): an order only,
  // for speed (a cluster that holds the eye or straddles a split may come early or late).
  void near_to_far(const glm::dvec3& eye, std::vector<int>& out) const;
  int size() const { return int(object.size()); }
  int cluster_count() const { return int(bound_radius.size()); }
};

// A 3D scene packed for casting: the spheres' centres and radii as columns (32 bytes a sphere, where the
// scene's Sphere is 72 with its name), their colours, and the same columns again in clusters (36 bytes a
// sphere). The fast caster reads every sphere of a cluster in view once a frame to project it; from columns
// that loop vectorises, and 10⁵ spheres fit in less cache. A copy: build it when the scene changes and keep it
// between frames (the app keys it on its scene_version); cast_primary_rays on a Scene3D packs a fresh one
// every call. Sphere i of the columns is object i of the scene (its id); the plain loop reads them.
struct PackedScene3D {
  std::vector<double> x, y, z, radius;
  std::vector<Rgb8> colour;
  Rgb8 background = kDefaultBackground;
  SphereClusters clusters;
  std::vector<Shape3D> shapes;  // the scene's other kinds, as they are: any one makes the cast the plain loop

  PackedScene3D() = default;
  explicit PackedScene3D(const Scene3D& scene) { pack(scene); }
  void pack(const Scene3D& scene);  // reuses the columns' memory
  int size() const { return int(radius.size()); }  // the spheres (ids 0 … size() - 1)
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
