// One language per window, error reasons included: every reason core, io and the checker can put in front of
// the user is produced here from its real code path, then translated (raycam/language.h's translate_reason).
// Its French must differ from the English, keep the variable parts (paths, numbers, field names) and hold
// none of the English words around them; every pattern of the table must serve at least one real reason.
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "../scratch_dir.h"
#include "check/answer.h"
#include "session/app_options.h"
#include "session/app_state.h"
#include "check/case_image.h"
#include "check/check_report.h"
#include "check/check_run.h"
#include "session/figure_export.h"
#include "raycam/zip_archive.h"
#include "session/shown_files.h"
#include <unistd.h>
#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/exact_bar.h"
#include "raycam/image_files.h"
#include "raycam/language.h"
#include "raycam/limits.h"
#include "raycam/scene.h"
#include "raycam/scene_file.h"
#include "raycam/view_setup.h"
#include "session/text.h"

using namespace raycam;
namespace fs = std::filesystem;

namespace {
struct Reason {
  std::string english;            // what the code threw or reported
  std::vector<std::string> kept;  // its variable parts, which the French must show as they are
};

std::string thrown_by(const std::function<void()>& code) {
  try {
    code();
  } catch (const std::exception& error) {
    return error.what();
  }
  FAIL("expected an exception");
  return {};
}

std::string scene_error(const std::string& text) {
  return thrown_by([&] { parse_scene_json(text, "lesson.json"); });
}

// A 2D scene of two circles with a complete camera, as the checker needs it (width `n`).
SceneFile small_case() {
  return parse_scene_json(R"({"dimension": 2, "objects": [
      {"type": "circle", "center": [0, 0], "radius": 1}, {"type": "circle", "center": [3, 0], "radius": 1}],
      "camera": {"target": [0, 0], "d": 6, "theta": 90, "df": 1.5, "res": 1, "size": [4]}})",
                          "case.json");
}

std::string answer_error(const std::string& text, int dimension = 2) {
  return dimension == 2 ? check::parse_answer(text, 2, 1, 4, 2).error
                        : check::parse_answer(text, 3, 2, 2, 2).error;
}

check::RunResult ended(check::RunResult::End end, int code = 0) {
  check::RunResult run;
  run.end = end;
  run.exit_code = run.signal = code;
  return run;
}

std::string detail_of(const check::RunResult& run) {
  const check::CheckCase c{"the current camera", small_case()};
  return check::result_of_run(1, c, check::render_case(c.file), run).detail;
}

// Sets TMPDIR for one scope.
struct TemporaryFolder {
  explicit TemporaryFolder(const char* value) {
    if (const char* old = std::getenv("TMPDIR")) saved = old;
    ::setenv("TMPDIR", value, 1);
  }
  ~TemporaryFolder() {
    if (saved.empty())
      ::unsetenv("TMPDIR");
    else
      ::setenv("TMPDIR", saved.c_str(), 1);
  }
  std::string saved;
};

// The numbers of `text` ("line 3, column 11" → 3, 11).
std::vector<std::string> numbers_of(const std::string& text) {
  std::vector<std::string> numbers;
  for (std::size_t at = 0; (at = text.find_first_of("0123456789", at)) != std::string::npos;) {
    const std::size_t end = std::min(text.find_first_not_of("0123456789", at), text.size());
    numbers.push_back(text.substr(at, end - at));
    at = end;
  }
  return numbers;
}

// Every reason family, from the code that writes it.
std::vector<Reason> real_reasons(const test::ScratchDir& scratch) {
  std::vector<Reason> out;
  auto add = [&](std::string english, std::vector<std::string> kept) {
    for (const std::string& number : numbers_of(english)) kept.push_back(number);  // every number, as it is
    out.push_back({english, kept});
  };

  // ---- io: reading a scene file ----
  const std::string missing = scratch.path("missing.json");
  add(thrown_by([&] { load_scene_file(missing); }), {missing});
  const std::string huge = scratch.path("huge.json");
  std::ofstream(huge).put('{');
  fs::resize_file(huge, kMaxSceneFileBytes + 1);  // sparse: nothing is written
  add(thrown_by([&] { load_scene_file(huge); }), {huge, "256"});
  const std::string folder_reason = thrown_by([&] { load_scene_file(scratch.dir.string()); });
  CHECK(folder_reason.find("is a folder") != std::string::npos);  // not "larger than the limit"
  add(folder_reason, {scratch.dir.string()});
  // A file that holds less than its size says (sysfs gives every file 4096 bytes) cannot be read in full.
  const std::string short_file = "/sys/devices/system/cpu/online";
  add(thrown_by([&] { load_scene_file(short_file); }), {short_file});
  add(scene_error("{\"dimension\": tru}"), {"lesson.json", "tru}"});  // the word the reader stopped on
  add(scene_error("{1: 2}"), {"lesson.json"});
  add(scene_error("{\"a\" 1}"), {"lesson.json"});
  add(scene_error("{\"a\": 1 \"b\": 2}"), {"lesson.json"});
  add(scene_error("[1 2]"), {"lesson.json"});
  add(scene_error(""), {"lesson.json"});
  add(scene_error("{\"a\": \"abc"), {"lesson.json"});
  add(scene_error("{\"a\": \"a\nb\"}"), {"lesson.json"});
  add(scene_error("{\"a\": \"\xff\"}"), {"lesson.json"});
  add(scene_error("{\"a\": \"\\q\"}"), {"lesson.json"});
  add(scene_error("{\"a\": -x}"), {"lesson.json", "-x"});
  add(scene_error("{\"a\": 1} x"), {"lesson.json"});
  add(scene_error("{} {}"), {"lesson.json", "{"});
  add(scene_error("\xEF\xBB{}"), {"lesson.json"});  // a broken byte order mark
  add(scene_error("{\"dimension\": 1e999}"), {"lesson.json", "1e999"});

  // ---- io: a scene file's fields ----
  add(scene_error(R"({"dimension": 3, "objects": [], "colour": 1})"),
      {"lesson.json", "colour", "dimension, background, objects, camera"});
  add(scene_error("[1]"), {"lesson.json", "[1]"});
  add(scene_error(R"({"objects": []})"), {"lesson.json", "dimension"});
  add(scene_error(R"({"dimension": "3", "objects": []})"), {"lesson.json", "dimension", "[2, 3]", "\"3\""});
  add(scene_error(R"({"dimension": 3, "objects": 1})"), {"lesson.json", "objects"});
  add(scene_error(R"({"dimension": 3, "objects": [1]})"), {"lesson.json", "objects[0]", "\"type\""});
  add(scene_error(R"({"dimension": 3, "objects": [{"type": "circle"}]})"),
      {"lesson.json", "objects[0].type", "sphere", "3D", "\"circle\""});
  add(scene_error(R"({"dimension": 3, "objects": [{"type": 1}]})"), {"lesson.json", "objects[0].type"});
  add(scene_error(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0]}]})"),
      {"lesson.json", "objects[0].center", "3", "[0,0]"});
  add(scene_error(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, "x", 0]}]})"),
      {"lesson.json", "objects[0].center[1]", "\"x\""});
  add(scene_error(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]})"),
      {"lesson.json", "objects[0].radius", "]0, 1e12]", "-1"});
  add(scene_error(
          R"({"dimension": 2, "objects": [{"type": "circle", "center": [0, 0], "radius": 1, "color": [1, 2]}]})"),
      {"lesson.json", "objects[0].color", "3", "[0, 255]", "[1,2]"});
  add(scene_error(R"({"dimension": 2, "objects": [], "camera": 1})"), {"lesson.json", "camera"});
  add(scene_error(R"({"dimension": 2, "objects": [], "camera": {"theta": 1e7}})"),
      {"lesson.json", "camera.theta", "[-1e6, 1e6]", "10000000.0"});
  add(scene_error(R"({"dimension": 3, "objects": [], "camera": {"res": [0.5]}})"),
      {"lesson.json", "camera.res", "]0, 1]", "[0.5]"});
  add(scene_error(R"({"dimension": 3, "objects": [], "camera": {"res": [0.5, 0]}})"),
      {"lesson.json", "camera.res[1]", "]0, 1]"});
  add(scene_error(R"({"dimension": 3, "objects": [], "camera": {"size": [1]}})"),
      {"lesson.json", "camera.size"});
  add(scene_error(R"({"dimension": 3, "objects": [], "camera": {"size": [16384, 16384]}})"),
      {"lesson.json", "camera.size", std::to_string(kMaxPixels3D)});
  std::string many = "{\"dimension\": 2, \"objects\": [0";
  for (std::size_t i = 0; i < kMaxObjects; ++i) many += ",0";
  add(scene_error(many + "]}"), {"lesson.json", "objects", std::to_string(kMaxObjects)});

  // ---- io: writing ----
  SceneFile file;
  file.dimension = 2;
  file.scene2d.circles.resize(1);
  const std::string nowhere = scratch.path("no-such-folder/lesson.json");
  add(thrown_by([&] { save_scene_file(file, nowhere); }), {nowhere});
  const std::string folder = scratch.path("a-folder");
  fs::create_directories(folder + "/inside");  // rename() never replaces a folder that holds something
  add(thrown_by([&] { save_scene_file(file, folder); }), {folder});
  const std::string limited = scratch.path("limited.json");
  {
    // A file size limit makes the write itself fail, as a full disk would.
    rlimit old{};
    getrlimit(RLIMIT_FSIZE, &old);
    rlimit small = old;
    small.rlim_cur = 8;
    const auto previous = ::signal(SIGXFSZ, SIG_IGN);
    setrlimit(RLIMIT_FSIZE, &small);
    add(thrown_by([&] { save_scene_file(file, limited); }), {limited});
    setrlimit(RLIMIT_FSIZE, &old);
    ::signal(SIGXFSZ, previous);
  }
  const std::string png = scratch.path("empty.png");
  add(thrown_by([&] { write_png(ColourMap(0, 0, Rgb8{}), png); }), {png});
  const std::string unwritable = scratch.path("no-such-folder/map.png");
  add(thrown_by([&] { write_png(ColourMap(2, 2, Rgb8{}), unwritable); }), {unwritable});
  // The page's one download of several files (shown_files.h): an archive that cannot be written, a file gone.
  const std::string archive_folder = scratch.path("no-such-folder");
  add(thrown_by([&] { raycam::write_zip(archive_folder + "/steps.zip", {{"a.tex", "x"}}); }), {archive_folder + "/steps.zip"});
  const std::string gone = scratch.path("gone.tex");
  add(thrown_by([&] { session::as_one_download({gone}, "steps.zip"); }), {gone});

  // ---- the construction figure, exported from the window ----
  session::AppOptions options;
  options.language = Language::en;
  const session::AppState app = session::make_app_state(options);
  const std::string svg = scratch.path("no-such-folder/figure.svg");
  add(thrown_by([&] { session::export_construction_figure(app, {}, svg, false); }), {svg, scratch.path("no-such-folder")});
  // A figure is written under a temporary name (figure_files.h) made to open /dev/full: every write fails.
  for (const char* name : {"full.png", "full.svg"}) {
    const std::string full = scratch.path(name);
    fs::create_symlink("/dev/full", full + ".part" + std::to_string(::getpid()));
    const std::string reason = thrown_by([&] { session::export_construction_figure(app, {}, full, false); });
    if (reason.find('(') == std::string::npos) add(reason, {full});
    else add(reason, {full, reason.substr(reason.rfind('(') + 1)});  // the drawing library's reason, as it is
  }
  // A PNG whose temporary name is taken by a folder cannot even be opened.
  const std::string blocked = scratch.path("blocked.png");
  fs::create_directories(blocked + ".part" + std::to_string(::getpid()));
  add(thrown_by([&] { session::export_construction_figure(app, {}, blocked, false); }), {blocked});

  // ---- io: the scene file against the command line's flags ----
  const std::string scene3d = scratch.path("three.json");
  const std::string scene2d = scratch.path("two.json");
  std::ofstream(scene3d) << R"({"dimension": 3, "objects": []})";
  std::ofstream(scene2d) << R"({"dimension": 2, "objects": []})";
  auto setup_error = [&](const std::string& path, const std::function<void(ViewFlags&)>& set) {
    ViewFlags flags;
    flags.scene_path = path;
    set(flags);
    return thrown_by([&] { make_view_setup(flags); });
  };
  add(setup_error(scene3d, [](ViewFlags& f) { f.dimension = 2; }), {"--mode", "2", scene3d, "3D"});
  add(setup_error(scene3d,
                  [](ViewFlags& f) {
                    f.camera.target = std::vector<double>{1, 2};
                  }),
      {"--target", "x,y,z", "3D"});
  add(setup_error(scene2d, [](ViewFlags& f) { f.camera.phi_deg = 10; }), {"--phi", "3D", "2D"});
  add(setup_error(scene2d,
                  [](ViewFlags& f) {
                    f.camera.size = std::vector<int>{4, 4};
                  }),
      {"--size", "N", "2D"});
  add(setup_error(scene2d,
                  [](ViewFlags& f) {
                    f.camera.res = 0.5;
                    f.camera.res_rows = 0.25;
                  }),
      {"--res", "R", "RC,RL", "2D", "3D"});
  add(setup_error(scene2d, [](ViewFlags& f) { f.camera.size = std::vector<int>{kMaxPixels2D + 1}; }),
      {"--size", "N", std::to_string(kMaxPixels2D), "2D"});
  add(setup_error(scene3d, [](ViewFlags& f) { f.camera.size = std::vector<int>{kMaxSide3D + 1}; }),
      {"--size", "N", std::to_string(kMaxSide3D)});

  // ---- core: a camera or scene out of range ----
  Camera2D camera(64);
  add(thrown_by([&] { camera.set_free({1, 2}, {1, 2}, 1.5); }), {"position", "(P = C)", "P != C"});
  add(thrown_by([&] { camera.set_orbit(Orbit2D{{0, 0}, 0.0}); }), {"d", "0", "]0, 1e12]"});
  add(thrown_by([&] { camera.set_orbit(Orbit2D{{0, 0}, 6.0, 1.0, 0.0}); }), {"df", "0", "[1e-9, 1e9]"});
  add(thrown_by([&] { camera.set_orbit(Orbit2D{{0, 0}, 6.0, 1e7}); }), {"theta", "1e+07", "|angle| <= 1e6"});
  add(thrown_by([&] { camera.set_orbit(Orbit2D{{1e13, 0}}); }), {"target.x", "1e+13", "[-1e12, 1e12]"});
  add(thrown_by([&] { camera.set_res(2.0); }), {"res", "2", "]0, 1]"});
  add(thrown_by([] { Camera3D(0, 4); }), {"size (columns)", std::to_string(kMaxSide3D)});
  Scene2D crowded;
  crowded.circles.resize(kMaxExactBarCircles + 1);
  add(thrown_by([&] { exact_footprint(Camera2D(64), crowded); }),
      {"circles", std::to_string(kMaxExactBarCircles), std::to_string(kMaxExactBarCircles + 1)});

  // ---- the checker: how a run ended ----
  using End = check::RunResult::End;
  add(detail_of(ended(End::exited, 3)), {"3"});
  add(detail_of(ended(End::exited, 137)), {"137", "9", "SIGKILL"});
  add(detail_of(ended(End::exited, 128 + 40)), {"168", "40"});  // a real-time signal has no name
  add(detail_of(ended(End::signalled, 11)), {"11", "SIGSEGV"});
  add(detail_of(ended(End::timed_out)), {});
  check::RunResult flood = ended(End::output_too_large);
  flood.out.assign(std::size_t(17) << 20, ' ');
  add(detail_of(flood), {"17"});
  const std::string no_answer = scratch.path("answer.json");
  add(detail_of(check::read_answer_file(no_answer)), {no_answer});
  add(check::run_student({"raycam-no-such-program"}, "", {}, std::nullopt).error, {"raycam-no-such-program"});
  const std::string broken = scratch.path("broken.sh");
  std::ofstream(broken) << "#!/raycam-no-such-interpreter\n";
  ::chmod(broken.c_str(), 0755);
  const std::string cannot_run = check::run_student({broken}, "", {}, std::nullopt).error;
  add(cannot_run,
      {broken, cannot_run.substr(cannot_run.rfind(": ") + 2)});  // the C library's reason, as it is
  {
    const TemporaryFolder scope("/raycam-no-such-folder");
    const std::string no_folder = check::run_student({"true"}, "", {}, std::nullopt).error;
    add(no_folder, {no_folder.substr(no_folder.rfind(": ") + 2)});
    const check::CheckCase c{"the current camera", small_case()};
    const auto reports = check::check_submissions({{"student", {"true"}, std::nullopt}}, {c},
                                                  check::reference_images({c}), {}, 1);
    add(reports.at(0).results.at(0).detail, {no_folder.substr(no_folder.rfind(": ") + 2)});
  }

  // ---- the checker: what is wrong with an answer ----
  add(answer_error("{"), {});
  add(answer_error("{}"), {"ids"});
  add(answer_error(R"({"ids": [0, 0, 0, 0, 0]})"), {"4"});
  add(answer_error(R"({"ids": [0, 0]})"), {"4", "2"});
  add(answer_error(R"({"ids": [[0, 0], [0, 0], [0, 0]]})", 3), {"2", "2"});
  add(answer_error(R"({"ids": [[0, 0]]})", 3), {"2", "1"});
  add(answer_error(R"({"ids": [0, 0, 0, 7]})"), {"ids[3]", "7", "[-1, 1]"});
  add(answer_error(R"({"ids": [0, "x", 0, 0]})"), {"ids[1]"});
  add(answer_error(R"({"ids": [0, true]})"), {"ids[1]"});
  add(answer_error(R"({"ids": [0, 1.5]})"), {"ids[1]", "1.5"});
  add(answer_error(R"({"ids": [0, 1e999]})"), {"ids[1]"});
  add(answer_error(R"({"ids": 5})"), {"ids", "5"});
  add(answer_error(R"({"ids": 5})", 3), {"ids", "5"});
  add(answer_error(R"({"ids": [{}]})"), {"ids[0]"});
  add(answer_error(R"({"ids": [[1]]})"), {"ids[0]"});
  add(answer_error("[1]"), {"ids"});
  add(answer_error(R"({"ids": [0, 34359738368]})"), {"ids[1]", "34359738368"});
  add(answer_error(R"({"ids": [[0, 0], [0]]})", 3), {"ids[1]", "1", "2"});
  add(answer_error(R"({"ids": [[0], [0, 0]]})", 3), {"ids[1]", "2", "1"});
  add(answer_error("{\"x\": " + std::string(80, '[') + std::string(80, ']') + "}"), {"x"});
  add(answer_error(R"({"ids": [0, 0, 0, 0], "md": [[1, 2, 3]]})"), {"md", "3"});
  add(answer_error(R"({"ids": [0, 0, 0, 0], "md": [["x"]]})"), {"md", "3"});
  return out;
}

// The words of `text` (letters, accented ones included), lower case.
std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words(1);
  for (unsigned char c : text) {
    if (std::isalpha(c) || c >= 0x80)
      words.back() += char(std::tolower(c));
    else if (!words.back().empty())
      words.emplace_back();
  }
  return words;
}

// English words of the reasons; none of them is also a French word of the table.
const std::set<std::string> kEnglish = {
    "cannot",  "open",       "file",      "expected",   "syntax",  "error",   "write",     "failed",
    "replace", "unchanged",  "limit",     "larger",     "known",   "field",   "read",      "got",
    "number",  "array",      "object",    "string",     "integer", "must",    "only",      "scene",
    "exit",    "status",     "killed",    "answer",     "more",    "rows",    "columns",   "while",
    "parsing", "unexpected", "invalid",   "literal",    "the",     "is",      "of",        "in",
    "an",      "with",       "for",       "than",       "out",     "range",   "temporary", "directory",
    "program", "timeout",    "within",    "stopped",    "nested",  "deep",    "overflow",  "required",
    "finite",  "degrees",    "camera",    "sits",       "over",    "at",      "most",      "bar",
    "takes",   "circles",    "quadratic", "does",       "not",     "match",   "which",     "sides",
    "empty",   "map",        "colour",    "top",        "level",   "left",    "writable",  "exist",
    "list",    "boolean",    "find",      "executable", "run",     "could",   "checker",   "id",
    "where",   "row",        "has",       "quote",      "missing", "closing", "input",     "end",
    "key",     "separator",  "value",     "last",       "too",     "these",   "one",       "no",
    "such",    "beside",     "it"};

// `french` without the variable parts (they may hold any word).
std::string around_kept(std::string french, const Reason& reason) {
  for (const std::string& part : reason.kept)
    for (std::size_t at; !part.empty() && (at = french.find(part)) != std::string::npos;)
      french.erase(at, part.size());
  return french;
}
}  // namespace

TEST_CASE("error reasons: every reason the window can show reads in French, its variable parts kept",
          "[session][language][reasons]") {
  test::ScratchDir scratch("reasons");
  for (const Reason& reason : real_reasons(scratch)) {
    INFO(reason.english);
    const std::string french = translate_reason(Language::fr, reason.english);
    INFO(french);
    CHECK(french != reason.english);
    for (const std::string& part : reason.kept) CHECK_THAT(french, Catch::Contains(part));
    for (const std::string& word : words_of(around_kept(french, reason))) {
      CAPTURE(word);
      CHECK(kEnglish.count(word) == 0);
    }
    const std::string words = around_kept(french, reason);
    for (std::size_t at = words.find(':'); at != std::string::npos; at = words.find(':', at + 1))
      CHECK((at > 0 && words[at - 1] == ' '));  // French typography: a space before the colon
    CHECK(translate_reason(Language::en, reason.english) == reason.english);
  }
}

TEST_CASE("error reasons: every pattern of the table serves a real reason (no dead pattern)",
          "[session][language][reasons]") {
  test::ScratchDir scratch("reasons");
  std::vector<std::size_t> used;
  for (const Reason& reason : real_reasons(scratch)) translate_reason(Language::fr, reason.english, &used);
  const std::set<std::size_t> served(used.begin(), used.end());
  for (std::size_t i = 0; i < reason_patterns().size(); ++i) {
    INFO(reason_patterns()[i].english());
    CHECK(served.count(i) == 1);
  }
}

TEST_CASE("error reasons: each language's template places every part of its English pattern once",
          "[session][language][reasons]") {
  auto names = [](const std::string& text) {
    std::multiset<std::string> found;
    for (std::size_t at = 0; (at = text.find('{', at)) != std::string::npos; ++at) {
      const std::size_t end = text.find('}', at);
      std::string name = text.substr(at + 1, end == std::string::npos ? 0 : end - at - 1);
      if (!name.empty() && name.back() == '*') name.pop_back();
      if (!name.empty() && name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos)
        found.insert(name);
    }
    return found;
  };
  for (const ReasonPattern& p : reason_patterns()) {
    INFO(p.english());
    const std::multiset<std::string> english = names(p.english());
    for (Language language : kLanguages) CHECK(english == names(p[language]));
    CHECK(std::set<std::string>(english.begin(), english.end()).size() == english.size());
  }
}

TEST_CASE("error reasons: an unknown reason stays in English, whole, and a known one reads as written",
          "[session][language][reasons]") {
  CHECK(translate_reason(Language::fr, "a reason nobody wrote a pattern for") ==
        "a reason nobody wrote a pattern for");
  CHECK(translate_reason(Language::fr, "") == "");
  // A reason too long for the regular expressions' recursion (a pasted path) is shown as it is, whole.
  const std::string pasted = "/" + std::string(100000, 'x') + ": cannot open scene file";
  CHECK(translate_reason(Language::fr, pasted) == pasted);
  // Written by hand from the pattern's intent, not copied from the output.
  CHECK(translate_reason(Language::fr, "/tmp/x.json: cannot open scene file") ==
        "/tmp/x.json : impossible d'ouvrir le fichier de scène");
  CHECK(translate_reason(Language::fr, "s.json: objects[2].radius: expected a number in ]0, 1e12], got 0") ==
        "s.json : objects[2].radius : on attend un nombre dans ]0, 1e12] ; reçu : 0");
  CHECK(translate_reason(Language::fr, "exit status 139 (killed by signal 11 (SIGSEGV)?)") ==
        "code de sortie 139 (tué par le signal 11 (SIGSEGV) ?)");
  // A part that looks like a placeholder is shown as it is, never filled in turn.
  CHECK(translate_reason(Language::fr, "{path}: cannot open scene file") ==
        "{path} : impossible d'ouvrir le fichier de scène");
}

namespace {
// "SOURCE: JSON syntax error at line L, column C: WHAT", in French (WHAT written here, in French).
std::string french_syntax_error(int line, int column, const std::string& what) {
  return "lesson.json : erreur de syntaxe JSON à la ligne " + std::to_string(line) + ", colonne " +
         std::to_string(column) + " : " + what;
}
}  // namespace

TEST_CASE("error reasons: a sample of real reasons reads exactly as French writes it, each part in its place",
          "[session][language][reasons]") {
  test::ScratchDir scratch("reasons-exact");
  const std::string scene3d = scratch.path("three.json");
  std::ofstream(scene3d) << R"({"dimension": 3, "objects": []})";
  Scene2D crowded;
  crowded.circles.resize(kMaxExactBarCircles + 1);
  const std::string broken = scratch.path("broken.sh");
  std::ofstream(broken) << "#!/raycam-no-such-interpreter\n";
  ::chmod(broken.c_str(), 0755);
  const std::string cannot_run = check::run_student({broken}, "", {}, std::nullopt).error;
  const std::string c_library_reason = cannot_run.substr(cannot_run.rfind(": ") + 2);
  using End = check::RunResult::End;
  const std::pair<std::string, std::string> sample[] = {
      // A JSON syntax error in raycam's own words: what was found where something else was expected.
      {scene_error("{\"a\" 1}"), french_syntax_error(1, 6, "un nombre là où on attend « : »")},
      {scene_error("{1: 2}"), french_syntax_error(1, 2, "un nombre là où on attend une clé entre guillemets droits")},
      {scene_error("{\"a\": 1 \"b\": 2}"),
       french_syntax_error(1, 11, "une chaîne de caractères là où on attend « , » ou « } »")},
      {scene_error("[1 2]"), french_syntax_error(1, 4, "un nombre là où on attend « , » ou « ] »")},
      {scene_error(""), french_syntax_error(1, 1, "le texte s'arrête là où on attend une valeur")},
      {scene_error("{\"dimension\": tru}"),
       french_syntax_error(1, 18, "mot inconnu « tru} » : une valeur est un nombre, une chaîne, un objet, un tableau, "
                                  "true, false ou null")},
      {scene_error("{\"a\": 1} x"), french_syntax_error(1, 10, "du texte après la fin de la valeur JSON")},
      // A field, what it expects, what it got.
      {scene_error(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]})"),
       "lesson.json : objects[0].radius : on attend un nombre dans ]0, 1e12] ; reçu : -1"},
      {scene_error(R"({"dimension": "3", "objects": []})"),
       "lesson.json : dimension : on attend un entier dans [2, 3] ; reçu : \"3\""},
      // The flags against the file: the flag's value first, the file's kind last.
      {thrown_by([&] {
         ViewFlags flags;
         flags.scene_path = scene3d;
         flags.dimension = 2;
         make_view_setup(flags);
       }),
       "--mode : 2d ne correspond pas au fichier de scène " + scene3d + ", qui est en 3D"},
      // The exact bar: its maximum, then the count it got.
      {thrown_by([&] { exact_footprint(Camera2D(64), crowded); }),
       "circles : la barre exacte prend au plus " + std::to_string(kMaxExactBarCircles) +
           " cercles (son coût est quadratique) ; reçu : " + std::to_string(kMaxExactBarCircles + 1)},
      // How a run ended: the exit status, then the signal it stands for.
      {detail_of(ended(End::exited, 137)), "code de sortie 137 (tué par le signal 9 (SIGKILL) ?)"},
      {detail_of(ended(End::signalled, 11)), "tué par le signal 11 (SIGSEGV)"},
      {cannot_run, "impossible de lancer « " + broken + " » : " + c_library_reason},
      // Answers: what was expected, then what came.
      {answer_error(R"({"ids": [0, 0]})"), "on attend 4 identifiants ; reçu : 2"},
      {answer_error(R"({"ids": [0, 0, 0, 7]})"), "ids[3] = 7 : on attend un identifiant dans [-1, 1]"},
      {answer_error(R"({"ids": [[0, 0], [0]]})", 3), "ids[1] : 1 colonne alors que la ligne 0 en a 2"},
      {answer_error(R"({"ids": [[0, 0], [0, 0], [0, 0]]})", 3), "on attend 2 lignes de 2 identifiants ; davantage reçues"},
  };
  for (const auto& [english, french] : sample) {
    INFO(english);
    CHECK(translate_reason(Language::fr, english) == french);
  }
}

// A count in a reason takes its noun's number in each language: English plural but for 1, French for 2 and
// more. Each reason is the checker's own, for an answer with 1 and with 2 (or more) of the thing counted.
TEST_CASE("error reasons: a count of 1 and of 2 read right in English and in French",
          "[session][language][reasons][plural]") {
  // An answer checked against one row of 1 pixel (3D: rows x columns), or a 2D image of n pixels.
  auto answer_3d = [](const std::string& text, int rows, int columns) {
    return check::parse_answer(text, 3, rows, columns, 2).error;
  };
  auto answer_2d = [](const std::string& text, int n) { return check::parse_answer(text, 2, 1, n, 2).error; };
  const std::vector<std::pair<std::string, std::pair<std::string, std::string>>> reasons = {
      // ragged rows: the row's own count
      {answer_3d(R"({"ids": [[0, 0], [0]]})", 2, 2),
       {"ids[1]: 1 column where row 0 has 2", "ids[1] : 1 colonne alors que la ligne 0 en a 2"}},
      {answer_3d(R"({"ids": [[0, 0, 0], [0, 0]]})", 2, 3),
       {"ids[1]: 2 columns where row 0 has 3", "ids[1] : 2 colonnes alors que la ligne 0 en a 3"}},
      {answer_3d(R"({"ids": [[0], [0, 0]]})", 2, 2),
       {"ids[1]: 2 columns (or more) where row 0 has 1",
        "ids[1] : 2 colonnes (ou plus) alors que la ligne 0 en a 1"}},
      // the size expected: one id, or two
      {answer_2d(R"({"ids": [0, 0]})", 1),
       {"expected 1 id, got more", "on attend 1 identifiant ; davantage reçus"}},
      {answer_2d(R"({"ids": [0]})", 2), {"expected 2 ids, got 1", "on attend 2 identifiants ; reçu : 1"}},
      {answer_2d(R"({"ids": []})", 1), {"expected 1 id, got 0", "on attend 1 identifiant ; reçu : 0"}},
      // one row of one id, two rows of two
      {answer_3d(R"({"ids": [[0], [0]]})", 1, 1),
       {"expected 1 row of 1 id, got more", "on attend 1 ligne de 1 identifiant ; davantage reçues"}},
      {answer_3d(R"({"ids": [[0, 0]]})", 2, 2),
       {"expected 2 rows of 2 ids, got 1 of 2", "on attend 2 lignes de 2 identifiants ; reçu : 1 × 2"}},
  };
  for (const auto& [english, expected] : reasons) {
    INFO(english);
    CHECK(english == expected.first);
    CHECK(translate_reason(Language::en, english) == expected.first);
    CHECK(translate_reason(Language::fr, english) == expected.second);
  }
}

TEST_CASE("error reasons: the window's messages and the check report show them in the window's language",
          "[session][language][reasons]") {
  test::ScratchDir scratch("reasons");
  session::AppState state;
  state.language = Language::fr;
  const std::string missing = scratch.path("typo.json");
  CHECK_FALSE(session::open_scene(state, missing));
  // The window's French puts a no-break space before a colon.
  CHECK(state.message ==
        "impossible d'ouvrir\u00a0: " + missing + "\u00a0: impossible d'ouvrir le fichier de scène");
  CHECK(session::tr_reason(Language::fr, "exit status 2") == "code de sortie 2");
  CHECK(session::tr_reason(Language::en, "exit status 2") == "exit status 2");

  check::StudentReport report;
  check::CaseResult crash;
  crash.number = 1;
  crash.status = check::CaseStatus::crash;
  crash.detail = "exit status 2";
  report.results.push_back(crash);
  check::ReportHeader header;
  header.language = Language::fr;
  const std::string text = check::text_report(header, {check::CheckCase{"", small_case()}}, report);
  CHECK_THAT(text, Catch::Contains("code de sortie 2"));
  header.language = Language::en;
  CHECK_THAT(check::text_report(header, {check::CheckCase{"", small_case()}}, report),
             Catch::Contains("exit status 2"));
}
