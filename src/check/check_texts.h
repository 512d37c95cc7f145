// The check command's visible text in English or French (the language is per call: --batch grades many
// students on many threads). The machinery is the window's (raycam/language.h): the English text is the
// key, the French in check_texts.cpp's own table. The mistakes' own explanations live beside them in the
// core (classic_mistakes.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "raycam/language.h"

namespace raycam::check {

// `english` in `language` (english itself if the table lacks it).
const char* text(Language language, const char* english);
// text() then printf-style formatting in `language`'s way (format_text(): decimal mark, plural groups
// "%zu {{case|cases}}").
std::string textf(Language language, const char* english_format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

// The time a batch has left at its pace so far (`done` of `total` runs in `elapsed_seconds`): "about 3 min
// 05 s left", in `language`; "" before the first run ends and once the last has.
std::string time_left(Language language, std::size_t done, std::size_t total, double elapsed_seconds);

// --lang's language, or the environment's (LANGUAGE, LC_ALL, LC_MESSAGES, LANG) when it was not given.
Language check_language(std::optional<Language> flag);

// The whole table (for the test that every text has every language).
const std::vector<Translation>& check_translations();

}  // namespace raycam::check
