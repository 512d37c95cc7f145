// The packed scene's clusters (SphereClusters): every sphere once, inside its cluster's bounding sphere, and
// clusters compact; their near-to-far order; and the culling of a cluster out of view, against every
// member's box or its rays, and against the plain loop's ids.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "raycam/ray_caster.h"
#include "core/screen_footprint.h"
#include "test_support.h"

using namespace raycam;

namespace {
Scene3D spheres_in_a_cube(test::Random& random, int count, double spread, double min_radius, double max_radius) {
  Scene3D scene;
  for (int i = 0; i < count; ++i)
    scene.spheres.push_back({{random.uniform(-spread, spread), random.uniform(-spread, spread),
                              random.uniform(-spread, spread)},
                             random.log_uniform(min_radius, max_radius),
                             {std::uint8_t(i), std::uint8_t(i >> 8), 7},
                             ""});
  return scene;
}

glm::dvec3 member_centre(const SphereClusters& c, int j) {
  return {c.x[std::size_t(j)], c.y[std::size_t(j)], c.z[std::size_t(j)]};
}
glm::dvec3 bound_centre(const SphereClusters& c, int k) {
  return {c.bound_x[std::size_t(k)], c.bound_y[std::size_t(k)], c.bound_z[std::size_t(k)]};
}
}  // namespace

TEST_CASE("the clusters hold every sphere once, each inside its cluster's bounding sphere, and are compact",
          "[scene][clusters]") {
  test::Random random(64);
  for (int count : {0, 1, 63, 64, 65, 1000, 20000}) {
    INFO(count << " spheres");
    const Scene3D scene = spheres_in_a_cube(random, count, 10.0, 0.01, 0.05);
    const PackedScene3D packed(scene);
    const SphereClusters& c = packed.clusters;
    REQUIRE(c.size() == count);
    REQUIRE(c.cluster_count() == (count + SphereClusters::kSize - 1) / SphereClusters::kSize);
    std::vector<int> seen(std::size_t(count), 0);
    double mean_bound = 0.0;
    for (int j = 0; j < count; ++j) {
      const int object = c.object[std::size_t(j)];
      REQUIRE(object >= 0);
      REQUIRE(object < count);
      ++seen[std::size_t(object)];
      const Sphere& s = scene.spheres[std::size_t(object)];
      CHECK(member_centre(c, j) == s.centre);  // the same numbers, not recomputed
      CHECK(c.radius[std::size_t(j)] == s.radius);
      const int k = j / SphereClusters::kSize;
      CHECK(glm::length(s.centre - bound_centre(c, k)) + s.radius <= c.bound_radius[std::size_t(k)]);
    }
    CHECK(std::count(seen.begin(), seen.end(), 1) == count);
    for (int k = 0; k < c.cluster_count(); ++k) mean_bound += c.bound_radius[std::size_t(k)] / c.cluster_count();
    // Compact: 64 spheres of a uniform cube of side 20 fill a cube of side ~20·(64/N)^(1/3); its bounding
    // sphere's radius is ~0.87 of that side. A cluster of spheres taken at random would span the whole cube.
    if (count >= 1000) {
      const double side = 20.0 * std::cbrt(double(SphereClusters::kSize) / count);
      INFO("mean bounding radius " << mean_bound << ", a cluster's cube side " << side);
      CHECK(mean_bound < 1.3 * side);
    }
  }
}

TEST_CASE("the clusters' near-to-far order visits each cluster once, the eye's side first", "[scene][clusters]") {
  // Spheres on a line along x, 1 apart: clusters are runs of 64 along it, the nearest the eye's end.
  Scene3D scene;
  const int count = 64 * 20;
  for (int i = 0; i < count; ++i) scene.spheres.push_back({{double((i * 7919) % count), 0.0, 0.0}, 0.1, {}, ""});
  const PackedScene3D packed(scene);
  const SphereClusters& c = packed.clusters;
  for (double eye_x : {-100.0, 2000.0, 640.0}) {
    INFO("eye at x = " << eye_x);
    std::vector<int> order;
    c.near_to_far({eye_x, 5.0, 0.0}, order);
    REQUIRE(int(order.size()) == c.cluster_count());
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> all(order.size());
    std::iota(all.begin(), all.end(), 0);
    CHECK(sorted == all);
    // Distances from the eye to each cluster's centre never fall by more than a cluster's length (64) on
    // the eye's side of the line: the eye's side first, outward.
    int inversions = 0;
    for (std::size_t n = 1; n < order.size(); ++n) {
      const double before = std::abs(c.bound_x[std::size_t(order[n - 1])] - eye_x);
      const double now = std::abs(c.bound_x[std::size_t(order[n])] - eye_x);
      inversions += now < before - 1e-9 && (eye_x < 0 || eye_x > count);
    }
    CHECK(inversions == 0);
    const double first = std::abs(c.bound_x[std::size_t(order.front())] - eye_x);
    for (int k = 0; k < c.cluster_count(); ++k) CHECK(first <= std::abs(c.bound_x[std::size_t(k)] - eye_x) + 64.0);
  }
}

namespace {
// The clusters a part of the split tree holds (a child >= 0 is a split, -1 - k is cluster k).
void clusters_under(const SphereClusters& c, int part, std::vector<int>& out) {
  if (part < 0) {
    out.push_back(-1 - part);
    return;
  }
  clusters_under(c, c.splits[std::size_t(part)].first, out);
  clusters_under(c, c.splits[std::size_t(part)].second, out);
}
}  // namespace

TEST_CASE("every split keeps its first part's centres at or below it and its second part's at or above",
          "[scene][clusters]") {
  // The documented rule (raycam/scene.h) that near_to_far relies on: a centre up to `at` went to `first`,
  // from `at` on to `second`. Random cubes, flat and lined-up scenes (ties on every axis), many sizes.
  test::Random random(3832);
  for (int trial = 0; trial < 24; ++trial) {
    const int count = trial < 8 ? 65 + trial * 37 : random.integer(65, 6000);
    Scene3D scene = spheres_in_a_cube(random, count, trial % 3 == 0 ? 1.0 : 50.0, 0.01, 0.5);
    for (Sphere& s : scene.spheres) {
      if (trial % 4 == 1) s.centre.z = 0.0;                                 // flat
      if (trial % 4 == 2) s.centre = {std::round(s.centre.x), 0.0, 0.0};  // on a line, many equal centres
    }
    INFO("trial " << trial << ", " << count << " spheres");
    const PackedScene3D packed(scene);
    const SphereClusters& c = packed.clusters;
    REQUIRE(!c.splits.empty());
    std::vector<int> seen(std::size_t(c.cluster_count()), 0);
    for (std::size_t n = 0; n < c.splits.size(); ++n) {
      const SphereClusters::Split& split = c.splits[n];
      REQUIRE(split.axis >= 0);
      REQUIRE(split.axis < 3);
      int wrong = 0;
      for (const int side : {0, 1}) {
        std::vector<int> clusters;
        clusters_under(c, side == 0 ? split.first : split.second, clusters);
        for (int k : clusters) {
          if (n == 0) ++seen[std::size_t(k)];
          const int end = std::min(c.size(), (k + 1) * SphereClusters::kSize);
          for (int j = k * SphereClusters::kSize; j < end; ++j) {
            const double centre = member_centre(c, j)[split.axis];
            wrong += side == 0 ? centre > split.at : centre < split.at;
          }
        }
      }
      INFO("split " << n << " along axis " << split.axis << " at " << split.at);
      CHECK(wrong == 0);
    }
    CHECK(std::count(seen.begin(), seen.end(), 1) == c.cluster_count());  // the root's parts hold every cluster once
  }
}

TEST_CASE("a cluster culled as out of view holds no sphere that a pixel's ray hits", "[caster][clusters][vector]") {
  test::Random random(77);
  const int columns = 40, rows = 30;
  int culled_clusters = 0, kept_clusters = 0, loose_boxes = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Camera3D camera(columns, rows);
    camera.set_orbit({{random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2)},
                      random.log_uniform(0.5, 40), random.uniform(-test::kPi, test::kPi),
                      random.uniform(0.05, test::kPi - 0.05), trial % 4 == 0 ? 1e-2 : random.log_uniform(1e-2, 50)});
    // Small and large spheres around the target, the eye and the screen's edges.
    const Scene3D scene = spheres_in_a_cube(random, 3000, camera.orbit().d + 4, 1e-4, 2.0);
    const PackedScene3D packed(scene);
    const SphereClusters& c = packed.clusters;
    for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
      const detail::Footprint footprint(camera, formula);
      CHECK(footprint.culls_clusters() == (formula == IntersectFormula::stable));
      if (!footprint.culls_clusters()) continue;
      std::vector<unsigned char> out(std::size_t(c.cluster_count()));
      footprint.clusters_out_of_view({c.bound_x.data(), c.bound_y.data(), c.bound_z.data(), c.bound_radius.data()},
                                     c.cluster_count(), out.data());
      std::vector<detail::PixelBox> boxes(std::size_t(c.size()));
      footprint.sphere_boxes({c.x.data(), c.y.data(), c.z.data(), c.radius.data()}, c.size(), rows, columns,
                             boxes.data());
      for (int k = 0; k < c.cluster_count(); ++k) {
        (out[std::size_t(k)] ? culled_clusters : kept_clusters) += 1;
        if (!out[std::size_t(k)]) continue;
        for (int j = k * SphereClusters::kSize; j < std::min(c.size(), (k + 1) * SphereClusters::kSize); ++j) {
          // A sphere across the eye's plane gets the whole image as its box (a loose bound): then every
          // pixel's ray is tried.
          if (boxes[std::size_t(j)].empty()) continue;
          ++loose_boxes;
          for (int row = 0; row < rows; ++row)
            for (int column = 0; column < columns; ++column) {
              const Ray3D ray = camera.primary_ray(row, column);
              INFO("trial " << trial << ", cluster " << k << ", sphere " << c.object[std::size_t(j)] << ", pixel "
                            << row << ", " << column);
              CHECK(nearest_hit_t(ray.origin, ray.direction, member_centre(c, j), c.radius[std::size_t(j)],
                                  formula) == kNoHit<double>);
            }
        }
      }
    }
    // And the cast: the plain loop's ids with the clusters culled.
    Camera3D small(columns / 2, rows / 2);
    small.set_orbit(camera.orbit());
    CastOptions plain, fast;
    plain.method = CastMethod::plain;
    fast.threads = 2;
    const ColourMap want = cast_primary_rays(small, scene, plain), got = cast_primary_rays(small, scene, fast);
    INFO("trial " << trial);
    CHECK(want.ids == got.ids);
  }
  // Enough of both to mean something.
  CHECK(culled_clusters > 200);
  CHECK(kept_clusters > 200);
  CHECK(loose_boxes > 0);  // spheres across the eye's plane were among the culled, and tried ray by ray
}
