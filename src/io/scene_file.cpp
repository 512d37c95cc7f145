// Scene files (JSON). Section index: field readers · objects · camera preset · parse · write.
#include "raycam/scene_file.h"

#include <cstring>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "raycam/language.h"
#include "raycam/limits.h"
#include "io/scene_file_parts.h"

namespace raycam {

namespace {
using nlohmann::json;

// ---- field readers: each error names the source, the field path and what was expected ----------------
// A field's path in the messages ("objects[12].center[2]"), made only for a message: built for every field
// of every object, the paths were most of the time the page took to read 10⁵ spheres (docs/web.md). A part
// refers to its parent, which lives as long as the call that reads the field.
class FieldName {
 public:
  FieldName(const char* whole) : text_(whole) {}  // NOLINT: a literal path reads as one
  FieldName(const std::string& whole) : text_(whole.c_str()) {}  // NOLINT
  FieldName(const FieldName& parent, const char* member) : parent_(&parent), text_(member) {}
  FieldName(const FieldName& parent, std::size_t index) : parent_(&parent), index_(index), indexed_(true) {}
  std::string str() const {
    std::string path = parent_ ? parent_->str() : std::string();
    return indexed_ ? path + "[" + std::to_string(index_) + "]" : path + text_;
  }

 private:
  const FieldName* parent_ = nullptr;
  const char* text_ = "";
  std::size_t index_ = 0;
  bool indexed_ = false;
};

class FieldReader {
 public:
  // `source` outlives the reader (the parse's argument): one reader per object costs no copy.
  explicit FieldReader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const FieldName& field, const std::string& expected,
                         const json* got = nullptr) const {
    std::string message = source_ + ": " + field.str() + ": expected " + expected;
    if (got) message += ", got " + got->dump().substr(0, 60);
    throw std::invalid_argument(message);
  }

  void require_known_keys(const json& object, const FieldName& field,
                          std::initializer_list<const char*> keys) const {
    // The messages' words are made only for a field that fails: made for every field of every object they
    // were most of the time the page took to read 10⁵ spheres (docs/web.md), as in the other readers here.
    for (const auto& item : object.items()) {
      if (std::any_of(keys.begin(), keys.end(), [&](const char* key) { return item.key() == key; })) continue;
      std::string list;
      for (const char* key : keys) list += std::string(list.empty() ? "" : ", ") + key;
      const std::string path = field.str();
      fail(path + (path.empty() ? "" : ".") + item.key(), "no such field (known: " + list + ")");
    }
  }

  double number(const json& value, const FieldName& field) const {
    if (!value.is_number()) fail(field, "a number", &value);
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(field, "a finite number", &value);
    return x;
  }

  double number_in(const json& value, const FieldName& field, double lo, double hi, bool lo_open,
                   const char* range) const {
    const double x = number(value, field);
    if ((lo_open ? x <= lo : x < lo) || x > hi) fail(field, std::string("a number in ") + range, &value);
    return x;
  }

  long long integer_in(const json& value, const FieldName& field, long long lo, long long hi) const {
    const auto range = [&] { return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]"; };
    if (!value.is_number_integer() &&
        !(value.is_number_float() && std::floor(value.get<double>()) == value.get<double>()))
      fail(field, range(), &value);
    const double x = value.get<double>();
    if (x < double(lo) || x > double(hi)) fail(field, range(), &value);
    return static_cast<long long>(x);
  }

  std::vector<double> vector_of(const json& value, const FieldName& field, std::size_t count) const {
    if (!value.is_array() || value.size() != count)
      fail(field, formatted(Language::en, "an array of %zu {{number|numbers}}", count), &value);
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i) {
      const double x = number(value[i], FieldName(field, i));
      if (std::abs(x) > kMaxCoordinate) fail(FieldName(field, i), "|x| <= 1e12", &value[i]);
      out.push_back(x);
    }
    return out;
  }

  Rgb8 colour(const json& value, const FieldName& field) const {
    if (!value.is_array() || value.size() != 3) fail(field, "an array of 3 integers in [0, 255]", &value);
    int c[3];
    for (int i = 0; i < 3; ++i)
      c[i] = int(integer_in(value[i], FieldName(field, std::size_t(i)), 0, 255));
    return Rgb8{std::uint8_t(c[0]), std::uint8_t(c[1]), std::uint8_t(c[2])};
  }

  std::string string(const json& value, const FieldName& field) const {
    if (!value.is_string()) fail(field, "a string", &value);
    return value.get<std::string>();
  }

  const json& member(const json& object, const char* key, const FieldName& field) const {
    if (!object.contains(key)) fail(field, "a field \"" + std::string(key) + "\" (it is required)");
    return object.at(key);
  }

 private:
  const std::string& source_;
};

// ---- objects -----------------------------------------------------------------------------------------
// An object's "type" in a file, and how many coordinates its centre has.
const char* object_type(const Circle&) { return "circle"; }
const char* object_type(const Sphere&) { return "sphere"; }
template <class Object>
constexpr int kCoordinates = decltype(Object::centre)::length();

template <class Object>
Object read_object(const FieldReader& reader, const json& item, const FieldName& field) {
  constexpr int dimension = kCoordinates<Object>;
  if (!item.is_object()) reader.fail(field, "an object {\"type\", \"center\", \"radius\", ...}", &item);
  reader.require_known_keys(item, field, {"type", "center", "radius", "color", "name"});
  const char* wanted = object_type(Object{});
  const std::string type = reader.string(reader.member(item, "type", field), FieldName(field, ".type"));
  if (type != wanted)
    reader.fail(FieldName(field, ".type"), std::string("\"") + wanted + "\" in a " + std::to_string(dimension) + "D scene",
                &item["type"]);
  Object object;
  const std::vector<double> c =
      reader.vector_of(reader.member(item, "center", field), FieldName(field, ".center"), dimension);
  for (int i = 0; i < dimension; ++i) object.centre[i] = c[std::size_t(i)];
  object.radius = reader.number_in(reader.member(item, "radius", field), FieldName(field, ".radius"), 0.0,
                                   kMaxCoordinate, true, "]0, 1e12]");
  if (item.contains("color")) object.colour = reader.colour(item["color"], FieldName(field, ".color"));
  if (item.contains("name")) object.name = reader.string(item["name"], FieldName(field, ".name"));
  return object;
}

// ---- camera preset -----------------------------------------------------------------------------------
// Where the two dimensions' cameras differ: 2D has no phi, one res and a size N; 3D has phi, res as one
// number or [columns, rows], and a size [columns, rows]. One function per dimension (the scene picks it).
void require_camera_keys(const FieldReader& reader, const json& camera, const Scene2D&) {
  reader.require_known_keys(camera, "camera", {"target", "d", "theta", "df", "res", "size"});
}
void require_camera_keys(const FieldReader& reader, const json& camera, const Scene3D&) {
  reader.require_known_keys(camera, "camera", {"target", "d", "theta", "phi", "df", "res", "size"});
}

double read_res(const FieldReader& reader, const json& res) {
  return reader.number_in(res, "camera.res", 0.0, 1.0, true, "]0, 1]");
}

void read_res_and_size(const FieldReader& reader, const json& camera, CameraPreset& preset, const Scene2D&) {
  if (camera.contains("res")) {
    const json& res = camera["res"];
    if (!res.is_number()) reader.fail("camera.res", "a number in ]0, 1]", &res);  // one res
    preset.res = read_res(reader, res);
  }
  if (camera.contains("size")) {
    const json& size = camera["size"];
    const json& n = size.is_array() && size.size() == 1 ? size[0] : size;
    preset.size = std::vector<int>{int(reader.integer_in(n, "camera.size", 1, kMaxPixels2D))};
  }
}

void read_res_and_size(const FieldReader& reader, const json& camera, CameraPreset& preset, const Scene3D&) {
  if (camera.contains("res")) {
    const json& res = camera["res"];
    if (res.is_array()) {  // [columns, rows]
      if (res.size() != 2) reader.fail("camera.res", "a number in ]0, 1] or [columns, rows], each in ]0, 1]", &res);
      preset.res = reader.number_in(res[0], "camera.res[0]", 0.0, 1.0, true, "]0, 1]");
      preset.res_rows = reader.number_in(res[1], "camera.res[1]", 0.0, 1.0, true, "]0, 1]");
    } else {
      preset.res = read_res(reader, res);
    }
  }
  if (camera.contains("size")) {
    const json& size = camera["size"];
    if (!size.is_array() || size.size() != 2) reader.fail("camera.size", "[columns, rows]", &size);
    const int columns = int(reader.integer_in(size[0], "camera.size[0]", 1, kMaxSide3D));
    const int rows = int(reader.integer_in(size[1], "camera.size[1]", 1, kMaxSide3D));
    if (static_cast<long long>(columns) * rows > kMaxPixels3D)
      reader.fail("camera.size", "columns x rows <= " + std::to_string(kMaxPixels3D), &size);
    preset.size = std::vector<int>{columns, rows};
  }
}

template <class Scene>
CameraPreset read_camera(const FieldReader& reader, const json& camera, const Scene& scene) {
  constexpr int dimension = kCoordinates<typename std::decay_t<decltype(objects_of(scene))>::value_type>;
  if (!camera.is_object()) reader.fail("camera", "an object", &camera);
  require_camera_keys(reader, camera, scene);
  CameraPreset preset;
  if (camera.contains("target"))
    preset.target = reader.vector_of(camera["target"], "camera.target", dimension);
  if (camera.contains("d"))
    preset.d = reader.number_in(camera["d"], "camera.d", 0.0, kMaxCoordinate, true, "]0, 1e12]");
  if (camera.contains("theta"))
    preset.theta_deg =
        reader.number_in(camera["theta"], "camera.theta", -1e6, 1e6, false, "[-1e6, 1e6] degrees");
  if (camera.contains("phi"))
    preset.phi_deg = reader.number_in(camera["phi"], "camera.phi", -1e6, 1e6, false, "[-1e6, 1e6] degrees");
  if (camera.contains("df"))
    preset.df = reader.number_in(camera["df"], "camera.df", kMinFocalDistance, kMaxFocalDistance, false,
                                 "[1e-9, 1e9]");
  read_res_and_size(reader, camera, preset, scene);
  return preset;
}

// nlohmann's what() is "[json.exception.X] parse error at line L, column C: reason"; keep the reason.
std::string reason_of(const json::exception& error) {
  std::string message = error.what();
  const std::size_t tag_end = message.find("] ");
  if (tag_end != std::string::npos) message = message.substr(tag_end + 2);
  const std::size_t column = message.find(", column ");
  const std::size_t colon = column == std::string::npos ? column : message.find(": ", column);
  return colon == std::string::npos ? message : message.substr(colon + 2);
}

std::string line_column_of(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// The JSON library's name of a token, in raycam's own words (translated by reason_table.cpp).
std::string token_words(const std::string& name, bool wanted) {
  if (name == "number literal") return "a number";
  if (name == "string literal") return wanted ? "a key in double quotes" : "a string";
  if (name == "true literal" || name == "false literal" || name == "null literal") return "a value";
  if (name == "'[', '{', or a literal") return "a value";
  if (name == "end of input") return "the end of the text";
  if (wanted && name == "'}'") return "',' or '}'";  // after a member, a comma would do too
  if (wanted && name == "']'") return "',' or ']'";
  return name;  // a punctuation mark: ':', '}', ']', ',', '[', '{'
}

// The word the lexer stopped on, from its "last read: '...'" (which starts at the token before).
std::string last_word(const std::string& message) {
  const std::size_t at = message.find("last read: '");
  if (at == std::string::npos) return "";
  const std::size_t begin = at + 12, end = message.find('\'', begin);
  std::string read = message.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
  const std::size_t cut = read.find_last_of(" \t:,[{");
  return cut == std::string::npos ? read : read.substr(cut + 1);
}

// A syntax error in raycam's own sentence: where (line, column, from the error's byte) and what was found
// or expected, in words a student reads (and reason_table.cpp translates), never the JSON library's own.
std::string syntax_error_reason(const json::parse_error& error, const std::string& text, const std::string& source) {
  const std::string message = error.what();
  const std::string at = source + ": JSON syntax error at " + line_column_of(text, error.byte ? error.byte - 1 : 0) + ": ";
  const std::size_t dash = message.find(" - ");
  const std::string reason = dash == std::string::npos ? message : message.substr(dash + 3);
  auto has = [&](const char* part) { return reason.find(part) != std::string::npos; };
  auto after = [&](const char* mark) {
    const std::size_t found = reason.find(mark);
    if (found == std::string::npos) return std::string();
    const std::size_t begin = found + std::strlen(mark);
    return reason.substr(begin, reason.find(';', begin) == std::string::npos ? std::string::npos
                                                                              : reason.find(';', begin) - begin);
  };
  if (has("invalid string: missing closing quote")) return at + "a string has no closing double quote";
  if (has("invalid string: control character")) return at + "a line break or a tab inside a string (write \\n or \\t)";
  if (has("invalid string: ill-formed UTF-8")) return at + "the text is not UTF-8";
  if (has("invalid string")) return at + "a backslash in a string starts one of \\\", \\\\, \\n, \\t, \\uXXXX";
  if (has("invalid number")) return at + "a malformed number '" + last_word(reason) + "'";
  if (has("invalid literal") && has("expected end of input")) return at + "text after the end of the JSON value";
  if (has("invalid literal"))
    return at + "unknown word '" + last_word(reason) + "': a value is a number, a string, an object, an array, " +
           "true, false or null";
  const std::string found = after("unexpected "), wanted = after("; expected ");
  if (found == "end of input") return at + "the text ends where " + token_words(wanted, true) + " was expected";
  if (!found.empty() && !wanted.empty())
    return at + token_words(found, false) + " where " + token_words(wanted, true) + " was expected";
  return at + "not JSON here";
}
}  // namespace

// ---- parse -------------------------------------------------------------------------------------------
SceneFile parse_scene_json(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& error) {
    throw std::invalid_argument(syntax_error_reason(error, text, source));
  } catch (const json::exception& error) {  // e.g. a number too large for a double
    throw std::invalid_argument(source + ": invalid JSON: " + reason_of(error));
  }
  return scene_file_parts::read_scene(root, source);
}

namespace scene_file_parts {
SceneFile read_scene(const json& root, const std::string& source) {
  const FieldReader reader(source);
  if (!root.is_object()) reader.fail("(top level)", "a JSON object {\"dimension\", \"objects\", ...}", &root);
  reader.require_known_keys(root, "", {"dimension", "background", "objects", "camera", "protocol"});
  SceneFile file;
  file.dimension = int(reader.integer_in(reader.member(root, "dimension", "dimension"), "dimension", 2, 3));
  Rgb8 background = kDefaultBackground;
  if (root.contains("background")) background = reader.colour(root["background"], "background");
  file.scene2d.background = file.scene3d.background = background;

  const json& objects = reader.member(root, "objects", "objects");
  if (!objects.is_array()) reader.fail("objects", "an array", &objects);
  if (objects.size() > kMaxObjects)
    reader.fail("objects", "at most " + std::to_string(kMaxObjects) + " objects");
  for (std::size_t i = 0; i < objects.size(); ++i) read_scene_object(file, objects[i], i, source);
  if (root.contains("camera"))
    visit_scene(file, [&](const auto& scene) { file.camera = read_camera(reader, root["camera"], scene); });
  if (root.contains("protocol")) file.protocol = int(reader.integer_in(root["protocol"], "protocol", 1, 1000));
  return file;
}

void read_scene_object(SceneFile& file, const json& item, std::size_t index, const std::string& source) {
  const FieldReader reader(source);
  const FieldName objects_path("objects");
  visit_scene(file, [&](auto& scene) {
    auto& read = objects_of(scene);
    using Object = typename std::decay_t<decltype(read)>::value_type;
    read.push_back(read_object<Object>(reader, item, FieldName(objects_path, index)));
  });
}
}  // namespace scene_file_parts

std::string read_scene_text(const std::string& path) {
  // A folder opens as a stream whose size reads as huge: it would be refused as "larger than the limit".
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw std::invalid_argument(path + ": is a folder, not a scene file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::invalid_argument(path + ": cannot open scene file");
  const std::streamoff size = in.tellg();
  if (size < 0 || static_cast<unsigned long long>(size) > kMaxSceneFileBytes)
    throw std::invalid_argument(path + ": file is larger than the limit of " +
                                std::to_string(kMaxSceneFileBytes >> 20) + " MiB");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(text.data(), size);
  if (!in) throw std::invalid_argument(path + ": cannot read scene file");
  return text;
}

SceneFile load_scene_file(const std::string& path) { return parse_scene_json(read_scene_text(path), path); }

// ---- write -------------------------------------------------------------------------------------------
namespace {
json colour_json(Rgb8 c) { return json::array({c.r, c.g, c.b}); }

template <class Object>
json object_json(const Object& object) {
  json centre = json::array();
  for (int i = 0; i < kCoordinates<Object>; ++i) centre.push_back(object.centre[i]);
  json out = {{"type", object_type(object)},
              {"center", centre},
              {"radius", object.radius},
              {"color", colour_json(object.colour)}};
  if (!object.name.empty()) out["name"] = object.name;
  return out;
}

// The camera's fields that differ by dimension (phi, and read_res_and_size's).
void write_phi_res_and_size(json& camera, const CameraPreset& p, const Scene2D&) {
  if (p.res) camera["res"] = *p.res;
  if (p.size) camera["size"] = (*p.size)[0];
}
void write_phi_res_and_size(json& camera, const CameraPreset& p, const Scene3D&) {
  if (p.phi_deg) camera["phi"] = *p.phi_deg;
  if (p.res) camera["res"] = p.res_rows ? json({*p.res, *p.res_rows}) : json(*p.res);
  if (p.size) camera["size"] = *p.size;
}
}  // namespace

namespace {
// JSON for people: a value that fits on one line of at most kReadableLine characters and holds no array or
// object bigger than a short array of scalars stays on one line ("center": [1, 2, 3], and each object of
// "objects" as one line, as in docs/cli.md's example); anything bigger is indented by 2.
constexpr std::size_t kReadableLine = 120;

bool is_flat(const json& value) {
  if (value.is_array())
    return value.size() <= 4 &&
           std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_primitive(); });
  if (value.is_object())
    return std::all_of(value.begin(), value.end(),
                       [](const json& v) { return v.is_primitive() || (v.is_array() && is_flat(v)); });
  return true;
}

std::string one_line(const json& value) {
  if (value.is_primitive()) return value.dump();
  std::string text = value.is_array() ? "[" : "{";
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!first) text += ", ";
    first = false;
    if (value.is_object()) text += json(it.key()).dump() + ": ";
    text += one_line(*it);
  }
  return text + (value.is_array() ? "]" : "}");
}

std::string readable_json(const json& value, int indent) {
  if (value.is_primitive() || value.empty()) return value.dump();
  if (is_flat(value)) {  // only a flat value may go on one line: the whole scene's text is not built for it
    const std::string flat = one_line(value);
    if (flat.size() + std::size_t(indent) <= kReadableLine) return flat;
  }
  const std::string inner(std::size_t(indent + 2), ' ');
  std::string text = value.is_array() ? "[\n" : "{\n";
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!first) text += ",\n";
    first = false;
    text += inner;
    if (value.is_object()) text += json(it.key()).dump() + ": ";
    text += readable_json(*it, indent + 2);
  }
  return text + "\n" + std::string(std::size_t(indent), ' ') + (value.is_array() ? "]" : "}");
}
}  // namespace

namespace {
// Scene files hold circles and spheres (no "kind" field yet: docs/architecture.md, "Adding a kind of object"):
// a scene with objects of another kind is refused, never written without them.
void require_file_kinds(const Scene2D&) {}
void require_file_kinds(const Scene3D& scene) {
  if (!scene.shapes.empty())
    throw std::invalid_argument("objects: " + std::to_string(scene.shapes.size()) +
                                " of the scene's objects are not spheres (planes), which a scene file cannot hold yet");
}
}  // namespace

std::string scene_to_json(const SceneFile& file) {
  json root;
  root["dimension"] = file.dimension;
  json objects = json::array();
  const CameraPreset& p = file.camera;
  json camera = json::object();
  if (p.target) camera["target"] = *p.target;
  if (p.d) camera["d"] = *p.d;
  if (p.theta_deg) camera["theta"] = *p.theta_deg;
  if (p.df) camera["df"] = *p.df;
  visit_scene(file, [&](const auto& scene) {
    require_file_kinds(scene);
    root["background"] = colour_json(scene.background);
    for (const auto& object : objects_of(scene)) objects.push_back(object_json(object));
    write_phi_res_and_size(camera, p, scene);
  });
  root["objects"] = objects;
  if (!camera.empty()) root["camera"] = camera;
  if (file.protocol) root["protocol"] = *file.protocol;
  return readable_json(root, 0) + "\n";
}

void save_scene_file(const SceneFile& file, const std::string& path) {
  const std::string text = scene_to_json(file);
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot write (no temporary file beside it); left unchanged");
    out << text;
    out.flush();
    if (!out) {
      std::remove(temporary.c_str());
      throw std::runtime_error(path + ": write failed; left unchanged");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot replace file; left unchanged");
  }
}

}  // namespace raycam
