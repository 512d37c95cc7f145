// The check command's visible text in English or French (the language is per call: --batch grades many
// students on many threads). The machinery is the window's (raycam/language.h): the English text is the
// key, the French in check_texts.cpp's own table. The mistakes' own explanations live beside them in the
// core (classic_mistakes.cpp).
#pragma once

#include <string>

namespace raycam::check {

// The French of `english` when lang is "fr" (english itself if the table lacks it); english otherwise.
const char* text(const std::string& lang, const char* english);
// text() then printf-style formatting.
std::string textf(const std::string& lang, const char* english_format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

// "fr" or "en" from --lang, or from the environment (LANGUAGE, LC_ALL, LC_MESSAGES, LANG) when empty.
// Throws std::invalid_argument naming --lang for another value.
std::string check_language(const std::string& flag_value);

}  // namespace raycam::check
