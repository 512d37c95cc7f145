// The ray caster (handout, exercise 2): one primary ray per pixel, the nearest hit with t ≥ 0 wins, ties go
// to the lower object index, a miss gives the background colour.
//
// CastMethod::plain is the handout's loop, every object tested for every pixel: the reference. The other
// methods skip work the scene doesn't need (docs/speed.md) and give the SAME ids: they run the plain
// loop's own ray and intersection code, only on the pixels an object can cover.
#pragma once

#include <vector>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/cast_options.h"
#include "raycam/colour_map.h"
#include "raycam/intersect.h"
#include "raycam/scene.h"

namespace raycam {

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
