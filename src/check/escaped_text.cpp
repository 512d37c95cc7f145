#include "check/escaped_text.h"

#include <cstdio>

namespace raycam::check {

namespace {
void append_hex(std::string& out, unsigned char byte) {
  char code[5];
  std::snprintf(code, sizeof code, "\\x%02x", byte);
  out += code;
}

unsigned char byte_at(const std::string& text, std::size_t i) {
  return i < text.size() ? static_cast<unsigned char>(text[i]) : 0;  // 0: never a continuation byte
}

// The length of the valid UTF-8 sequence at `text[at]` (1 to 4), or 0 when the bytes there are not one.

// Unicode's table 3-7 (well-formed UTF-8): the second byte's range excludes overlong forms (E0, F0),
// surrogates (ED) and values past U+10FFFF (F4); C0, C1 and F5..FF never lead.
std::size_t utf8_sequence_length(const std::string& text, std::size_t at) {
  const unsigned char lead = byte_at(text, at), second = byte_at(text, at + 1);
  auto continuation = [&](std::size_t i) { return (byte_at(text, i) & 0xc0) == 0x80; };
  if (at >= text.size()) return 0;
  if (lead < 0x80) return 1;
  if (lead >= 0xc2 && lead <= 0xdf) return continuation(at + 1) ? 2 : 0;
  unsigned char low = 0x80, high = 0xbf;
  if (lead == 0xe0) low = 0xa0;
  else if (lead == 0xed) high = 0x9f;
  else if (lead == 0xf0) low = 0x90;
  else if (lead == 0xf4) high = 0x8f;
  else if (lead < 0xe0 || lead > 0xf4) return 0;
  if (second < low || second > high) return 0;
  const std::size_t length = lead < 0xf0 ? 3 : 4;
  for (std::size_t k = 2; k < length; ++k)
    if (!continuation(at + k)) return 0;
  return length;
}
}  // namespace

bool valid_utf8(const std::string& text) {
  for (std::size_t i = 0, length; i < text.size(); i += length)
    if ((length = utf8_sequence_length(text, i)) == 0) return false;
  return true;
}

std::string escaped_control(const std::string& text, bool keep_newlines) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const std::size_t length = utf8_sequence_length(text, i);
    // Not UTF-8: this byte alone is shown, and the next one is looked at afresh (a lead byte cut short must
    // not swallow an ESC after it).
    if (length == 0) {
      append_hex(out, byte);
      ++i;
      continue;
    }
    const bool c1 = byte == 0xc2 && byte_at(text, i + 1) <= 0x9f;  // U+0080..U+009F
    const bool c0 = length == 1 && ((byte < 0x20 && byte != '\t' && !(keep_newlines && byte == '\n')) || byte == 0x7f);
    if (c0 || c1)
      for (std::size_t k = 0; k < length; ++k) append_hex(out, byte_at(text, i + k));
    else
      out.append(text, i, length);
    i += length;
  }
  return out;
}

}  // namespace raycam::check
