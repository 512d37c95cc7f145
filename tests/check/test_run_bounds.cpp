// A contest grader's guarantees, tried as hostile students would (tests/check/students/misbehaving.py): each
// run bounded as a whole (memory of all its processes, processes, disk), its status in the report and CSV, a
// fresh keyring, nothing shown that the student did not bring, nothing left behind, set-up errors charged to
// the instructor, and text a student controls escaped. Run as root by CTest, and as an ordinary user by
// tests/check/as_ordinary_user.sh (tests needing root say so and return).
#include <linux/keyctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "../scratch_dir.h"
#include "check/check_run.h"
#include "check/escaped_text.h"
#include "check/folder_removal.h"
#include "check/run_group.h"
#include "check/student_process.h"

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace raycam::check;

namespace {
const std::string kPython = std::string("python3 ") + MISBEHAVING_PY;

struct Cli {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// How much slower than a machine's own this one runs (RAYCAM_TEST_TIME_SCALE: the cgroup v2 VM's software
// emulation, tests/vm): the timeouts that a slow but right run must not reach are scaled by it.
double time_scale() {
  const char* scale = std::getenv("RAYCAM_TEST_TIME_SCALE");
  return scale ? std::max(1.0, std::atof(scale)) : 1.0;
}

std::string seconds_text(double seconds) { return std::to_string(int(seconds * time_scale())); }

// `ENV raycam-cli check ARGS` through the shell, with a minute's guard (a hang fails instead of blocking).
Cli raycam_check(const std::string& args, const std::string& env = "") {
  const std::string command = env + " /usr/bin/timeout " + seconds_text(60) + " " + RAYCAM_CLI + " check " + args + " 2>&1";
  Cli result;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  return in ? json::parse(in) : json();
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A submission folder readable by anyone (as a checked-out class is) holding run.sh with `body`, run from the
// folder, beside copies of the test students (a sandbox shows a program its own folder, not the source tree):
// misbehaving.py and camera.py.
std::string submission(const std::string& root, const std::string& name, const std::string& body) {
  const std::string folder = root + "/" + name;
  fs::create_directories(folder);
  std::ofstream(folder + "/run.sh") << "#!/bin/sh\ncd \"$(dirname \"$0\")\"\n" << body << "\n";
  fs::permissions(folder + "/run.sh", fs::perms(0755));
  fs::copy_file(MISBEHAVING_PY, folder + "/misbehaving.py", fs::copy_options::overwrite_existing);
  fs::copy_file(EXAMPLE_STUDENT_PY, folder + "/camera.py", fs::copy_options::overwrite_existing);
  for (const char* file : {"/misbehaving.py", "/camera.py"}) fs::permissions(folder + file, fs::perms(0644));
  fs::permissions(folder, fs::perms(0755));
  return folder;
}

// A scratch folder every user may cross and read (the sandbox's user has no rights of root's).
struct OpenScratch : raycam::test::ScratchDir {
  explicit OpenScratch(const std::string& name) : ScratchDir(name) { fs::permissions(dir, fs::perms(0777)); }
};

bool groups_here() {
  std::string why;
  return run_groups_available(why);
}

std::optional<Sandbox> sandbox_here() {
  std::string why;
  return probe_sandbox(why);
}
}  // namespace

TEST_CASE("bounds: a run's memory counts all its processes together", "[check][bounds][memory]") {
  if (!groups_here()) {
    WARN("no control group here: per-process limits only (tests/check/as_ordinary_user.sh checks the message)");
    return;
  }
  RunLimits limits;
  limits.memory_bytes = 256LL << 20;
  limits.timeout_seconds *= time_scale();  // the memory bound, not the clock, must end the hog
  const std::vector<std::string> hog = {"python3", MISBEHAVING_PY, "hog", "4", "100"};  // 400 MiB in 4 processes
  const RunResult bounded = run_student(hog, "", limits, sandbox_here());
  CHECK(bounded.limit == kMemoryLimit);
  CHECK(bounded.bounded_per_run);
  // The same run under per-process caps alone holds its 400 MiB: what the group adds.
  limits.use_run_groups = false;
  const RunResult per_process = run_student(hog, "", limits, sandbox_here());
  CHECK(per_process.end == RunResult::End::exited);
  CHECK(per_process.exit_code == 0);
  CHECK(per_process.limit.empty());
  // Files in memory count too: 8 memory files of 64 MiB are no address space at all.
  const std::vector<std::string> memfd = {"python3", MISBEHAVING_PY, "memfd", "8", "64"};
  CHECK(run_student(memfd, "", limits, sandbox_here()).err == "held\n");
  limits.use_run_groups = true;
  CHECK(run_student(memfd, "", limits, sandbox_here()).limit == kMemoryLimit);
}

TEST_CASE("bounds: a run's CPU time counts all its processes and ends it like the wall clock",
          "[check][bounds][cpu]") {
  if (!groups_here()) return;  // per process (RLIMIT_CPU) without a group
  RunLimits limits;
  limits.timeout_seconds = 60;
  limits.cpu_seconds = 0.5;
  // Two processes spinning: the run's CPU time grows twice as fast as either's.
  const std::string spin = "import os\nos.fork()\nwhile True: pass\n";
  const RunResult run = run_student({"python3", "-c", spin}, "", limits, sandbox_here());
  CHECK(run.end == RunResult::End::timed_out);
  CHECK(run.limit == kTimeLimit);
  CHECK(run.seconds < 30);  // the CPU bound, not the wall clock's minute
  CHECK(run.cpu_seconds >= 0.5);
}

TEST_CASE("bounds: a run's writable folder is a tmpfs of --disk MB: a full disk is that run's failure",
          "[check][bounds][disk]") {
  const std::optional<Sandbox> sandbox = sandbox_here();
  if (!sandbox) return;  // the tmpfs is the sandbox's
  RunLimits limits;
  limits.disk_bytes = 8LL << 20;
  const RunResult run = run_student({"python3", MISBEHAVING_PY, "disk", "64"}, "", limits, sandbox);
  CHECK(run.limit == kDiskLimit);
  CHECK_THAT(run.err, Catch::Contains("disk stopped after 8 MiB") || Catch::Contains("disk stopped after 7 MiB"));
  limits.disk_bytes = 128LL << 20;  // room enough: the same program writes its 64 MiB
  const RunResult roomy = run_student({"python3", MISBEHAVING_PY, "disk", "64"}, "", limits, sandbox);
  CHECK(roomy.limit.empty());
  CHECK_THAT(roomy.err, Catch::Contains("wrote 64 MiB"));
}

TEST_CASE("bounds: a run's processes are its own: a bomb is stopped at --processes and named",
          "[check][bounds][processes]") {
  if (!groups_here()) return;
  RunLimits limits;
  limits.max_processes = 40;
  limits.timeout_seconds = 20 * time_scale();
  const RunResult run = run_student({"python3", MISBEHAVING_PY, "bomb", "1"}, "", limits, sandbox_here());
  CHECK(run.limit == kProcessLimit);
  int started = -1;
  std::sscanf(run.err.c_str() + std::min(run.err.size(), run.err.find("bomb started")), "bomb started %d", &started);
  CHECK(started >= 0);
  CHECK(started < 40);
}

// Without a group and as an ordinary user, processes are counted per user: the runs then go one at a time.
TEST_CASE("bounds: a fork bomb beside a correct program fails only its author", "[check][bounds][processes][cli]") {
  const OpenScratch scratch("bomb");
  const std::string root = scratch.path("class");
  fs::create_directories(root);
  fs::permissions(root, fs::perms(0755));
  submission(root, "a-bomb", "exec python3 misbehaving.py bomb 4");
  // The neighbour needs 32 processes of its own (within its 64) once the bomb has taken what it could, then
  // answers right.
  submission(root, "b-neighbour",
             "sleep 1\npython3 misbehaving.py forks 32 2>&1 | grep -q 'started 32' || exit 3\nexec python3 camera.py");
  const std::string csv = scratch.path("grades.csv");
  const Cli c = raycam_check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + csv +
                             " --cases 2 --threads 4 --timeout " + seconds_text(20) + " --processes 64");
  INFO(c.output);
  const std::vector<std::string> rows = lines_of(csv);
  REQUIRE(rows.size() == 3);
  CHECK(rows[2].rfind("b-neighbour,2,2,100.0,", 0) == 0);  // every case passed
  // A check started by a process that has groups has them too (in cgroup v2, from inside the leaf its
  // starter moved into); without, an ordinary user's runs go one at a time, said once.
  if (groups_here()) CHECK_THAT(c.output, !Catch::Contains("not bounded per run"));
  else if (geteuid() != 0) CHECK_THAT(c.output, Catch::Contains("one run at a time") && Catch::Contains("1 thread"));
}

TEST_CASE("bounds: each run's status (CPU, peak memory, the bound that ended it) is in the report and the CSV",
          "[check][bounds][status][cli]") {
  const OpenScratch scratch("status");
  const std::string report = scratch.path("report.json");
  Cli c = raycam_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --cases 2 --report " + report);
  CHECK(c.exit_code == 0);
  CHECK_THAT(c.output, Catch::Contains("s of CPU in all; peak memory"));  // the terminal's summary
  const json r = read_json(report);
  REQUIRE(r["results"].size() == 2);
  for (const json& result : r["results"]) {
    CHECK(result["cpu_seconds"].get<double>() > 0);
    CHECK(result["cpu_seconds"].get<double>() <= result["seconds"].get<double>() * 2 + 0.05);
    CHECK(result["peak_memory_bytes"].get<long long>() > 100 * 1024);  // a process's pages at least
    CHECK_FALSE(result.contains("limit"));
  }
  // A batch row ends with the runs ended by each bound, the CPU seconds and the largest peak, then the grade.
  const std::string root = scratch.path("class");
  submission(root, "hog", "exec python3 misbehaving.py memory");
  const std::string csv = scratch.path("grades.csv");
  c = raycam_check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + csv + " --cases 1 --memory 128");
  const std::vector<std::string> rows = lines_of(csv);
  REQUIRE(rows.size() == 2);
  CHECK_THAT(rows[0], Catch::EndsWith(",memory_limit,process_limit,disk_limit,output_limit,cpu_seconds,peak_memory_mb,grade_20"));
  if (groups_here()) CHECK_THAT(rows[1], Catch::Contains(",yes,0,1,0,0,0,"));  // memory-limit once
}

TEST_CASE("bounds: a run has a fresh session keyring: no key of the checker's session or of an earlier run",
          "[check][bounds][keyring]") {
  if (find_program("keyctl").empty()) {
    WARN("keyctl (Debian package keyutils) missing: keyring test skipped");
    return;
  }
  // This test's own session keyring, holding the instructor's token (kept out of the user's real session).
  REQUIRE(syscall(SYS_keyctl, KEYCTL_JOIN_SESSION_KEYRING, "raycam-test-session") >= 0);
  const long token = syscall(SYS_add_key, "user", "raycam-instructor-token", "s3cret", 6, KEY_SPEC_SESSION_KEYRING);
  REQUIRE(token > 0);
  const std::optional<Sandbox> sandbox = sandbox_here();
  for (const std::optional<Sandbox>& where : {sandbox, std::optional<Sandbox>()}) {
    INFO((where ? "sandboxed" : "not sandboxed"));
    const RunLimits limits;
    const RunResult read = run_student({"keyctl", "print", std::to_string(token)}, "", limits, where);
    CHECK(read.out.find("s3cret") == std::string::npos);
    CHECK(read.exit_code != 0);
    const RunResult shown = run_student({"keyctl", "show", "@s"}, "", limits, where);
    CHECK(shown.out.find("raycam-instructor-token") == std::string::npos);
    // A key one run leaves in its session keyring is not in the next run's. Sandboxed, keyctl is refused
    // outright (the system-call filter): no key can be added at all.
    const RunResult left = run_student({"keyctl", "add", "user", "raycam-left", "x", "@s"}, "", limits, where);
    CHECK((left.exit_code == 0) == !where);
    const RunResult found = run_student({"keyctl", "search", "@s", "user", "raycam-left"}, "", limits, where);
    CHECK(found.exit_code != 0);
  }
}

TEST_CASE("bounds: a run's temporary folder is removed whatever modes it set", "[check][bounds][cleanup]") {
  const OpenScratch scratch("removal");
  const std::string folder = scratch.path("run");
  // As an ordinary user (root ignores modes): root checks this as nobody, in a child.
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    if (geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0)) _exit(3);
    std::error_code error;
    fs::create_directories(folder + "/locked/inner", error);
    std::ofstream(folder + "/locked/inner/file") << "x";
    chmod((folder + "/locked/inner").c_str(), 0500);
    chmod((folder + "/locked").c_str(), 0500);
    fs::create_directories(folder + "/closed", error);
    chmod((folder + "/closed").c_str(), 0);
    _exit(remove_folder_whatever_modes(folder) ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK_FALSE(fs::exists(folder));
}

TEST_CASE("bounds: a run that locks folders in its own (modes 500, 000) leaves nothing in TMPDIR",
          "[check][bounds][cleanup][cli]") {
  const OpenScratch scratch("locked");
  const std::string tmp = scratch.path("tmp");
  fs::create_directories(tmp);
  fs::permissions(tmp, fs::perms(01777));
  // Unsandboxed (the sandbox's folder is a tmpfs, never on the host) and, under root, as nobody: root would
  // ignore the modes.
  const std::string as_user = geteuid() == 0 ? "/usr/bin/setpriv --reuid 65534 --regid 65534 --clear-groups" : "";
  const Cli c = raycam_check("--no-sandbox --student \"" + kPython + " lock\" --cases 2", "TMPDIR=" + tmp + " " + as_user);
  INFO(c.output);
  CHECK(c.exit_code == 1);  // graded (bad output), not failed
  CHECK(fs::is_empty(tmp));
}

TEST_CASE("bounds: a hang-up (closed ssh session) stops the programs and leaves no folder nor group",
          "[check][bounds][cleanup][cli]") {
  const OpenScratch scratch("hangup");
  const std::string tmp = scratch.path("tmp");
  fs::create_directories(tmp);
  fs::permissions(tmp, fs::perms(01777));  // like /tmp: a sandboxed run's own uid makes its folder here
  const std::string command = "TMPDIR=" + tmp + " " + RAYCAM_CLI + " check --student \"" + kPython +
                              " hang\" --cases 2 --timeout 60 > " + scratch.path("out.txt") +
                              " 2>&1 & pid=$!; sleep 2; kill -HUP $pid; wait $pid; echo $? $pid";
  FILE* shell = popen(command.c_str(), "r");
  REQUIRE(shell);
  int code = 0, pid = 0;
  REQUIRE(fscanf(shell, "%d %d", &code, &pid) == 2);
  pclose(shell);
  CHECK(code == 128 + SIGHUP);
  CHECK(fs::is_empty(tmp));
  const std::string groups = "find /sys/fs/cgroup -maxdepth 5 -name 'raycam-run-" + std::to_string(pid) + "-*' 2>/dev/null";
  FILE* found = popen(groups.c_str(), "r");
  REQUIRE(found);
  char line[512] = {};
  CHECK(fgets(line, sizeof line, found) == nullptr);  // no group left
  pclose(found);
}

TEST_CASE("bounds: the sandbox never shows the home, an output's folder or the class's folder",
          "[check][bounds][exposure][cli]") {
  const OpenScratch scratch("exposure");
  const std::string home = scratch.path("home");
  fs::create_directories(home);
  fs::copy_file(EXAMPLE_STUDENT_PY, home + "/camera.py");
  Cli c = raycam_check("--student \"python3 " + home + "/camera.py\" --cases 1", "HOME=" + home);
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("home") && Catch::Contains("a folder of its own"));
  // The program beside the report it would read.
  const std::string work = scratch.path("work");
  fs::create_directories(work);
  fs::copy_file(EXAMPLE_STUDENT_PY, work + "/camera.py");
  c = raycam_check("--student \"python3 " + work + "/camera.py\" --cases 1 --report " + work + "/report.json");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("report.json") && Catch::Contains("a folder of its own"));
  // A batch command naming a file of the class's folder would show every student's folder.
  const std::string root = scratch.path("class");
  submission(root, "alice", "exit 0");
  std::ofstream(root + "/grader.sh") << "#!/bin/sh\n";
  c = raycam_check("--batch " + root + " --student-cmd \"sh " + root + "/grader.sh {dir}\" --csv " +
                   scratch.path("g.csv") + " --cases 1");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("--student-cmd") && Catch::Contains("a folder of its own"));
}

TEST_CASE("bounds: a batch inside a shown system folder (/usr/local) shows no student the others' folders",
          "[check][bounds][exposure][cli]") {
  if (geteuid() != 0 || !sandbox_here()) return;  // making a folder in /usr/local needs root
  // /usr is shown to every run: a class kept under it is hidden behind an empty folder, the student's own
  // shown again inside it.
  const fs::path root = fs::path("/usr/local") / ("raycam-class-" + std::to_string(getpid()));
  fs::remove_all(root);
  const std::string secret = submission(root.string(), "bob", "exit 0") + "/secret.txt";
  std::ofstream(secret) << "bob's answer";
  fs::permissions(secret, fs::perms(0644));
  const std::string alice = (root / "alice").string();
  submission(root.string(), "alice", "exec python3 misbehaving.py snoop list.txt");
  std::ofstream(alice + "/list.txt") << secret << "\n";
  fs::permissions(alice + "/list.txt", fs::perms(0644));
  const OpenScratch scratch("opt");
  const Cli c = raycam_check("--batch " + root.string() + " --student-cmd \"{dir}/run.sh\" --csv " +
                             scratch.path("g.csv") + " --cases 1 --report " + scratch.path("reports"));
  const json report = read_json(scratch.path("reports/alice.json"));
  fs::remove_all(root);
  INFO(c.output);
  REQUIRE(report.is_object());
  CHECK_THAT(report["results"][0]["stderr"].get<std::string>(), Catch::Contains("stopped " + secret));
}

TEST_CASE("bounds: set-up errors are the instructor's (exit 2 or checker-error), never the student's crash",
          "[check][bounds][setup][cli]") {
  const OpenScratch scratch("setup");
  const std::string root = scratch.path("class");
  const std::string csv = scratch.path("g.csv");
  // --student-cmd without {dir}: every student would crash.
  submission(root, "alice", "exec python3 camera.py");
  Cli c = raycam_check("--batch " + root + " --student-cmd \"python3 camera.py\" --csv " + csv + " --cases 1");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("--student-cmd") && Catch::Contains("{dir}"));
  // A script with Windows line ends, and a program without its run bit: the student's, with a hint.
  const std::string crlf = submission(root, "carol", "") + "/run.sh";
  std::ofstream(crlf, std::ios::binary) << "#!/bin/sh\r\nexit 0\r\n";
  c = raycam_check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + csv + " --cases 1 --report " +
                   scratch.path("reports"));
  CHECK_THAT(read_json(scratch.path("reports/carol.json"))["results"][0]["detail"].get<std::string>(),
             Catch::Contains("Windows line ends"));
  // The usual Python first line: env starts, then finds no 'python3\r' (exit 127): the same hint.
  const std::string env_crlf = submission(root, "erin", "") + "/run.sh";
  std::ofstream(env_crlf, std::ios::binary) << "#!/usr/bin/env python3\r\nprint('{}')\r\n";
  c = raycam_check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + csv + " --cases 1 --report " +
                   scratch.path("reports"));
  CHECK_THAT(read_json(scratch.path("reports/erin.json"))["results"][0]["detail"].get<std::string>(),
             Catch::Contains("Windows line ends"));
  const std::string plain = scratch.path("camera");
  fs::copy_file(EXAMPLE_STUDENT_CPP, plain);
  fs::permissions(plain, fs::perms(0644));
  c = raycam_check("--student " + plain + " --cases 1");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("no run bit"));
  // A bound out of its range names the flag and the range, before any run.
  for (const auto& [flag, range] : {std::pair<const char*, const char*>{"--disk 0", "--disk: expected an integer in [1, 65536]"},
                                    {"--processes 2", "--processes: expected an integer in [8, 65536]"},
                                    {"--memory 10", "--memory: expected an integer in [64, 65536]"}}) {
    c = raycam_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --cases 1 " + flag);
    CHECK(c.exit_code == 2);
    CHECK_THAT(c.output, Catch::Contains(range));
  }
  // bwrap missing: refused unless --no-sandbox is given.
  const std::string empty_path = scratch.path("bin");
  fs::create_directories(empty_path);
  c = raycam_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --cases 1", "PATH=" + empty_path);
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("--no-sandbox"));
  c = raycam_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --cases 1 --no-sandbox", "PATH=" + empty_path);
  CHECK(c.exit_code == 0);
  if (geteuid() != 0) return;  // the rest: a folder root can read but the sandbox's user cannot
  const std::string closed = submission(root, "dave", "exec python3 camera.py");
  fs::permissions(closed, fs::perms(0700));
  const std::string graded = scratch.path("g2.csv");
  c = raycam_check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + graded + " --cases 2");
  bool seen = false;
  for (const std::string& row : lines_of(graded))
    if (row.rfind("dave,", 0) == 0) {
      seen = true;
      CHECK(row.find(",0,2,0.0,,0,0,0,0,0,yes,2,") != std::string::npos);  // 2 checker errors, no crash
    }
  CHECK(seen);
  c = raycam_check("--student " + closed + "/run.sh --cases 1");
  CHECK(c.exit_code == 2);
  CHECK_THAT(c.output, Catch::Contains("not readable by other users"));
}

TEST_CASE("bounds: a folder named x{dir} is substituted once, and control characters are shown escaped",
          "[check][bounds][text][cli]") {
  const OpenScratch scratch("text");
  const std::string root = scratch.path("class");
  submission(root, "x{dir}", "exec python3 camera.py");
  submission(root, "e\x1b[2Jq", "exec python3 misbehaving.py terminal");
  const std::string csv = scratch.path("g.csv");
  const Cli c = raycam_check("--batch " + root + " --student-cmd \"{dir}/run.sh\" --csv " + csv + " --cases 1");
  CHECK(c.exit_code == 1);  // it ends (it used to loop forever)
  const std::vector<std::string> rows = lines_of(csv);
  REQUIRE(rows.size() == 3);
  CHECK(rows[1].rfind("e\\x1b[2Jq,0,1,", 0) == 0);
  CHECK(rows[2].rfind("x{dir},1,1,", 0) == 0);
  CHECK(c.output.find('\x1b') == std::string::npos);
  const Cli single = raycam_check("--student \"" + kPython + " terminal\" --cases 1");
  CHECK(single.output.find('\x1b') == std::string::npos);
  CHECK_THAT(single.output, Catch::Contains("| \\x1b[2J\\x1b[Hscore: 12 / 12"));
  // The 8-bit CSI alone is not UTF-8: escaped as well (tests/check/test_escaped_text.cpp, byte by byte).
  CHECK(escaped_control("a\x9b" "b\xc2\x9b" "c\x7f\td\n", false) == "a\\x9b" "b\\xc2\\x9bc\\x7f\td\\x0a");
}

TEST_CASE("bounds: without a control group the report says so once, and --require-limits refuses",
          "[check][bounds][fallback][cli]") {
  if (groups_here()) return;  // tests/check/as_ordinary_user.sh runs this where no group can be made
  const Cli c = raycam_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --cases 1");
  CHECK(c.exit_code == 0);
  CHECK_THAT(c.output, Catch::Contains("memory not bounded per run: no control group can be made here: "));
  // Why, and what to type (cgroup v2: a scope with -p Delegate=yes, without which nothing is delegated).
  if (access("/sys/fs/cgroup/cgroup.controllers", F_OK) == 0)
    CHECK_THAT(c.output, Catch::Contains("systemd-run --user --scope -p Delegate=yes raycam-cli check"));
  else
    CHECK_THAT(c.output, Catch::Contains("cannot write its cgroup v1 group") || Catch::Contains("cgroup v1 has no"));
  // A sandboxed run's CPU time then reads as bwrap's own (a few ms): said, not shown as the program's.
  if (c.output.find("sandbox: bubblewrap") != std::string::npos)
    CHECK_THAT(c.output, Catch::Contains("CPU seconds not counted"));
  const Cli refused = raycam_check(std::string("--student ") + EXAMPLE_STUDENT_CPP + " --cases 1 --require-limits");
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.output, Catch::Contains("--require-limits"));
}

TEST_CASE("bounds: a submission that leads out of its folder is refused in its own row, the class graded",
          "[check][bounds][exposure][cli]") {
  const OpenScratch scratch("refused");
  const std::string root = scratch.path("class");
  submission(root, "alice", "exit 0");
  fs::remove(submission(root, "bob", "exit 0") + "/camera.py");
  fs::create_directory_symlink("/", root + "/bob/camera.py");  // the whole machine as a "script"
  fs::remove(submission(root, "carol", "exit 0") + "/camera.py");
  fs::create_symlink("../alice/camera.py", root + "/carol/camera.py");  // a neighbour's file
  fs::create_directory_symlink(root + "/alice", root + "/dave");  // a folder that is a link
  const std::string csv = scratch.path("g.csv"), reports = scratch.path("reports");
  const Cli c = raycam_check("--batch " + root + " --student-cmd \"python3 {dir}/camera.py\" --csv " + csv +
                             " --cases 1 --report " + reports);
  INFO(c.output);
  CHECK(c.exit_code == 1);  // students failed: never 2 (the batch refused) for one submission's links
  const std::vector<std::string> rows = lines_of(csv);
  REQUIRE(rows.size() == 5);
  for (const std::string& row : rows) {
    if (row.rfind("student,", 0) == 0) continue;
    INFO(row);
    const bool passes = row.rfind("alice,1,1,", 0) == 0;
    CHECK((passes || row.rfind("bob,0,1,", 0) == 0 || row.rfind("carol,0,1,", 0) == 0 ||
           row.rfind("dave,0,1,", 0) == 0));
  }
  const std::pair<const char*, const char*> reasons[] = {
      {"bob", "camera.py leads out of the student's folder (to /)"},
      {"carol", "camera.py leads out of the student's folder"},
      {"dave", "the submission folder dave is a symbolic link"}};
  for (const auto& [student, reason] : reasons) {
    INFO(student);
    const json report = read_json(reports + "/" + student + ".json");
    REQUIRE(report.is_object());
    CHECK(report["results"][0]["status"] != "checker-error");
    CHECK_THAT(report.dump(), Catch::Contains(reason));
  }
}

TEST_CASE("bounds: a killed check's control groups are swept by the next check", "[check][bounds][cleanup][sweep][cli]") {
  if (geteuid() != 0 || !groups_here()) return;  // root's groups: made where any check of root's makes them
  const pid_t dead = fork();  // a checker pid that no longer runs
  if (dead == 0) _exit(0);
  REQUIRE(dead > 0);
  waitpid(dead, nullptr, 0);
  // Where the next check makes its runs' groups: cgroup v2's root, or under this process's own group in
  // cgroup v1's memory hierarchy (a child check inherits it).
  fs::path parent = "/sys/fs/cgroup";
  if (!fs::exists("/sys/fs/cgroup/cgroup.controllers")) {
    std::ifstream self("/proc/self/cgroup");
    std::string own;
    for (std::string line; std::getline(self, line);)
      if (line.find(":memory:") != std::string::npos) own = line.substr(line.find(":memory:") + 8);
    parent = fs::path("/sys/fs/cgroup/memory") / fs::path(own).relative_path();
  }
  const fs::path run = parent / ("raycam-run-" + std::to_string(dead) + "-0");
  const fs::path check = parent / ("raycam-check-" + std::to_string(dead));
  const fs::path inner = check / ("raycam-run-" + std::to_string(dead) + "-1");
  const fs::path alive = parent / ("raycam-run-" + std::to_string(getpid()) + "-999");
  for (const fs::path& folder : {run, check, inner, alive}) REQUIRE(fs::create_directory(folder));
  const Cli c = raycam_check(std::string("--student \"python3 ") + EXAMPLE_STUDENT_PY + "\" --cases 1");
  INFO(c.output);
  CHECK_FALSE(fs::exists(run));
  CHECK_FALSE(fs::exists(inner));
  CHECK_FALSE(fs::exists(check));
  CHECK(fs::exists(alive));  // its checker (this test) still runs
  fs::remove(alive);
}
