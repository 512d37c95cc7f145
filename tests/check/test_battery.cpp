// The default battery reveals every classic mistake, and the diagnosis tells single mistakes apart.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "battery.h"
#include "case_image.h"
#include "grading.h"

using namespace raycam;
using namespace raycam::check;

namespace {
// The image of `mistakes` differs from the right image at a pixel neither marks ambiguous, or in size.
bool differs(const CaseImage& a, const CaseImage& b) {
  if (a.rows != b.rows || a.columns != b.columns) return true;
  for (std::size_t i = 0; i < a.pixels(); ++i)
    if (!a.ambiguous[i] && !b.ambiguous[i] && a.ids[i] != b.ids[i]) return true;
  return false;
}

ClassicMistakes only(const MistakeInfo& info) {
  ClassicMistakes m;
  m.*info.flag = true;
  return m;
}
}  // namespace

TEST_CASE("the battery reveals every classic mistake (default seed and two others)", "[check][battery]") {
  for (const std::uint64_t seed : {kDefaultSeed, std::uint64_t(914273), std::uint64_t(1)}) {
    const std::vector<CheckCase> battery =
        make_battery(BatteryMode::both, designed_case_count(BatteryMode::both), seed);
    for (const MistakeInfo& info : kClassicMistakes) {
      INFO(info.id << " seed " << seed << ": no case reveals it; the battery needs " << info.battery_needs);
      int revealing = 0;
      for (const CheckCase& c : battery) {
        const CaseImage right = render_case(c.file);
        bool both_formulas = differs(render_case(c.file, only(info)), right);
        if (info.flag == &ClassicMistakes::skip_renormalise)
          both_formulas =
              both_formulas && differs(render_case(c.file, only(info), IntersectFormula::naive), right);
        revealing += both_formulas;
      }
      CHECK(revealing >= 1);
    }
  }
}

namespace {
// A simulated student: the core's image under `mistakes` as the answer to every case (ids only).
std::vector<CaseResult> simulated_results(const std::vector<CheckCase>& battery, const ClassicMistakes& mistakes,
                                          IntersectFormula formula) {
  std::vector<CaseResult> results;
  for (std::size_t i = 0; i < battery.size(); ++i) {
    const CaseImage right = render_case(battery[i].file);
    const CaseImage student = render_case(battery[i].file, mistakes, formula);
    ParsedAnswer parsed;
    parsed.answer = Answer{student.rows, student.columns, student.ids, std::nullopt};
    parsed.wrong_size = student.rows != right.rows || student.columns != right.columns;
    if (parsed.wrong_size) parsed.error = "wrong size";
    results.push_back(grade_answer(right, parsed));
    results.back().number = int(i) + 1;
  }
  return results;
}
}  // namespace

TEST_CASE("on the default battery, each single mistake is the first explanation of its own images",
          "[check][battery][diagnosis]") {
  const std::vector<CheckCase> battery =
      make_battery(BatteryMode::both, designed_case_count(BatteryMode::both), kDefaultSeed);
  for (const MistakeInfo& info : kClassicMistakes)
    for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
      INFO(info.id << (formula == IntersectFormula::naive ? " (naive)" : ""));
      std::vector<CaseResult> results = simulated_results(battery, only(info), formula);
      int failing = 0;
      for (const CaseResult& r : results) failing += r.status != CaseStatus::pass;
      CHECK(failing > 0);
      const std::vector<Explanation> diagnosis = diagnose(battery, results);
      REQUIRE(!diagnosis.empty());
      CHECK(diagnosis[0].id() == info.id);
      CHECK(int(diagnosis[0].cases.size()) == failing);
    }
}

TEST_CASE("a 3D case has two resolutions, and its image has the handout's nbl rows of nbc columns",
          "[check][battery][res]") {
  // The handout's useful size, from its formula: res·N rounded, at least 1.
  const auto handout_count = [](double res, int size) { return std::max(1, int(std::floor(res * size + 0.5))); };
  for (const std::uint64_t seed : {kDefaultSeed, std::uint64_t(914273), std::uint64_t(1)}) {
    int two = 0;
    for (const CheckCase& c : make_battery(BatteryMode::three_d, designed_case_count(BatteryMode::three_d), seed)) {
      const CameraPreset& camera = c.file.camera;
      if (!camera.res_rows) continue;
      ++two;
      INFO(c.purpose << " seed " << seed);
      const int columns = (*camera.size)[0], rows = (*camera.size)[1];
      const CaseImage image = render_case(c.file);
      CHECK(image.columns == handout_count(*camera.res, columns));  // nbc
      CHECK(image.rows == handout_count(*camera.res_rows, rows));   // nbl
      // One res for both sides would give another row count: the case tells a program that reads one apart.
      CHECK(handout_count(*camera.res, rows) != image.rows);
      CHECK(scene_to_json(c.file).find("\"res\": [") != std::string::npos);  // the protocol's input has both
    }
    CHECK(two >= 1);
  }
}
