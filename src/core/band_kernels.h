// The accelerated 3D caster's inner loops over a band of rows, written to vectorise (vector_loops.h): the
// band's rays made as columns, and one sphere tested against a run of them.
#pragma once

#include <cstddef>
#include <vector>

#include "raycam/camera3d.h"
#include "raycam/intersect.h"

namespace raycam::detail {

// A band of pixels, row after row: its rays as columns (pixel p's ray starts at (ox, oy, oz)[p] with unit
// direction (dx, dy, dz)[p]) and its depth buffer: the nearest t so far, that object's index (-1: none),
// and whether any object's box covers the pixel.
struct BandPixels {
  std::vector<double> ox, oy, oz, dx, dy, dz;
  std::vector<double> depth;
  std::vector<int> id;
  std::vector<unsigned char> covered;
  void reset(std::size_t pixels);  // nothing seen, nothing covered (the rays are left to make_row_rays)
};

// The rays of columns first…last of a row into the band's pixels row_at + first … row_at + last: column c's
// from column_x[c], its canonical x (Camera3D::canonical_x, computed once a cast), so exactly the rays of
// Camera3D::primary_rays (the same ray_on_line on the same numbers), for a camera whose classic mistakes,
// if any, only move it (the only cameras the accelerated casters see).
void make_row_rays(const Camera3D& camera, int row, int first, int last, const std::vector<double>& column_x,
                   BandPixels& band, std::size_t row_at);

// A run of pixels in a band: `count` pixels from `at` on each of `rows` rows, `stride` apart.
struct PixelRun {
  std::size_t at;
  int count, rows, stride;
};

// One sphere against a run of the band's pixels: the plain loop's nearest_hit_t, and a depth test that
// gives the plain loop's answer whatever order the objects come in (nearer_hit: the smaller t, and on a tie
// the lower index, which the plain loop's strict '<' in index order keeps). kFormula is fixed for the whole
// loop, so that only its own arithmetic is in it. Scalar and inline, for runs shorter than kVectorRun: at
// 10⁵ spheres most boxes are one to three pixels wide, where a vectorised row (a call, a vector's set-up)
// costs more than its tests. With nearest_hit_t written without branches, a ray that misses costs no
// mispredicted branch.
inline bool nearer_hit(double t, int object, double depth, int id) { return t < depth || (t == depth && object < id); }

template <IntersectFormula kFormula>
inline void test_pixel(const glm::dvec3& centre, double radius, int object, std::size_t p, const double* ox,
                       const double* oy, const double* oz, const double* dx, const double* dy, const double* dz,
                       double* depth, int* id, unsigned char* covered) {
  const double t = nearest_hit_t(glm::dvec3(ox[p], oy[p], oz[p]), glm::dvec3(dx[p], dy[p], dz[p]), centre, radius,
                                 kFormula);
  const bool nearer = nearer_hit(t, object, depth[p], id[p]);
  depth[p] = nearer ? t : depth[p];
  id[p] = nearer ? object : id[p];
  covered[p] = 1;
}

template <IntersectFormula kFormula>
inline void test_sphere_scalar(const glm::dvec3& centre, double radius, int object, const PixelRun& run,
                               BandPixels& band) {
  for (int row = 0; row < run.rows; ++row) {
    const std::size_t begin = run.at + std::size_t(row) * std::size_t(run.stride), end = begin + std::size_t(run.count);
    for (std::size_t p = begin; p < end; ++p)
      test_pixel<kFormula>(centre, radius, object, p, band.ox.data(), band.oy.data(), band.oz.data(), band.dx.data(),
                           band.dy.data(), band.dz.data(), band.depth.data(), band.id.data(), band.covered.data());
  }
}

// The same for runs of at least kVectorRun pixels a row: each row's tests vectorised (as many pixels at once
// as a vector holds doubles), with the same nearest_hit_t, so the same t. The threshold was measured with
// `bench speed` (4, 8 and 16: 4 best at K = 10⁵, 8 or less 20 % faster than 16 at K = 1000, 1024²).
inline constexpr int kVectorRun = 4;
void test_sphere_vectorised(const glm::dvec3& centre, double radius, int object, IntersectFormula formula,
                            const PixelRun& run, BandPixels& band);

// Whether any of a row's `count` pixels has its hit so far at nearest_t or beyond: only those can take an
// object no ray reaches before nearest_t (a tie at nearest_t may still win on its index).
inline bool row_can_change(const double* depth, int count, double nearest_t) {
  bool open = false;
  for (int i = 0; i < count; ++i) open |= depth[i] >= nearest_t;
  return open;
}

// What the casters call, row by row: a row whose pixels all hold a hit nearer than nearest_t (the sphere's
// bound, -∞ for none) is skipped; the others get the vectorised rows for runs of kVectorRun pixels or more,
// else the scalar loop. Returns the tests run.
inline long long test_sphere(const glm::dvec3& centre, double radius, double nearest_t, int object,
                             IntersectFormula formula, const PixelRun& run, BandPixels& band) {
  long long tests = 0;
  for (int row = 0; row < run.rows; ++row) {
    const PixelRun one{run.at + std::size_t(row) * std::size_t(run.stride), run.count, 1, run.stride};
    if (!row_can_change(&band.depth[one.at], one.count, nearest_t)) continue;
    tests += one.count;
    if (one.count >= kVectorRun) test_sphere_vectorised(centre, radius, object, formula, one, band);
    else if (formula == IntersectFormula::naive) test_sphere_scalar<IntersectFormula::naive>(centre, radius, object, one, band);
    else test_sphere_scalar<IntersectFormula::stable>(centre, radius, object, one, band);
  }
  return tests;
}

}  // namespace raycam::detail
