// The ray caster (handout, exercise 2): one primary ray per pixel, the nearest hit with t ≥ 0 wins, ties go
// to the lower object index, a miss gives the background colour.
//
// CastMethod::plain is the handout's loop, every object tested for every pixel: the reference. The other
// methods skip work the scene doesn't need (docs/speed.md) and give the SAME ids: they run the plain
// loop's own ray and intersection code, only on the pixels an object can cover.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/colour_map.h"
#include "raycam/intersect.h"
#include "raycam/scene.h"

namespace raycam {

struct Hit {
  int id = -1;  // object index, -1 for background
  double t = kNoHit<double>;
};

enum class CastMethod {
  automatic,  // footprint or binned, by the crossover measured with `raycam-cli bench speed`
  plain,      // every object for every pixel (the handout's loop; the reference)
  culled,     // objects behind the screen or outside the field of view dropped once, then every pixel
  footprint,  // each object tested only on the pixels of its projection's bounding box
  binned,     // footprint, with objects sorted into bands of rows first (for many objects)
};
inline constexpr CastMethod kCastMethods[] = {CastMethod::automatic, CastMethod::plain, CastMethod::culled,
                                             CastMethod::footprint, CastMethod::binned};
// "automatic", "plain", ...: the names the command line and the app show.
const char* cast_method_name(CastMethod method);
// The method of that name, or nothing (a pure lookup: what to say about a bad name is the caller's business).
std::optional<CastMethod> cast_method_named(std::string_view name);

struct CastOptions {
  IntersectFormula formula = IntersectFormula::stable;
  CastMethod method = CastMethod::automatic;
  int threads = 0;  // 0: all hardware threads; 3D only (a 2D bar takes microseconds on one)
  // 3D footprint and binned casters: take each pixel's candidates near to far and skip those that cannot
  // be nearer than its hit so far (the stable formula only). false: object order and every test, the
  // caster as it was before (the speed bench's before/after). The ids are the same either way.
  bool near_to_far = true;
  // 3D footprint and binned casters: a first culling pass in single precision, proven never to drop a sphere
  // the double pass keeps (src/core/float_culling.cpp), where most spheres are culled; the same ids either
  // way. false: the double pass alone (the speed bench's before/after).
  bool float_culling = true;
};

// Work done by one cast, shown by the app's status line.
struct CastStats {
  long long rays = 0;                // pixels answered
  long long intersection_tests = 0;  // ray/object tests actually run
  long long objects_culled = 0;      // behind the screen or outside the field of view: never tested
  long long pixels_skipped = 0;      // pixels no object can cover: background without casting a ray
  int threads = 1;                   // threads that shared the pixels (one when the work is too small)
  long long box_tests = 0;           // 3D accelerated: the tests with no skipping (the boxes' total area,
                                     // so box_tests / rays is the depth complexity of what overlaps)
};

Hit nearest_hit(const std::vector<Circle>& circles, const Ray2D& ray, IntersectFormula formula);
Hit nearest_hit(const std::vector<Sphere>& spheres, const Ray3D& ray, IntersectFormula formula);
// Every object of a 3D scene, whatever its kind (spheres, then the other kinds: Shape3D): the plain loop's hit.
Hit nearest_hit(const Scene3D& scene, const Ray3D& ray, IntersectFormula formula);

// 2D: a 1-row map of n columns in image order (column 0 = the eye's left = pixel k = n-1).
ColourMap cast_primary_rays(const Camera2D& camera, const Scene2D& scene, const CastOptions& options = {},
                            CastStats* stats = nullptr);
// 3D: rows × columns, row 0 at the top.
ColourMap cast_primary_rays(const Camera3D& camera, const Scene3D& scene, const CastOptions& options = {},
                            CastStats* stats = nullptr);
// The same into an existing map, reusing its memory (no allocation when the size is unchanged).
void cast_primary_rays(const Camera2D& camera, const Scene2D& scene, ColourMap& out,
                       const CastOptions& options = {}, CastStats* stats = nullptr);
void cast_primary_rays(const Camera3D& camera, const Scene3D& scene, ColourMap& out,
                       const CastOptions& options = {}, CastStats* stats = nullptr);
// The same from a scene packed once and kept between frames (PackedScene3D, raycam/scene.h): what the app
// and `bench speed` cast, as Embree casts from a BVH built once.
void cast_primary_rays(const Camera3D& camera, const PackedScene3D& scene, ColourMap& out,
                       const CastOptions& options = {}, CastStats* stats = nullptr);

// For `bench speed`: the accelerated casters' first stage alone (every sphere culled or projected to its
// pixel box, on options.threads threads), writing no map; returns how many spheres survive culling.
int project_spheres_only(const Camera3D& camera, const PackedScene3D& scene, const CastOptions& options = {});

}  // namespace raycam
