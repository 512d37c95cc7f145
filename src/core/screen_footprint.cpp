#include "core/screen_footprint.h"

#include "core/vector_loops.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>

namespace raycam::detail {

namespace {
constexpr double kEpsilon = 1.1102230246251565e-16;  // double's unit roundoff
// Relative slack on the slopes (the frame's and the rays' directions are good to ~1e-15).
constexpr double kRelativeSlack = 1e-9;
constexpr double kIndexSlack = 1e-6;  // of a pixel: far above the rounding of a pixel index

// Everything below is branch-free (selects on values, no early return), so that sphere_boxes' loop over
// many spheres vectorises; one object alone runs the same code.
inline double clamped(double x, double lo, double hi) { return lower(higher(x, lo), hi); }
// The constants of the selects in axis_pixels, given to the loops as values. With a constant C, LLVM compiles
// `x < C ? C : x` for WebAssembly to f64x2.max, which must order -0 below +0 and pass NaNs on, and which V8
// runs as eight x86 instructions; with a value the compiler cannot see, the same select is f64x2.pmax, one
// instruction, with the same result (pmax is defined as that select). In the page, projecting 10⁵ spheres
// then took 1.64 ms instead of 2.07 (clumps, K = 10⁵, in Node). The native build keeps the constants.
struct SelectConstants {
  double zero, lowest_index;
};
inline SelectConstants select_constants() {
#ifdef __wasm__
  volatile double zero = 0.0, lowest_index = -2.0;  // read once per loop, outside it
  return SelectConstants{zero, lowest_index};
#else
  return SelectConstants{0.0, -2.0};
#endif
}
// A whole number in a double (|whole| < 2³¹) as an int, by adding 1.5·2⁵²: the sum's last mantissa bit is
// then 1, so the int is the low 32 bits of its bits. An add and a copy, which every vector unit does; a
// float-to-int conversion is not vectorised everywhere: in WebAssembly, the page's projection of 10⁵ spheres
// took 1.8 times as long with int() (docs/web.md).
inline int whole_to_int(double whole) {
  const double shifted = whole + 6755399441055744.0;
  std::uint64_t bits;
  std::memcpy(&bits, &shifted, sizeof bits);
  return int(std::int32_t(std::uint32_t(bits)));
}

// What both axes of one object share: the depth c0 of its centre along the view, its radius, and the
// slack for the rounding that a computed ray and the intersection's arithmetic may suffer near it. The ray's
// origin and f = origin - centre round at the scale of the coordinates; the naive formula's b² - c cancels,
// which moves its silhouette by ~ε·|f|²/r (docs/accuracy.md).
struct Depth {
  double c0, r;
  bool bounded;         // false when the object reaches the eye's plane (c0 ≤ r): every slope is possible
  bool behind_screen;   // wholly on the eye's side of the screen: no ray (t ≥ 0) reaches it
  double inverse_room;  // 1 / (c0² - r²) when bounded
  double slope_slack;   // the slack as a slope at the object's nearest depth, c0 - r
};

// kNaive is the footprint's formula, fixed for a whole loop: its extra division then costs nothing when
// the formula is the stable one.
template <bool kNaive>
inline Depth depth_of(const Footprint& f, double qx, double qy, double qz, double r) {
  Depth d;
  d.c0 = qx * f.forward.x + qy * f.forward.y + qz * f.forward.z;
  d.r = r;
  const double distance = std::abs(qx) + std::abs(qy) + std::abs(qz);  // ≥ |q|, without a square root
  double slack = 64 * kEpsilon * (f.coordinate_scale + distance + r);
  if (kNaive) slack += 16 * kEpsilon * (distance + r) * (distance + r) / r;
  d.bounded = d.c0 - r > slack + kRelativeSlack * d.c0;
  // Every point at depth c < d_f: rays start on the screen and move away from the eye, so never reach it.
  d.behind_screen = d.c0 + r < f.df - slack - kRelativeSlack * (std::abs(d.c0) + r + f.df);
  const double room = d.bounded ? (d.c0 - r) * (d.c0 + r) : 1.0;
  d.inverse_room = 1.0 / room;
  d.slope_slack = slack * (d.c0 + r) * d.inverse_room;  // slack / (c0 - r), with the one division
  return d;
}

// Pixels (along one axis) whose centre's ray can touch the object: the tangent slopes m = a/c of the lines
// from the eye touching the circle of centre (a0, c0) and radius r (the object's trace in the plane through
// the forward axis and this axis), widened by the slack, mapped to pixel centres -1 + (2i+1)/count on the
// screen at distance d_f through the core's pixel <-> screen pair. increasing = false for rows, whose screen
// y decreases with i. The whole axis when the object reaches the eye's plane.
// The first and last pixel, as whole numbers in doubles: comparing a double with an int would keep GCC from
// vectorising the loop, so the conversion to int comes last.
struct AxisRange {
  double first, last;
};

inline AxisRange axis_pixels(const Depth& d, double a0, double df, int count, bool increasing, SelectConstants k) {
  const double under_root = a0 * a0 + (d.c0 - d.r) * (d.c0 + d.r);
  const double spread = d.r * std::sqrt(higher(under_root, k.zero));
  double m_lo = (a0 * d.c0 - spread) * d.inverse_room, m_hi = (a0 * d.c0 + spread) * d.inverse_room;
  const double widen = kRelativeSlack * (std::abs(m_lo) + std::abs(m_hi) + 1.0) + d.slope_slack;
  m_lo -= widen;
  m_hi += widen;
  const double screen_lo = increasing ? df * m_lo : -df * m_lo;  // rows: raster y grows as screen y falls
  const double screen_hi = increasing ? df * m_hi : -df * m_hi;
  // Pixel i has its centre at index i, raster coordinate i + 1/2.
  const double a0_index = clamped(raster_from_screen(screen_lo, count) - 0.5, k.lowest_index, double(count) + 1.0);
  const double b0_index = clamped(raster_from_screen(screen_hi, count) - 0.5, k.lowest_index, double(count) + 1.0);
  const double a = lower(a0_index, b0_index) - kIndexSlack, b = higher(a0_index, b0_index) + kIndexSlack;
  // floor and ceil are one instruction on the vector units that matter (SSE4.1 and up, WebAssembly); on plain
  // SSE2 GCC inlines them too, as these files are built without trapping math.
  const double ceil_a = std::ceil(a), floor_b = std::floor(b);
  return AxisRange{d.bounded ? higher(k.zero, ceil_a) : 0.0, d.bounded ? lower(double(count - 1), floor_b) : double(count - 1)};
}

template <bool kNaive>
inline PixelBox sphere_box(const Footprint& f, double x, double y, double z, double r, int rows, int columns,
                           SelectConstants k) {
  const double qx = x - f.eye.x, qy = y - f.eye.y, qz = z - f.eye.z;
  const Depth d = depth_of<kNaive>(f, qx, qy, qz, r);
  // The planes through the eye containing the up axis that touch the sphere are the tangent lines of its
  // projection on the (right, forward) plane, a circle of the same radius: so each axis is a 2D problem.
  const AxisRange across = axis_pixels(d, qx * f.right.x + qy * f.right.y + qz * f.right.z, f.df, columns, true, k);
  const AxisRange down = axis_pixels(d, qx * f.up.x + qy * f.up.y + qz * f.up.z, f.df, rows, false, k);
  PixelBox box;
  box.columns = PixelRange{whole_to_int(across.first), whole_to_int(across.last)};
  box.rows = PixelRange{whole_to_int(down.first), whole_to_int(d.behind_screen ? -1.0 : down.last)};
  return box;
}

RAYCAM_VECTOR_LOOP void sphere_boxes_of(const Footprint frame, const double* x, const double* y, const double* z,
                     const double* radius, int count, int rows, int columns, PixelBox* boxes) {
  const SelectConstants k = select_constants();
  if (frame.formula == IntersectFormula::naive)
    for (int i = 0; i < count; ++i) boxes[i] = sphere_box<true>(frame, x[i], y[i], z[i], radius[i], rows, columns, k);
  else
    for (int i = 0; i < count; ++i) boxes[i] = sphere_box<false>(frame, x[i], y[i], z[i], radius[i], rows, columns, k);
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

bool Footprint::culls_clusters() const { return formula == IntersectFormula::stable && df >= 1e-2; }

void Footprint::clusters_out_of_view(const SphereColumns& bounds, int count, unsigned char* out) const {
  const double edge = std::sqrt(df * df + 1.0);  // |(d_f, -1)|: the side planes' normals unnormalised
  for (int k = 0; k < count; ++k) {
    const double qx = bounds.x[k] - eye.x, qy = bounds.y[k] - eye.y, qz = bounds.z[k] - eye.z;
    const double a = qx * right.x + qy * right.y + qz * right.z, b = qx * up.x + qy * up.y + qz * up.z;
    const double c = qx * forward.x + qy * forward.y + qz * forward.z;
    const double r = bounds.radius[k];
    const double grown = r * (1.0 + 1e-3) + 1e-6 * (std::abs(qx) + std::abs(qy) + std::abs(qz) + r + coordinate_scale);
    // The screen is |a|, |b| ≤ c/d_f at depth c ≥ d_f: outside a side plane by more than the grown radius.
    const double beyond = grown * edge;
    out[k] = (c + grown < df) | (df * a - c > beyond) | (-df * a - c > beyond) | (df * b - c > beyond) |
             (-df * b - c > beyond);
  }
}

PixelRange Footprint::circle_pixels(const Circle& circle, int pixel_count) const {
  const double qx = circle.centre.x - eye.x, qy = circle.centre.y - eye.y;
  const Depth d = formula == IntersectFormula::naive ? depth_of<true>(*this, qx, qy, 0.0, circle.radius)
                                                     : depth_of<false>(*this, qx, qy, 0.0, circle.radius);
  if (d.behind_screen) return PixelRange{};
  const AxisRange range = axis_pixels(d, qx * right.x + qy * right.y, df, pixel_count, true, select_constants());
  return PixelRange{int(range.first), int(range.last)};
}

PixelBox Footprint::sphere_pixels(const Sphere& sphere, int rows, int columns) const {
  PixelBox box;
  sphere_boxes_of(*this, &sphere.centre.x, &sphere.centre.y, &sphere.centre.z, &sphere.radius, 1, rows, columns, &box);
  return box;
}

void Footprint::sphere_boxes(const SphereColumns& spheres, int count, int rows, int columns, PixelBox* boxes) const {
  // By value: the boxes' int stores could alias this footprint's fields (its formula), which would keep
  // the loop from vectorising.
  sphere_boxes_of(*this, spheres.x, spheres.y, spheres.z, spheres.radius, count, rows, columns, boxes);
}

}  // namespace raycam::detail
