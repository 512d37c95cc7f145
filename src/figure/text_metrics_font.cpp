// Text measured from DejaVu Sans's font files (stb_truetype), for the web page, which has no cairo: cairo's
// hinted metrics, reproduced (each glyph's advance rounded to a whole point, the font's ascent and descent
// rounded up, no kerning), so that the page's TikZ places its labels where raycam-cli figure does. The test
// that compares the two on the figures' own words: tests/figure/test_text_metrics.cpp.
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC  // private to this file: Dear ImGui builds its own copy
#include <stb/stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "figure/text_metrics.h"

namespace raycam::figure {

namespace {

// The Debian paths (fonts-dejavu-core), where the web page's file system holds them too (src/web).
constexpr const char* kRegularFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kBoldFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

struct FontFile {
  std::vector<unsigned char> bytes;
  stbtt_fontinfo info{};
  double per_em = 1.0 / 2048;  // font units to the font's size
  int ascender = 0, descender = 0;

  explicit FontFile(const char* path) {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (bytes.empty() || !stbtt_InitFont(&info, bytes.data(), stbtt_GetFontOffsetForIndex(bytes.data(), 0)))
      throw std::runtime_error(std::string(path) + ": cannot read the figures' font");
    per_em = double(stbtt_ScaleForMappingEmToPixels(&info, 1.0f));
    int gap = 0;
    stbtt_GetFontVMetrics(&info, &ascender, &descender, &gap);
  }
};

const FontFile& font(bool bold) {
  static const FontFile regular(kRegularFile), heavy(kBoldFile);
  return bold ? heavy : regular;
}

// The next code point of UTF-8 `text` at `at` (advanced past it); U+FFFD for a malformed byte.
int next_code_point(const std::string& text, std::size_t& at) {
  const auto byte = [&](std::size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0u; };
  const unsigned first = byte(at);
  const int length = first < 0x80 ? 1 : (first >> 5) == 6 ? 2 : (first >> 4) == 14 ? 3 : (first >> 3) == 30 ? 4 : 0;
  if (length == 0) {
    ++at;
    return 0xFFFD;
  }
  unsigned code = length == 1 ? first : first & (0x7Fu >> length);
  for (int i = 1; i < length; ++i) code = (code << 6) | (byte(at + std::size_t(i)) & 0x3Fu);
  at += std::size_t(length);
  return int(code);
}

}  // namespace

RunMetrics measure_run_in_font_files(const std::string& text, double size, bool bold) {
  const FontFile& f = font(bold);
  const double scale = size * f.per_em;
  RunMetrics m;
  m.ascent = std::ceil(f.ascender * scale);
  m.descent = std::ceil(-f.descender * scale);
  double top = 0.0, bottom = 0.0;
  bool inked = false;
  for (std::size_t at = 0; at < text.size();) {
    const int glyph = stbtt_FindGlyphIndex(&f.info, next_code_point(text, at));
    int advance = 0, bearing = 0;
    stbtt_GetGlyphHMetrics(&f.info, glyph, &advance, &bearing);
    m.x_advance += std::round(advance * scale);
    int x0, y0, x1, y1;
    if (stbtt_GetGlyphBox(&f.info, glyph, &x0, &y0, &x1, &y1) && x1 > x0) {
      top = inked ? std::max(top, y1 * scale) : y1 * scale;
      bottom = inked ? std::min(bottom, y0 * scale) : y0 * scale;
      inked = true;
    }
  }
  if (inked) {
    m.y_bearing = -std::round(top);
    m.height = std::round(top) - std::round(bottom);
  }
  return m;
}

}  // namespace raycam::figure
