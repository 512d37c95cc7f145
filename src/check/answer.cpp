#include "check/answer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <nlohmann/json.hpp>

#include "raycam/language.h"

namespace raycam::check {

namespace {
using json = nlohmann::json;

// How the protocol lays out the ids in each dimension: 2D's "ids" is one flat list (the bar's n ids), 3D's a
// list of rows.
bool ids_are_flat(int dimension) { return dimension == 2; }

constexpr int kMaxIgnoredDepth = 64;  // members the protocol ignores may nest, within reason

// Reads the answer as nlohmann's parser streams it (SAX), so that no student output can make the checker
// allocate, recurse or throw without bound: the ids are stored as they come and refused beyond the case's
// size, nesting the protocol does not have is refused at once, and an out-of-range number (1e999) is an
// error naming its field, not an exception. The first problem stops the reading.
class AnswerReader final : public nlohmann::json_sax<json> {
 public:
  AnswerReader(int dimension, int rows, int columns)
      : dimension_(dimension), flat_(ids_are_flat(dimension)), rows_(rows), columns_(columns) {
    answer.rows = flat_ ? 1 : 0;  // rows: counted as they come
  }

  Answer answer;
  bool seen_ids = false;
  bool too_big = false;  // more ids than the case has: refused while reading
  std::string error;

  bool null() override { return scalar("null", std::nullopt); }
  bool boolean(bool) override { return scalar("a boolean", std::nullopt); }
  bool number_integer(number_integer_t value) override { return integer(double(value), value); }
  bool number_unsigned(number_unsigned_t value) override {
    return value > number_unsigned_t(1) << 40 ? scalar("a number out of range", std::nullopt)
                                                : integer(double(value), number_integer_t(value));
  }
  bool number_float(number_float_t value, const string_t& text) override {
    if (!std::isfinite(value)) return scalar("a number out of range (" + text.substr(0, 24) + ")", std::nullopt);
    if (place() == Place::md_number) return md_number(value);
    if (value == std::floor(value) && std::abs(value) < 2e9) return integer(value, number_integer_t(value));
    return scalar("the number " + text.substr(0, 24), std::nullopt);
  }
  bool string(string_t&) override { return scalar("a string", std::nullopt); }
  bool binary(binary_t&) override { return scalar("binary data", std::nullopt); }

  bool start_object(std::size_t) override {
    if (stack_.empty()) {
      stack_.push_back({Kind::root, 0, ""});
      return true;
    }
    if (place() != Place::ignored) return fail(where() + ": expected " + expected() + ", got an object");
    return push(Kind::ignored);
  }
  bool key(string_t& name) override {
    if (stack_.size() == 1) stack_.back().key = name;
    return true;
  }
  bool end_object() override { return pop(); }
  bool start_array(std::size_t) override {
    switch (place()) {
      case Place::ids:
        seen_ids = true;
        return push(Kind::ids);
      case Place::ids_row:
        if (answer.rows >= rows_) return too_many();
        row_length_ = 0;
        return push(Kind::row);
      case Place::md:
        answer.md.emplace();
        return push(Kind::md);
      case Place::md_row:
        if (md_rows_ >= dimension_ + 1) return fail(md_expected());
        md_columns_ = 0;
        return push(Kind::md_row);
      case Place::ignored:
        return push(Kind::ignored);
      default:
        return fail(where() + ": expected " + expected() + ", got a list");
    }
  }
  bool end_array() override {
    const Kind kind = stack_.back().kind;
    if (kind == Kind::row) {
      if (answer.rows == 0) answer.columns = row_length_;
      if (row_length_ != answer.columns)
        return fail(formatted(Language::en, "ids[%d]: %d {{column|columns}} where row 0 has %d", answer.rows,
                              row_length_, answer.columns));
      ++answer.rows;
    } else if (kind == Kind::md_row) {
      if (md_columns_ != dimension_ + 1) return fail(md_expected());
      ++md_rows_;
    } else if (kind == Kind::md && md_rows_ != dimension_ + 1) {
      return fail(md_expected());
    } else if (kind == Kind::ids && flat_) {
      answer.columns = int(answer.ids.size());
    }
    return pop();
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    if (e.id == 406) return scalar("a number out of range", std::nullopt);  // 1e999: the lexer's overflow
    return fail("not JSON: syntax error at byte " + std::to_string(position));
  }

 private:
  enum class Kind { root, ids, row, md, md_row, ignored };
  enum class Place { root_value, ids, ids_row, ids_number, md, md_row, md_number, ignored, nowhere };
  struct Level {
    Kind kind;
    int index;  // the next element's index in an array
    std::string key;
  };

  // Where the next value goes, from the levels open around it.
  Place place() const {
    if (stack_.empty()) return Place::root_value;
    const Level& top = stack_.back();
    switch (top.kind) {
      case Kind::root:
        return top.key == "ids" ? Place::ids : top.key == "md" ? Place::md : Place::ignored;
      case Kind::ids:
        return flat_ ? Place::ids_number : Place::ids_row;
      case Kind::row:
        return Place::ids_number;
      case Kind::md:
        return Place::md_row;
      case Kind::md_row:
        return Place::md_number;
      case Kind::ignored:
        return Place::ignored;
    }
    return Place::nowhere;
  }
  std::string where() const {
    if (stack_.size() <= 1) return stack_.empty() ? "the answer" : stack_.back().key;
    std::string path = stack_[0].key;
    for (std::size_t i = 1; i < stack_.size(); ++i) path += "[" + std::to_string(stack_[i].index) + "]";
    return path;
  }
  std::string expected() const {
    switch (place()) {
      case Place::root_value:
        return "a JSON object with \"ids\"";
      case Place::ids:
        return flat_ ? "a list of integers" : "a list of rows";
      case Place::ids_row:
        return "a list of integers";
      case Place::ids_number:
        return "an integer id";
      default:
        return "a number";
    }
  }
  std::string md_expected() const {
    return formatted(Language::en, "md: expected %d {{row|rows}} of %d {{number|numbers}}", dimension_ + 1,
                     dimension_ + 1);
  }
  bool fail(std::string message) {
    error = std::move(message);
    return false;
  }
  bool too_many() {
    too_big = true;
    return fail(flat_ ? formatted(Language::en, "expected %d {{id|ids}}, got more", columns_)
                      : formatted(Language::en, "expected %d {{row|rows}} of %d {{id|ids}}, got more", rows_,
                                  columns_));
  }
  bool push(Kind kind) {
    if (stack_.size() >= std::size_t(kMaxIgnoredDepth)) return fail(where() + ": nested too deep");
    stack_.push_back({kind, 0, ""});
    return true;
  }
  bool pop() {
    stack_.pop_back();
    if (!stack_.empty()) ++stack_.back().index;
    return true;
  }
  bool advance() {
    if (!stack_.empty()) ++stack_.back().index;
    return true;
  }
  // A value that is not what its place takes (or a number that is no id there).
  bool scalar(const std::string& got, std::optional<double>) {
    const Place at = place();
    if (at == Place::ignored) return advance();
    if (at == Place::md && got == "null") return advance();  // "md": null is no matrix
    if (at == Place::md_number) return fail(md_expected() + " (finite), got " + got);
    if (at == Place::md || at == Place::md_row) return fail(md_expected());
    return fail(where() + ": expected " + expected() + ", got " + got);
  }
  bool integer(double value, number_integer_t exact) {
    const Place at = place();
    if (at == Place::md_number) return md_number(value);
    if (at != Place::ids_number) return scalar("the number " + std::to_string(exact), std::nullopt);
    if (exact < -(number_integer_t(1) << 31) || exact > (number_integer_t(1) << 31) - 1)
      return fail(where() + ": " + std::to_string(exact) + " is not an id");
    if (!flat_ && answer.rows > 0 && row_length_ >= answer.columns)  // ragged: named before "too many"
      return fail(formatted(Language::en, "ids[%d]: %d {{column|columns}} (or more) where row 0 has %d",
                            answer.rows, row_length_ + 1, answer.columns));
    if (flat_ ? int(answer.ids.size()) >= columns_ : row_length_ >= columns_) return too_many();
    answer.ids.push_back(int(exact));
    ++row_length_;
    return advance();
  }
  bool md_number(double value) {
    if (md_columns_ >= dimension_ + 1) return fail(md_expected());
    answer.md->push_back(value);
    ++md_columns_;
    return advance();
  }

  int dimension_;
  bool flat_;
  int rows_, columns_;
  std::vector<Level> stack_;
  int row_length_ = 0, md_rows_ = 0, md_columns_ = 0;
};
}  // namespace

ParsedAnswer parse_answer(const std::string& text, int dimension, int rows, int columns, int objects) {
  ParsedAnswer parsed;
  AnswerReader reader(dimension, rows, columns);
  bool read = false;
  try {
    read = json::sax_parse(text, &reader);
  } catch (const std::exception& error) {  // nlohmann reports through parse_error; this is a last guard
    reader.error = std::string("not JSON: ") + error.what();
  }
  if (!read && reader.error.empty()) reader.error = "not JSON";
  if (read && !reader.seen_ids) reader.error = "expected a JSON object with \"ids\"";
  if (reader.too_big) {  // the protocol's shape, too many pixels: a wrong size, without the excess
    parsed.wrong_size = true;
    parsed.error = reader.error;
    return parsed;
  }
  if (!reader.error.empty()) {
    parsed.error = reader.error;
    return parsed;
  }
  Answer& answer = reader.answer;
  const bool flat = ids_are_flat(dimension);
  if (flat) answer.rows = 1;
  const std::size_t width = std::size_t(std::max(answer.columns, 1));
  for (std::size_t i = 0; i < answer.ids.size(); ++i)
    if (answer.ids[i] < -1 || answer.ids[i] >= objects) {
      const std::string at = flat ? "ids[" + std::to_string(i) + "]"
                                            : "ids[" + std::to_string(i / width) + "][" +
                                                  std::to_string(i % width) + "]";
      parsed.error = at + " = " + std::to_string(answer.ids[i]) + ": expected an id in [-1, " +
                     std::to_string(objects - 1) + "]";
      return parsed;
    }
  if (answer.rows != rows || answer.columns != columns) {
    parsed.wrong_size = true;
    // (the English names each count's noun in its number: the reason table's patterns take either form)
    parsed.error = flat ? formatted(Language::en, "expected %d {{id|ids}}, got %d", columns, answer.columns)
                        : formatted(Language::en, "expected %d {{row|rows}} of %d {{id|ids}}, got %d of %d", rows,
                                    columns, answer.rows, answer.columns);
  }
  parsed.answer.emplace(std::move(answer));
  return parsed;
}

std::string answer_to_json(const Answer& answer, int dimension) {
  json root;
  if (ids_are_flat(dimension)) {
    root["ids"] = answer.ids;
  } else {
    json rows = json::array();
    for (int r = 0; r < answer.rows; ++r)
      rows.push_back(std::vector<int>(answer.ids.begin() + std::ptrdiff_t(r) * answer.columns,
                                      answer.ids.begin() + std::ptrdiff_t(r + 1) * answer.columns));
    root["ids"] = rows;
  }
  if (answer.md) {
    const int side = dimension + 1;
    json md = json::array();
    for (int r = 0; r < side; ++r)
      md.push_back(std::vector<double>(answer.md->begin() + r * side, answer.md->begin() + (r + 1) * side));
    root["md"] = md;
  }
  return root.dump() + "\n";
}

}  // namespace raycam::check
