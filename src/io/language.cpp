#include "raycam/language.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace raycam {

TranslationTable::TranslationTable(const std::vector<Translation>& entries) {
  for (const Translation& t : entries) french_.emplace(t.en, t.fr);
}

const char* TranslationTable::lookup(Language language, const char* english) const {
  if (language == Language::en) return english;
  const auto found = french_.find(english);
  return found == french_.end() ? english : found->second;
}

std::string format_text(const char* format, va_list args) {
  va_list copy;
  va_copy(copy, args);
  const int size = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string text(size > 0 ? std::size_t(size) : 0, '\0');
  if (size > 0) std::vsnprintf(text.data(), text.size() + 1, format, args);
  return text;
}

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

const char* mistake_label(const MistakeInfo& info, Language language) {
  return language == Language::fr ? info.label_fr : info.label_en;
}

const char* mistake_explanation(const MistakeInfo& info, Language language) {
  return language == Language::fr ? info.explanation_fr : info.explanation_en;
}

}  // namespace raycam
