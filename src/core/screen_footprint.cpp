#include "screen_footprint.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raycam::detail {

namespace {
constexpr double kEpsilon = 1.1102230246251565e-16;  // double's unit roundoff
// Relative slack on the slopes (the frame's and the rays' directions are good to ~1e-15).
constexpr double kRelativeSlack = 1e-9;

// What both axes of one object share: the depth c0 of its centre along the view, its radius, and the
// slack for the rounding that a computed ray and the intersection's arithmetic may suffer near it. The ray's
// origin and f = origin - centre round at the scale of the coordinates; the naive formula's b² - c cancels,
// which moves its silhouette by ~ε·|f|²/r (README, "Accuracy").
struct Depth {
  double c0, r, slack;
  bool bounded;              // false when the object reaches the eye's plane (c0 ≤ r): every slope is possible
  double inverse_room = 0;   // 1 / (c0² - r²)
  double slope_slack = 0;    // the slack as a slope at the object's nearest depth, c0 - r

  Depth(const Footprint& f, const glm::dvec3& q, double radius) : c0(glm::dot(q, f.forward)), r(radius) {
    const double distance = std::abs(q.x) + std::abs(q.y) + std::abs(q.z);  // ≥ |q|, without a square root
    slack = 64 * kEpsilon * (f.coordinate_scale + distance + r);
    if (f.formula == IntersectFormula::naive) slack += 16 * kEpsilon * (distance + r) * (distance + r) / r;
    bounded = c0 - r > slack + kRelativeSlack * c0;
    if (bounded) {
      inverse_room = 1.0 / ((c0 - r) * (c0 + r));
      slope_slack = slack * (c0 + r) * inverse_room;  // slack / (c0 - r), with the one division
    }
  }

  // Wholly on the eye's side of the screen plane (every point at depth c < d_f): rays start on the screen
  // and move away from the eye, so they never reach it with t ≥ 0.
  bool behind_screen(double df) const { return c0 + r < df - slack - kRelativeSlack * (std::abs(c0) + r + df); }
};

int floor_of(double x) {  // x in a few pixels of [0, count]: no library call, no overflow
  const int i = int(x);
  return i - (x < i);
}
int ceil_of(double x) {
  const int i = int(x);
  return i + (x > i);
}

// Pixels (along one axis) whose centre's ray can touch the object: the tangent slopes m = a/c of the lines
// from the eye touching the circle of centre (a0, c0) and radius r (the object's trace in the plane through
// the forward axis and this axis), widened by the slack, mapped to pixel centres -1 + (2i+1)/count on the
// screen at distance d_f through the core's pixel <-> screen pair. increasing = false for rows, whose screen
// y decreases with i.
PixelRange axis_pixels(const Depth& d, double a0, double df, int count, bool increasing) {
  if (!d.bounded) return PixelRange{0, count - 1};
  const double spread = d.r * std::sqrt(a0 * a0 + (d.c0 - d.r) * (d.c0 + d.r));
  double m_lo = (a0 * d.c0 - spread) * d.inverse_room, m_hi = (a0 * d.c0 + spread) * d.inverse_room;
  const double widen = kRelativeSlack * (std::abs(m_lo) + std::abs(m_hi) + 1.0) + d.slope_slack;
  m_lo -= widen;
  m_hi += widen;
  auto index_of = [&](double slope) {  // pixel i has its centre at index i, raster coordinate i + 1/2
    const double screen = increasing ? df * slope : -df * slope;  // rows: raster y grows as screen y falls
    return std::clamp(raster_from_screen(screen, count) - 0.5, -2.0, double(count) + 1.0);
  };
  double a = index_of(m_lo), b = index_of(m_hi);
  if (a > b) std::swap(a, b);
  constexpr double kIndexSlack = 1e-6;  // of a pixel: far above the rounding of index_of
  return PixelRange{std::max(0, ceil_of(a - kIndexSlack)), std::min(count - 1, floor_of(b + kIndexSlack))};
}
}  // namespace

Footprint::Footprint(const Camera2D& camera, IntersectFormula intersect) : formula(intersect) {
  const glm::dmat3& m = camera.world_from_camera();
  eye = glm::dvec3(camera.eye(), 0.0);
  right = glm::dvec3(glm::normalize(glm::dvec2(m[0])), 0.0);  // R·x: the canonical screen's direction
  const glm::dvec3 back(glm::dvec2(m[1]), 0.0);                // d_f·R·y, from the screen towards the eye
  df = glm::length(back);
  forward = -back / df;
  coordinate_scale = glm::length(eye) + df;
}

Footprint::Footprint(const Camera3D& camera, IntersectFormula intersect) : formula(intersect) {
  const glm::dmat4& m = camera.world_from_camera();
  eye = camera.eye();
  right = glm::normalize(glm::dvec3(m[0]));
  up = glm::normalize(glm::dvec3(m[1]));
  const glm::dvec3 back(m[2]);  // d_f·R·z
  df = glm::length(back);
  forward = -back / df;
  coordinate_scale = glm::length(eye) + df;
}

PixelRange Footprint::circle_pixels(const Circle& circle, int pixel_count) const {
  const glm::dvec3 q = glm::dvec3(circle.centre, 0.0) - eye;
  const Depth depth(*this, q, circle.radius);
  if (depth.behind_screen(df)) return PixelRange{};
  return axis_pixels(depth, glm::dot(q, right), df, pixel_count, true);
}

PixelBox Footprint::sphere_pixels(const Sphere& sphere, int rows, int columns) const {
  const glm::dvec3 q = sphere.centre - eye;
  const Depth depth(*this, q, sphere.radius);
  if (depth.behind_screen(df)) return PixelBox{};
  // The planes through the eye containing the up axis that touch the sphere are the tangent lines of its
  // projection on the (right, forward) plane, a circle of the same radius: so each axis is a 2D problem.
  PixelBox box;
  box.columns = axis_pixels(depth, glm::dot(q, right), df, columns, true);
  box.rows = axis_pixels(depth, glm::dot(q, up), df, rows, false);
  return box;
}

}  // namespace raycam::detail
