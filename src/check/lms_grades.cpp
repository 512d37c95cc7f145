#include "check/lms_grades.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "check/check_texts.h"

namespace raycam::check {

namespace {
using json = nlohmann::json;

double grade_of(const StudentReport& report, double scale) {
  const std::size_t n = report.results.size();
  return n ? scale * report.passed() / double(n) : 0.0;
}

// What Gradescope shows under a test: the case's line of the table, then the mistakes that reproduce it.
std::string case_output(Language lang, const CheckCase& c, const CaseResult& r,
                        const std::vector<Explanation>& diagnosis) {
  std::string out = c.purpose + "\n" + text(lang, status_name(r.status));
  if (r.status == CaseStatus::pass || r.status == CaseStatus::fail)
    out += textf(lang, ": %lld / %lld wrong {{pixel|pixels}}", r.wrong_pixels, r.pixels);
  const std::string reason = case_reason(lang, r);
  if (!reason.empty()) out += "; " + reason;
  out += "\n";
  for (const Explanation& e : diagnosis)
    for (int number : e.cases)
      if (number == r.number) out += e.id() + ": " + e.text(lang) + "\n";
  return out;
}
}  // namespace

std::string scaled_grade(const StudentReport& report, double scale) {
  char grade[32];
  std::snprintf(grade, sizeof grade, "%.2f", grade_of(report, scale));
  return grade;
}

std::string grade_column_name(double scale) {
  char name[48];
  std::snprintf(name, sizeof name, "grade_%g", scale);
  return name;
}

std::string with_last_field(const std::string& line, const std::string& field) {
  const bool ended = !line.empty() && line.back() == '\n';
  return line.substr(0, line.size() - (ended ? 1 : 0)) + "," + field + "\n";
}

const std::vector<std::string>& gradescope_visibilities() {
  static const std::vector<std::string> values = {"visible", "hidden", "after_due_date", "after_published"};
  return values;
}

std::string gradescope_results_json(const ReportHeader& header, const std::vector<CheckCase>& cases,
                                    const StudentReport& report, double scale, const std::string& visibility) {
  const double per_case = cases.empty() ? 0.0 : scale / double(cases.size());
  json tests = json::array();
  for (std::size_t i = 0; i < report.results.size() && i < cases.size(); ++i) {
    const CaseResult& r = report.results[i];
    const bool passed = r.status == CaseStatus::pass;
    tests.push_back({{"name", textf(header.language, "case %d (%dD)", r.number, r.dimension)},
                     {"number", std::to_string(r.number)},
                     {"score", passed ? per_case : 0.0},
                     {"max_score", per_case},
                     {"status", passed ? "passed" : "failed"},
                     {"output", case_output(header.language, cases[i], r, report.diagnosis)},
                     {"visibility", visibility}});
  }
  // The top level holds only fields Gradescope documents: the maximum is the sum of the tests' max_score.
  const json root = {{"score", grade_of(report, scale)},
                     {"output", text_report(header, cases, report)},
                     {"visibility", visibility},
                     {"tests", tests}};
  // Student output may hold any bytes: replace invalid UTF-8 rather than fail.
  return root.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace raycam::check
