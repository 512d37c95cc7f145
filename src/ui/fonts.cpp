#include "ui/fonts.h"

#include <imgui.h>

#include <cmath>
#include <fstream>
#include <vector>
#ifdef RAYCAM_HAVE_FONTCONFIG
#include <fontconfig/fontconfig.h>
#endif

#include "check/check_texts.h"
#include "raycam/classic_mistakes.h"
#include "raycam/demo_names.h"
#include "ui/renderer_backend.h"
#include "ui/words.h"

namespace raycam::ui {

namespace {
constexpr const char* kKnownFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
float g_built_scale = -1.0f;
float g_built_density = -1.0f;
const ImGuiContext* g_built_for = nullptr;  // a new ImGui context starts with the default atlas
const ImFont* g_built_font = nullptr;       // the first font of the atlas built last
bool g_truetype = false;

bool readable(const std::string& path) { return !path.empty() && std::ifstream(path).good(); }

}  // namespace

std::vector<const char*> shown_table_texts() {
  std::vector<const char*> texts;
  auto add = [&](const LocalText& t) {
    for (Language language : kLanguages) texts.push_back(t[language]);
  };
  for (const Translation& t : translations()) add(t);
  for (const Translation& t : check::check_translations()) add(t);
  for (const ReasonPattern& t : reason_patterns()) add(t);
  for (const Translation& t : demo_object_name_texts()) add(t);
  for (const MistakeInfo& m : kClassicMistakes) {
    add(m.label);
    add(m.explanation);
  }
  return texts;
}

// Latin-1 and Latin Extended-A (œ), Greek (θ φ ψ α Ω), super- and subscripts (u⁰ₖ, ψ₀, φᵥ), and every
// character of the tables (·, —, ≥, ⌊ ...).
const ImWchar* ui_glyph_ranges() {
  static ImVector<ImWchar> ranges;
  if (ranges.empty()) {
    ImFontGlyphRangesBuilder builder;
    static const ImWchar kBase[] = {0x0020, 0x017F, 0x0391, 0x03C9, 0x1D62, 0x1D6A, 0x2010, 0x2027, 0x2070,
                                    0x209F, 0x2190, 0x2193, 0x2212, 0x2212, 0x2248, 0x2248, 0x2260, 0x2265, 0};
    builder.AddRanges(kBase);
    for (const char* text : shown_table_texts()) builder.AddText(text);
    builder.BuildRanges(&ranges);
  }
  return ranges.Data;
}

std::string find_ui_font() {
#ifdef RAYCAM_HAVE_FONTCONFIG
  std::string found;
  if (FcInit()) {
    FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>("DejaVu Sans"));
    FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    if (FcPattern* match = FcFontMatch(nullptr, pattern, &result)) {
      FcChar8* file = nullptr;
      FcChar8* family = nullptr;
      // fontconfig always answers with some font: take it only if it is DejaVu (accents, Greek, TrueType).
      if (FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch &&
          FcPatternGetString(match, FC_FAMILY, 0, &family) == FcResultMatch &&
          std::string(reinterpret_cast<char*>(family)).find("DejaVu") != std::string::npos)
        found = reinterpret_cast<char*>(file);
      FcPatternDestroy(match);
    }
    FcPatternDestroy(pattern);
  }
  if (readable(found)) return found;
#endif
  return readable(kKnownFontPath) ? kKnownFontPath : "";
}

bool update_fonts(float font_scale, float pixel_density) {
  // A context made where a destroyed one was (the tests make one per window size) has the same address and
  // a new atlas: the atlas's first font tells whether it is the one built here.
  const ImFontAtlas* atlas = ImGui::GetIO().Fonts;
  const bool atlas_is_ours = !atlas->Fonts.empty() && atlas->Fonts[0] == g_built_font;
  if (g_built_for == ImGui::GetCurrentContext() && atlas_is_ours && std::abs(font_scale - g_built_scale) < 1e-4f &&
      std::abs(pixel_density - g_built_density) < 1e-4f)
    return false;
  static const std::string path = find_ui_font();
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  g_truetype = false;
  // The size in UI pixels, as at density 1; the glyphs rasterised at `pixel_density` times as many pixels.
  const float shown_pixels = std::round(kBaseFontPixels * font_scale);
  const float raster_pixels = std::round(kBaseFontPixels * font_scale * pixel_density);
  if (!path.empty()) {
    ImFontConfig config;
    config.OversampleH = 2;  // sharper at fractional positions; the atlas stays small at 1 oversample in y
    config.OversampleV = 1;
    g_truetype = io.Fonts->AddFontFromFileTTF(path.c_str(), raster_pixels, &config, ui_glyph_ranges()) != nullptr;
  }
  if (!g_truetype) {
    ImFontConfig config;
    config.SizePixels = std::round(13.0f * font_scale * pixel_density);  // the built-in bitmap font, scaled at build time
    io.Fonts->AddFontDefault(&config);
  }
  io.Fonts->Build();
  io.FontGlobalScale = g_truetype ? shown_pixels / raster_pixels : 1.0f / pixel_density;
  // The backend's next NewFrame re-creates its device objects, the font texture from the new atlas included.
  restart_renderer_backend();
  g_built_scale = font_scale;
  g_built_density = pixel_density;
  g_built_for = ImGui::GetCurrentContext();
  g_built_font = io.Fonts->Fonts[0];
  return true;
}

bool using_truetype_font() { return g_truetype; }

}  // namespace raycam::ui
