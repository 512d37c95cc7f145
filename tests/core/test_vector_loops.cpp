// The loops rewritten for speed against independent forms: nearest_hit_t without branches
// against the textbook early-return form, bit for bit; the vectorised projection against the pixels whose
// rays actually hit; a band's ray columns against the camera's own primary rays, bit for bit.
#include <catch2/catch.hpp>
#include <random>


#include "core/band_kernels.h"
#include "raycam/ray_caster.h"
#include "core/screen_footprint.h"
#include "test_support.h"

using namespace raycam;

namespace {
// The early-return form nearest_hit_t had before it was written without branches (the reference here).
template <class T>
T textbook_nearest_hit_t(const glm::vec<3, T>& origin, const glm::vec<3, T>& u, const glm::vec<3, T>& centre,
                         T radius, IntersectFormula formula) {
  const glm::vec<3, T> f = origin - centre;
  const T b = glm::dot(f, u);
  const T c = glm::dot(f, f) - radius * radius;
  if (c > T(0) && b > T(0)) return kNoHit<T>;
  T t_near, t_far;
  if (formula == IntersectFormula::naive) {
    const T disc = b * b - c;
    if (disc < T(0)) return kNoHit<T>;
    t_near = -b - std::sqrt(disc);
    t_far = -b + std::sqrt(disc);
  } else {
    const glm::vec<3, T> perpendicular = f - b * u;
    const T disc = radius * radius - glm::dot(perpendicular, perpendicular);
    if (disc < T(0)) return kNoHit<T>;
    const T q = -b - std::copysign(std::sqrt(disc), b);
    if (q == T(0)) return T(0);
    const T t_other = c / q;
    t_near = q < t_other ? q : t_other;
    t_far = q < t_other ? t_other : q;
  }
  if (t_near >= T(0)) return t_near;
  if (t_far >= T(0)) return t_far;
  return kNoHit<T>;
}

// The same value, the sign of a zero included (long double's padding bytes are not part of its value).
template <class T>
bool same_bits(T a, T b) {
  return (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
}

template <class T>
void check_against_textbook(test::Random& random, IntersectFormula formula) {
  using V = glm::vec<3, T>;
  int mismatches = 0, hits = 0;
  const auto check = [&](const V& origin, const V& u, const V& centre, T radius) {
    const T t = nearest_hit_t(origin, u, centre, radius, formula);
    const T expected = textbook_nearest_hit_t(origin, u, centre, radius, formula);
    mismatches += !same_bits(t, expected);
    hits += t < kNoHit<T>;
  };
  for (int i = 0; i < 20000; ++i) {
    const V centre(T(random.uniform(-5, 5)), T(random.uniform(-5, 5)), T(random.uniform(-5, 5)));
    const T radius = T(random.log_uniform(1e-3, 4));
    // Origins inside, on and outside the ball; rays towards the centre, grazing and away.
    const V offset(T(random.uniform(-1, 1)), T(random.uniform(-1, 1)), T(random.uniform(-1, 1)));
    const V origin = centre + offset * T(random.log_uniform(1e-3, 20));
    V aim = centre - origin + V(T(random.uniform(-1, 1)), T(random.uniform(-1, 1)), T(random.uniform(-1, 1))) * radius;
    if (i % 7 == 0) aim = -aim;
    if (glm::dot(aim, aim) == T(0)) continue;
    check(origin, glm::normalize(aim), centre, radius);
  }
  // Exact cases: the origin on the sphere with a tangent direction (q = 0), the origin at the centre, a ray
  // through the centre from outside, one leaving from the surface.
  const V centre(T(1), T(2), T(3));
  check(centre + V(T(2), T(0), T(0)), V(T(0), T(1), T(0)), centre, T(2));
  check(centre, V(T(0), T(0), T(1)), centre, T(2));
  check(centre + V(T(0), T(0), T(5)), V(T(0), T(0), T(-1)), centre, T(2));
  check(centre + V(T(0), T(0), T(2)), V(T(0), T(0), T(1)), centre, T(2));
  check(centre + V(T(0), T(0), T(2)), V(T(0), T(0), T(-1)), centre, T(2));
  CHECK(mismatches == 0);
  CHECK(hits > 5000);  // the random rays hit often enough to test the roots, and miss often enough
  CHECK(hits < 19000);
}

Camera3D random_camera(test::Random& random, int columns, int rows) {
  Camera3D camera(columns, rows);
  camera.set_orbit({{random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2)},
                    random.log_uniform(0.5, 40), random.uniform(-test::kPi, test::kPi),
                    random.uniform(0.05, test::kPi - 0.05), random.log_uniform(0.2, 5)});
  return camera;
}
}  // namespace

TEST_CASE("nearest_hit_t without branches returns the early-return form's t, bit for bit",
          "[intersect][vector]") {
  test::Random random(14);
  for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
    check_against_textbook<double>(random, formula);
    check_against_textbook<float>(random, formula);
    check_against_textbook<long double>(random, formula);
  }
}

TEST_CASE("the vectorised projection's boxes hold every pixel a sphere's rays hit, and little more",
          "[caster][vector]") {
  test::Random random(1414);
  const int columns = 48, rows = 36;
  int tight_checks = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Camera3D camera = random_camera(random, columns, rows);
    for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
      const detail::Footprint footprint(camera, formula);
      // Spheres around the target and the eye: in view, behind the screen, around the eye, tiny and huge.
      std::vector<double> x, y, z, radius;
      for (int i = 0; i < 301; ++i) {  // not a multiple of a vector's width: the loop's tail runs too
        const glm::dvec3 around = i % 5 == 0 ? camera.eye() : camera.orbit().target;
        const double spread = camera.orbit().d;
        x.push_back(around.x + random.uniform(-spread, spread));
        y.push_back(around.y + random.uniform(-spread, spread));
        z.push_back(around.z + random.uniform(-spread, spread));
        radius.push_back(random.log_uniform(1e-3, spread));
      }
      std::vector<detail::PixelBox> boxes(x.size());
      footprint.sphere_boxes({x.data(), y.data(), z.data(), radius.data()}, int(x.size()), rows, columns, boxes.data());
      int loose = 0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        const Sphere sphere{{x[i], y[i], z[i]}, radius[i], {}, ""};
        const detail::PixelBox& box = boxes[i];
        const detail::PixelBox alone = footprint.sphere_pixels(sphere, rows, columns);
        CHECK((box.empty() == alone.empty() && (box.empty() || (box.rows.first == alone.rows.first &&
               box.rows.last == alone.rows.last && box.columns.first == alone.columns.first &&
               box.columns.last == alone.columns.last))));
        // The pixels whose rays hit, found by brute force.
        detail::PixelBox hit{{rows, -1}, {columns, -1}};
        for (int row = 0; row < rows; ++row)
          for (int column = 0; column < columns; ++column) {
            const Ray3D ray = camera.primary_ray(row, column);
            if (nearest_hit_t(ray.origin, ray.direction, sphere.centre, sphere.radius, formula) == kNoHit<double>)
              continue;
            const bool inside = !box.empty() && row >= box.rows.first && row <= box.rows.last &&
                                column >= box.columns.first && column <= box.columns.last;
            CHECK(inside);
            hit.rows = {std::min(hit.rows.first, row), std::max(hit.rows.last, row)};
            hit.columns = {std::min(hit.columns.first, column), std::max(hit.columns.last, column)};
          }
        // Little more: a box reaches at most two pixels past the hit pixels (its edge pixel, and the slack),
        // for a sphere wholly beyond the screen whose box the image's edges do not cut. (One across the
        // screen's plane is bounded by its whole tangent cone, of which the rays, starting on the screen,
        // see only the far part; and the image's edges cut each axis's range, not the ellipse.)
        const double depth = glm::dot(sphere.centre - camera.eye(), camera.view_direction());
        if (box.empty() || depth - sphere.radius < 1.01 * camera.orbit().df) continue;
        if (box.rows.first == 0 || box.rows.last == rows - 1 || box.columns.first == 0 || box.columns.last == columns - 1)
          continue;
        const int slack_rows = hit.rows.empty() ? box.rows.last - box.rows.first + 1
                                                : std::max(hit.rows.first - box.rows.first, box.rows.last - hit.rows.last);
        const int slack_columns = hit.columns.empty() ? box.columns.last - box.columns.first + 1
                                                      : std::max(hit.columns.first - box.columns.first,
                                                                 box.columns.last - hit.columns.last);
        loose += slack_rows > 2 || slack_columns > 2;
        ++tight_checks;
      }
      CHECK(loose == 0);
    }
  }
  CHECK(tight_checks > 200);  // enough spheres wholly in view to mean something
}

TEST_CASE("a band's ray columns are the camera's primary rays, bit for bit", "[caster][vector]") {
  test::Random random(4141);
  for (int trial = 0; trial < 40; ++trial) {
    const int columns = random.integer(1, 70), rows = random.integer(1, 20);
    Camera3D camera = random_camera(random, columns, rows);
    ClassicMistakes placement_only;  // the mistakes the accelerated casters still serve
    placement_only.printed_rotation_sign = trial % 3 == 1;
    placement_only.no_focal_scale = trial % 4 == 2;
    camera.set_mistakes(placement_only);
    std::vector<double> column_x(std::size_t(camera.columns()));
    for (int c = 0; c < camera.columns(); ++c) column_x[std::size_t(c)] = camera.canonical_x(c);
    detail::BandPixels band;
    band.reset(std::size_t(camera.columns()));
    const int row = random.integer(0, camera.rows() - 1);
    const int first = random.integer(0, camera.columns() - 1), last = random.integer(first, camera.columns() - 1);
    detail::make_row_rays(camera, row, first, last, column_x, band, 0);
    std::vector<Ray3D> rays(std::size_t(last - first + 1));
    camera.primary_rays(row, first, last, rays.data());
    int differing = 0;
    for (int c = first; c <= last; ++c) {
      const Ray3D& ray = rays[std::size_t(c - first)];
      const std::size_t p = std::size_t(c);
      differing += !(same_bits(band.ox[p], ray.origin.x) && same_bits(band.oy[p], ray.origin.y) &&
                     same_bits(band.oz[p], ray.origin.z) && same_bits(band.dx[p], ray.direction.x) &&
                     same_bits(band.dy[p], ray.direction.y) && same_bits(band.dz[p], ray.direction.z));
    }
    CHECK(differing == 0);
  }
}

// The depth test the casters run in any object order (near to far): a tie keeps the lower index whichever
// comes first, as the plain loop's strict '<' in index order does; a row whose hit is nearer than a
// sphere's bound is skipped (no test, no change).
TEST_CASE("a band's depth test keeps the lower index on a tie in any order, and skips what is hidden",
          "[caster][vector]") {
  for (int count : {1, detail::kVectorRun + 1}) {  // the scalar and the vectorised rows
    INFO(count << " pixels a row");
    detail::BandPixels band;
    band.reset(std::size_t(count));
    for (int p = 0; p < count; ++p) {  // rays along -z from z = 10, 0.01 apart in x
      band.ox[std::size_t(p)] = 0.01 * p;
      band.oy[std::size_t(p)] = band.dx[std::size_t(p)] = band.dy[std::size_t(p)] = 0.0;
      band.oz[std::size_t(p)] = 10.0;
      band.dz[std::size_t(p)] = -1.0;
    }
    const detail::PixelRun run{0, count, 1, count};
    const glm::dvec3 centre{0.0, 0.0, 0.0};
    const double none = -kNoHit<double>;  // no bound: always tested
    CHECK(detail::test_sphere(centre, 1.0, none, 7, IntersectFormula::stable, run, band) == count);
    CHECK(detail::test_sphere(centre, 1.0, none, 3, IntersectFormula::stable, run, band) == count);  // the same sphere
    CHECK(detail::test_sphere(centre, 1.0, none, 5, IntersectFormula::stable, run, band) == count);
    detail::run_pending_tests(IntersectFormula::stable, band);  // short rows' tests wait in a queue
    for (int p = 0; p < count; ++p) CHECK(band.id[std::size_t(p)] == 3);
    const double hit = band.depth[0];
    CHECK(hit == Approx(9.0).margin(1e-3));
    // A bigger sphere behind, whose bound says it cannot be nearer than 9.5: skipped, nothing changes.
    CHECK(detail::test_sphere({0.0, 0.0, -5.0}, 4.0, 9.5, 0, IntersectFormula::stable, run, band) == 0);
    // The same sphere with a bound at the hit itself: tested (a tie there could still win on its index).
    CHECK(detail::test_sphere({0.0, 0.0, -5.0}, 4.0, hit, 0, IntersectFormula::stable, run, band) == count);
    detail::run_pending_tests(IntersectFormula::stable, band);
    for (int p = 0; p < count; ++p) CHECK(band.id[std::size_t(p)] == 3);
  }
}

// The candidates keep their near bound as a float: rounded to the nearest, it would land above the double
// half the time, and a pixel whose hit is just nearer than the bound but not than the float would skip a
// sphere that wins it.
TEST_CASE("a bound kept as a float is never above the double it came from, and close to it", "[caster][vector]") {
  std::mt19937_64 random(24);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-140, 120);
  int below = 0;
  for (int i = 0; i < 200000; ++i) {
    const double d = std::ldexp(mantissa(random), exponent(random));
    const double kept = detail::float_below(d);
    INFO(d);
    REQUIRE(kept <= d);
    REQUIRE(d - kept <= std::abs(d) * 0x1p-20 + 0x1p-125);
    below += kept < double(float(d));  // where rounding to the nearest would have gone above
  }
  CHECK(below > 1000);
  CHECK(detail::float_below(-kNoHit<double>) == -kNoHit<float>);
  CHECK(detail::float_below(0.0) <= 0.0);
  CHECK(detail::float_below(1e13) <= 1e13);
}
