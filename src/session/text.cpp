#include "session/text.h"

#include <cstdarg>

namespace raycam::session {

const std::vector<Translation>& translation_table();  // text_table.cpp

namespace {
const TranslationTable& table() {
  static const TranslationTable built(translation_table());
  return built;
}
}  // namespace

const std::vector<Translation>& translations() { return translation_table(); }

const char* tr(Language language, const char* english) { return table().lookup(language, english); }

std::string trf(Language language, const char* english_format, ...) {
  va_list args;
  va_start(args, english_format);
  std::string text = format_text(language, tr(language, english_format), args);
  va_end(args);
  return text;
}

std::string with_no_break_spaces(std::string text) {
  for (const char* mark : {" ;", " :", " ?", " !"})
    for (std::size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at + 2))
      text.replace(at, 1, "\u00a0");
  return text;
}

std::string tr_reason(Language language, const std::string& english) {
  const std::string shown = translate_reason(language, english);
  return language == Language::fr ? with_no_break_spaces(shown) : shown;
}

}  // namespace raycam::session
