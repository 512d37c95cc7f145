// What every translated text needs, on top of the core's Language and LocalText (raycam/languages.h): the
// language from a flag or the environment, a table looked up by its English key, and printf-style
// formatting. The window's table is src/session/text_table.cpp (tr(), text.h), the check command's
// src/check/check_texts.cpp (the figures' src/figure/figure_texts.cpp has the same shape with a lookup of its
// own: the figure does not link io); the English text is the key in each, as gettext's msgid. Error reasons (what
// core, io and the checker throw or report, in English, with paths, numbers and field names inside) are
// translated by pattern where they are shown: translate_reason().
#pragma once

#include <cstdarg>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "raycam/languages.h"

namespace raycam {

// An entry of a table of texts: {"English key", "Français", ...}, in Language's order.
using Translation = LocalText;

// A table's texts by their English key, built once from its entries.
class TranslationTable {
 public:
  explicit TranslationTable(const std::vector<Translation>& entries);
  // `english` in `language`: the entry's text, or `english` itself when the table lacks it.
  const char* lookup(Language language, const char* english) const;

 private:
  std::unordered_map<std::string_view, const Translation*> entries_;
};

// printf into a std::string, in `language`'s way (src/io/local_format.cpp), the one formatter of every
// visible text:
// - numbers: a floating conversion (%f, %e, %g) is written with the language's decimal mark (French "0,4 s",
//   English "0.4 s"); integers as printf writes them. Machine outputs (CSV, JSON) do not come here.
// - plurals: a group "{{one|many}}" holds the singular and the plural of the words after an integer
//   conversion: the last integer written before the group picks the form by takes_plural() ("%d {{file
//   written|files written}}", "%lld {{cast|casts}} in %lld {{frame|frames}}"). A group holds no conversion.
// `args` is consumed.
std::string format_text(Language language, const char* format, va_list args);
std::string formatted(Language language, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
// Whether `count` takes the plural in `language`: English all but 1 ("0 pixels", "1 pixel"), French 2 and
// more ("0 pixel", "1 pixel", "2 pixels").
bool takes_plural(Language language, long long count);

// "fr", "fr_FR.UTF-8", "en_GB:en" ... → the language, or nothing for another language or "C"/"POSIX".
std::optional<Language> language_from_code(std::string_view code);
// The first of LANGUAGE, LC_ALL, LC_MESSAGES, LANG that is set and not empty decides (as gettext does);
// French if it names French, English otherwise.
Language language_from_environment();
// The --lang flag: one of kLanguageCodes; throws std::invalid_argument naming the flag and the accepted values.
Language parse_language_flag(const std::string& value, const std::string& flag = "--lang");
inline const char* language_code(Language language) { return kLanguageCodes[std::size_t(language)]; }

// An error reason's phrasing in every language, English first. In English, "{name}" stands for a variable
// part (a path, a number, a field name), kept as it is; "{name*}" for a nested reason, itself translated.
// Each other language places each name once, as "{name}" (without the star). A plural group "{{one|many}}"
// after a count's placeholder: the English matches either form (the code writes the one its count asks for,
// "1 column", "2 columns"), each other language's template keeps the form the number filled in before it asks
// for (takes_plural()). Any other brace is literal.
using ReasonPattern = LocalText;

// Every reason raycam may show (src/io/reason_table.cpp); the first pattern matching the whole text wins.
const std::vector<ReasonPattern>& reason_patterns();

// `english` (an exception's what(), a checker's detail) in `language`: that language's template of the first
// pattern it matches, or `english` itself (no pattern matches, Language::en, or longer than 2 KiB): no reason is lost. `used`, when
// given, receives the index in reason_patterns() of every pattern applied, nested ones included.
std::string translate_reason(Language language, const std::string& english,
                             std::vector<std::size_t>* used = nullptr);

}  // namespace raycam
