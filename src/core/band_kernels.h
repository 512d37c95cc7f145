// The accelerated 3D caster's inner loops over a band of rows, written to vectorise (vector_loops.h): the
// band's rays made as columns, and one sphere tested against a run of them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "raycam/camera3d.h"
#include "raycam/intersect.h"

namespace raycam::detail {

// A band of pixels, row after row: its rays as columns (pixel p's ray starts at (ox, oy, oz)[p] with unit
// direction (dx, dy, dz)[p]) and its depth buffer: the nearest t so far, that object's index (-1: none),
// and whether any object's box covers the pixel; and the tests pending on it (run_pending_tests).
// Tests of short box rows waiting to run together: (pixel, sphere) pairs, their rays and spheres copied
// into columns so that one vectorised loop runs them. Alone, a 1–3 pixel row is a chain of dependent
// scalar steps (a square root, a division) and a branch or two; at 10⁵ spheres most rows are such.
struct PendingTests {
  static constexpr int kCapacity = 128;  // its columns (11 KB) stay in L1 beside the band's rays
  alignas(64) double ox[kCapacity], oy[kCapacity], oz[kCapacity], dx[kCapacity], dy[kCapacity], dz[kCapacity];
  alignas(64) double cx[kCapacity], cy[kCapacity], cz[kCapacity], radius[kCapacity], t[kCapacity];
  int pixel[kCapacity], object[kCapacity];
  int count = 0;
};

struct BandPixels {
  std::vector<double> ox, oy, oz, dx, dy, dz;
  std::vector<double> depth;
  std::vector<int> id;
  std::vector<unsigned char> covered;
  PendingTests pending;
  void reset(std::size_t pixels);  // nothing seen, nothing covered, nothing pending (the rays are left to make_row_rays)
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
// loop, so that only its own arithmetic is in it. With nearest_hit_t written without branches, a ray that
// misses costs no mispredicted branch, and a row of them vectorises.
// Both sides evaluated, no short circuit: the loops that store its answer's selects stay branch-free (below).
inline bool nearer_hit(double t, int object, double depth, int id) { return (t < depth) | ((t == depth) & (object < id)); }

template <IntersectFormula kFormula>
inline void test_pixel(const glm::dvec3& centre, double radius, int object, std::size_t p, const double* ox,
                       const double* oy, const double* oz, const double* dx, const double* dy, const double* dz,
                       double* depth, int* id, unsigned char* covered) {
  const double t = nearest_hit_t(glm::dvec3(ox[p], oy[p], oz[p]), glm::dvec3(dx[p], dy[p], dz[p]), centre, radius,
                                 kFormula);
  // Stores of selects of locals, and nearer_hit without a short circuit: with `||` and `&&` LLVM made the two
  // stores conditional, which WebAssembly (no masked store) runs as a branch per lane, a coin toss where the
  // sphere's silhouette crosses the row (the page's cast of radii ×20 at K = 10³: 1.03 -> 0.84 ms, in Node).
  const double held = depth[p];
  const int held_id = id[p];
  const bool nearer = nearer_hit(t, object, held, held_id);
  depth[p] = nearer ? t : held;
  id[p] = nearer ? object : held_id;
  covered[p] = 1;
}

// Runs the pending tests (vectorised: the same nearest_hit_t, so the same t) and applies them to the depth
// buffer with nearer_hit, whose answer does not depend on the order of the tests.
void run_pending_tests(IntersectFormula formula, BandPixels& band);

// Queues a short row's tests (the pixels that could still change), running the queue when it is full.
// Returns the tests queued.
inline int queue_row_tests(const glm::dvec3& centre, double radius, double nearest_t, int object, std::size_t at,
                            int count, IntersectFormula formula, BandPixels& band) {
  PendingTests& q = band.pending;
  if (q.count + count > PendingTests::kCapacity) run_pending_tests(formula, band);
  const int before = q.count;
  // Locals: the byte stores to `covered` may alias anything, and made the compiler reload every column's
  // address and the count at each pixel.
  const double *ox = band.ox.data(), *oy = band.oy.data(), *oz = band.oz.data(), *dx = band.dx.data(),
               *dy = band.dy.data(), *dz = band.dz.data(), *depth = band.depth.data();
  unsigned char* covered = band.covered.data();
  int i = before;
  for (std::size_t p = at; p < at + std::size_t(count); ++p) {
    q.ox[i] = ox[p];
    q.oy[i] = oy[p];
    q.oz[i] = oz[p];
    q.dx[i] = dx[p];
    q.dy[i] = dy[p];
    q.dz[i] = dz[p];
    q.cx[i] = centre.x;
    q.cy[i] = centre.y;
    q.cz[i] = centre.z;
    q.radius[i] = radius;
    q.pixel[i] = int(p);
    q.object[i] = object;
    i += depth[p] >= nearest_t;  // written always, kept only if the pixel could change
    covered[p] = 1;
  }
  q.count = i;
  return i - before;
}

// Runs of at least kVectorRun pixels a row: each row's tests vectorised in place (as many pixels at once as a
// vector holds doubles), with the same nearest_hit_t, so the same t. Shorter rows are queued: a row of 4 to 15
// is mostly a vector's set-up and a masked tail. The threshold was measured with `bench speed`'s families
// (4, 16 and 64: 16 best; the grazing layer at K = 10⁵, 1024²: 10.1, 7.1 and 7.7 ms).
inline constexpr int kVectorRun = 16;
void test_sphere_vectorised(const glm::dvec3& centre, double radius, int object, IntersectFormula formula,
                            const PixelRun& run, BandPixels& band);

// A lower bound kept as a float (half the bytes): at or below d, never above. d less 2⁻²² of itself (four
// times a float's rounding) and a float's least normal (for d near 0), then rounded to the nearest float;
// -∞ stays -∞. For |d| up to 10³⁰, far beyond any bound of a scene (kMaxCoordinate).
inline float float_below(double d) { return float(d - std::abs(d) * 0x1p-22 - 0x1p-126); }

// Whether any of a row's `count` pixels has its hit so far at nearest_t or beyond: only those can take an
// object no ray reaches before nearest_t (a tie at nearest_t may still win on its index).
inline bool row_can_change(const double* depth, int count, double nearest_t) {
  bool open = false;
  for (int i = 0; i < count; ++i) open |= depth[i] >= nearest_t;
  return open;
}

// What the casters call, row by row: a row whose pixels all hold a hit nearer than nearest_t (the sphere's
// bound, -∞ for none) is skipped; the others get the vectorised rows for runs of kVectorRun pixels or more,
// else join the pending tests (run_pending_tests must run before the band's depth buffer is read). Returns
// the tests run or queued.
inline long long test_sphere(const glm::dvec3& centre, double radius, double nearest_t, int object,
                             IntersectFormula formula, const PixelRun& run, BandPixels& band) {
  long long tests = 0;
  for (int row = 0; row < run.rows; ++row) {
    const PixelRun one{run.at + std::size_t(row) * std::size_t(run.stride), run.count, 1, run.stride};
    if (!row_can_change(&band.depth[one.at], one.count, nearest_t)) continue;
    if (one.count >= kVectorRun) {
      test_sphere_vectorised(centre, radius, object, formula, one, band);
      tests += one.count;
    } else {
      tests += queue_row_tests(centre, radius, nearest_t, object, one.at, one.count, formula, band);
    }
  }
  return tests;
}

}  // namespace raycam::detail
