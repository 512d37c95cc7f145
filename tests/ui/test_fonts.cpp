// The window's font holds every character its tables use (u⁰ₖ, ψ₀, φᵥ, ≥, π, ⌊ ...), and the mistakes'
// explanations and the window's texts write their maths typeset, not as plain-text code.
#include <imgui.h>

#include <catch2/catch.hpp>
#include <regex>
#include <string>
#include <vector>

#include "ui/fonts.h"
#include "raycam/classic_mistakes.h"
#include "session/text.h"

using namespace raycam;

namespace {
// The code points of a UTF-8 text (its bytes are well formed: the tables are written in UTF-8).
std::vector<unsigned> code_points(const std::string& text) {
  std::vector<unsigned> points;
  for (std::size_t at = 0; at < text.size();) {
    const unsigned char lead = static_cast<unsigned char>(text[at]);
    const int length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
    unsigned point = length == 1 ? lead : lead & (0xFF >> (length + 1));
    for (int i = 1; i < length && at + std::size_t(i) < text.size(); ++i)
      point = (point << 6) | (static_cast<unsigned char>(text[at + std::size_t(i)]) & 0x3F);
    points.push_back(point);
    at += std::size_t(length);
  }
  return points;
}

bool in_ranges(const ImWchar* ranges, unsigned point) {
  for (; ranges[0] != 0; ranges += 2)
    if (point >= ranges[0] && point <= ranges[1]) return true;
  return false;
}
}  // namespace

TEST_CASE("every character of the window's tables is in the font's glyph ranges, and in the font", "[ui][text][font]") {
  const ImWchar* ranges = ui::ui_glyph_ranges();
  CHECK_FALSE(in_ranges(ranges, 0x4E2D));  // the ranges are not everything (中)
  std::vector<unsigned> used;
  for (const char* text : ui::shown_table_texts())
    for (unsigned point : code_points(text)) {
      INFO(text);
      if (point >= 0x20) CHECK(in_ranges(ranges, point));
      used.push_back(point);
    }
  for (const char* typeset : {"u⁰ₖ", "ψ₀", "φᵥ", "π/180", "t ≥ 0"}) {
    INFO(typeset);
    for (unsigned point : code_points(typeset)) CHECK(in_ranges(ranges, point));
  }
  const std::string font = ui::find_ui_font();
  if (font.empty()) return;  // the built-in font: ASCII only, as documented
  ImFontAtlas atlas;
  ImFont* loaded = atlas.AddFontFromFileTTF(font.c_str(), 15.0f, nullptr, ranges);
  REQUIRE(loaded != nullptr);
  REQUIRE(atlas.Build());
  for (unsigned point : used)
    if (point >= 0x20 && point != 0xA0 && point <= 0xFFFF) {
      INFO("U+" << std::hex << point);
      CHECK(loaded->FindGlyphNoFallback(ImWchar(point)) != nullptr);
    }
}

TEST_CASE("the mistakes' explanations and the window's texts write their maths typeset", "[ui][text]") {
  std::vector<std::string> texts;
  for (const raycam::Translation& t : session::translations())
    for (Language language : kLanguages) texts.push_back(t[language]);
  for (const MistakeInfo& m : kClassicMistakes)
    for (Language language : kLanguages) {
      texts.push_back(m.label[language]);
      texts.push_back(m.explanation[language]);
    }
  // Plain-text code for maths: u_k^0, pi/180, t >= 0, psi0, sqrt(…), a hyphen for a minus, 1e-8 in prose.
  const std::regex plain(R"((_k\b|\^0|\bpi\b|>=|<=|!=|\bpsi|\btheta\b|\bphi\b|sqrt|(^|[ (\[=])-[0-9]|[0-9]e-[0-9]+ rad))");
  CHECK(std::regex_search(std::string("only hits with t >= 0 count"), plain));  // the scan sees it
  CHECK(std::regex_search(std::string("u_k = M_d·u_k^0"), plain));
  CHECK_FALSE(std::regex_search(std::string("uₖ = M_d·u⁰ₖ, t ≥ 0, π/180, −1"), plain));
  for (const std::string& text : texts) {
    INFO(text);
    CHECK_FALSE(std::regex_search(text.substr(0, text.find("###")), plain));  // an ImGui id is not shown
  }
}
