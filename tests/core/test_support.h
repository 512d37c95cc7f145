// Helpers shared by the core tests: deterministic random parameters and an independent "grazing" check.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/scene.h"
#include "raycam/scene_file.h"

namespace raycam::test {

inline constexpr double kPi = glm::pi<double>();  // the tests' short name for GLM's

// The message a scene file's text is refused with, or "(no error)".
inline std::string error_of(const std::string& text) {
  try {
    parse_scene_json(text, "scene.json");
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

struct Random {
  std::mt19937_64 engine;
  explicit Random(unsigned seed) : engine(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }
  // log-uniform in [lo, hi], lo > 0
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
};

// A ray grazes a ball when its perpendicular distance to the centre is within `tolerance` of the radius:
// such pixels may legitimately flip between two computations that round differently.
template <int D>
bool grazes(const glm::vec<D, double>& origin, const glm::vec<D, double>& unit_direction,
            const glm::vec<D, double>& centre, double radius, double tolerance) {
  const glm::vec<D, double> f = centre - origin;
  const glm::vec<D, double> perpendicular = f - glm::dot(f, unit_direction) * unit_direction;
  return std::abs(glm::length(perpendicular) - radius) <= tolerance * (radius + glm::length(f));
}

inline bool ray_grazes_any(const Ray2D& ray, const std::vector<Circle>& circles, double tolerance = 1e-9) {
  for (const Circle& c : circles)
    if (grazes<2>(ray.origin, ray.direction, c.centre, c.radius, tolerance)) return true;
  return false;
}
inline bool ray_grazes_any(const Ray3D& ray, const std::vector<Sphere>& spheres, double tolerance = 1e-9) {
  for (const Sphere& s : spheres)
    if (grazes<3>(ray.origin, ray.direction, s.centre, s.radius, tolerance)) return true;
  return false;
}

// 2D rotation of a point about the origin, written independently of raycam's transform.h.
inline glm::dvec2 rotated(glm::dvec2 p, double angle) {
  return {std::cos(angle) * p.x - std::sin(angle) * p.y, std::sin(angle) * p.x + std::cos(angle) * p.y};
}

}  // namespace raycam::test
