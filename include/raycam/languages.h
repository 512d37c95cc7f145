// The languages of raycam's visible text, and a text in every one of them: the one type every table uses
// (the window's and the checker's texts, the error reasons' patterns, the classic mistakes' labels, the
// figures' words), and the one way to look a text up, text[language].
//
// Adding a language: its value in Language, its code in kLanguageCodes, and its column in every table.
// Nothing else: tests/session/test_text.cpp fails on any text without it.
#pragma once

#include <cstddef>

namespace raycam {

enum class Language { en, fr };
inline constexpr std::size_t kLanguageCount = 2;
// ISO 639-1 codes, in Language's order (--lang, ?lang=, LANG).
inline constexpr const char* kLanguageCodes[kLanguageCount] = {"en", "fr"};
inline constexpr Language kLanguages[kLanguageCount] = {Language::en, Language::fr};

// A text in every language, in Language's order: {"English", "Français"}. English first: it is the key
// the tables are looked up by (gettext's msgid).
struct LocalText {
  const char* in[kLanguageCount];
  const char* operator[](Language language) const { return in[std::size_t(language)]; }
  const char* english() const { return in[0]; }
};

}  // namespace raycam
