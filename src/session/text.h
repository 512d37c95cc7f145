// Visible text in French or English. Every string the window shows goes through tr() (or trf() when it has
// arguments), with the English text as the key, as gettext's _() does; the French of every key is in one
// table, src/session/text_table.cpp. The table is compiled in: it works on a fresh machine with no locale
// generated. tests/session/test_text.cpp checks that every entry has both languages with the same printf
// conversions and ImGui "###id", and that every tr("...") / trf("...") / tr_later("...") anywhere under src/
// (the window's src/session, src/ui, src/app, the page's src/web) has an entry; the same test holds the
// checker's check::text("...") calls to src/check/check_texts.cpp, the figures' figure_text("...") to
// src/figure/figure_texts.cpp, and a tr_reason() of a literal to a pattern of src/io/reason_table.cpp
// (docs/architecture.md, "Where each text lives").
//
// Add a string: write tr(state.language, "English text") where it is shown (the language is passed: there is no
// language global), and add {"English text", "Texte français"} to
// text_table.cpp (French in the handout's words: distance focale d_f, cible C, œil E, écran, point de visée,
// résolution res, carte des couleurs, M_d = T·R·H).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raycam/language.h"

namespace raycam::session {

// (Language, Translation and the language helpers are raycam/language.h's, shared with the check command.)

// The text in `language` (the window's: AppState::language, passed; there is no language global). `english`
// must be a key of the table (the test enforces it); a missing key is shown as it is, in English.
const char* tr(Language language, const char* english);
// tr() then printf-style formatting (the French entry must keep the English conversions, in order).
std::string trf(Language language, const char* english_format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

// Marks a string that is translated later, where it is shown (gettext's N_): arrays of labels, choices.
constexpr const char* tr_later(const char* english) { return english; }

// French typography in a text written with plain spaces (the core's, the reasons' table): a no-break space
// before ; : ? ! so that a wrapped line never starts with one.
std::string with_no_break_spaces(std::string text);

// An error reason (an exception's what(), a checker's detail: English from core, io or the checker) in
// `language`, by raycam/language.h's translate_reason(), French spacing included. Every reason the window
// shows goes through it.
std::string tr_reason(Language language, const std::string& english);

// The whole table (for the tests and for the font's glyph ranges).
const std::vector<Translation>& translations();

}  // namespace raycam::session
