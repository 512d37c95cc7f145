// Exercise 2, shared by the 2D and 3D cameras: canonical primary rays sent into the world by M_d.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>

namespace raycam::detail {

// The rays through a run of pixels on one canonical screen line, P^0 = (x, …, 0) with x = x_of(i):
//   P_k = M_d·P^0 is a point:  origin_base + x·M0, origin_base = M_d's translation (+ the row's y·M1 in 3D);
//   u_k = M_d·(P^0 - E0) is a vector (no translation): direction_base + x·M0, direction_base = -M_d·E0's
//   linear part (+ y·M1), renormalised because H scales (unless the "forgot to renormalise" mistake is on).
// M_d's columns are used directly: the zero terms of the full product are dropped and the line's terms
// computed once. Every caster calls this through the cameras, so all of them see the same rays, bit for bit.
// One ray of the line, at x: the one formula every caster's rays come from.
template <class Vector>
inline void ray_on_line(const Vector& origin_base, const Vector& direction_base, const Vector& screen_axis, double x,
                        bool renormalise, Vector& origin, Vector& direction) {
  origin = origin_base + x * screen_axis;
  direction = direction_base + x * screen_axis;
  if (renormalise) direction *= 1.0 / std::sqrt(glm::dot(direction, direction));  // as glm::normalize
}

template <class Ray, class Vector, class XOf>
void rays_along_line(const Vector& origin_base, const Vector& direction_base, const Vector& screen_axis, XOf x_of,
                     int first, int last, bool renormalise, Ray* rays) {
  for (int i = first; i <= last; ++i) {
    Ray& ray = rays[i - first];
    ray_on_line(origin_base, direction_base, screen_axis, x_of(i), renormalise, ray.origin, ray.direction);
  }
}

}  // namespace raycam::detail
