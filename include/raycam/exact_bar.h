// The exact 2D colour bar: the visible footprint of every circle on the screen segment, computed
// analytically (no sampling), and from it each pixel's exact coverage fraction per object.
//
// The screen segment is parametrised by the canonical coordinate s ∈ [-1, 1] (handout, exercise 1: the
// canonical screen runs from (-1,0) to (+1,0)); pixel k covers s ∈ [-1 + 2k/n, -1 + 2(k+1)/n] and is shown in
// column n-1-k (the eye's left first, as Camera2D). The ray for s starts on the screen at M_d·(s,0) and heads
// away from the eye, so what it sees is constant between these breakpoints:
//   - the tangent lines from the eye to each circle (a circle's silhouette),
//   - the lines from the eye through each circle-circle intersection point (where one circle passes in front
//     of another: both surfaces are at the same depth only there),
//   - the points where the screen line enters or leaves a circle (a screen cutting an object: the ray then
//     starts inside and sees the far side, or nothing if the circle lies between eye and screen).
// Between consecutive breakpoints the visible object is found by one ray cast in long double.
// Everything is computed in long double from the camera's double-precision M_d. The classic mistakes other
// than the printed rotation sign (which is inside M_d) are ignored: this is the reference for the right
// camera.
#pragma once

#include <cstddef>
#include <vector>

#include "raycam/camera2d.h"
#include "raycam/colour_map.h"
#include "raycam/coverage_image.h"
#include "raycam/scene.h"

namespace raycam {

// The breakpoints and the casts between them cost O(m²) for m circles: the exact bar is a reference for
// scenes a person composes, not for the 100k-object stress scenes (std::invalid_argument above this).
inline constexpr std::size_t kMaxExactBarCircles = 4096;

// A maximal interval of the screen where one object (or the background, id -1) is visible.
struct VisibleInterval {
  double s_begin = -1.0;  // canonical screen coordinate, s_begin < s_end
  double s_end = 1.0;
  int id = -1;
};

struct ExactBar {
  int pixels = 0;   // n, the camera's useful pixel count
  int objects = 0;  // number of circles; coverage slot `objects` is the background
  std::vector<VisibleInterval>
      footprint;                 // sorted by s, adjacent intervals have different ids, covers [-1, 1]
  std::vector<double> coverage;  // (objects + 1) fractions per column, image order; each sums to 1
  std::vector<int> centre_ids;   // exact id of each pixel-centre ray, image order

  double coverage_of(int column, int id) const {
    return coverage[std::size_t(column) * (objects + 1) + std::size_t(id < 0 ? objects : id)];
  }
};

// The visible intervals of the whole screen segment [-1, 1]. Throws std::invalid_argument naming
// "circles" if the scene has more than kMaxExactBarCircles.
std::vector<VisibleInterval> exact_footprint(const Camera2D& camera, const Scene2D& scene);

// Footprint, per-pixel coverage and exact centre ids.
ExactBar exact_bar(const Camera2D& camera, const Scene2D& scene);

// The "exact" bar as an image: area-weighted colours; ids are the exact centre ids.
CoverageImage exact_bar_image(const ExactBar& bar, const Scene2D& scene);

// The id seen along the ray through canonical screen coordinate s, in long double (ties: lower index).
int exact_id_at(const Camera2D& camera, const Scene2D& scene, long double s);

}  // namespace raycam
