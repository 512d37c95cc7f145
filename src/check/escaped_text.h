// Text a student controls (its stderr, a submission folder's name, what it printed) shown on a terminal or in
// a report without the terminal obeying it: an escape sequence could clear the screen and print a fake score.
#pragma once

#include <string>

namespace raycam::check {

// `text` with every control character written as \xNN: C0 (but tab, and newline when `keep_newlines`), DEL
// and the C1 controls encoded in UTF-8 (U+0080..U+009F, e.g. CSI U+009B). A backslash stays as it is.
std::string escaped_control(const std::string& text, bool keep_newlines = false);

}  // namespace raycam::check
