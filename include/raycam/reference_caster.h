// A configurable caster for accuracy work: the same primary rays as the plain caster (handout, exercise 2),
// with every knob that trades time against error exposed.
//
//   scalar            float, double or long double for the per-ray arithmetic. M_d itself is always built
//                     by the core in double (once per frame) and then rounded to the scalar.
//   formula           IntersectFormula::naive (textbook b² - c) or ::stable (Ray Tracing Gems 2019).
//   samples_per_pixel stratified samples: in 2D spp equal strata along the pixel, each sampled at its centre;
//                     in 3D a g × g grid with g² = spp (spp must be a perfect square). Colours are the
//                     samples' mean; ids always come from the ray through the pixel centre.
//   camera_relative   false: origins and centres in world coordinates, as the core (P_k = M_d·P_k^0);
//                     true: everything relative to the eye, so the scalar only ever holds small numbers
//                     (origin = L·(P_k^0 - E0) with L the linear part of M_d, centres c - E rounded once).
//
// With scalar = double, formula = stable, spp = 1 and world coordinates, the ids equal cast_primary_rays'
// id for id (same operations in the same order; tests/core/test_reference_caster.cpp checks it).
// Image order as ColourMap (2D: one row, column 0 = the eye's left).
#pragma once

#include <string>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/coverage_image.h"
#include "raycam/intersect.h"
#include "raycam/scene.h"

namespace raycam {

enum class Scalar { float32, float64, extended };  // float, double, long double

struct ReferenceOptions {
  Scalar scalar = Scalar::float64;
  IntersectFormula formula = IntersectFormula::stable;
  int samples_per_pixel = 1;
  bool camera_relative = false;
};

inline constexpr int kMaxSamplesPerPixel = 1 << 16;

// The caster with the scalar fixed at compile time (instantiated for float, double, long double).
// Throws std::invalid_argument if samples_per_pixel is outside [1, kMaxSamplesPerPixel] (or, in 3D, not a
// perfect square).
template <class T>
CoverageImage reference_cast_as(const Camera2D& camera, const Scene2D& scene,
                                const ReferenceOptions& options);
template <class T>
CoverageImage reference_cast_as(const Camera3D& camera, const Scene3D& scene,
                                const ReferenceOptions& options);

// The one rule for which caster draws an image, for the app and the CLI alike: cast_primary_rays gives the
// reference's ids and colours exactly for double arithmetic, one sample per pixel and world coordinates,
// with either intersection formula; anything else, or the exact 2D bar (`exact_bar`, 2D only), needs the
// reference caster.
bool needs_reference_caster(const ReferenceOptions& options, bool exact_bar);

// Dispatch on options.scalar.
CoverageImage reference_cast(const Camera2D& camera, const Scene2D& scene, const ReferenceOptions& options);
CoverageImage reference_cast(const Camera3D& camera, const Scene3D& scene, const ReferenceOptions& options);

inline constexpr Scalar kScalars[] = {Scalar::float32, Scalar::float64, Scalar::extended};
inline constexpr IntersectFormula kIntersectFormulas[] = {IntersectFormula::naive, IntersectFormula::stable};
// Names used by the CLI and the CSV: "float" / "double" / "long-double", "naive" / "stable".
const char* scalar_name(Scalar scalar);
const char* formula_name(IntersectFormula formula);

}  // namespace raycam
