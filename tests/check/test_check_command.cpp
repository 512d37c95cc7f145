// `raycam-cli check` end to end, with "student" programs written for these tests independently of raycam's
// core (tests/check/students/): the examples pass, each classic mistake and some pairs are named, programs
// that crash, hang, print garbage or too much are reported per case, the memory cap holds, the sandbox
// stops a program that writes outside its folder or opens a socket, --answers, --batch (CSV), --diff-dir
// and bad usage.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "raycam/classic_mistakes.h"
#include "raycam/scene_file.h"
#include "../scratch_dir.h"
#include "check/student_process.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {
constexpr int kDefaultCases = 12;  // the designed battery, 6 per dimension

// A folder of its own for each use, inside this process's temporary folder (removed at exit).
std::string scratch(const std::string& name) {
  static const raycam::test::ScratchDir root("check");
  const std::string dir = root.path("check_scratch_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct Checked {
  int exit_code = -1;
  json report;  // --report FILE (--batch: a folder, read by the test)
  std::string report_path;
  std::string output;
};

// Runs `raycam-cli check ARGS --report FILE` and reads back the report (when one was written).
Checked check(const std::string& args, const std::string& name) {
  const std::string dir = scratch(name);
  const std::string report = dir + "/report.json", output = dir + "/output.txt";
  const std::string command =
      std::string(RAYCAM_CLI) + " check " + args + " --report " + report + " > " + output + " 2>&1";
  Checked result;
  const int status = std::system(command.c_str());
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream text(output);
  std::stringstream buffer;
  buffer << text.rdbuf();
  result.output = buffer.str();
  result.report_path = report;
  std::ifstream in(report);
  if (in && fs::is_regular_file(report)) result.report = json::parse(in);
  return result;
}

std::string mistaken(const std::string& mistakes, bool md = false) {
  return std::string("--student \"") + MISTAKEN_STUDENT + " --mistake " + mistakes + (md ? " --md" : "") +
         "\"";
}

std::string top_diagnosis(const Checked& c) {
  return c.report["diagnosis"].empty() ? std::string("(none)")
                                       : c.report["diagnosis"][0]["mistake"].get<std::string>();
}

bool sandbox_works() {
  std::string why;
  return bool(raycam::check::probe_sandbox(why));
}

// PNG width and height from the IHDR chunk (bytes 16-23, big-endian).
std::pair<int, int> png_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), 24);
  auto be = [&](int at) {
    return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3];
  };
  return {be(16), be(20)};
}
}  // namespace

TEST_CASE("the example students (C++ and Python) pass the default battery", "[check][cli]") {
  for (const std::string student :
       {std::string(EXAMPLE_STUDENT_CPP), std::string("python3 ") + EXAMPLE_STUDENT_PY}) {
    INFO(student);
    const Checked c = check("--student \"" + student + "\"", "examples");
    CHECK(c.exit_code == 0);
    CHECK(c.report["cases"] == kDefaultCases);
    CHECK(c.report["passed"] == kDefaultCases);
    CHECK(c.report["sandbox"] == sandbox_works());
    for (const json& r : c.report["results"]) CHECK(r["md"] == "match");
  }
}

TEST_CASE("check names each classic mistake first, alone", "[check][cli][diagnosis]") {
  for (const raycam::MistakeInfo& mistake : raycam::kClassicMistakes) {
    INFO(mistake.id);
    const Checked c = check(mistaken(mistake.id), std::string("single_") + mistake.id);
    CHECK(c.exit_code == 1);
    const int failing = kDefaultCases - c.report["passed"].get<int>();
    CHECK(failing > 0);
    CHECK(top_diagnosis(c) == mistake.id);
    CHECK(c.report["diagnosis"][0]["explains"] == failing);
  }
}

TEST_CASE("check names pairs of mistakes", "[check][cli][diagnosis]") {
  // The pair's ID lists its mistakes in the table's order.
  for (const auto& [given, named] :
       {std::pair<std::string, std::string>{"no_t_min,mirrored", "mirrored+no_t_min"},
        {"degrees_as_radians,pixel_edges", "pixel_edges+degrees_as_radians"},
        {"eye_origin,skip_renormalise", "skip_renormalise+eye_origin"},
        {"theta_phi_swapped,no_focal_scale", "no_focal_scale+theta_phi_swapped"},
        {"res_truncated,direction_translated", "direction_translated+res_truncated"}}) {
    INFO(given);
    const Checked c = check(mistaken(given), "pair");
    CHECK(c.exit_code == 1);
    CHECK(top_diagnosis(c) == named);
    CHECK(c.report["diagnosis"][0]["explains"] == kDefaultCases - c.report["passed"].get<int>());
  }
}

TEST_CASE("upside down and mirrored + rows flipped give one image, md tells them apart",
          "[check][cli][diagnosis]") {
  Checked c = check(mistaken("upside_down"), "upside_ids");
  REQUIRE(c.report["diagnosis"].size() >= 2);
  CHECK(c.report["diagnosis"][0]["mistake"] == "upside_down");  // the simplest first
  CHECK(c.report["diagnosis"][1]["mistake"] == "mirrored+rows_flipped");
  CHECK(c.report["diagnosis"][0]["explains"] == c.report["diagnosis"][1]["explains"]);

  c = check(mistaken("upside_down", true), "upside_md");
  REQUIRE(c.report["diagnosis"].size() == 1);
  CHECK(c.report["diagnosis"][0]["mistake"] == "upside_down");

  c = check(mistaken("mirrored,rows_flipped", true), "flipped_md");
  CHECK(top_diagnosis(c) == "mirrored+rows_flipped");
  for (const json& d : c.report["diagnosis"]) CHECK(d["mistake"] != "upside_down");
}

TEST_CASE("crashing, hanging, garbage-printing and huge-output students are reported per case",
          "[check][cli]") {
  const std::string student = std::string("--student \"python3 ") + MISBEHAVING_PY + " ";
  for (const auto& [mode, status, detail] :
       {std::tuple<const char*, const char*, const char*>{"crash", "crash", "exit status 1"},
        {"abort", "crash", "SIGABRT"},
        {"hang", "timeout", "timeout"},
        {"garbage", "bad-output", "not JSON"},
        {"huge", "bad-output", "MiB on stdout"},
        {"no-read", "bad-output", "expected 48 ids, got 0"},
        {"bad-ids", "bad-output", "expected an id in [-1, 3]"}}) {
    INFO(mode);
    // Only the hanging one gets a short timeout: under load, Python alone may take a second to start.
    const std::string timeout = std::string(mode) == "hang" ? " --timeout 1" : "";
    const Checked c = check(student + mode + "\" --cases 2" + timeout, std::string("bad_") + mode);
    CHECK(c.exit_code == 1);  // reported, not crashed: a crash of raycam-cli would give no report
    REQUIRE(c.report["results"].size() == 2);
    for (const json& r : c.report["results"]) CHECK(r["status"] == status);
    CHECK_THAT(c.report["results"][0]["detail"].get<std::string>(), Catch::Contains(detail));
  }
  const Checked crashed = check(student + "crash\" --cases 1", "bad_crash_stderr");
  CHECK_THAT(crashed.report["results"][0]["stderr"].get<std::string>(), Catch::Contains("fell over"));
  CHECK_THAT(crashed.output, Catch::Contains("fell over"));
}

TEST_CASE("the memory cap stops a student that allocates too much", "[check][cli][sandbox]") {
  const std::string student = std::string("--student \"python3 ") + MISBEHAVING_PY + " memory\" --cases 1";
  const Checked capped = check(student + " --memory 128", "memory_capped");
  CHECK(capped.report["results"][0]["status"] == "crash");
  if (capped.report.contains("limits_note"))  // no control group here: the address space per process
    CHECK_THAT(capped.report["results"][0]["stderr"].get<std::string>(), Catch::Contains("MemoryError"));
  else  // the run's group: killed at its bound, named as such
    CHECK(capped.report["results"][0]["limit"] == "memory-limit");
  const Checked roomy = check(student + " --memory 1024", "memory_roomy");  // it allocates, then answers nonsense
  CHECK(roomy.report["results"][0]["status"] == "bad-output");
}

// Canaries outside /tmp (the sandbox's own empty /tmp would hide them whatever the sandbox shows): a folder
// of its own under /var/tmp, removed at the end.
struct VarTmpDir {
  fs::path dir = fs::path("/var/tmp") / ("raycam-canary-" + std::to_string(getpid()));
  VarTmpDir() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~VarTmpDir() { fs::remove_all(dir); }
  std::string plant(const std::string& name, fs::perms perms = fs::perms::owner_read | fs::perms::owner_write) const {
    const fs::path file = dir / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file) << "secret";
    fs::permissions(file, perms);
    return file.string();
  }
};

TEST_CASE("the sandbox stops a student writing outside its folder or opening a socket",
          "[check][cli][sandbox]") {
  // A TCP server on the host's loopback, and a file path outside the student's folder.
  const int server = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(bind(server, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
  REQUIRE(listen(server, 4) == 0);
  socklen_t length = sizeof address;
  getsockname(server, reinterpret_cast<sockaddr*>(&address), &length);
  fcntl(server, F_SETFL, O_NONBLOCK);
  const VarTmpDir outside_dir;  // not under /tmp, which the sandbox replaces by an empty folder of its own
  const std::string outside = (outside_dir.dir / "escaped.txt").string();
  const std::string student = std::string("--student \"python3 ") + MISBEHAVING_PY + " escape " +
                              std::to_string(ntohs(address.sin_port)) + " " + outside + "\" --cases 1";
  auto connections = [&] {
    int count = 0;
    for (int fd; (fd = accept(server, nullptr, nullptr)) >= 0; ++count) close(fd);
    return count;
  };

  if (sandbox_works()) {
    const Checked c = check(student + " --require-sandbox", "escape_sandboxed");
    CHECK(c.report["sandbox"] == true);
    CHECK(connections() == 0);
    CHECK_FALSE(fs::exists(outside));
    CHECK_THAT(c.report["results"][0]["stderr"].get<std::string>(), Catch::Contains("write stopped"));
  } else {
    const Checked c = check(student + " --require-sandbox", "escape_refused");
    CHECK(c.exit_code == 2);  // refused: nothing ran
    CHECK_THAT(c.output, Catch::Contains("--require-sandbox"));
  }
  // Without the sandbox the same program gets out: the checks above can fail.
  const Checked open = check(student + " --no-sandbox", "escape_open");
  CHECK(open.report["sandbox"] == false);
  CHECK_THAT(open.output, Catch::Contains("WITHOUT a sandbox"));
  CHECK(connections() == 1);
  CHECK(fs::exists(outside));
  close(server);
}

TEST_CASE("the sandbox shows a student only what running needs", "[check][cli][sandbox]") {
  if (!sandbox_works()) return;  // the sandbox cannot start here: the test above checks the refusal
  const VarTmpDir canaries;
  // The student's own folder, world-readable as a checked-out submission is, with a file only its owner reads.
  const std::string own = canaries.plant("alice/camera.py", fs::perms(0644));
  fs::copy_file(MISBEHAVING_PY, own, fs::copy_options::overwrite_existing);
  fs::permissions(canaries.dir / "alice", fs::perms(0755));
  fs::permissions(canaries.dir, fs::perms(0755));
  const std::string owners_only = canaries.plant("alice/owners-only.txt");
  const std::string home = canaries.plant("home/prof/.ssh/id_ed25519");
  const std::string beside = canaries.plant("bob/camera.py", fs::perms(0644));  // another student
  const std::string other_report = canaries.plant("reports/previous.json", fs::perms(0644));  // the CSV's folder
  const std::vector<std::string> secrets = {home, beside, other_report, owners_only, "/etc/shadow", "/root/.bashrc"};
  // The list goes in a file of the student's own folder: paths on its command line would be shown to it.
  const std::string list = canaries.plant("alice/secrets.txt", fs::perms(0644));
  {
    std::ofstream names(list);
    for (const std::string& secret : secrets) names << secret << "\n";
  }
  const Checked c = check("--student \"python3 " + own + " snoop " + list + "\" --cases 1 --require-sandbox", "snoop");
  INFO(c.output);
  REQUIRE(c.report.is_object());
  REQUIRE(c.report["sandbox"] == true);
  const std::string err = c.report["results"][0]["stderr"].get<std::string>();
  for (const std::string& secret : secrets) {
    INFO(err);
    // Root gives each run a uid of its own: the owner's file is closed to it. An ordinary user cannot: the
    // program has that user's rights on what it is shown (docs/check.md, "Run by an ordinary user").
    if (secret == owners_only && geteuid() != 0)
      CHECK_THAT(err, Catch::Contains("read " + secret));
    else
      CHECK_THAT(err, Catch::Contains("stopped " + secret));
  }
  if (geteuid() == 0) CHECK_THAT(err, !Catch::Contains("uid 0\n"));  // never root's rights in the sandbox
}

TEST_CASE("deadlines hold to fractions of a second: a program inside its limit passes, one past it times out",
          "[check][cli][timeout]") {
  // The example student behind a sleep: `sh -c 'sleep S; exec STUDENT' STUDENT`. No sandbox: the limit is
  // the same with it, and the run starts faster (0.3 s is the margin on each side).
  auto run = [](const char* limit, const char* sleep) {
    const std::string student = std::string("--student \"sh -c 'sleep ") + sleep + "; exec \\$0' " +
                                EXAMPLE_STUDENT_CPP + "\"";
    return check(student + " --mode 2d --cases 1 --no-sandbox --timeout " + limit,
                 std::string("deadline_") + limit + "_" + sleep);
  };
  for (const auto& [limit, sleep, status] : {std::tuple<const char*, const char*, const char*>{"0.5", "0.2", "pass"},
                                             {"1.5", "1.2", "pass"},
                                             {"0.5", "0.8", "timeout"},
                                             {"1.5", "1.8", "timeout"}}) {
    INFO("--timeout " << limit << ", a program of " << sleep << " s");
    const Checked c = run(limit, sleep);
    INFO(c.output);
    REQUIRE(c.report["results"].size() == 1);
    const json& result = c.report["results"][0];
    CHECK(result["status"] == status);
    if (std::string(status) == "timeout") {  // stopped at its limit, not before
      CHECK(result["seconds"].get<double>() >= std::stod(limit) - 0.01);
      CHECK(result["seconds"].get<double>() < std::stod(sleep));
    }
  }
}

TEST_CASE("write-cases then answers: answer files made by hand are graded", "[check][cli]") {
  const std::string dir = scratch("answers");
  const Checked written = check("--write-cases " + dir, "write_cases");
  CHECK(written.exit_code == 0);
  for (int i = 1; i <= kDefaultCases; ++i) {
    // Any length of folder (a long TMPDIR cut a 64-byte name short).
    const std::string name = dir + "/case_" + (i < 10 ? "0" : "") + std::to_string(i) + ".json";
    CHECK_NOTHROW(raycam::load_scene_file(name));  // the scene-file format of the README
    std::string answer = name;
    answer.replace(answer.find("case_"), 5, "answer_");
    REQUIRE(std::system((std::string(EXAMPLE_STUDENT_CPP) + " < " + name + " > " + answer).c_str()) == 0);
  }
  Checked c = check("--answers " + dir, "answers_all");
  CHECK(c.exit_code == 0);
  CHECK(c.report["passed"] == kDefaultCases);

  fs::remove(dir + "/answer_03.json");
  c = check("--answers " + dir, "answers_missing");
  CHECK(c.exit_code == 1);
  CHECK(c.report["passed"] == kDefaultCases - 1);
  CHECK(c.report["results"][2]["status"] == "bad-output");
}

TEST_CASE("batch grades every folder in parallel into one CSV row each (a hanging one included)",
          "[check][cli][batch]") {
  const std::string root = scratch("batch");
  // Each submission holds its own program, as a student's folder would: the sandbox shows a program only
  // its own folder (a build tree under /tmp would be hidden behind the sandbox's empty /tmp).
  auto student = [&](const std::string& name, const std::string& program, const std::string& command) {
    const std::string folder = root + "/" + name;
    fs::create_directories(folder);
    fs::copy_file(program, folder + "/" + fs::path(program).filename().string());
    const std::string run = folder + "/run.sh";
    std::ofstream(run) << "#!/bin/sh\ncd \"$(dirname \"$0\")\"\nexec " << command << "\n";
    // Runnable by anyone, as an unzipped or cloned submission is: run by root, a sandboxed program has no
    // more rights than any user.
    fs::permissions(run, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add);
  };
  const auto file_name = [](const char* path) { return fs::path(path).filename().string(); };
  student("alice", EXAMPLE_STUDENT_CPP, "./" + file_name(EXAMPLE_STUDENT_CPP));
  student("bob", MISTAKEN_STUDENT, "./" + file_name(MISTAKEN_STUDENT) + " --mistake mirrored");
  student("carol", MISBEHAVING_PY, "python3 " + file_name(MISBEHAVING_PY) + " hang");
  const std::string csv = root + "/grades.csv";
  const Checked c =
      check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + csv + " --cases 2 --timeout 1",
            "batch_run");
  CHECK(c.exit_code == 1);
  std::ifstream in(csv);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  REQUIRE(lines.size() == 4);
  CHECK(lines[0].rfind("student,passed,cases,score,top_diagnosis", 0) == 0);
  CHECK(lines[1].rfind("alice,2,2,100.0,,0,0,0,0,0,", 0) == 0);
  CHECK(lines[2].rfind("bob,0,2,0.0,mirrored,2,2,0,0,0,", 0) == 0);
  CHECK(lines[3].rfind("carol,0,2,0.0,,0,0,0,2,0,", 0) == 0);
  std::ifstream bob(c.report_path + "/bob.json");  // --report in --batch: one report per student
  REQUIRE(bob);
  CHECK(json::parse(bob)["diagnosis"][0]["mistake"] == "mirrored");
}

TEST_CASE("diff-dir writes reference then student then difference per failing case (2D bars tall)",
          "[check][cli]") {
  const std::string dir = scratch("diff");
  const Checked c = check(mistaken("mirrored") + " --cases 2 --diff-dir " + dir, "diff_run");
  CHECK(c.exit_code == 1);
  const auto [width2, height2] = png_size(dir + "/case_01.png");  // 2D, 48 pixels
  CHECK(width2 >= 3 * 48);
  CHECK(height2 >= 32);
  const auto [width3, height3] = png_size(dir + "/case_02.png");  // 3D, 40 × 30
  CHECK(width3 >= 3 * 40);
  CHECK(height3 >= 30);
  CHECK(double(width3) / height3 >= 3.0 * 40 / 30);  // three panels side by side, square pixels
}

TEST_CASE("bad usage exits 2 with the flag named", "[check][cli]") {
  CHECK(check("", "usage_none").exit_code == 2);
  CHECK(check("--student true --answers x", "usage_two").exit_code == 2);
  for (const auto& [args, named] : {std::pair<std::string, std::string>{"--student true --mode 4d", "--mode"},
                                    {"--batch . --student-cmd x", "--csv"},
                                    {"--student \"'unclosed\"", "--student: unclosed"},
                                    {"--student no-such-program-raycam", "no-such-program-raycam"},
                                    {"--student true --timeout 0", "--timeout"},
                                    {"--student true --seed abc", "--seed: expected an integer in [0, 2147483647], got 'abc'"}}) {
    INFO(args);
    const Checked c = check(args, "usage");
    CHECK(c.exit_code == 2);
    CHECK_THAT(c.output, Catch::Contains(named));
  }
}

TEST_CASE("lang fr gives the table and the score and the diagnosis in French", "[check][cli]") {
  const Checked c = check(mistaken("mirrored") + " --lang fr", "french");
  CHECK_THAT(c.output, Catch::Contains("cas réussis"));
  CHECK_THAT(c.output, Catch::Contains("diagnostic"));
  CHECK_THAT(c.output, Catch::Contains("le pixel k va à l'indice k"));
  CHECK_THAT(c.report["diagnosis"][0]["text"].get<std::string>(), Catch::Contains("le pixel k"));
}

TEST_CASE("bad outputs, a folder as the program and a repeated flag are bad usage before any run",
          "[check][cli][usage]") {
  const std::string dir = scratch("usage");
  const std::string file = dir + "/a-file";
  std::ofstream(file) << "x";
  const std::string example = "--student \"python3 " + std::string(EXAMPLE_STUDENT_PY) + "\" --cases 1";
  Checked c = check(example + " --diff-dir " + file, "usage_diff_file");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("--diff-dir: expected a folder") && Catch::Contains("(not a folder)"));
  CHECK_THAT(c.output, !Catch::Contains("score"));  // nothing ran
  c = check(example + " --csv " + dir + "/missing/grades.csv", "usage_csv");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("--csv: expected a file") && Catch::Contains("does not exist"));
  // A new folder written with a trailing slash, as docs/check.md writes them, is in an existing folder.
  c = check("--write-cases " + dir + "/new-cases/", "usage_new_folder");
  CHECK(c.exit_code == 0);
  CHECK(fs::is_regular_file(dir + "/new-cases/case_01.json"));
  c = check(example + " --diff-dir " + dir + "/new-diffs/", "usage_new_diffs");
  CHECK(c.exit_code == 0);
  c = check("--student " + dir, "usage_student_folder");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("--student: expected a program") && Catch::Contains("(a folder)"));
  c = check(example + " --student \"python3 x.py\"", "usage_twice");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("raycam-cli check: error: --student: expected one value, given more than once"));
  // A batch whose --diff-dir is a file stops before its first student.
  fs::create_directories(dir + "/class/alice");
  c = check("--batch " + dir + "/class --student-cmd \"{dir}/run.sh\" --csv " + dir + "/g.csv --diff-dir " + file,
            "usage_batch_diff");
  CHECK(c.exit_code == 2);
  CHECK_FALSE(fs::exists(dir + "/g.csv"));
}

TEST_CASE("an interrupted check stops its programs and leaves no temporary folder", "[check][cli][signal]") {
  const std::string dir = scratch("interrupt");
  const std::string tmp = dir + "/tmp";
  fs::create_directories(tmp);
  fs::permissions(tmp, fs::perms::all);  // like /tmp: a sandboxed run's own uid makes its folder here
  const std::string command = "TMPDIR=" + tmp + " " + RAYCAM_CLI + " check --student \"python3 " +
                              MISBEHAVING_PY + " hang\" --cases 2 --timeout 60 > " + dir +
                              "/out.txt 2>&1 & pid=$!; sleep 2; kill -INT $pid; wait $pid; echo $?";
  FILE* shell = popen(command.c_str(), "r");
  REQUIRE(shell);
  char status[16] = {};
  REQUIRE(fgets(status, sizeof status, shell));
  pclose(shell);
  CHECK(std::string(status) == "130\n");  // 128 + SIGINT
  CHECK(fs::is_empty(tmp));  // the runs' folders are gone
}

TEST_CASE("the text report's score line counts the cases passed", "[check][cli][report]") {
  // A mirrored camera passes the cases where mirroring changes nothing, fails the others.
  const Checked c = check(mistaken("mirrored") + " --mode 2d", "score_line");
  const int passed = c.report["passed"].get<int>(), cases = int(c.report["results"].size());
  REQUIRE(passed < cases);  // a mix, so that passed and failed counts differ
  const std::string line = "score: " + std::to_string(passed) + " / " + std::to_string(cases) + " cases passed";
  CHECK_THAT(c.output, Catch::Contains(line));
}

TEST_CASE("outputs replace a link left where they go, never write through it", "[check][cli][usage]") {
  const std::string dir = scratch("links");
  const std::string victim = dir + "/victim.txt", diffs = dir + "/diffs";
  std::ofstream(victim) << "keep me";
  fs::create_directories(diffs);
  fs::create_symlink(victim, diffs + "/case_01.png");  // where the first failing case's image goes
  fs::create_symlink(victim, dir + "/report-link.json");
  const Checked c = check(mistaken("mirrored") + " --no-sandbox --diff-dir " + diffs, "links_run");
  REQUIRE(c.exit_code == 1);
  std::ifstream in(victim);
  std::string content;
  std::getline(in, content);
  CHECK(content == "keep me");
  CHECK_FALSE(fs::is_symlink(diffs + "/case_01.png"));
  CHECK(fs::is_regular_file(diffs + "/case_01.png"));
}

TEST_CASE("a look-at camera with square pixels is named square_pixels", "[check][cli][diagnosis]") {
  // An independent camera (Ray Tracing in One Weekend's frame from P, C and up = z), not the mistaken
  // student's switch: what students bring. It agrees on the square 2D bars and near the poles.
  const Checked c = check(std::string("--student \"python3 ") + LOOKAT_PY + " " + EXAMPLES_DIR + "\"", "lookat");
  CHECK(c.exit_code == 1);
  CHECK(top_diagnosis(c) == "square_pixels");
  CHECK(c.report["diagnosis"][0]["explains"] == kDefaultCases - c.report["passed"].get<int>());
}

TEST_CASE("the French report says why in French, details included", "[check][cli][language]") {
  for (const char* mode : {"crash", "garbage", "bad-ids"}) {
    INFO(mode);
    const Checked c = check(std::string("--lang fr --cases 1 --student \"python3 ") + MISBEHAVING_PY + " " + mode + "\"",
                            std::string("fr_") + mode);
    CHECK_THAT(c.output, Catch::Contains("score : 0 / 1 cas réussi"));
    for (const char* english : {"exit status", "expected", "not JSON", "got "}) CHECK_THAT(c.output, !Catch::Contains(english));
  }
  const Checked wrong = check("--lang fr --mode 2d --cases 1 --student \"python3 -c 'print(\\\"{\\\\\\\"ids\\\\\\\": [0]}\\\")'\"", "fr_size");
  CHECK_THAT(wrong.output, Catch::Contains("identifiants ; reçu : 1"));
}

TEST_CASE("batch counts one submission, one case and one thread in the singular", "[check][cli][batch]") {
  const std::string root = scratch("singular_batch");
  const std::string folder = root + "/alice";
  fs::create_directories(folder);
  const std::string run = folder + "/run.sh";
  std::ofstream(run) << "#!/bin/sh\nexec " << MISTAKEN_STUDENT << " --mistake mirrored\n";
  fs::permissions(run, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
  const Checked c = check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + root + "/grades.csv" +
                              " --mode 2d --cases 1 --threads 1 --no-sandbox",
                          "singular_batch_run");
  INFO(c.output);
  CHECK(c.output.find("1 submission x 1 case on 1 thread\n") != std::string::npos);
}
