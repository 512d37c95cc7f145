// A very small JSON reader, enough to read a check case (objects, arrays, numbers, strings, true/false/null).
// Standard library only, so that camera.cpp builds with nothing but a C++17 compiler. Throws
// std::runtime_error on malformed input.
#pragma once

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mini_json {

struct Value {
  enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
  double number = 0;
  bool boolean = false;
  std::string string;
  std::vector<Value> array;
  std::map<std::string, Value> object;

  const Value& operator[](const std::string& key) const {
    const auto found = object.find(key);
    if (kind != Kind::object || found == object.end()) throw std::runtime_error("missing key '" + key + "'");
    return found->second;
  }
  const Value& operator[](std::size_t i) const { return array.at(i); }
  std::size_t size() const { return array.size(); }
  bool is_array() const { return kind == Kind::array; }
};

class Parser {
 public:
  explicit Parser(const std::string& text) : text_(text) {}

  Value parse() {
    Value value = parse_value();
    skip_blanks();
    if (at_ < text_.size()) fail("trailing characters");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(at_));
  }
  void skip_blanks() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool take(char c) {
    skip_blanks();
    if (at_ < text_.size() && text_[at_] == c) return ++at_, true;
    return false;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("expected '") + c + "'");
  }

  Value parse_value() {
    skip_blanks();
    if (at_ >= text_.size()) fail("unexpected end");
    Value value;
    const char c = text_[at_];
    if (c == '{') {
      value.kind = Value::Kind::object;
      ++at_;
      if (take('}')) return value;
      do {
        skip_blanks();
        const std::string key = parse_string();
        expect(':');
        value.object[key] = parse_value();
      } while (take(','));
      expect('}');
    } else if (c == '[') {
      value.kind = Value::Kind::array;
      ++at_;
      if (take(']')) return value;
      do value.array.push_back(parse_value());
      while (take(','));
      expect(']');
    } else if (c == '"') {
      value.kind = Value::Kind::string;
      value.string = parse_string();
    } else if (text_.compare(at_, 4, "true") == 0 || text_.compare(at_, 5, "false") == 0) {
      value.kind = Value::Kind::boolean;
      value.boolean = text_[at_] == 't';
      at_ += value.boolean ? 4 : 5;
    } else if (text_.compare(at_, 4, "null") == 0) {
      at_ += 4;
    } else {
      char* end = nullptr;
      value.kind = Value::Kind::number;
      value.number = std::strtod(text_.c_str() + at_, &end);  // strtod reads JSON numbers exactly
      if (end == text_.c_str() + at_) fail("expected a value");
      at_ = std::size_t(end - text_.c_str());
    }
    return value;
  }

  std::string parse_string() {
    if (at_ >= text_.size() || text_[at_] != '"') fail("expected a string");
    std::string out;
    for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
      if (text_[at_] == '\\' && ++at_ < text_.size()) {
        const char e = text_[at_];
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e;  // \uXXXX is not needed for check cases
      } else {
        out += text_[at_];
      }
    }
    if (at_ >= text_.size()) fail("unclosed string");
    ++at_;
    return out;
  }

  const std::string& text_;
  std::size_t at_ = 0;
};

inline Value parse(const std::string& text) { return Parser(text).parse(); }

}  // namespace mini_json
