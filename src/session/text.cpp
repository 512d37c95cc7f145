#include "text.h"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <unordered_map>

namespace raycam::ui {

const std::vector<Translation>& translation_table();  // text_table.cpp

namespace {
Language g_language = Language::en;  // like ImGui's own context: one window, one language at a time

const std::unordered_map<std::string_view, const char*>& french_of() {
  static const auto table = [] {
    std::unordered_map<std::string_view, const char*> map;
    for (const Translation& t : translation_table()) map.emplace(t.en, t.fr);
    return map;
  }();
  return table;
}
}  // namespace

const std::vector<Translation>& translations() { return translation_table(); }

const char* tr(const char* english) {
  if (g_language == Language::en) return english;
  const auto& table = french_of();
  const auto found = table.find(english);
  return found == table.end() ? english : found->second;
}

std::string trf(const char* english_format, ...) {
  const char* format = tr(english_format);
  va_list args, copy;
  va_start(args, english_format);
  va_copy(copy, args);
  const int size = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string text(size > 0 ? std::size_t(size) : 0, '\0');
  if (size > 0) std::vsnprintf(text.data(), text.size() + 1, format, args);
  va_end(args);
  return text;
}

void set_language(Language language) { g_language = language; }
Language current_language() { return g_language; }

std::optional<Language> language_from_code(std::string_view code) {
  const std::string_view first = code.substr(0, code.find(':'));  // LANGUAGE is a list: fr:en
  if (first.size() >= 2 && first.substr(0, 2) == "fr" &&
      (first.size() == 2 || first[2] == '_' || first[2] == '.'))
    return Language::fr;
  if (first.size() >= 2 && first.substr(0, 2) == "en" &&
      (first.size() == 2 || first[2] == '_' || first[2] == '.'))
    return Language::en;
  return std::nullopt;
}

Language language_from_environment() {
  for (const char* name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) {
    const char* value = std::getenv(name);
    if (value && *value) return language_from_code(value).value_or(Language::en);
  }
  return Language::en;
}

Language parse_language_flag(const std::string& value, const std::string& flag) {
  if (value == "fr") return Language::fr;
  if (value == "en") return Language::en;
  throw std::invalid_argument(flag + ": expected fr or en, got '" + value + "'");
}

const char* language_code(Language language) { return language == Language::fr ? "fr" : "en"; }

}  // namespace raycam::ui
