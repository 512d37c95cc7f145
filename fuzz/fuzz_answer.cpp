// libFuzzer target: the reader of a student's answer (raycam-cli check), fed any bytes a program may print.
// It may refuse them (an error naming the field); it may never crash, throw, allocate beyond the case's size,
// or accept an answer of the wrong size or with an id out of range as valid.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "check/answer.h"

namespace {
void check(bool condition) {
  if (!condition) std::abort();  // a broken guarantee: libFuzzer saves the input
}

void read_as(const std::string& text, int dimension, int rows, int columns, int objects) {
  using namespace raycam::check;
  const ParsedAnswer parsed = parse_answer(text, dimension, rows, columns, objects);
  if (parsed.answer) {
    const Answer& answer = *parsed.answer;
    check(answer.ids.size() == std::size_t(answer.rows) * std::size_t(answer.columns));
    check(answer.rows <= rows && answer.columns <= columns);  // never more than the case has
    if (answer.md) check(answer.md->size() == std::size_t((dimension + 1) * (dimension + 1)));
  }
  if (!parsed.error.empty()) return;
  // Valid: the case's size, ids in range, and what it writes back reads the same.
  const Answer& answer = *parsed.answer;
  check(answer.rows == rows && answer.columns == columns);
  for (int id : answer.ids) check(id >= -1 && id < objects);
  const ParsedAnswer again = parse_answer(answer_to_json(answer, dimension), dimension, rows, columns, objects);
  check(again.error.empty() && again.answer && again.answer->ids == answer.ids);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  read_as(text, 2, 1, 4, 3);
  read_as(text, 3, 2, 3, 3);
  return 0;
}
