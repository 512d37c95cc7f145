// The resumable scene reader against parse_scene_json, its reference: for every shipped scene, generated big
// files in odd layouts, and malformed files, at budgets from one object per step to the whole file in one, the
// same scene field by field, or the same error word for word; and on a valid file it really works in steps.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "raycam/scene_file.h"
#include "raycam/scene_file_reader.h"

using namespace raycam;

namespace {
const double kBudgetsMs[] = {0.0, 0.001, 1.0, 1e9};  // 0: one object per step; 1e9: the whole file at once

template <class Object>
void require_same_objects(const std::vector<Object>& got, const std::vector<Object>& expected) {
  REQUIRE(got.size() == expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("object " << i);
    REQUIRE(got[i].centre == expected[i].centre);
    REQUIRE(got[i].radius == expected[i].radius);
    REQUIRE(got[i].colour == expected[i].colour);
    REQUIRE(got[i].name == expected[i].name);
  }
}

void require_same_file(const SceneFile& got, const SceneFile& expected) {
  REQUIRE(got.dimension == expected.dimension);
  REQUIRE(got.scene2d.background == expected.scene2d.background);
  REQUIRE(got.scene3d.background == expected.scene3d.background);
  require_same_objects(got.scene2d.circles, expected.scene2d.circles);
  require_same_objects(got.scene3d.spheres, expected.scene3d.spheres);
  const CameraPreset &a = got.camera, &b = expected.camera;
  REQUIRE(a.target == b.target);
  REQUIRE(a.d == b.d);
  REQUIRE(a.theta_deg == b.theta_deg);
  REQUIRE(a.phi_deg == b.phi_deg);
  REQUIRE(a.df == b.df);
  REQUIRE(a.res == b.res);
  REQUIRE(a.res_rows == b.res_rows);
  REQUIRE(a.size == b.size);
}

std::string error_of(const std::function<SceneFile()>& read) {
  try {
    read();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

struct Stepped {
  SceneFile file;
  std::size_t steps = 0;
  bool one_object_per_step = true;  // while reading the objects: each step read exactly one more
};

Stepped read_in_steps(const std::string& text, double budget_ms) {
  SceneFileReader reader(text, "scene.json");
  Stepped out;
  std::size_t read_before = reader.objects_read();
  bool more = true;
  while (more) {
    const bool reading = reader.phase() == SceneFileReader::Phase::reading;
    more = reader.step(budget_ms);
    ++out.steps;
    REQUIRE(out.steps <= text.size() + 2);  // no step without progress
    if (reading && more && reader.objects_read() != read_before + 1) out.one_object_per_step = false;
    read_before = reader.objects_read();
  }
  REQUIRE(reader.phase() == SceneFileReader::Phase::done);
  REQUIRE_FALSE(reader.step(budget_ms));
  out.file = reader.take();
  return out;
}

// The reader agrees with parse_scene_json at every budget: the same scene, or the same error. A valid file
// is read in steps (`in_steps`): at budget 0, one object per step, never parse_scene_json's one go.
void check_like_parse_scene_json(const std::string& text, bool in_steps = false) {
  std::string expected_error;
  SceneFile expected;
  try {
    expected = parse_scene_json(text, "scene.json");
  } catch (const std::invalid_argument& error) {
    expected_error = error.what();
  }
  for (const double budget : kBudgetsMs) {
    INFO("budget " << budget << " ms; text: " << text.substr(0, 300));
    if (!expected_error.empty()) {
      REQUIRE(error_of([&] { return read_in_steps(text, budget).file; }) == expected_error);
    } else {
      const Stepped stepped = read_in_steps(text, budget);
      require_same_file(stepped.file, expected);
      if (in_steps && budget == 0.0) {
        const std::size_t objects = expected.scene2d.circles.size() + expected.scene3d.spheres.size();
        REQUIRE(stepped.one_object_per_step);
        REQUIRE(stepped.steps > objects);
      }
    }
  }
}

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A scene of `count` objects in a layout that changes with `seed`: spaces, tabs, CRs or none between tokens,
// the top level's keys in any order, each object's keys in any order, names holding brackets, quotes,
// backslashes and unicode escapes.
std::string generated_scene(int dimension, std::size_t count, unsigned seed) {
  std::mt19937 random(seed);
  const char* spaces[] = {"", " ", "\n", "\t", "\r\n", "  \n\t "};
  const auto space = [&] { return std::string(spaces[random() % 6]); };
  const auto number = [&] {
    std::ostringstream out;
    out.precision(int(random() % 17) + 1);
    out << (double(random()) / random.max() * 20.0 - 10.0);
    return out.str();
  };
  const char* names[] = {"plain", "br]ack}ets{[", "quo\\\"te\\\"", "back\\\\slash\\\\", "\\u00e9t\\u00e9 \\ud83d\\ude00",
                         "comma, colon: \\\"]\\\"", "\\/\\b\\f\\n\\r\\t"};
  std::string objects = "[" + space();
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<std::string> fields = {
        "\"type\"" + space() + ":" + space() + (dimension == 2 ? "\"circle\"" : "\"sphere\""),
        "\"radius\":" + space() + "0.0" + std::to_string(1 + random() % 9),
        "\"color\":[" + std::to_string(random() % 256) + "," + space() + "0" + space() + ",255]"};
    std::string centre = "\"center\":" + space() + "[" + number();
    for (int c = 1; c < dimension; ++c) centre += "," + space() + number();
    fields.push_back(centre + space() + "]");
    if (random() % 3 == 0) fields.push_back("\"name\":\"" + std::string(names[random() % 7]) + "\"");
    std::shuffle(fields.begin(), fields.end(), random);
    objects += (i ? "," + space() : "") + "{" + space();
    for (std::size_t f = 0; f < fields.size(); ++f) objects += (f ? "," + space() : "") + fields[f];
    objects += space() + "}";
  }
  objects += space() + "]";
  std::vector<std::string> members = {"\"dimension\":" + space() + std::to_string(dimension),
                                      "\"objects\"" + space() + ":" + space() + objects,
                                      "\"background\": [1, 2, 3]",
                                      dimension == 2 ? "\"camera\": {\"d\": 9, \"size\": 300}"
                                                     : "\"camera\": {\"phi\": 40, \"res\": [0.5, 1], \"size\": [64, 48]}"};
  std::shuffle(members.begin(), members.end(), random);
  std::string text = space() + "{";
  for (std::size_t m = 0; m < members.size(); ++m) text += (m ? "," : "") + space() + members[m];
  return text + space() + "}" + space();
}
}  // namespace

TEST_CASE("the resumable reader reads every shipped scene as parse_scene_json does", "[scene_file_reader]") {
  std::size_t scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RAYCAM_SCENES)) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path());
    check_like_parse_scene_json(file_text(entry.path()), true);
    ++scenes;
  }
  CHECK(scenes >= 5);
}

TEST_CASE("the resumable reader reads generated scenes in odd layouts as parse_scene_json does",
          "[scene_file_reader]") {
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const int dimension = seed % 3 == 0 ? 2 : 3;
    const std::string text = generated_scene(dimension, 300 + seed * 37, seed);
    INFO("seed " << seed);
    REQUIRE_NOTHROW(parse_scene_json(text, "scene.json"));  // the generator makes valid files
    check_like_parse_scene_json(text, true);
  }
}

TEST_CASE("the resumable reader works in steps: one object per step at budget 0, all in one at a large budget",
          "[scene_file_reader]") {
  const std::string text = generated_scene(3, 2000, 99);
  const Stepped one_by_one = read_in_steps(text, 0.0);
  CHECK(one_by_one.file.scene3d.spheres.size() == 2000);
  CHECK(one_by_one.one_object_per_step);
  CHECK(one_by_one.steps > 2000);  // the objects, and finding them (64 per step) before
  CHECK(read_in_steps(text, 1e9).steps == 1);

  SceneFileReader reader(text, "big.json");
  REQUIRE(reader.phase() == SceneFileReader::Phase::finding);
  while (reader.phase() == SceneFileReader::Phase::finding) {
    const std::size_t scanned = reader.bytes_scanned();
    reader.step(0.0);
    CHECK(reader.bytes_scanned() >= scanned);
  }
  CHECK(reader.objects_found() == 2000);  // the count the page shows ("objects read N of 2000")
  CHECK(reader.objects_read() <= 1);
}

TEST_CASE("the resumable reader gives parse_scene_json's error, word for word, for malformed files",
          "[scene_file_reader]") {
  const std::string sphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";
  const std::string good = R"({"dimension": 3, "objects": [)" + sphere + ", " + sphere + R"(], "camera": {"d": 9}})";
  REQUIRE_NOTHROW(parse_scene_json(good, "scene.json"));
  const std::vector<std::string> texts = {
      "", "   ", "[]", "{}", "null", "{\"dimension\": 3}", good + "x", good + "}", good + " {}",
      "\xEF\xBB\xBF" + good,  // a byte-order mark, which nlohmann accepts at the start only
      R"({"dimension": 3, "objects": []})",
      R"({"dimension": 3, "objects": [,]})",
      R"({"dimension": 3, "objects": [)" + sphere + ",]}",
      R"({"dimension": 3, "objects": [)" + sphere + " " + sphere + "]}",
      R"({"dimension": 3, "objects": [)" + sphere,
      R"({"dimension": 3, "objects": [)" + sphere + "}",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1]}})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "name": "unterminated}]})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 1e999], "radius": 1}]})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1e12}, )" + sphere + "]}",
      R"({"dimension": 3, "objects": [)" + sphere + R"(, {"type": "sphere", "center": [0, 0], "radius": 1}]})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(, {"type": "circle", "center": [0, 0, 0], "radius": 1}]})",
      R"({"dimension": 2, "objects": [)" + sphere + "]}",
      R"({"dimension": 3, "objects": [)" + sphere + R"(, 7]})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(, "sphere"]})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(, [1, 2]]})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "extra": {"a": [1, {"b": "]}"}]}}]})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "radius": -1}]})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 2, "radius": 1}]})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(], "objects": []})",
      R"({"dimension": 3, "dimension": 2, "objects": [{"type": "circle", "center": [0, 0], "radius": 1}]})",
      R"({"dimension": 3, "obj\u0065cts": [)" + sphere + "]}",
      R"({"dimension": 3, "objects": {"0": )" + sphere + "}}",
      R"({"dimension": 3, "objects": [)" + sphere + R"(], "camera": {"d": -1}})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(], "colour": [1, 2, 3]})",
      R"({"objects": [)" + sphere + R"(], "dimension": 4})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(], "camera": {"d": 9} /* a comment */})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(] "camera": {"d": 9}})",
      R"({"dimension": 3 "objects": [)" + sphere + "]}",
      R"({"dimension": 3, "objects" [)" + sphere + "]}",
      R"({dimension: 3, "objects": [)" + sphere + "]}",
      R"({"dimension": 3, "objects": [)" + sphere + R"(], "background": [1, 2, 3,]})",
      R"({"dimension": 3, "objects": [)" + sphere + R"(], "background": tru})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "name": "a\qb"}]})",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "name": "\ud800"}]})",
      std::string(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "name": "a)") +
          '\0' + "b\"}]}",
      std::string(R"({"dimension": 3, "objects": [)") + '\0' + sphere + "]}",
      R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "name": "\xff"}]})",
      "{\"dimension\": 3,\n\n  \"objects\": [\n" + sphere + ",\n" + sphere + "\n  ]\n}\n\n\tx",
  };
  for (const std::string& text : texts) check_like_parse_scene_json(text);
  // Errors deep in a long file: the object's index and the line and column are parse_scene_json's.
  const std::string long_file = generated_scene(3, 500, 7);
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"\"radius\":", "\"radius\": -"}, {"\"sphere\"", "\"circle\""}, {"]", "]]"}, {",", ",,"}}) {
    std::string broken = long_file;
    const std::size_t at = broken.rfind(from, broken.size() * 3 / 4);
    REQUIRE(at != std::string::npos);
    broken.replace(at, from.size(), to);
    REQUIRE(error_of([&] { return parse_scene_json(broken, "scene.json"); }) != "(no error)");
    check_like_parse_scene_json(broken);
  }
}
