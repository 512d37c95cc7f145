// Ray / ball intersection against analytic roots, and the naive and stable formulas against each other.
#include <catch2/catch.hpp>
#include <cmath>

#include "raycam/intersect.h"
#include "test_support.h"

using namespace raycam;

TEST_CASE("a ray through the centre hits at distance - radius", "[intersect][analytic]") {
  for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
    const glm::dvec3 origin{0, 0, 10}, down{0, 0, -1};
    CHECK(nearest_hit_t<3>(origin, down, glm::dvec3(0.0), 2.0, formula) == Approx(8.0));
    // Moving away from the ball: no hit.
    CHECK(nearest_hit_t<3>(origin, -down, glm::dvec3(0.0), 2.0, formula) == kNoHit<double>);
    // Starting inside: the far side.
    CHECK(nearest_hit_t<3>(glm::dvec3(0, 0, 1), down, glm::dvec3(0.0), 2.0, formula) == Approx(3.0));
    // Offset by h from the centre line: t = L - sqrt(r² - h²).
    const double h = 1.2;
    CHECK(nearest_hit_t<2>(glm::dvec2(h, 10), glm::dvec2(0, -1), glm::dvec2(0.0), 2.0, formula) ==
          Approx(10.0 - std::sqrt(4.0 - h * h)));
    // Just outside: a miss.
    CHECK(nearest_hit_t<2>(glm::dvec2(2.0000001, 10), glm::dvec2(0, -1), glm::dvec2(0.0), 2.0, formula) ==
          kNoHit<double>);
  }
}

TEST_CASE("stable and naive formulas agree on ordinary rays", "[intersect]") {
  test::Random random(12);
  for (int trial = 0; trial < 20000; ++trial) {
    const glm::dvec3 origin{random.uniform(-10, 10), random.uniform(-10, 10), random.uniform(-10, 10)};
    const glm::dvec3 direction =
        glm::normalize(glm::dvec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)));
    const glm::dvec3 centre{random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3)};
    const double radius = random.uniform(0.1, 3);
    const double a = nearest_hit_t<3>(origin, direction, centre, radius, IntersectFormula::stable);
    const double b = nearest_hit_t<3>(origin, direction, centre, radius, IntersectFormula::naive);
    if (test::grazes<3>(origin, direction, centre, radius, 1e-7)) continue;
    REQUIRE((a == kNoHit<double>) == (b == kNoHit<double>));
    if (a != kNoHit<double>) {
      CHECK(a == Approx(b).epsilon(1e-9).margin(1e-9));
      // The hit point lies on the sphere.
      CHECK(glm::length(origin + a * direction - centre) == Approx(radius).epsilon(1e-9));
    }
  }
}

TEST_CASE("far away, the stable formula keeps the hit point on the sphere where the naive one does not",
          "[intersect][precision]") {
  // A unit sphere seen from 1e7 in float: b² ≈ c, so b² - c cancels in the naive formula.
  const glm::vec3 origin{0.0f, 0.0f, 1e4f}, down{0.0f, 0.0f, -1.0f};
  const float h = 0.9f;  // offset from the centre line
  const glm::vec3 offset_origin = origin + glm::vec3(h, 0.0f, 0.0f);
  const float exact = 1e4f - std::sqrt(1.0f - h * h);
  const float stable = nearest_hit_t<3>(offset_origin, down, glm::vec3(0.0f), 1.0f, IntersectFormula::stable);
  const float naive = nearest_hit_t<3>(offset_origin, down, glm::vec3(0.0f), 1.0f, IntersectFormula::naive);
  CHECK(std::abs(stable - exact) <= 1e-3f);
  // The naive discriminant b² - c = 1e8 - (1e8 - 0.19) is lost in float: it misses or lands far off.
  CHECK((naive == kNoHit<float> || std::abs(naive - exact) > 1e-2f));
}
