// `raycam-cli check`: grades a student's camera program (or answer files, or a whole class) on a battery of
// cases and names the classic mistakes that reproduce its output (docs/check.md, "Checking a camera").
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <csignal>
#include <functional>
#include <mutex>
#include <pthread.h>
#include <thread>

#include "check/batch_record.h"
#include "check/check_report.h"
#include "check/check_texts.h"
#include "check/lms_grades.h"
#include "check/escaped_text.h"
#include "check/run_group.h"
#include "check/shown_folders.h"
#include "cli/commands.h"
#include "flags/flag_values.h"
#include "raycam/parallel.h"
#include "raycam/scene_file.h"
#include "flags/view_options.h"

namespace raycam::cli {

namespace {
namespace fs = std::filesystem;
using namespace raycam::check;

struct CheckFlags {
  std::string student, write_cases, answers, batch, student_cmd, csv, report, diff_dir, mode = "both";
  std::optional<Language> lang;
  int cases = 0;  // 0: the designed cases of the mode
  unsigned long long seed = kDefaultSeed;
  double timeout = 10.0;
  int memory_mb = 1024, disk_mb = 256, processes = 256;
  int threads = 0;
  bool require_sandbox = false, no_sandbox = false, require_limits = false;
  bool two_res = false;  // ask the 3D case whose res is [res_c, res_l] (the handout's optional second variable)
  std::string shard, gradescope, visibility = "visible";  // a large course (shards) and grade books
  double scale = kDefaultGradeScale;
};

// Every output named on the command line is checked before the first run: a mistyped folder is bad usage
// (exit 2) at once, not a failure after a class's programs have run.
void require_output(const std::string& flag, const std::string& path, bool folder) {
  if (path.empty()) return;
  std::error_code error;
  fs::path target(path);
  // "reports/" (as the docs write a folder) names reports, whose folder is ".", not what parent_path() says.
  while (!target.has_filename() && target.has_relative_path()) target = target.parent_path();
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string expected = folder ? "a folder to write in (existing, or new in an existing folder)"
                                      : "a file to write (new, or a file to replace) in an existing folder";
  std::string got;
  if (folder && fs::exists(target, error) && !fs::is_directory(target, error)) got = " (not a folder)";
  else if (!folder && fs::is_directory(target, error)) got = " (a folder)";
  else if (!fs::is_directory(parent, error)) got = " (its folder does not exist)";
  else if (access(parent.c_str(), W_OK) != 0 && !(folder && fs::is_directory(target, error))) got = " (not writable)";
  if (!got.empty()) throw std::invalid_argument(flags::bad_value_message(flag, expected, path) + got);
}

// The sandbox to use, or none when --no-sandbox says so (a warning on the terminal); refused otherwise.
std::optional<Sandbox> choose_sandbox(const CheckFlags& flags, ReportHeader& header) {
  if (flags.no_sandbox) {
    header.sandbox_note = "--no-sandbox given";
  } else {
    std::string why;
    if (std::optional<Sandbox> sandbox = probe_sandbox(why)) {
      header.sandboxed = true;
      return sandbox;
    }
    // Never unsandboxed by accident (bwrap missing, or unable to start): only when asked by --no-sandbox.
    throw std::invalid_argument(textf(header.language, "the sandbox cannot start (%s): student programs run only in "
                                      "it, or without one when --no-sandbox is given", why.c_str()));
  }
  std::fprintf(stderr, "raycam-cli check: %s\n",
               textf(header.language, "running student programs WITHOUT a sandbox (%s): they can read and write what you can",
                     header.sandbox_note.c_str())
                   .c_str());
  return std::nullopt;
}

RunLimits limits_of(const CheckFlags& flags) {
  RunLimits limits;
  limits.timeout_seconds = flags.timeout;
  limits.memory_bytes = static_cast<long long>(flags.memory_mb) << 20;
  limits.disk_bytes = static_cast<long long>(flags.disk_mb) << 20;
  limits.max_processes = flags.processes;
  return limits;
}

// Each run bounded as a whole (a control group), or said once at the top of the report (--batch: on the
// terminal, and in each JSON report); --require-limits refuses instead. Returns how many runs may go at once.
int choose_limits(const CheckFlags& flags, ReportHeader& header) {
  const int threads = detail::resolve_threads(flags.threads);
  std::string why;
  if (run_groups_available(why)) return threads;
  if (flags.require_limits) throw std::invalid_argument("--require-limits: runs cannot be bounded as a whole: " + why);
  header.limits_note = "memory not bounded per run: " + why + "; per-process limits instead";
  // bwrap's pid 1 exits without passing its program's CPU time on: only a group counts it (seen: 2 ms for a
  // Python run of 20 ms).
  if (header.sandboxed) header.limits_note += "; CPU seconds not counted (the sandbox's launcher's only)";
  // Without a group, processes are counted per uid (RLIMIT_NPROC). Root's sandboxed runs each have a uid of
  // their own (student_process.cpp); anyone else's runs share one, so a fork bomb would take the processes of
  // every run beside it, a neighbour's or another case of its own author (whose grade would then depend on
  // timing). One run at a time: the next starts once the last one's processes are gone.
  if (!(header.sandboxed && geteuid() == 0)) {
    header.limits_note += "; one run at a time (processes are counted per user, shared by runs side by side)";
    return 1;
  }
  return threads;
}

// What the sandbox will show of the machine (folders_named): refused (bad usage) when it holds the home, an
// output or (in a batch) the class's folder.
void guard_shown_folders(const CheckFlags& flags, const std::vector<std::string>& folders, const std::string& batch_root,
                         const std::string& flag) {
  const char* home = std::getenv("HOME");
  refuse_exposed_folders(folders, home ? home : "", {flags.report, flags.csv, flags.diff_dir, flags.gradescope, batch_root}, flag);
}

// Table, score, diagnosis; --report and --diff-dir. Exit 0 when every case passes, 1 otherwise.
int finish(const CheckFlags& flags, const ReportHeader& header, const std::vector<CheckCase>& cases,
           const std::vector<CaseImage>& references, const StudentReport& report) {
  std::fputs(text_report(header, cases, report).c_str(), stdout);
  if (!flags.report.empty()) write_text_file(flags.report, json_report(header, cases, report));
  if (!flags.gradescope.empty())
    write_text_file(flags.gradescope, gradescope_results_json(header, cases, report, flags.scale, flags.visibility));
  if (!flags.diff_dir.empty()) {
    const std::vector<std::string> written = write_difference_images(flags.diff_dir, cases, references, report);
    std::printf("%s", textf(header.language, "wrote %zu difference {{image|images}} to %s\n", written.size(), flags.diff_dir.c_str()).c_str());
  }
  return report.passed() == int(cases.size()) ? 0 : 1;
}

// ---- --batch ---------------------------------------------------------------------------------------------
// One pass over the template: a folder named "x{dir}" is put in once, never substituted again.
std::string substituted(const std::string& word, const std::string& dir, const std::string& name) {
  std::string out;
  for (std::size_t at = 0; at < word.size();) {
    if (word.compare(at, 5, "{dir}") == 0) {
      out += dir;
      at += 5;
    } else if (word.compare(at, 6, "{name}") == 0) {
      out += name;
      at += 6;
    } else {
      out += word[at++];
    }
  }
  return out;
}

// What the CSV is graded with, and every student of the batch (not only the shard's): written beside the CSV.
BatchRecord batch_record_of(const CheckFlags& flags, const std::vector<Submission>& submissions) {
  BatchRecord record;
  record.seed = flags.seed;
  record.cases = flags.cases > 0 ? flags.cases : designed_case_count(parse_battery_mode(flags.mode, "--mode"));
  record.mode = flags.mode;
  record.two_res = flags.two_res;
  record.timeout_seconds = flags.timeout;
  record.memory_mb = flags.memory_mb;
  record.disk_mb = flags.disk_mb;
  record.processes = flags.processes;
  record.student_cmd = flags.student_cmd;
  if (!flags.shard.empty()) record.shard = parse_shard(flags.shard, "--shard");
  for (const Submission& s : submissions) record.students.push_back(s.name);
  return record;
}

void keep_shard(std::vector<Submission>& submissions, const Shard& shard) {
  submissions.erase(std::remove_if(submissions.begin(), submissions.end(),
                                   [&](const Submission& s) { return shard_of(s.name, shard.count) != shard.index; }),
                    submissions.end());
  std::fprintf(stderr, "shard %s: %zu students\n", shard_text(shard).c_str(), submissions.size());
}

// A shard's exit status says whether it must be graded again (GNU parallel's --resume-failed, a Slurm
// requeue): 1 when a run failed on the checker's side (a checker-error case), 0 once every student of the
// slice has a trustworthy row, whatever the students scored.
int shard_exit_status(const std::vector<StudentReport>& reports) {
  for (const StudentReport& report : reports)
    if (report.count(CaseStatus::checker_error) > 0) return 1;
  return 0;
}

int run_batch(const CheckFlags& flags, ReportHeader& header, const std::vector<CheckCase>& cases,
              const std::vector<CaseImage>& references) {
  if (flags.student_cmd.empty() || flags.csv.empty())
    throw std::invalid_argument("--batch: needs --student-cmd TEMPLATE and --csv FILE");
  const fs::path root = fs::absolute(flags.batch).lexically_normal();
  if (!fs::is_directory(root)) throw std::invalid_argument("--batch: '" + flags.batch + "' is not a folder");
  const std::vector<std::string> words = split_command(flags.student_cmd, "--student-cmd");
  if (flags.student_cmd.find("{dir}") == std::string::npos)
    throw std::invalid_argument(flags::bad_value_message("--student-cmd", "a command naming the student's folder "
                                                         "as {dir} (e.g. \"python3 {dir}/camera.py\")",
                                                         flags.student_cmd));
  const std::optional<Sandbox> sandbox = choose_sandbox(flags, header);
  const int threads = choose_limits(flags, header);
  if (!header.limits_note.empty()) std::fprintf(stderr, "raycam-cli check: %s\n", header.limits_note.c_str());

  std::vector<Submission> submissions;
  for (const fs::directory_entry& entry : fs::directory_iterator(root))
    if (entry.is_directory() && entry.path().filename().string()[0] != '.') {  // a link to a folder too: refused below
      Submission s;
      s.name = entry.path().filename().string();
      const std::string folder = entry.path().string();
      for (const std::string& word : words) s.argv.push_back(substituted(word, folder, s.name));
      // A submission that leads out of its folder is refused in its own row, before anything of it is shown.
      s.refusal = submission_refusal(folder, root.string(), s.argv);
      if (sandbox && s.refusal.empty()) {
        s.sandbox = Sandbox{sandbox->bwrap, {root.string()}, {folder}};
        // The instructor's own paths in the template (the student's are refused above if they leave).
        std::vector<std::string> shown;
        for (const std::string& dir : folders_named(s.argv))
          if (dir != folder && dir.rfind(folder + "/", 0) != 0) shown.push_back(dir);
        guard_shown_folders(flags, shown, root.string(), "--student-cmd");
        if (geteuid() == 0) s.setup_error = unreadable_by_others(folder);
      }
      submissions.push_back(s);
    }
  std::sort(submissions.begin(), submissions.end(), [](auto& a, auto& b) { return a.name < b.name; });
  if (submissions.empty()) throw std::invalid_argument("--batch: no submission folder in '" + flags.batch + "'");
  const BatchRecord record = batch_record_of(flags, submissions);
  if (!flags.shard.empty()) keep_shard(submissions, record.shard);
  write_text_file(battery_sidecar_path(flags.csv), battery_record_json(record));

  // Rows are appended as students finish (nothing is lost if the run is interrupted), then sorted at the end.
  std::ofstream csv(flags.csv, std::ios::trunc);
  if (!csv) throw std::runtime_error(flags.csv + ": cannot write");
  const std::string header_line = with_last_field(csv_header(), grade_column_name(flags.scale));
  csv << header_line << std::flush;
  const Language language = header.language;
  std::fprintf(stderr, "%s",
               textf(language, "%s x %s on %s\n",
                     textf(language, "%zu {{submission|submissions}}", submissions.size()).c_str(),
                     textf(language, "%zu {{case|cases}}", cases.size()).c_str(),
                     textf(language, "%zu {{thread|threads}}", std::size_t(threads)).c_str())
                   .c_str());
  const bool terminal = isatty(2);
  std::size_t students_done = 0, runs_done = 0;
  const auto started = std::chrono::steady_clock::now();
  auto left = [&] {  // at the pace so far, "" until a run has ended
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const std::string text = time_left(language, runs_done, submissions.size() * cases.size(), elapsed);
    return text.empty() ? text : " (" + text + ")";
  };
  auto on_run = [&](std::size_t done, std::size_t total) {
    runs_done = done;
    if (!terminal) return;
    const int width = 30, filled = int(width * done / total);
    // Padded: a shorter line (the time left shrinking) must cover the longer one it replaces.
    std::fprintf(stderr, "\r[%s%s] %s%s   ", std::string(std::size_t(filled), '#').c_str(),
                 std::string(std::size_t(width - filled), '.').c_str(),
                 textf(language, "%zu/%zu {{run|runs}}, %zu/%zu {{student|students}}", done, total, students_done, submissions.size()).c_str(),
                 left().c_str());
    std::fflush(stderr);
  };
  std::vector<std::string> rows(submissions.size());
  std::function<void(std::size_t, const StudentReport&)> record_student;
  std::vector<std::string> output_errors;  // a write that failed for one student: said at the end
  std::mutex output_mutex;
  auto on_student = [&](std::size_t s, const StudentReport& report) {
    try {
      record_student(s, report);
    } catch (const std::exception& error) {  // never out of a worker thread: the batch goes on
      std::lock_guard<std::mutex> lock(output_mutex);
      output_errors.push_back(submissions[s].name + ": " + error.what());
    }
  };
  // The bookkeeping for one student (called from the workers, one student at a time).
  record_student = [&](std::size_t s, const StudentReport& report) {
    ++students_done;
    rows[s] = with_last_field(csv_row(submissions[s].name, report, bool(sandbox)), scaled_grade(report, flags.scale));
    csv << rows[s] << std::flush;
    if (!terminal)
      std::fprintf(stderr, "%zu/%zu %s: %d/%zu%s\n", students_done, submissions.size(),
                   escaped_control(submissions[s].name).c_str(), report.passed(), cases.size(), left().c_str());
    if (!flags.report.empty()) {
      fs::create_directories(flags.report);
      write_text_file(flags.report + "/" + submissions[s].name + ".json", json_report(header, cases, report));
    }
    if (!flags.diff_dir.empty())
      write_difference_images(flags.diff_dir + "/" + submissions[s].name, cases, references, report);
  };
  const std::vector<StudentReport> reports =
      submissions.empty() ? std::vector<StudentReport>()  // a slice with no student in it: a CSV of its header
                          : check_submissions(submissions, cases, references, limits_of(flags), threads, on_run, on_student);
  if (terminal && !submissions.empty()) {
    const std::size_t runs = submissions.size() * cases.size();
    on_run(runs, runs);  // the bar ends at N/N students, whatever order the last callbacks came in
    std::fprintf(stderr, "\n");
  }
  for (const std::string& error : output_errors)  // they name the student's folder
    std::fprintf(stderr, "raycam-cli check: %s\n", escaped_control(error).c_str());
  csv.close();
  std::string sorted = header_line;
  for (const std::string& row : rows) sorted += row;
  write_text_file(flags.csv, sorted);
  std::printf("%s", textf(header.language, "wrote %s (%zu {{student|students}})\n", flags.csv.c_str(), submissions.size()).c_str());
  if (!output_errors.empty()) return 1;
  if (!flags.shard.empty()) return shard_exit_status(reports);
  for (const StudentReport& report : reports)
    if (report.passed() != int(cases.size())) return 1;
  return 0;
}

// Ctrl-C or SIGTERM during a check: the programs still running are killed and their temporary folders
// removed before the process ends (a signal's default action would leave both behind). The signals are
// taken by one thread (sigwait); the workers never see them.
void clean_up_on_interrupt() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGHUP);  // a closed ssh session
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);  // inherited by every thread started after this
  std::thread([signals] {
    int received = 0;
    sigwait(&signals, &received);
    stop_live_runs_for_good();
    std::fprintf(stderr, "\nraycam-cli check: interrupted; the running programs were stopped\n");
    _exit(128 + received);
  }).detach();
}
}  // namespace

int run_check(const Args& args) {
  if (!args.empty() && args[0] == "merge") return run_check_merge(Args(args.begin() + 1, args.end()));
  CheckFlags flags;
  CLI::App app{"Grades a student's camera program on a battery of cases and names the classic mistakes that "
               "reproduce its output. The program reads one case (a scene file, JSON) on stdin and prints "
               "{\"ids\": ..., \"md\": ...} (docs/check.md, \"Checking a camera\"; a start: "
               "examples/student/README.md).",
               "raycam-cli check"};
  app.footer("A large course: --batch DIR --shard i/N on each machine or job, then `raycam-cli check merge --csv "
             "OUT SHARD.csv...` (docs/check.md, \"A large course\"; `check merge --help`).");
  auto* source = app.add_option_group("what to grade");
  source->add_option("--student", flags.student, "the program: \"COMMAND ARGS\" (split like a shell, run without one)");
  source->add_option("--write-cases", flags.write_cases, "write the cases as case_NN.json into DIR and stop");
  source->add_option("--answers", flags.answers, "grade DIR/answer_NN.json, made by hand");
  source->add_option("--batch", flags.batch, "grade every folder of DIR (one student each) with --student-cmd");
  source->require_option(1);
  app.add_option("--student-cmd", flags.student_cmd,
                 "--batch: the command for one student; {dir} is its folder, {name} its name");
  app.add_option("--csv", flags.csv, "--batch: one row per student (score, top diagnosis, faults)");
  using flags::add_checked_option;
  const std::vector<std::string> modes = {"2d", "3d", "both"};
  add_checked_option<int>(app, "--mode", "2d|3d|both", "which cameras the cases use (default both)",
                          flags::one_of(modes), [&](int i) { flags.mode = modes[std::size_t(i)]; });
  app.add_flag("--two-res", flags.two_res,
               "also ask the handout's optional second resolution variable: the 3D case with res = [res_c, res_l] "
               "(the default battery has one number res in every case)");
  add_checked_option<int>(app, "--cases", "N",
                          "number of cases (default: the designed ones, 6 per dimension)",
                          flags::integer_in(1, 1000), [&](int n) { flags.cases = n; });
  add_checked_option<int>(app, "--seed", "S", "the battery's seed (default 2026, shared by a class)",
                          flags::integer_in(0, 2147483647), [&](int seed) { flags.seed = static_cast<unsigned long long>(seed); });
  add_checked_option<double>(app, "--timeout", "SEC", "seconds per case (default 10)",
                             flags::number_in({0.1, 3600}), [&](double t) { flags.timeout = t; });
  add_checked_option<int>(app, "--memory", "MB", "memory of each run, all its processes together, MiB (default 1024)",
                          flags::integer_in(64, 65536), [&](int mb) { flags.memory_mb = mb; });
  add_checked_option<int>(app, "--processes", "N", "processes and threads of each run (default 256)",
                          flags::integer_in(8, 65536), [&](int n) { flags.processes = n; });
  add_checked_option<int>(app, "--disk", "MB", "size of each run's writable folder, MiB (default 256)",
                          flags::integer_in(1, 65536), [&](int mb) { flags.disk_mb = mb; });
  add_checked_option<int>(app, "--threads", "T", "runs at once (default: every core)",
                          flags::integer_in(1, 256), [&](int t) { flags.threads = t; });
  app.add_option("--report", flags.report, "JSON report (--batch: a folder of them)");
  app.add_option("--diff-dir", flags.diff_dir, "PNG per failing case: reference | student | difference");
  add_checked_option<Language>(app, "--lang", flags::language_metavar(),
                               "language of the report (default: from LANG)", flags::language_rule(),
                               [&](Language language) { flags.lang = language; });
  app.add_option("--shard", flags.shard,
                 "--batch: grade only slice i of N (a student's slice is a hash of its folder name)")
      ->type_name("i/N");
  add_checked_option<double>(app, "--scale", "MAX", "the CSV's last column and Gradescope's score: out of MAX (default 20)",
                             flags::number_in({0.01, 1e6}), [&](double scale) { flags.scale = scale; });
  app.add_option("--gradescope", flags.gradescope, "--student or --answers: write Gradescope's results.json to FILE")
      ->type_name("FILE");
  add_checked_option<int>(app, "--visibility", "visible|hidden|after_due_date|after_published",
                          "--gradescope: when students see the tests (default visible)",
                          flags::one_of(gradescope_visibilities()),
                          [&](int i) { flags.visibility = gradescope_visibilities()[std::size_t(i)]; });
  app.add_flag("--require-sandbox", flags.require_sandbox, "refuse to run programs when bubblewrap cannot start (the default)");
  app.add_flag("--no-sandbox", flags.no_sandbox, "run programs without bubblewrap (a warning is printed)");
  app.add_flag("--require-limits", flags.require_limits,
               "refuse to run programs when runs cannot be bounded as a whole (no control group)");
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::ParseError& error) {
    throw std::invalid_argument(flags::usage_error_message(app, error));  // the one message format
  }
  if (flags.require_sandbox && flags.no_sandbox)
    throw std::invalid_argument("--require-sandbox and --no-sandbox contradict each other");

  const bool batch = !flags.batch.empty();
  if (!flags.shard.empty() && !batch) throw std::invalid_argument("--shard: only with --batch");
  if (!flags.shard.empty()) parse_shard(flags.shard, "--shard");  // bad usage before any run
  if (!flags.gradescope.empty() && (batch || !flags.write_cases.empty()))
    throw std::invalid_argument("--gradescope: one submission's results, with --student or --answers");
  require_output("--gradescope", flags.gradescope, false);
  require_output("--report", flags.report, batch);  // --batch: a folder of reports
  require_output("--csv", flags.csv, false);
  require_output("--diff-dir", flags.diff_dir, true);
  require_output("--write-cases", flags.write_cases, true);

  ReportHeader header;
  header.language = check_language(flags.lang);
  header.mode = flags.mode;
  header.seed = flags.seed;
  header.two_res = flags.two_res;
  const BatteryMode mode = parse_battery_mode(flags.mode, "--mode");
  const std::vector<CheckCase> cases =
      make_battery(mode, flags.cases > 0 ? flags.cases : designed_case_count(mode), flags.seed, flags.two_res);
  // An opt-in that asks nothing would be read as passed: bad usage, before any run.
  if (flags.two_res && std::none_of(cases.begin(), cases.end(), asks_two_res))
    throw std::invalid_argument("--two-res: the two-resolution case is a designed 3D case (case 8 with --mode both, "
                                "case 4 with --mode 3d); this battery (--mode " + flags.mode + ", " +
                                std::to_string(cases.size()) + " cases) has none");

  if (!flags.write_cases.empty()) {
    fs::create_directories(flags.write_cases);
    for (std::size_t i = 0; i < cases.size(); ++i)
      write_text_file(flags.write_cases + "/" + case_file_name(int(i) + 1, int(cases.size())),
                      scene_to_json(cases[i].file));
    std::printf("%s", textf(header.language, "wrote %zu case {{file|files}} to %s (answers go in answer_NN.json beside them)\n",
                            cases.size(), flags.write_cases.c_str()).c_str());
    return 0;
  }
  const std::vector<CaseImage> references = reference_images(cases);
  if (!flags.answers.empty()) {
    header.sandbox_note = "answer files: no program run";
    return finish(flags, header, cases, references, check_answer_files(flags.answers, cases, references));
  }
  clean_up_on_interrupt();
  if (!flags.batch.empty()) return run_batch(flags, header, cases, references);

  Submission submission;
  submission.name = "student";
  submission.argv = absolutise_paths(split_command(flags.student, "--student"));
  std::error_code not_a_folder;
  if (fs::is_directory(submission.argv[0], not_a_folder))
    throw std::invalid_argument(flags::bad_value_message("--student", "a program (\"COMMAND ARGS\")",
                                                         flags.student) + " (a folder)");
  if (find_program(submission.argv[0]).empty()) {
    const std::string hint = launch_hint(submission.argv);  // no run bit, Windows line ends
    throw std::invalid_argument("--student: " +
                                (hint.empty() ? "cannot find an executable program '" + submission.argv[0] + "'" : hint));
  }
  submission.sandbox = choose_sandbox(flags, header);
  const int threads = choose_limits(flags, header);
  if (submission.sandbox) {
    guard_shown_folders(flags, folders_named(submission.argv), "", "--student");
    for (const std::string& folder : folders_named(submission.argv))
      if (const std::string why = geteuid() == 0 ? unreadable_by_others(folder) : ""; !why.empty())
        throw std::invalid_argument("--student: " + why);
  }
  const std::vector<StudentReport> reports =
      check_submissions({submission}, cases, references, limits_of(flags), threads);
  return finish(flags, header, cases, references, reports[0]);
}

}  // namespace raycam::cli
