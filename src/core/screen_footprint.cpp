#include "screen_footprint.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raycam::detail {

namespace {
// Slack on every bound: far above the rounding of the frame, the slopes and the rays (~1e-15 relative),
// far below a pixel at any allowed size.
constexpr double kRelativeSlack = 1e-9;

// Tangent slopes m = a/c of the lines from the eye touching a circle of centre (a0, c0) and radius r in
// one plane through the forward axis. False when the circle reaches the eye's plane (c0 ≤ r): the lines
// that touch it are not bounded in slope, so every pixel is a candidate.
bool tangent_slopes(double a0, double c0, double r, double& m_lo, double& m_hi) {
  if (!(c0 > r * (1.0 + kRelativeSlack))) return false;
  const double room = (c0 - r) * (c0 + r);  // c0² - r², > 0
  const double spread = r * std::sqrt(a0 * a0 + room);
  m_lo = (a0 * c0 - spread) / room;
  m_hi = (a0 * c0 + spread) / room;
  const double slack = kRelativeSlack * (std::abs(m_lo) + std::abs(m_hi) + 1.0);
  m_lo -= slack;
  m_hi += slack;
  return true;
}

// Pixels whose centre -1 + (2i+1)/count lies in the screen interval [df·m_lo, df·m_hi], padded by one.
// increasing = false for rows, whose screen coordinate y = 1 - (2i+1)/count decreases with i.
PixelRange pixels_between(double df, double m_lo, double m_hi, int count, bool increasing) {
  auto index_of = [&](double screen) {
    const double s = increasing ? screen : -screen;
    return std::clamp(((s + 1.0) * count - 1.0) / 2.0, -2.0, double(count) + 1.0);
  };
  double a = index_of(df * m_lo), b = index_of(df * m_hi);
  if (a > b) std::swap(a, b);
  return PixelRange{std::max(0, int(std::floor(a)) - 1), std::min(count - 1, int(std::ceil(b)) + 1)};
}

PixelRange axis_pixels(double df, double a0, double c0, double r, int count, bool increasing) {
  double m_lo, m_hi;
  if (!tangent_slopes(a0, c0, r, m_lo, m_hi)) return PixelRange{0, count - 1};
  return pixels_between(df, m_lo, m_hi, count, increasing);
}

// Wholly on the eye's side of the screen plane (every point at depth c < d_f): rays start on the screen
// and move away from the eye, so they never reach it with t ≥ 0.
bool behind_screen(double c0, double r, double df) {
  return c0 + r < df - kRelativeSlack * (std::abs(c0) + r + df);
}
}  // namespace

EyeFrame2D::EyeFrame2D(const Camera2D& camera) {
  const glm::dmat3& m = camera.world_from_camera();
  eye = camera.eye();
  right = glm::normalize(glm::dvec2(m[0]));  // R·x: the canonical screen's direction
  const glm::dvec2 back(m[1]);               // d_f·R·y, from the screen towards the eye
  df = glm::length(back);
  forward = -back / df;
}

EyeFrame3D::EyeFrame3D(const Camera3D& camera) {
  const glm::dmat4& m = camera.world_from_camera();
  eye = camera.eye();
  right = glm::normalize(glm::dvec3(m[0]));
  up = glm::normalize(glm::dvec3(m[1]));
  const glm::dvec3 back(m[2]);  // d_f·R·z
  df = glm::length(back);
  forward = -back / df;
}

PixelRange circle_pixels(const EyeFrame2D& frame, const Circle& circle, int pixel_count) {
  const glm::dvec2 q = circle.centre - frame.eye;
  const double a0 = glm::dot(q, frame.right), c0 = glm::dot(q, frame.forward);
  if (behind_screen(c0, circle.radius, frame.df)) return PixelRange{};
  return axis_pixels(frame.df, a0, c0, circle.radius, pixel_count, true);
}

PixelBox sphere_pixels(const EyeFrame3D& frame, const Sphere& sphere, int rows, int columns) {
  const glm::dvec3 q = sphere.centre - frame.eye;
  const double c0 = glm::dot(q, frame.forward);
  if (behind_screen(c0, sphere.radius, frame.df)) return PixelBox{};
  // The planes through the eye containing the up axis that touch the sphere are the tangent lines of its
  // projection on the (right, forward) plane, a circle of the same radius: so each axis is a 2D problem.
  PixelBox box;
  box.columns = axis_pixels(frame.df, glm::dot(q, frame.right), c0, sphere.radius, columns, true);
  if (box.columns.empty()) return box;
  box.rows = axis_pixels(frame.df, glm::dot(q, frame.up), c0, sphere.radius, rows, false);
  return box;
}

}  // namespace raycam::detail
