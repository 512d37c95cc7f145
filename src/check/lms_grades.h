// Grades where a course keeps them: a grade-book column for the --batch CSV (Moodle imports a CSV column as
// a grade, e.g. out of 20 as French courses grade) and Gradescope's results.json for one submission.
#pragma once

#include <string>
#include <vector>

#include "check/check_report.h"

namespace raycam::check {

constexpr double kDefaultGradeScale = 20;

// The share of cases passed, out of `scale`, with two decimals: "13.33".
std::string scaled_grade(const StudentReport& report, double scale);
// The grade column's name: "grade_20", "grade_100", "grade_12.5".
std::string grade_column_name(double scale);
// A CSV line (ending in "\n") with one more field at its end: the grade column is always the last.
std::string with_last_field(const std::string& line, const std::string& field);

// Gradescope's visibility values, as its autograder specification lists them.
const std::vector<std::string>& gradescope_visibilities();

// Gradescope's results.json: "score" (out of scale, the sum of the tests' max_score), "output" (the text
// report), "visibility",
// and one test per case: "name" (number, dimension, what the case exercises), "number", "score",
// "max_score" (scale / cases), "status" ("passed" or "failed"), "output" (the case's line of the table and
// the mistakes that reproduce it), "visibility".
std::string gradescope_results_json(const ReportHeader& header, const std::vector<CheckCase>& cases,
                                    const StudentReport& report, double scale, const std::string& visibility);

}  // namespace raycam::check
