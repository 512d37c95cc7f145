#include "check/grading.h"

#include <algorithm>
#include <cmath>

#include "raycam/language.h"

namespace raycam::check {

const char* status_name(CaseStatus status) {
  switch (status) {
    case CaseStatus::pass: return "pass";
    case CaseStatus::fail: return "fail";
    case CaseStatus::crash: return "crash";
    case CaseStatus::timeout: return "timeout";
    case CaseStatus::bad_output: return "bad-output";
    case CaseStatus::checker_error: return "checker-error";
  }
  return "?";
}

namespace {
// For every pixel, the Chebyshev distance (in pixels) to the nearest pixel whose reference id differs from
// its own or is ambiguous; the image's border does not count as an edge. A two-pass distance transform:
// 1 beside an edge, 0 on an ambiguous pixel, then d(p) = min over the 8 neighbours of d(q) + 1. O(pixels),
// so a full 256² image grades at once.
std::vector<int> depth_map(const CaseImage& reference) {
  const int rows = reference.rows, columns = reference.columns;
  const int far = std::max(rows, columns);
  std::vector<int> depth(reference.pixels(), far);
  auto at = [&](int r, int c) { return std::size_t(r) * std::size_t(columns) + std::size_t(c); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const std::size_t i = at(r, c);
      if (reference.ambiguous[i]) {
        depth[i] = 0;
        continue;
      }
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = r + dr, cc = c + dc;
          if (rr >= 0 && rr < rows && cc >= 0 && cc < columns &&
              reference.ids[at(rr, cc)] != reference.ids[i])
            depth[i] = 1;
        }
    }
  auto relax = [&](int r, int c, int dr, int dc) {
    const int rr = r + dr, cc = c + dc;
    if (rr >= 0 && rr < rows && cc >= 0 && cc < columns)
      depth[at(r, c)] = std::min(depth[at(r, c)], depth[at(rr, cc)] + 1);
  };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c)
      for (const auto& [dr, dc] : {std::pair{-1, -1}, {-1, 0}, {-1, 1}, {0, -1}}) relax(r, c, dr, dc);
  for (int r = rows - 1; r >= 0; --r)
    for (int c = columns - 1; c >= 0; --c)
      for (const auto& [dr, dc] : {std::pair{1, 1}, {1, 0}, {1, -1}, {0, 1}}) relax(r, c, dr, dc);
  return depth;
}
}  // namespace

std::vector<std::uint8_t> wrong_pixel_mask(const CaseImage& reference, const Answer& answer) {
  std::vector<std::uint8_t> wrong(reference.pixels(), 0);
  if (answer.rows != reference.rows || answer.columns != reference.columns) return wrong;
  for (std::size_t i = 0; i < reference.pixels(); ++i)
    wrong[i] = pixel_is_wrong(reference.ambiguous[i], reference.ids[i], answer.ids[i]);
  return wrong;
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
  const std::vector<int> depths = depth_map(reference);
  for (std::size_t i = 0; i < reference.pixels(); ++i) {
    if (!pixel_is_wrong(reference.ambiguous[i], reference.ids[i], answer.ids[i])) continue;
    ++result.wrong_pixels;
    const int depth = depths[i];
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

std::string Explanation::text(Language language) const {
  std::string joined;
  for (const MistakeInfo* mistake : mistakes)
    joined += (joined.empty() ? "" : " + ") + std::string(mistake->explanation[language]);
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
      const Answer& a = *result.answer;
      const std::vector<double>* md = a.md ? &*a.md : nullptr;
      bool match = case_reproduces(file, on, IntersectFormula::stable, a.rows, a.columns, a.ids, md);
      // Without renormalising, the textbook (naive) formula and the stable one give different images.
      if (!match && on.skip_renormalise)
        match = case_reproduces(file, on, IntersectFormula::naive, a.rows, a.columns, a.ids, md);
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
