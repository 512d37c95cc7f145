#include "screen_footprint.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raycam::detail {

namespace {
constexpr double kEpsilon = 1.1102230246251565e-16;  // double's unit roundoff
// Relative slack on the slopes (the frame's and the rays' directions are good to ~1e-15).
constexpr double kRelativeSlack = 1e-9;

// How far, in world units, a computed ray and the intersection's arithmetic may stray from the exact ones
// near this object: the ray's origin and f = origin - centre round at the scale of the coordinates, and
// the naive formula's b² - c cancels, which moves its silhouette by ~ε·|f|²/r (README, "Accuracy").
double position_slack(const Footprint& f, double distance, double radius, IntersectFormula formula) {
  double slack = 64 * kEpsilon * (f.coordinate_scale + distance + radius);
  if (formula == IntersectFormula::naive) slack += 16 * kEpsilon * (distance + radius) * (distance + radius) / radius;
  return slack;
}

// Tangent slopes m = a/c of the lines from the eye touching a circle of centre (a0, c0) and radius r in
// one plane through the forward axis, widened by `slack` world units at the circle's nearest depth. False
// when the circle reaches the eye's plane (c0 ≤ r): the lines that touch it are not bounded in slope, so
// every pixel is a candidate.
bool tangent_slopes(double a0, double c0, double r, double slack, double& m_lo, double& m_hi) {
  if (!(c0 - r > slack + kRelativeSlack * c0)) return false;
  const double room = (c0 - r) * (c0 + r);  // c0² - r², > 0
  const double spread = r * std::sqrt(a0 * a0 + room);
  m_lo = (a0 * c0 - spread) / room;
  m_hi = (a0 * c0 + spread) / room;
  const double widen = kRelativeSlack * (std::abs(m_lo) + std::abs(m_hi) + 1.0) + slack / (c0 - r);
  m_lo -= widen;
  m_hi += widen;
  return true;
}

// Pixels whose centre -1 + (2i+1)/count lies in the screen interval [df·m_lo, df·m_hi]. increasing = false
// for rows, whose screen coordinate y = 1 - (2i+1)/count decreases with i.
PixelRange pixels_between(double df, double m_lo, double m_hi, int count, bool increasing) {
  auto index_of = [&](double screen) {
    const double s = increasing ? screen : -screen;
    return std::clamp(((s + 1.0) * count - 1.0) / 2.0, -2.0, double(count) + 1.0);
  };
  double a = index_of(df * m_lo), b = index_of(df * m_hi);
  if (a > b) std::swap(a, b);
  constexpr double kIndexSlack = 1e-6;  // of a pixel: far above the rounding of index_of
  return PixelRange{std::max(0, int(std::ceil(a - kIndexSlack))), std::min(count - 1, int(std::floor(b + kIndexSlack)))};
}

PixelRange axis_pixels(double df, double a0, double c0, double r, double slack, int count, bool increasing) {
  double m_lo, m_hi;
  if (!tangent_slopes(a0, c0, r, slack, m_lo, m_hi)) return PixelRange{0, count - 1};
  return pixels_between(df, m_lo, m_hi, count, increasing);
}

// Wholly on the eye's side of the screen plane (every point at depth c < d_f): rays start on the screen
// and move away from the eye, so they never reach it with t ≥ 0.
bool behind_screen(double c0, double r, double df, double slack) {
  return c0 + r < df - slack - kRelativeSlack * (std::abs(c0) + r + df);
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
  const double a0 = glm::dot(q, right), c0 = glm::dot(q, forward);
  const double slack = position_slack(*this, glm::length(q), circle.radius, formula);
  if (behind_screen(c0, circle.radius, df, slack)) return PixelRange{};
  return axis_pixels(df, a0, c0, circle.radius, slack, pixel_count, true);
}

PixelBox Footprint::sphere_pixels(const Sphere& sphere, int rows, int columns) const {
  const glm::dvec3 q = sphere.centre - eye;
  const double c0 = glm::dot(q, forward);
  const double slack = position_slack(*this, glm::length(q), sphere.radius, formula);
  if (behind_screen(c0, sphere.radius, df, slack)) return PixelBox{};
  // The planes through the eye containing the up axis that touch the sphere are the tangent lines of its
  // projection on the (right, forward) plane, a circle of the same radius: so each axis is a 2D problem.
  PixelBox box;
  box.columns = axis_pixels(df, glm::dot(q, right), c0, sphere.radius, slack, columns, true);
  if (box.columns.empty()) return box;
  box.rows = axis_pixels(df, glm::dot(q, up), c0, sphere.radius, slack, rows, false);
  return box;
}

}  // namespace raycam::detail
