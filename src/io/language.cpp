#include "raycam/language.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace raycam {

TranslationTable::TranslationTable(const std::vector<Translation>& entries) {
  for (const Translation& t : entries) entries_.emplace(t.english(), &t);
}

const char* TranslationTable::lookup(Language language, const char* english) const {
  const auto found = entries_.find(english);
  return found == entries_.end() ? english : (*found->second)[language];
}

std::optional<Language> language_from_code(std::string_view code) {
  const std::string_view first = code.substr(0, code.find(':'));  // LANGUAGE is a list: fr:en
  for (Language language : kLanguages) {
    const std::string_view name = language_code(language);
    if (first.substr(0, name.size()) == name &&
        (first.size() == name.size() || first[name.size()] == '_' || first[name.size()] == '.'))
      return language;
  }
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
  std::string accepted;
  for (Language language : kLanguages) {
    if (value == language_code(language)) return language;
    accepted += std::string(accepted.empty() ? "" : " or ") + language_code(language);
  }
  throw std::invalid_argument(flag + ": expected " + accepted + ", got '" + value + "'");
}

}  // namespace raycam
