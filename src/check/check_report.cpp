// Section index: terminal text · JSON report · CSV · difference images.
#include "raycam/image_files.h"
#include "check/check_report.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "check/check_texts.h"
#include "check/escaped_text.h"
#include "raycam/colour_map.h"
#include "raycam/language.h"

namespace raycam::check {

namespace {
using json = nlohmann::json;

std::string pixel_text(Language lang, const CaseResult& r) {
  if (!r.worst) return {};
  const WorstPixel& w = *r.worst;
  return r.dimension == 2 ? textf(lang, "pixel k = %d: expected %d, got %d", w.column, w.expected, w.got)
                          : textf(lang, "row %d, column %d: expected %d, got %d", w.row, w.column, w.expected, w.got);
}

std::string case_list(const std::vector<int>& cases) {
  std::string list;
  for (int c : cases) list += (list.empty() ? "" : ", ") + std::to_string(c);
  return list;
}

int failing(const StudentReport& report) { return int(report.results.size()) - report.passed(); }

// What a student's runs used, as isolate's meta file gives it per run: summed, and the largest peak.
struct RunTotals {
  double wall = 0, cpu = 0;
  long long peak = 0;
  int peak_case = 0;
};
RunTotals totals_of(const StudentReport& report) {
  RunTotals t;
  for (const CaseResult& r : report.results) {
    t.wall += r.seconds;
    t.cpu += r.cpu_seconds;
    if (r.peak_memory_bytes > t.peak) {
      t.peak = r.peak_memory_bytes;
      t.peak_case = r.number;
    }
  }
  return t;
}
constexpr double kMiB = 1 << 20;

// The first lines of a program's stderr, indented.
std::string stderr_excerpt(const std::string& err) {
  std::string out;
  int lines = 0;
  for (std::size_t start = 0; start < err.size() && lines < 6; ++lines) {
    std::size_t end = err.find('\n', start);
    if (end == std::string::npos) end = err.size();
    out += "      | " + escaped_control(err.substr(start, std::min<std::size_t>(end - start, 160))) + "\n";
    start = end + 1;
  }
  return out;
}
}  // namespace

// ---- terminal text -----------------------------------------------------------------------------------------
namespace {
// The run's detail in the report's language. The checker writes its details in English (they also go to the
// JSON report, which tools read); the French text report translates them with the module that translates
// every error reason (raycam/language.h), numbers and names kept. A reason a program printed itself stays as
// it is.
// The bounds' sentences (check_run.h's limit_detail) are the check command's own texts. Escaped: a detail may
// quote what a student named (a program, a folder).
std::string detail_text(Language lang, const std::string& detail) {
  const std::string own = text(lang, detail.c_str());
  return escaped_control(own != detail ? own : translate_reason(lang, detail));
}
}  // namespace

std::string two_res_note(Language lang, const std::vector<CheckCase>& cases, const StudentReport& report) {
  int two_res_case = 0, other_failures = 0;
  for (const CaseResult& r : report.results) {
    if (r.status == CaseStatus::pass) continue;
    const bool two_res = std::size_t(r.number - 1) < cases.size() && asks_two_res(cases[std::size_t(r.number - 1)]);
    // The checker's own failure says nothing of how the program reads res.
    if (two_res && r.status != CaseStatus::checker_error && two_res_case == 0) two_res_case = r.number;
    else ++other_failures;
  }
  if (two_res_case == 0 || other_failures > 0) return {};
  return textf(lang,
               "fails only the two-resolution case (case %d, res = [res_c, res_l]): your program most likely reads "
               "res as one number. One resolution variable is what the handout requires and all the default "
               "battery asks; this case is asked only by --two-res.\n",
               two_res_case);
}

std::string case_reason(Language lang, const CaseResult& r) {
  return r.status == CaseStatus::fail ? pixel_text(lang, r) : detail_text(lang, r.detail);
}

std::string text_report(const ReportHeader& h, const std::vector<CheckCase>& cases, const StudentReport& report) {
  const Language lang = h.language;
  std::string out =
      textf(lang, "raycam-cli check: %zu {{case|cases}} (mode %s, seed %llu), sandbox: %s\n", cases.size(),
            h.mode.c_str(), h.seed, h.sandboxed ? "bubblewrap" : text(lang, "none"));
  if (!h.sandboxed && !h.sandbox_note.empty()) out += textf(lang, "warning: %s\n", h.sandbox_note.c_str());
  if (!h.limits_note.empty()) out += textf(lang, "warning: %s\n", h.limits_note.c_str());
  // The table's layout has no words of its own (formatted(), not textf(): nothing to look up).
  out += formatted(lang, "%5s  %3s  %-10s  %15s  %s\n", text(lang, "case"), text(lang, "dim"),
                   text(lang, "status"), text(lang, "wrong pixels"), text(lang, "worst pixel or reason"));
  for (const CaseResult& r : report.results) {
    const std::string wrong = r.status == CaseStatus::pass || r.status == CaseStatus::fail
                                  ? std::to_string(r.wrong_pixels) + " / " + std::to_string(r.pixels)
                                  : std::string();
    const std::string why = case_reason(lang, r);
    out += formatted(lang, "%5d  %dD   %-10s  %15s  %s%s\n", r.number, r.dimension,
                     text(lang, status_name(r.status)), wrong.c_str(), why.c_str(),
                     r.md == "differs" ? text(lang, " (md differs)") : "");
  }
  const int n = int(report.results.size());
  out += textf(lang, "score: %d / %d {{case|cases}} passed (%.0f %%)\n",
               report.passed(), n,
               n ? 100.0 * report.passed() / n : 0.0);
  if (const RunTotals t = totals_of(report); t.peak > 0)  // nothing ran for answer files
    out += textf(lang, "runs: %.2f s, %.2f s of CPU in all; peak memory %.1f MiB (case %d)\n", t.wall, t.cpu,
                 double(t.peak) / kMiB, t.peak_case);
  out += two_res_note(lang, cases, report);  // before the diagnosis: a crash on it has none
  bool answered = false;  // a diagnosis needs at least one failing case with an answer to compare
  for (const CaseResult& r : report.results)
    answered = answered || (r.answer && r.status != CaseStatus::pass);
  if (answered) {
    if (report.diagnosis.empty()) {
      out += text(lang, "diagnosis: no classic mistake, alone or in pairs, reproduces your output.\n");
    } else {
      out += text(lang, "diagnosis (mistakes that reproduce your output exactly):\n");
      for (std::size_t i = 0; i < report.diagnosis.size(); ++i) {
        const Explanation& e = report.diagnosis[i];
        out += textf(lang, "  %zu. %s: explains %zu of %d failing {{case|cases}} (%s)\n", i + 1, e.id().c_str(),
                     e.cases.size(), failing(report), case_list(e.cases).c_str());
        out += "     " + e.text(lang) + "\n";
      }
    }
  }
  for (const CaseResult& r : report.results)
    if (r.status != CaseStatus::pass && !r.stderr_text.empty())
      out += textf(lang, "stderr of case %d:\n", r.number) + stderr_excerpt(r.stderr_text);
  return out;
}

// ---- JSON report -------------------------------------------------------------------------------------------
std::string json_report(const ReportHeader& h, const std::vector<CheckCase>& cases, const StudentReport& report) {
  json root;
  root["cases"] = report.results.size();
  root["passed"] = report.passed();
  root["seed"] = h.seed;
  root["mode"] = h.mode;
  root["protocol"] = kProtocolVersion;
  root["two_res"] = h.two_res;
  if (const std::string note = two_res_note(h.language, cases, report); !note.empty())
    root["two_res_note"] = note.substr(0, note.size() - 1);  // the line without its end
  root["sandbox"] = h.sandboxed;
  if (!h.sandbox_note.empty()) root["sandbox_note"] = h.sandbox_note;
  if (!h.limits_note.empty()) root["limits_note"] = h.limits_note;
  json diagnosis = json::array();
  for (const Explanation& e : report.diagnosis) {
    json mistakes = json::array();
    for (const MistakeInfo* m : e.mistakes) mistakes.push_back(m->id);
    diagnosis.push_back({{"mistake", e.id()},
                         {"mistakes", mistakes},
                         {"explains", e.cases.size()},
                         {"cases", e.cases},
                         {"text", e.text(h.language)}});
  }
  root["diagnosis"] = diagnosis;
  json results = json::array();
  for (const CaseResult& r : report.results) {
    json entry = {{"case", r.number},        {"dimension", r.dimension},         {"status", status_name(r.status)},
                  {"wrong_pixels", r.wrong_pixels}, {"pixels", r.pixels}, {"ambiguous_pixels", r.ambiguous_pixels},
                  {"md", r.md},             {"seconds", r.seconds}};
    if (r.worst) {
      json pixel = r.dimension == 2 ? json{{"k", r.worst->column}} : json{{"row", r.worst->row}, {"column", r.worst->column}};
      pixel["expected"] = r.worst->expected;
      pixel["got"] = r.worst->got;
      entry["worst_pixel"] = pixel;
    }
    // What a student controls, escaped as on the terminal: a tool printing the JSON prints no control, and
    // the file is valid UTF-8 whatever the program wrote.
    if (!r.detail.empty()) entry["detail"] = escaped_control(r.detail);
    entry["cpu_seconds"] = r.cpu_seconds;  // the run's status, as isolate's meta file gives it
    entry["peak_memory_bytes"] = r.peak_memory_bytes;
    if (!r.limit.empty()) entry["limit"] = r.limit;
    if (!r.stderr_text.empty()) entry["stderr"] = escaped_control(r.stderr_text, true);
    entry["explained_by"] = r.explained_by;
    results.push_back(entry);
  }
  root["results"] = results;
  // Student text is escaped above; `replace` stays as the last guard: a report is never a crash of the grader.
  return root.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

// ---- CSV -------------------------------------------------------------------------------------------------
namespace {
// A text field holding what a student chose (its folder's name): escaped, and read by a spreadsheet as text.
// One starting with = + - @, a tab or a carriage return would be a live formula (CSV injection: =HYPERLINK,
// =cmd|...): it gets a ' inside double quotes, as OWASP advises. Quoted too when it holds a separator a
// spreadsheet may split on (',', ';' where the locale's list separator is one, as in French, a tab), so that
// no piece of it starts a cell of its own. Numbers raycam writes never come here: a grade is not mangled.
std::string csv_text_field(const std::string& raw) {
  const std::string text = escaped_control(raw);
  const bool formula = !text.empty() && std::string("=+-@\t\r").find(text[0]) != std::string::npos;
  if (!formula && text.find_first_of(",;\"\t\r\n") == std::string::npos) return text;
  std::string quoted = formula ? "\"'" : "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}
}  // namespace

namespace {
// The end of a CSV row: the runs ended by each bound, the CPU seconds of all runs, the largest peak in MiB.
std::string run_bounds_fields(const StudentReport& report) {
  std::string fields;
  for (const char* limit : {kMemoryLimit, kProcessLimit, kDiskLimit, kOutputLimit}) {
    int runs = 0;
    for (const CaseResult& r : report.results) runs += r.limit == limit;
    fields += "," + std::to_string(runs);
  }
  const RunTotals t = totals_of(report);
  char figures[64];
  std::snprintf(figures, sizeof figures, ",%.3f,%.1f", t.cpu, double(t.peak) / kMiB);
  return fields + figures;
}
}  // namespace

std::string csv_header() {
  return "student,passed,cases,score,top_diagnosis,explains,fail,crash,timeout,bad_output,sandbox,checker_error"
         ",memory_limit,process_limit,disk_limit,output_limit,cpu_seconds,peak_memory_mb\n";
}

std::string csv_row(const std::string& student, const StudentReport& report, bool sandboxed) {
  const int n = int(report.results.size());
  char score[32];
  std::snprintf(score, sizeof score, "%.1f", n ? 100.0 * report.passed() / n : 0.0);
  const bool explained = !report.diagnosis.empty();
  return csv_text_field(student) + "," + std::to_string(report.passed()) + "," + std::to_string(n) + "," + score + "," +
         (explained ? report.diagnosis[0].id() : std::string()) + "," +
         (explained ? std::to_string(report.diagnosis[0].cases.size()) : std::string("0")) + "," +
         std::to_string(report.count(CaseStatus::fail)) + "," + std::to_string(report.count(CaseStatus::crash)) + "," +
         std::to_string(report.count(CaseStatus::timeout)) + "," + std::to_string(report.count(CaseStatus::bad_output)) +
         "," + (sandboxed ? "yes" : "no") + "," + std::to_string(report.count(CaseStatus::checker_error)) +
         run_bounds_fields(report) + "\n";
}

// ---- difference images -------------------------------------------------------------------------------------
namespace {
constexpr Rgb8 kGap{255, 255, 255};
constexpr Rgb8 kInvalid{255, 0, 255};
constexpr Rgb8 kWrong{255, 0, 0};
constexpr Rgb8 kAmbiguous{255, 220, 0};

Rgb8 colour_of(const SceneFile& file, int id) {
  return visit_scene(file, [id](const auto& scene) {
    const auto& objects = objects_of(scene);
    if (id < 0) return scene.background;
    if (std::size_t(id) >= objects.size()) return kInvalid;
    return objects[std::size_t(id)].colour;
  });
}

// Protocol index → where it is drawn: a 2D bar in image order (column 0 = the eye's left = pixel n-1).
int drawn_column(int dimension, int columns, int column) { return dimension == 2 ? columns - 1 - column : column; }
}  // namespace

void write_replacing(const std::string& path, const std::function<void(const std::string& temporary)>& write_to) {
  std::string temporary = path + ".XXXXXX";
  const int fd = mkstemp(temporary.data());
  if (fd < 0) throw std::runtime_error(path + ": cannot write");
  ::close(fd);
  try {
    write_to(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot write");
  }
}

void write_text_file(const std::string& path, const std::string& text) {
  write_replacing(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!(out << text) || !out.flush()) throw std::runtime_error(path + ": cannot write");
  });
}

std::vector<std::string> write_difference_images(const std::string& dir, const std::vector<CheckCase>& cases,
                                                 const std::vector<CaseImage>& references,
                                                 const StudentReport& report) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> written;
  for (const CaseResult& r : report.results) {
    if (!r.answer || r.status == CaseStatus::pass) continue;
    const std::size_t i = std::size_t(r.number - 1);
    const SceneFile& file = cases[i].file;
    const CaseImage& ref = references[i];
    const Answer& answer = *r.answer;
    const int height = std::max(ref.rows, answer.rows);
    const int x_student = ref.columns + 1, x_difference = x_student + answer.columns + 1;
    ColourMap canvas(x_difference + ref.columns, height, kGap);
    auto put = [&](int x, int y, Rgb8 colour) { canvas.colours[canvas.index(y, x)] = colour; };
    for (int y = 0; y < ref.rows; ++y)
      for (int x = 0; x < ref.columns; ++x) {
        const std::size_t p = std::size_t(y) * ref.columns + x;
        const int drawn = drawn_column(ref.dimension, ref.columns, x);
        put(drawn, y, colour_of(file, ref.ids[p]));
        const bool inside = y < answer.rows && x < answer.columns;
        const int got = inside ? answer.ids[std::size_t(y) * answer.columns + x] : -2;
        Rgb8 difference = colour_of(file, ref.ids[p]);
        difference = {std::uint8_t(difference.r / 3), std::uint8_t(difference.g / 3), std::uint8_t(difference.b / 3)};
        if (pixel_is_wrong(ref.ambiguous[p], ref.ids[p], got))
          difference = kWrong;
        else if (got != ref.ids[p])
          difference = kAmbiguous;
        put(x_difference + drawn, y, difference);
      }
    for (int y = 0; y < answer.rows; ++y)
      for (int x = 0; x < answer.columns; ++x)
        put(x_student + drawn_column(ref.dimension, answer.columns, x), y,
            colour_of(file, answer.ids[std::size_t(y) * answer.columns + x]));
    // A 2D bar is one pixel high: drawn 48 high and at least ~6 image pixels per map pixel.
    const int scale_x = std::max(1, 480 / std::max(1, canvas.width));
    const int scale_y = ref.dimension == 2 ? 48 : scale_x;
    std::string name = case_file_name(r.number, int(cases.size()));  // case_NN.json → case_NN.png
    const std::string path = dir + "/" + name.replace(name.size() - 5, 5, ".png");
    write_replacing(path, [&](const std::string& temporary) { write_png(canvas, temporary, scale_x, scale_y); });
    written.push_back(path);
  }
  return written;
}

}  // namespace raycam::check
