// A student's answer (the protocol's output): {"ids": ..., "md": ...} as JSON.
//   2D: "ids" is a list of n integers in the handout's pixel order k, -1 for the background;
//   3D: "ids" is a list of nbl rows of nbc integers, row 0 at the top, column 0 at the left;
//   "md" (optional): M_d row-major, 3×3 (2D) or 4×4 (3D), finite numbers.
// Other members are ignored. Integers may be written 3 or 3.0 (some languages print every number as a float).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace raycam::check {

struct Answer {
  int rows = 1;     // 1 in 2D
  int columns = 0;  // n in 2D
  std::vector<int> ids;
  std::optional<std::vector<double>> md;  // row-major
};

struct ParsedAnswer {
  std::optional<Answer> answer;  // set when the JSON has the protocol's shape (even with a wrong size)
  std::string error;             // empty when the answer is valid for the case
  bool wrong_size = false;       // well formed but not the case's size (res_truncated makes this)
};

// Checks `text` against a case of `dimension` with `rows` × `columns` pixels and `objects` objects.
ParsedAnswer parse_answer(const std::string& text, int dimension, int rows, int columns, int objects);

// The answer as JSON text (for answer files and the reference students).
std::string answer_to_json(const Answer& answer, int dimension);

}  // namespace raycam::check
