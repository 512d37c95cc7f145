// Exercise 2, shared by the 2D and 3D cameras: a canonical primary ray sent into the world by M_d.
#pragma once

#include <glm/geometric.hpp>

#include "raycam/transform.h"

namespace raycam::detail {

// P_k = M_d·P_k^0 is a point; u_k = M_d·(P_k^0 - E0) is a vector, so it is not translated, and it is
// renormalised because H scales (unless the "forgot to renormalise" mistake is on).
template <class Ray, class Matrix, class Vector>
Ray primary_ray_through(const Matrix& world_from_camera, Vector canonical_pixel, Vector canonical_eye,
                        bool renormalise) {
  Ray ray;
  ray.origin = transform_point(world_from_camera, canonical_pixel);
  ray.direction = transform_vector(world_from_camera, canonical_pixel - canonical_eye);
  if (renormalise) ray.direction = glm::normalize(ray.direction);
  return ray;
}

}  // namespace raycam::detail
