// Text a student controls (its stderr, a submission folder's name, what it printed) shown on a terminal or in
// a report without the terminal obeying it: an escape sequence could clear the screen and print a fake score.
#pragma once

#include <string>

namespace raycam::check {

// `text` as valid UTF-8 with every control written as \xNN, byte by byte: C0 (but tab, and newline when
// `keep_newlines`), DEL, the C1 controls encoded in UTF-8 (U+0080..U+009F, e.g. CSI U+009B), and every byte
// that is not part of a valid UTF-8 sequence (a raw 0x9B, the 8-bit CSI; overlong forms, surrogates, values
// past U+10FFFF, a sequence cut short). Valid UTF-8 (é, 学, emoji) and a backslash stay as they are.
std::string escaped_control(const std::string& text, bool keep_newlines = false);

// Whether `text` is valid UTF-8 (what escaped_control leaves as it is, controls aside).
bool valid_utf8(const std::string& text);

}  // namespace raycam::check
