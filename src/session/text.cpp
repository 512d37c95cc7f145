#include "text.h"

#include <cstdarg>

namespace raycam::ui {

const std::vector<Translation>& translation_table();  // text_table.cpp

namespace {
Language g_language = Language::en;  // like ImGui's own context: one window, one language at a time

const TranslationTable& table() {
  static const TranslationTable built(translation_table());
  return built;
}
}  // namespace

const std::vector<Translation>& translations() { return translation_table(); }

const char* tr(const char* english) { return table().lookup(g_language, english); }

std::string trf(const char* english_format, ...) {
  va_list args;
  va_start(args, english_format);
  std::string text = format_text(tr(english_format), args);
  va_end(args);
  return text;
}

void set_language(Language language) { g_language = language; }
Language current_language() { return g_language; }

}  // namespace raycam::ui
