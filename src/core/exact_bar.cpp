// The exact 2D bar (see the header for the geometry). Sections: the camera frame in long double; the
// breakpoints; the footprint; coverage per pixel.
#include "raycam/exact_bar.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "raycam/intersect.h"

namespace raycam {

namespace {
using Real = long double;
using Vec = glm::vec<2, Real>;

Vec to_real(glm::dvec2 v) { return {Real(v.x), Real(v.y)}; }

// M_d's columns in long double. Canonical point (s, y) maps to P + s·right + y·up_scaled, where up_scaled =
// M_d·(0,1) = -d_f·v; the eye is M_d·E0 = P + up_scaled.
struct ScreenFrame {
  Vec centre;     // P
  Vec right;      // M_d·(1,0): the screen's +s direction, unit length (H scales y only)
  Vec up_scaled;  // M_d·(0,1)
  Vec eye;

  explicit ScreenFrame(const Camera2D& camera) {
    const glm::dmat3& m = camera.world_from_camera();
    right = Vec(Real(m[0][0]), Real(m[0][1]));
    up_scaled = Vec(Real(m[1][0]), Real(m[1][1]));
    centre = Vec(Real(m[2][0]), Real(m[2][1]));
    eye = centre + up_scaled;
  }

  Vec screen_point(Real s) const { return centre + s * right; }

  // Where the line from the eye along `w` (w = 0 excluded) crosses the screen line, as canonical s.
  // In canonical coordinates w = α·(1,0) + β·(0,1); starting from E0 = (0,1) the line reaches y = 0 after
  // λ = -1/β, at s = -α/β. Only β < 0 goes forward (towards the screen); otherwise there is no crossing.
  bool project_direction(Vec w, Real& s) const {
    const Real det = right.x * up_scaled.y - up_scaled.x * right.y;
    const Real alpha = (w.x * up_scaled.y - up_scaled.x * w.y) / det;
    const Real beta = (right.x * w.y - w.x * right.y) / det;
    if (!(beta < 0)) return false;
    s = -alpha / beta;
    return std::isfinite(double(s));
  }
};

Real cross(Vec a, Vec b) { return a.x * b.y - a.y * b.x; }

int nearest_id(const ScreenFrame& frame, const Scene2D& scene, Real s) {
  const Vec origin = frame.screen_point(s);
  const Vec direction = glm::normalize(origin - frame.eye);
  int id = -1;
  Real best = kNoHit<Real>;
  for (std::size_t i = 0; i < scene.circles.size(); ++i) {
    const Circle& c = scene.circles[i];
    const Real t = nearest_hit_t<2, Real>(origin, direction, to_real(c.centre), Real(c.radius),
                                          IntersectFormula::stable);
    if (t < best) {  // strict: ties keep the lower index, as the plain caster
      best = t;
      id = int(i);
    }
  }
  return id;
}

// All screen coordinates in (-1, 1) where what is visible may change.
std::vector<Real> breakpoints(const ScreenFrame& frame, const Scene2D& scene) {
  std::vector<Real> points;
  auto add_direction = [&](Vec w) {
    Real s;
    if (frame.project_direction(w, s) && s > -1 && s < 1) points.push_back(s);
  };
  const auto& circles = scene.circles;
  for (const Circle& circle : circles) {
    const Vec c = to_real(circle.centre);
    const Real r = circle.radius;
    // Silhouette: the two tangent directions from the eye make an angle asin(r/D) with the eye→centre line.
    const Vec f = c - frame.eye;
    const Real distance = glm::length(f);
    if (distance > r) {
      const Real sin_beta = r / distance;
      const Real cos_beta = std::sqrt((distance - r) * (distance + r)) / distance;
      const Vec u = f / distance;
      add_direction(Vec(cos_beta * u.x - sin_beta * u.y, sin_beta * u.x + cos_beta * u.y));
      add_direction(Vec(cos_beta * u.x + sin_beta * u.y, -sin_beta * u.x + cos_beta * u.y));
    }
    // The screen line entering / leaving the circle: |P + s·right - c|² = r², |right| = 1.
    const Vec g = frame.centre - c;
    const Real half_b = glm::dot(frame.right, g);
    const Real perpendicular = cross(frame.right, g);  // distance from c to the screen line
    const Real disc = (r - perpendicular) * (r + perpendicular);
    if (disc >= 0) {
      const Real root = std::sqrt(disc);
      for (Real s : {-half_b - root, -half_b + root})
        if (s > -1 && s < 1) points.push_back(s);
    }
  }
  // Circle-circle intersection points: two surfaces are at the same depth only there.
  for (std::size_t i = 0; i < circles.size(); ++i) {
    for (std::size_t j = i + 1; j < circles.size(); ++j) {
      const Vec c1 = to_real(circles[i].centre), c2 = to_real(circles[j].centre);
      const Real r1 = circles[i].radius, r2 = circles[j].radius;
      const Vec between = c2 - c1;
      const Real d = glm::length(between);
      if (d == 0 || d > r1 + r2 || d < std::abs(r1 - r2)) continue;
      const Real a = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
      const Real h = std::sqrt(std::max(Real(0), r1 * r1 - a * a));
      const Vec e = between / d;
      const Vec base = c1 + a * e;
      const Vec normal(-e.y, e.x);
      add_direction(base + h * normal - frame.eye);
      add_direction(base - h * normal - frame.eye);
    }
  }
  points.push_back(-1);
  points.push_back(1);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}
}  // namespace

int exact_id_at(const Camera2D& camera, const Scene2D& scene, long double s) {
  return nearest_id(ScreenFrame(camera), scene, s);
}

std::vector<VisibleInterval> exact_footprint(const Camera2D& camera, const Scene2D& scene) {
  if (scene.circles.size() > kMaxExactBarCircles)
    throw std::invalid_argument(
        "circles: the exact bar takes at most " + std::to_string(kMaxExactBarCircles) +
        " circles (its cost is quadratic), got " + std::to_string(scene.circles.size()));
  const ScreenFrame frame(camera);
  const std::vector<Real> points = breakpoints(frame, scene);
  std::vector<VisibleInterval> footprint;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Real middle = (points[i] + points[i + 1]) / 2;
    const int id = nearest_id(frame, scene, middle);
    if (!footprint.empty() && footprint.back().id == id)
      footprint.back().s_end = double(points[i + 1]);
    else
      footprint.push_back(VisibleInterval{double(points[i]), double(points[i + 1]), id});
  }
  return footprint;
}

ExactBar exact_bar(const Camera2D& camera, const Scene2D& scene) {
  ExactBar bar;
  bar.pixels = camera.pixel_count();
  bar.objects = int(scene.circles.size());
  bar.footprint = exact_footprint(camera, scene);
  const int n = bar.pixels;
  const std::size_t slots = std::size_t(bar.objects) + 1;
  bar.coverage.assign(std::size_t(n) * slots, 0.0);
  // Pixel k covers [-1 + 2k/n, -1 + 2(k+1)/n]; its coverage of an interval is the overlap over 2/n.
  const Real pixel_width = Real(2) / n;
  for (const VisibleInterval& interval : bar.footprint) {
    const Real lo = interval.s_begin, hi = interval.s_end;
    const int first = std::max(0, int(std::floor((lo + 1) / pixel_width)));
    const int last = std::min(n - 1, int(std::floor((hi + 1) / pixel_width)));
    const std::size_t slot = interval.id < 0 ? std::size_t(bar.objects) : std::size_t(interval.id);
    for (int k = first; k <= last; ++k) {
      const Real edge_lo = -1 + k * pixel_width, edge_hi = -1 + (k + 1) * pixel_width;
      const Real overlap = std::min(hi, edge_hi) - std::max(lo, edge_lo);
      if (overlap > 0)
        bar.coverage[std::size_t(camera.column_of_pixel(k)) * slots + slot] += double(overlap / pixel_width);
    }
  }
  const ScreenFrame frame(camera);
  bar.centre_ids.assign(std::size_t(n), -1);
  for (int k = 0; k < n; ++k) {
    const Real s = -1 + Real(2 * k + 1) / n;
    bar.centre_ids[std::size_t(camera.column_of_pixel(k))] = nearest_id(frame, scene, s);
  }
  return bar;
}

CoverageImage exact_bar_image(const ExactBar& bar, const Scene2D& scene) {
  CoverageImage image;
  image.width = bar.pixels;
  image.height = 1;
  image.ids = bar.centre_ids;
  image.colours.assign(std::size_t(bar.pixels), glm::dvec3(0.0));
  for (int column = 0; column < bar.pixels; ++column) {
    glm::dvec3 colour(0.0);
    double total = 0.0;
    for (int id = -1; id < bar.objects; ++id) {
      const double w = bar.coverage_of(column, id);
      colour += w * to_dvec3(id < 0 ? scene.background : scene.circles[std::size_t(id)].colour);
      total += w;
    }
    image.colours[std::size_t(column)] = total > 0 ? colour / total : to_dvec3(scene.background);
  }
  return image;
}

}  // namespace raycam
