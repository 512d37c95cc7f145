// One case graded on its own (check::grade_case, as the app's "Check my camera" uses it): the wrong-pixel
// rule skips ambiguous pixels, the mask agrees with the count, and an answer file is read as a program's
// output (one that cannot be read is a crash naming the file).
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "check/case_verdict.h"

using namespace raycam;
using namespace raycam::check;
namespace fs = std::filesystem;

TEST_CASE("a pixel is wrong where its id differs and the reference is not ambiguous", "[check][verdict]") {
  CaseImage reference;
  reference.dimension = 2;
  reference.rows = 1;
  reference.columns = 4;
  reference.ids = {0, 1, -1, 0};
  reference.ambiguous = {0, 1, 0, 0};
  reference.md.assign(9, 0.0);
  Answer answer;
  answer.rows = 1;
  answer.columns = 4;
  answer.ids = {0, 0, -1, 1};  // differs at 1 (ambiguous: not wrong) and at 3 (wrong)
  CHECK(wrong_pixel_mask(reference, answer) == std::vector<std::uint8_t>{0, 0, 0, 1});
  ParsedAnswer parsed;
  parsed.answer = answer;
  const CaseResult graded = grade_answer(reference, parsed);
  CHECK(graded.wrong_pixels == 1);
  CHECK(graded.status == CaseStatus::fail);
  answer.columns = 3;  // another size: nothing to mark pixel by pixel
  answer.ids.pop_back();
  CHECK(wrong_pixel_mask(reference, answer) == std::vector<std::uint8_t>(4, 0));
}

TEST_CASE("grade_case reads an answer file, marks its one wrong pixel, and names a file it cannot read",
          "[check][verdict]") {
  const fs::path dir = fs::temp_directory_path() / ("raycam-verdict-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const CheckCase checked = make_battery(BatteryMode::three_d, 1, kDefaultSeed).at(0);
  const CaseImage reference = render_case(checked.file);
  // The right image with one unambiguous pixel changed to another id.
  Answer answer{reference.rows, reference.columns, reference.ids, std::nullopt};
  std::size_t changed = 0;
  while (reference.ambiguous[changed]) ++changed;
  answer.ids[changed] = reference.ids[changed] == -1 ? 0 : -1;
  const fs::path path = dir / "answer.json";
  std::ofstream(path) << answer_to_json(answer, reference.dimension);

  CaseSource source;
  source.answer_path = path.string();
  source.diagnosis_budget = 0;  // the diagnosis is not what this test looks at
  const CaseVerdict verdict = grade_case(checked, source);
  CHECK(verdict.result.status == CaseStatus::fail);
  CHECK(verdict.result.wrong_pixels == 1);
  REQUIRE(verdict.wrong.size() == reference.pixels());
  CHECK(std::accumulate(verdict.wrong.begin(), verdict.wrong.end(), 0) == 1);
  CHECK(verdict.wrong[changed] == 1);
  CHECK_FALSE(verdict.diagnosed);

  source.answer_path = (dir / "missing.json").string();
  const CaseVerdict missing = grade_case(checked, source);
  CHECK(missing.result.status == CaseStatus::bad_output);  // no answer given: not a crash of a program
  CHECK_THAT(missing.result.detail, Catch::Contains("missing.json: cannot open the answer file"));
  fs::remove_all(dir);
}
