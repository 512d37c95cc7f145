// One check case rendered the way the student protocol lays it out (docs/check.md):
//   2D: one row of n ids in the handout's pixel order k (pixel k's canonical centre is x = -1 + (2k+1)/n);
//   3D: nbl rows of nbc ids, row 0 at the top (canonical y near +1), column 0 at the left (x near -1).
// Each pixel also says whether its centre ray is AMBIGUOUS: a pixel two correct programs may legitimately
// disagree on because double rounding decides it (see kAmbiguityTolerance).
#pragma once

#include <cstdint>
#include <vector>

#include "raycam/classic_mistakes.h"
#include "raycam/intersect.h"
#include "raycam/scene_file.h"

namespace raycam::check {

// A centre ray is ambiguous when, for some object, relative to the magnitudes involved (b² + |c| + r² for
// the discriminant, |f|² + r² for c, the distances for t):
//   - it grazes the object: |discriminant| ≤ tol·scale (a tangent ray);
//   - it starts on the object's surface: |c| ≤ tol·scale (t ≥ 0 decides between two answers);
//   - two objects tie: their hit distances differ by ≤ tol·scale (the lower index wins only if exact).
// Double arithmetic done in another order errs by ~1e-15 relative; 1e-9 leaves six orders of margin and
// still marks only a few pixels in a billion of random rays.
inline constexpr double kAmbiguityTolerance = 1e-9;

struct CaseImage {
  int dimension = 2;
  int rows = 1;     // 1 in 2D
  int columns = 0;  // n in 2D
  std::vector<int> ids;                 // rows·columns, protocol order
  std::vector<std::uint8_t> ambiguous;  // 1 where the centre ray is ambiguous
  std::vector<double> md;               // M_d row-major: 3×3 (2D) or 4×4 (3D)

  std::size_t pixels() const { return ids.size(); }
};

// The case's camera (its "camera" block must be complete: the battery writes every field) with `mistakes`
// on, rendered with the plain loop's rays and hit rule. Throws std::invalid_argument on a bad camera.
CaseImage render_case(const SceneFile& file, const ClassicMistakes& mistakes = {},
                      IntersectFormula formula = IntersectFormula::stable);

// Whether the case rendered with `mistakes` equals an answer of `rows` × `columns` `ids` at every pixel it
// does not mark ambiguous (and its M_d equals `md` when given). Stops at the first pixel that differs: the
// diagnosis tries 91 candidates per case, most of them wrong within a few pixels.
bool case_reproduces(const SceneFile& file, const ClassicMistakes& mistakes, IntersectFormula formula,
                     int rows, int columns, const std::vector<int>& ids, const std::vector<double>* md);

// M_d equal up to rounding: |a - b| ≤ 1e-6·max(1, max |b|) entry by entry.
bool md_matches(const std::vector<double>& answer, const std::vector<double>& expected);

// The pass rule at one pixel: an answer is wrong there when its id differs from the reference's and the
// reference's centre ray is not ambiguous (the only place this rule is written).
inline bool pixel_is_wrong(bool reference_ambiguous, int reference_id, int answer_id) {
  return !reference_ambiguous && reference_id != answer_id;
}

// Number of objects in the case (ids run from -1 to objects - 1).
int object_count(const SceneFile& file);

}  // namespace raycam::check
