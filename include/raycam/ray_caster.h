// The plain ray caster (handout, exercise 2): one primary ray per pixel, every object tested, the nearest
// hit with t ≥ 0 wins, ties go to the lower object index, a miss gives the background colour.
// This is the reference every faster caster must agree with, id for id.
#pragma once

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

struct CastOptions {
  IntersectFormula formula = IntersectFormula::stable;
};

// Work done by one cast, shown by the app's status line.
struct CastStats {
  long long rays = 0;
  long long intersection_tests = 0;
  long long objects_culled = 0;
};

Hit nearest_hit(const std::vector<Circle>& circles, const Ray2D& ray, IntersectFormula formula);
Hit nearest_hit(const std::vector<Sphere>& spheres, const Ray3D& ray, IntersectFormula formula);

// 2D: a 1-row map of n columns in image order (column 0 = the eye's left = pixel k = n-1).
ColourMap cast_primary_rays(const Camera2D& camera, const Scene2D& scene, const CastOptions& options = {},
                            CastStats* stats = nullptr);
// 3D: rows × columns, row 0 at the top.
ColourMap cast_primary_rays(const Camera3D& camera, const Scene3D& scene, const CastOptions& options = {},
                            CastStats* stats = nullptr);

}  // namespace raycam
