// The numerical stress cases (docs/accuracy.md, "Stress sweep"), shared by the CI tests
// (tests/stress/, short list) and `raycam-cli bench accuracy --stress` (long list), so both measure the
// same settings.
//
// Each case is a camera and a scene. Groups: far targets (d 1e-3 … 1e7, zoomed with d_f ∝ d so the scene
// still fills the view), focal distance (d_f 1e-3 … 1e3), poles (φ = 0, π exactly and ± a few ulp), θ at ±π
// and wrapping, res down to 1/N, everything translated by up to 1e7 and rotated, grazing rays (a circle
// tangent to a pixel-centre ray), a screen cutting an object, equal-depth overlaps.
// The reference ids are exact: the exact 2D bar's centre ids, and in 3D a long-double, stable,
// camera-relative cast.
#pragma once

#include <string>
#include <vector>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/coverage_image.h"
#include "raycam/reference_caster.h"
#include "raycam/scene.h"

namespace raycam {

struct StressCase2D {
  std::string group;  // e.g. "d", "translate"
  std::string name;   // e.g. "d=1e7"
  Camera2D camera;
  Scene2D scene;
};

struct StressCase3D {
  std::string group;
  std::string name;
  Camera3D camera;
  Scene3D scene;
};

// `long_sweep`: more values per group and larger images (for the script, not CI).
std::vector<StressCase2D> stress_cases_2d(bool long_sweep);
std::vector<StressCase3D> stress_cases_3d(bool long_sweep);

// The exact ids for a case (see the header comment).
CoverageImage stress_reference(const StressCase2D& stress_case);
CoverageImage stress_reference(const StressCase3D& stress_case);

struct StressResult {
  double id_error = 0.0;   // fraction of pixel ids differing from the reference
  bool all_finite = true;  // M_d, the eye and every primary ray finite; every id in [-1, objects)
};
StressResult measure(const StressCase2D& stress_case, const CoverageImage& reference,
                     const ReferenceOptions& options);
StressResult measure(const StressCase3D& stress_case, const CoverageImage& reference,
                     const ReferenceOptions& options);

}  // namespace raycam
