#include "grading.h"

#include <algorithm>
#include <cmath>

namespace raycam::check {

const char* status_name(CaseStatus status) {
  switch (status) {
    case CaseStatus::pass: return "pass";
    case CaseStatus::fail: return "fail";
    case CaseStatus::crash: return "crash";
    case CaseStatus::timeout: return "timeout";
    case CaseStatus::bad_output: return "bad-output";
  }
  return "?";
}

namespace {
// Distance (Chebyshev, in pixels) from pixel i to the nearest pixel whose reference id differs or is
// ambiguous; the image's border does not count as an edge.
int depth_in_region(const CaseImage& reference, std::size_t i) {
  const int row = int(i / std::size_t(reference.columns)), column = int(i % std::size_t(reference.columns));
  const int limit = std::max(reference.rows, reference.columns);
  for (int ring = 1; ring <= limit; ++ring)
    for (int r = std::max(0, row - ring); r <= std::min(reference.rows - 1, row + ring); ++r)
      for (int c = std::max(0, column - ring); c <= std::min(reference.columns - 1, column + ring); ++c) {
        if (std::max(std::abs(r - row), std::abs(c - column)) != ring) continue;
        const std::size_t j = std::size_t(r) * reference.columns + c;
        if (reference.ambiguous[j] || reference.ids[j] != reference.ids[i]) return ring;
      }
  return limit;
}

// The candidate reproduces the answer: same size, same ids wherever it is not ambiguous, same M_d if given.
bool reproduces(const CaseImage& candidate, const Answer& answer) {
  if (candidate.rows != answer.rows || candidate.columns != answer.columns) return false;
  for (std::size_t i = 0; i < candidate.pixels(); ++i)
    if (!candidate.ambiguous[i] && candidate.ids[i] != answer.ids[i]) return false;
  return !answer.md || md_matches(*answer.md, candidate.md);
}
}  // namespace

bool md_matches(const std::vector<double>& answer, const std::vector<double>& expected) {
  if (answer.size() != expected.size()) return false;
  double scale = 1.0;
  for (double value : expected) scale = std::max(scale, std::abs(value));
  for (std::size_t i = 0; i < answer.size(); ++i)
    if (!(std::abs(answer[i] - expected[i]) <= 1e-6 * scale)) return false;
  return true;
}

CaseResult grade_answer(const CaseImage& reference, const ParsedAnswer& parsed) {
  CaseResult result;
  result.dimension = reference.dimension;
  result.pixels = static_cast<long long>(reference.pixels());
  for (std::uint8_t a : reference.ambiguous) result.ambiguous_pixels += a;
  result.answer = parsed.answer;
  if (!parsed.error.empty()) {
    result.status = CaseStatus::bad_output;
    result.detail = parsed.error;
    result.wrong_pixels = result.pixels;
    return result;
  }
  const Answer& answer = *parsed.answer;
  if (answer.md) result.md = md_matches(*answer.md, reference.md) ? "match" : "differs";
  for (std::size_t i = 0; i < reference.pixels(); ++i) {
    if (reference.ambiguous[i] || reference.ids[i] == answer.ids[i]) continue;
    ++result.wrong_pixels;
    const int depth = depth_in_region(reference, i);
    if (!result.worst || depth > result.worst->depth)
      result.worst = WorstPixel{int(i / std::size_t(reference.columns)), int(i % std::size_t(reference.columns)),
                                reference.ids[i], answer.ids[i], depth};
  }
  result.status = result.wrong_pixels == 0 ? CaseStatus::pass : CaseStatus::fail;
  return result;
}

std::string Explanation::id() const {
  std::string joined;
  for (const MistakeInfo* mistake : mistakes) joined += (joined.empty() ? "" : "+") + std::string(mistake->id);
  return joined;
}

std::string Explanation::text(const std::string& lang) const {
  std::string joined;
  for (const MistakeInfo* mistake : mistakes)
    joined += (joined.empty() ? "" : " + ") + std::string(mistake_explanation(*mistake, lang));
  return joined;
}

std::vector<Explanation> diagnose(const std::vector<CheckCase>& cases, std::vector<CaseResult>& results) {
  // Candidates in the table's order: every single mistake, then every pair.
  std::vector<std::vector<const MistakeInfo*>> candidates;
  for (const MistakeInfo& a : kClassicMistakes) candidates.push_back({&a});
  for (std::size_t i = 0; i < kClassicMistakeCount; ++i)
    for (std::size_t j = i + 1; j < kClassicMistakeCount; ++j)
      candidates.push_back({&kClassicMistakes[i], &kClassicMistakes[j]});

  std::vector<std::vector<int>> reproduced(candidates.size());
  for (std::size_t r = 0; r < results.size() && r < cases.size(); ++r) {
    CaseResult& result = results[r];
    const bool failed_with_answer =
        result.answer && (result.status == CaseStatus::fail || result.status == CaseStatus::bad_output);
    if (!failed_with_answer) continue;
    const SceneFile& file = cases[r].file;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      // A 3D-only mistake changes nothing in 2D: with another one it still explains the student's 2D cases.
      ClassicMistakes on;
      for (const MistakeInfo* m : candidates[c]) on.*m->flag = true;
      bool match = reproduces(render_case(file, on), *result.answer);
      // Without renormalising, the textbook (naive) formula and the stable one give different images.
      if (!match && on.skip_renormalise)
        match = reproduces(render_case(file, on, IntersectFormula::naive), *result.answer);
      if (match) reproduced[c].push_back(result.number);
    }
  }
  // A pair is kept only when it reproduces a case that neither of its mistakes alone does (a mistake with no
  // effect on a case would otherwise pair with every explanation).
  auto covers = [](const std::vector<int>& all, const std::vector<int>& part) {
    return std::includes(all.begin(), all.end(), part.begin(), part.end());
  };
  for (std::size_t c = kClassicMistakeCount; c < candidates.size(); ++c) {
    const std::size_t a = std::size_t(candidates[c][0] - kClassicMistakes), b = std::size_t(candidates[c][1] - kClassicMistakes);
    if (covers(reproduced[a], reproduced[c]) || covers(reproduced[b], reproduced[c])) reproduced[c].clear();
  }
  std::vector<Explanation> explanations;
  for (std::size_t c = 0; c < candidates.size(); ++c)
    if (!reproduced[c].empty()) explanations.push_back({candidates[c], reproduced[c]});
  // Most cases first; stable, so singles stay before pairs and the table's order breaks the remaining ties.
  std::stable_sort(explanations.begin(), explanations.end(),
                   [](const Explanation& a, const Explanation& b) { return a.cases.size() > b.cases.size(); });
  for (const Explanation& e : explanations)
    for (int number : e.cases)
      for (CaseResult& result : results)
        if (result.number == number) result.explained_by.push_back(e.id());
  return explanations;
}

}  // namespace raycam::check
