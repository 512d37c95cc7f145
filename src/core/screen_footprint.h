// Where an object can appear on the screen, before any ray is cast: the primary rays of a pinhole camera
// are lines from the eye, so a circle or sphere can only be hit by rays inside its tangent cone from the
// eye. Its projection bounds a small range of pixels; pixels outside it never need to test the object.
//
// The bounds are conservative: widened by the rounding the rays and the intersection can suffer (a bound
// on it, from the size of the coordinates and the formula), so every pixel whose computed ray (in
// double, as the plain caster computes it) hits the object lies inside. The accelerated casters
// then run the plain caster's own intersection on those pixels, which keeps their ids identical.
#pragma once

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/intersect.h"
#include "raycam/scene.h"

namespace raycam::detail {

// A closed range of pixel indices, empty when first > last.
struct PixelRange {
  int first = 0, last = -1;
  bool empty() const { return first > last; }
  int size() const { return empty() ? 0 : last - first + 1; }
};

struct PixelBox {
  PixelRange rows, columns;
  bool empty() const { return rows.empty() || columns.empty(); }
  long long pixel_count() const { return static_cast<long long>(rows.size()) * columns.size(); }
};

// Spheres as columns (structure of arrays): what sphere_boxes' loop reads, so that it vectorises.
struct SphereColumns {
  const double *x, *y, *z, *radius;
};
// The same in single precision (SphereClusters' float copy), for the first pass of spheres_maybe_seen.
struct FloatSphereColumns {
  const float *x, *y, *z, *radius;
};

// The camera's frame, read off M_d = T·R·H: the eye, the unit right/up/forward axes and d_f, the eye's
// distance to the screen. A world direction (a, b, c) in this frame crosses the canonical screen at
// (d_f·a/c, d_f·b/c). A 2D camera is the plane z = 0 of this (no up axis).
struct Footprint {
  glm::dvec3 eye{0.0}, right{0.0}, up{0.0}, forward{0.0};
  double df = 1.0;
  double coordinate_scale = 0.0;  // size of the numbers the rays are made of (for the rounding slack)
  IntersectFormula formula;       // the naive formula's cancellation widens the bounds

  Footprint(const Camera2D& camera, IntersectFormula formula);
  Footprint(const Camera3D& camera, IntersectFormula formula);

  // Pixels k (not image columns) a circle can cover; empty if it lies wholly behind the screen or
  // outside the field of view.
  PixelRange circle_pixels(const Circle& circle, int pixel_count) const;
  // Rows and columns (image order) a sphere can cover; empty if culled.
  PixelBox sphere_pixels(const Sphere& sphere, int rows, int columns) const;
  // The same for spheres 0…count-1 of the columns, into boxes[0…count-1] (the same code, vectorised).
  void sphere_boxes(const SphereColumns& spheres, int count, int rows, int columns, PixelBox* boxes) const;

  // Clusters of spheres (SphereClusters) culled whole: out[k] = 1 where bounding sphere k lies wholly outside
  // the screen's pyramid from the eye, or wholly on the eye's side of the screen; then no pixel's ray can hit
  // a sphere inside it (whose own box may still be loose: the whole image, for one across the eye's plane). The sphere is first grown by 10⁻³ of its radius and 10⁻⁶ of the numbers' size,
  // far past a member's rounding slack (~10⁻¹⁴ of it). Four planes and a depth, not the box of the bounding
  // sphere: that cost the projection 4 % where nothing was culled. Only where the members' slack is bounded
  // so: the stable formula (the naive one's grows as a radius shrinks) and d_f ≥ 10⁻² (the slopes' relative
  // slack stays far below the growth); culls_clusters() says whether.
  bool culls_clusters() const;
  void clusters_out_of_view(const SphereColumns& bounds, int count, unsigned char* out) const;

  // A cheaper first pass, in single precision (float_culling.cpp): writes to kept[0…n-1] the indices, in
  // order, of the spheres whose box sphere_boxes may find non-empty, and returns n. Every sphere it drops has
  // an empty double box; some it keeps may too. scratch holds count bytes. Where culls_clusters() holds.
  int spheres_maybe_seen(const FloatSphereColumns& spheres, int count, int rows, int columns, int* kept,
                         unsigned char* scratch) const;
};

}  // namespace raycam::detail
