// Footprint::spheres_maybe_seen: a first, cheap pass in single precision that drops the spheres whose
// double-precision box (sphere_boxes) would be empty, four a vector where WebAssembly's SIMD holds two
// doubles. It may keep a sphere the double box then culls; it must never drop one the double box keeps.
//
// Why its verdict is safe (the test cross-checks it, tests/core/test_float_culling.cpp, where a growth of
// 2⁻²³ still passed and 2⁻²⁴ did not):
// - The sphere is grown first, by 2⁻¹⁵ of its radius and of the numbers' size (the centre's distance |q|₁
//   from the eye plus the eye's own size). The float centre (a, b, c) along the camera's axes is within
//   ~12·2⁻²⁴ of that size of the exact one (a few roundings of numbers that size), so the grown sphere about
//   it holds the exact sphere with 40 times room to spare.
// - What the growth adds to the slopes covers the rest. A tangent of slope m from the eye moves by at least
//   (1 + m²)/|q| per unit of radius (the distance of the line y = m·x from the centre (c, a) changes by
//   |c + a·m|/(1 + m²)^(3/2) ≤ |q|/(1 + m²) per unit of slope), so by about 2⁻¹⁵·(1 + m²): far more than the
//   double box's own slack (at most ~10⁻⁸ as a slope, screen_footprint.cpp) and than the float arithmetic
//   after the growth: each step a product, quotient or sum of numbers of one sign, or a difference computed
//   as a product of differences, about 10 roundings of 2⁻²⁴ relative to |m0| + half, which the bound below
//   keeps within 8 times the true slopes (6 times room). The mapping to pixel indices rounds four times more:
//   kIndexRoom, twice that, widens the index range.
// - The tangent slopes need a square root per axis; a bound on them does not: with c the depth, a the
//   offset along one axis and r the radius, the tangents m± = (a·c ± r·√(a² + c² - r²)) / (c² - r²) differ
//   from a/c by r·|a·r ± c·√(…)| / (c·(c² - r²)) ≤ r·(|a|·(r + c) + c²) / (c·(c² - r²)) (as √(a² + c²) ≤
//   |a| + c): one division for both axes, a box at most √2 wider than the exact one for a small sphere, and
//   at most 8 times under the guard below.
// - Only where that holds comfortably: the grown sphere wholly in front of the eye (c - r > (c + r)/64, so
//   no difference loses more than six bits) and the numbers' size below 2⁴⁰ (no overflow); otherwise, or on
//   a NaN, the sphere is kept. Only for the stable formula and d_f ≥ 10⁻² (Footprint::culls_clusters): the
//   naive formula's slack grows without bound as a radius shrinks.
#include "core/screen_footprint.h"

#include <cmath>

#include "core/vector_loops.h"

namespace raycam::detail {

namespace {
constexpr float kGrowth = 0x1p-15f;     // of the radius and of the numbers' size
constexpr float kIndexRoom = 0x1p-20f;  // of the indices' size: the four roundings mapping slopes to pixels
constexpr float kLargest = 0x1p40f;     // numbers' size beyond which nothing is culled

// True when no pixel centre of an axis of `count` pixels lies in the slope interval m0 ± half (screen
// coordinate sign·d_f·m): the pixel-index interval holds no whole number in [0, count - 1]. False on a NaN.
inline bool misses_every_centre(float m0, float half, float signed_df, float count) {
  const float half_count = 0.5f * count;
  const float i0 = (signed_df * (m0 - half) + 1.0f) * half_count - 0.5f;
  const float i1 = (signed_df * (m0 + half) + 1.0f) * half_count - 0.5f;
  const float room = kIndexRoom * (std::abs(i0) + std::abs(i1) + count);
  const float first = higher(std::ceil(lower(i0, i1) - room), 0.0f);
  const float last = lower(std::floor(higher(i0, i1) + room), count - 1.0f);
  return first > last;
}

// The float frame: what the loop reads, by value (the flags' stores could alias a reference's fields).
struct FloatFrame {
  float ex, ey, ez, rx, ry, rz, ux, uy, uz, fx, fy, fz, df, size_of_eye, rows, columns;
};

// Branch-free and with no early exit, so that it vectorises; the survivors are gathered after.
RAYCAM_VECTOR_LOOP void flag_unseen(const FloatFrame f, const float* x, const float* y, const float* z,
                                    const float* radius, int count, unsigned char* unseen) {
  for (int i = 0; i < count; ++i) {
    const float qx = x[i] - f.ex, qy = y[i] - f.ey, qz = z[i] - f.ez;
    const float a = qx * f.rx + qy * f.ry + qz * f.rz, b = qx * f.ux + qy * f.uy + qz * f.uz;
    const float c = qx * f.fx + qy * f.fy + qz * f.fz;
    const float size = std::abs(qx) + std::abs(qy) + std::abs(qz) + f.size_of_eye;
    const float r = radius[i] * (1.0f + kGrowth) + kGrowth * size;
    const float near = c - r, far = c + r;
    // Wholly between the eye and the screen: no ray (from the screen on) reaches it.
    const bool behind = far < f.df * (1.0f - kGrowth);
    const bool bounded = (near > far * (1.0f / 64.0f)) & (size < kLargest);
    const float room = near * far;  // c² - r²
    const float scale = 1.0f / (c * room);
    const float spread = r * scale, c2 = c * c;
    const bool off_columns = misses_every_centre(a * room * scale, spread * (std::abs(a) * far + c2), f.df, f.columns);
    const bool off_rows = misses_every_centre(b * room * scale, spread * (std::abs(b) * far + c2), -f.df, f.rows);
    unseen[i] = behind | (bounded & (off_columns | off_rows));
  }
}
}  // namespace

int Footprint::spheres_maybe_seen(const FloatSphereColumns& s, int count, int rows, int columns, int* kept,
                                  unsigned char* scratch) const {
  const FloatFrame frame{float(eye.x),     float(eye.y),     float(eye.z),     float(right.x),
                         float(right.y),   float(right.z),   float(up.x),      float(up.y),
                         float(up.z),      float(forward.x), float(forward.y), float(forward.z),
                         float(df),        float(coordinate_scale), float(rows), float(columns)};
  flag_unseen(frame, s.x, s.y, s.z, s.radius, count, scratch);
  int n = 0;
  for (int i = 0; i < count; ++i) {
    kept[n] = i;
    n += !scratch[i];
  }
  return n;
}

}  // namespace raycam::detail
