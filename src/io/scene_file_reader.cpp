// The resumable scene reader (scene_file_reader.h). Its one rule: a scene it returns is parse_scene_json's for
// the same text, because every byte between the pieces it hands to nlohmann is checked here (JSON's
// whitespace, the commas, the colons, the brackets), every piece is parsed by nlohmann whole (a piece that is
// not exactly one value is refused), and every field is checked by parse_scene_json's own code
// (scene_file_parts.h). Whatever else it meets goes to parse_scene_json, for its error.
#include "raycam/scene_file_reader.h"

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>

#include "raycam/limits.h"
#include "io/scene_file_parts.h"

namespace raycam {

namespace {
using nlohmann::json;
constexpr std::size_t kNone = std::string::npos;
// Finding an object costs about a hundredth of reading it: the clock is asked once per this many.
constexpr std::size_t kObjectsFoundPerClockLook = 64;

bool is_json_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::size_t skip_space(const std::string& text, std::size_t at) {
  while (at < text.size() && is_json_space(text[at])) ++at;
  return at;
}

// One past the closing quote of the string whose opening quote is at `at`; kNone if the text ends first.
std::size_t string_end(const std::string& text, std::size_t at) {
  for (++at; at < text.size(); ++at) {
    if (text[at] == '\\')
      ++at;  // the escaped character, a quote or a backslash included, cannot end the string
    else if (text[at] == '"')
      return at + 1;
  }
  return kNone;
}

// One past the JSON value starting at `at`, by its brackets and strings only (nlohmann then checks the
// value); kNone if the text ends first. A number or a literal ends at a space, a comma or a bracket.
std::size_t value_end(const std::string& text, std::size_t at) {
  if (at >= text.size()) return kNone;
  if (text[at] == '"') return string_end(text, at);
  if (text[at] != '{' && text[at] != '[') {
    while (at < text.size() && !is_json_space(text[at]) && text[at] != ',' && text[at] != ']' && text[at] != '}')
      ++at;
    return at;
  }
  std::size_t depth = 0;
  for (; at < text.size(); ++at) {
    const char c = text[at];
    if (c == '"') {
      at = string_end(text, at);
      if (at == kNone) return kNone;
      --at;  // the loop's ++at steps past the closing quote
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if ((c == '}' || c == ']') && --depth == 0) {
      return at + 1;
    }
  }
  return kNone;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

SceneFileReader::SceneFileReader(std::string text, std::string source)
    : text_(std::move(text)), source_(std::move(source)) {}

bool SceneFileReader::step(double budget_ms) {
  const auto start = std::chrono::steady_clock::now();
  try {
    while (phase_ != Phase::done) {
      bool regular = true;
      if (phase_ == Phase::reading) {
        regular = read_object();
      } else if (!in_objects_ && !members_done_) {
        regular = find_members();
      } else if (in_objects_) {
        for (std::size_t i = 0; regular && in_objects_ && i < kObjectsFoundPerClockLook; ++i) regular = find_objects();
      } else {
        regular = read_fields();
      }
      if (!regular) fall_back();
      if (phase_ == Phase::reading && next_object_ == objects_.size()) {
        phase_ = Phase::done;
        text_ = std::string();  // up to 256 MiB, no longer needed
        objects_ = {};
      }
      if (milliseconds_since(start) >= budget_ms) break;
    }
  } catch (const std::exception&) {  // nlohmann's or a field's error: parse_scene_json says which
    fall_back();
  }
  return phase_ != Phase::done;
}

bool SceneFileReader::find_members() {
  at_ = skip_space(text_, at_);
  if (first_) {  // the top level's opening brace
    if (at_ >= text_.size() || text_[at_] != '{') return false;
    at_ = skip_space(text_, at_ + 1);
  } else {  // after a member: a comma and the next, or the closing brace and nothing but space after it
    if (at_ < text_.size() && text_[at_] == '}') {
      members_done_ = true;
      at_ = skip_space(text_, at_ + 1);
      return at_ == text_.size();
    }
    if (at_ >= text_.size() || text_[at_] != ',') return false;
    at_ = skip_space(text_, at_ + 1);
  }
  first_ = false;
  if (at_ >= text_.size() || text_[at_] != '"') return false;
  const std::size_t key_end = string_end(text_, at_);
  if (key_end == kNone) return false;
  std::string key = text_.substr(at_, key_end - at_);
  if (key.find('\\') != kNone) return false;  // an escaped key: compared as written below, so not taken here
  if (std::any_of(members_.begin(), members_.end(), [&](const auto& member) { return member.first == key; }))
    return false;  // a repeated key: nlohmann keeps the last; not worth following here
  at_ = skip_space(text_, key_end);
  if (at_ >= text_.size() || text_[at_] != ':') return false;
  at_ = skip_space(text_, at_ + 1);
  if (key == "\"objects\"" && at_ < text_.size() && text_[at_] == '[') {
    members_.emplace_back(std::move(key), "[]");  // its objects are read one by one
    in_objects_ = true;
    first_ = true;
    ++at_;
    return true;
  }
  const std::size_t end = value_end(text_, at_);
  if (end == kNone || end == at_) return false;
  members_.emplace_back(std::move(key), text_.substr(at_, end - at_));
  at_ = end;
  return true;
}

bool SceneFileReader::find_objects() {
  at_ = skip_space(text_, at_);
  if (at_ >= text_.size()) return false;
  if (text_[at_] == ']') {  // the array's end (after an object, or an empty array)
    in_objects_ = false;
    first_ = false;
    ++at_;
    return true;
  }
  if (!first_) {
    if (text_[at_] != ',') return false;
    at_ = skip_space(text_, at_ + 1);
  }
  first_ = false;
  // An object is a JSON object: anything else is an error parse_scene_json words.
  if (at_ >= text_.size() || text_[at_] != '{') return false;
  const std::size_t end = value_end(text_, at_);
  if (end == kNone) return false;
  objects_.emplace_back(at_, end);
  at_ = end;
  return objects_.size() <= kMaxObjects;
}

bool SceneFileReader::read_fields() {
  // The top level as parse_scene_json sees it but with "objects": [], so that its checks run as they do there.
  std::string fields = "{";
  for (const auto& [key, value] : members_) fields += (fields.size() > 1 ? "," : "") + key + ":" + value;
  file_ = scene_file_parts::read_scene(json::parse(fields + "}"), source_);
  visit_scene(file_, [&](auto& scene) { objects_of(scene).reserve(objects_.size()); });
  phase_ = Phase::reading;
  return true;
}

bool SceneFileReader::read_object() {
  const auto [begin, end] = objects_[next_object_];
  scene_file_parts::read_scene_object(file_, json::parse(text_.data() + begin, text_.data() + end), next_object_,
                                      source_);
  ++next_object_;
  return true;
}

void SceneFileReader::fall_back() {
  try {
    file_ = parse_scene_json(text_, source_);
  } catch (...) {
    error_ = std::current_exception();
  }
  phase_ = Phase::done;
  text_ = std::string();
  objects_ = {};
}

SceneFile SceneFileReader::take() {
  if (error_) std::rethrow_exception(error_);
  return std::move(file_);
}

}  // namespace raycam
