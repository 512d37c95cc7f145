// French and English: every string of the table has both languages with the same printf conversions and
// ImGui ids, every string the sources show through tr()/trf()/tr_later() is in the table, no widget shows an
// English literal that bypasses the table, and the language comes from --lang or the environment.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

#include "app_state_for.h"
#include "check/check_texts.h"
#include "raycam/classic_mistakes.h"
#include "raycam/demo_names.h"
#include "raycam/language.h"
#include "raycam/ray_caster.h"
#include "session/text.h"

using namespace raycam;

namespace {
// The printf conversions of a format, in order ("%d", "%.1f", "%s"; "%%" is not one).
std::vector<std::string> conversions(const std::string& format) {
  static const std::regex conversion(
      R"re(%[-+ #0]*[0-9*]*(\.[0-9*]+)?(hh|h|ll|l|L|z|j|t)?[diouxXeEfFgGaAcspn%])re");
  std::vector<std::string> found;
  for (auto it = std::sregex_iterator(format.begin(), format.end(), conversion); it != std::sregex_iterator();
       ++it)
    if (it->str() != "%%") found.push_back(it->str());
  return found;
}

std::string imgui_id(const std::string& label) {
  const std::size_t at = label.find("###");
  return at == std::string::npos ? "" : label.substr(at);
}

// The C string literals joined into one argument: "a" "b" -> ab (escapes kept as written).
std::string joined_literals(const std::string& text) {
  static const std::regex literal(R"re("((?:[^"\\]|\\.)*)")re");
  std::string out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), literal); it != std::sregex_iterator(); ++it)
    out += (*it)[1].str();
  return out;
}

std::string unescape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      ++i;
      out += s[i] == 'n' ? '\n' : s[i];
    } else {
      out += s[i];
    }
  }
  return out;
}

std::vector<std::filesystem::path> ui_sources() {
  std::vector<std::filesystem::path> files;
  for (const char* dir : {"src/session", "src/ui", "src/app", "src/web"})
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(RAYCAM_SOURCE_DIR) / dir))
      if (entry.path().extension() == ".cpp" && entry.path().filename() != "text_table.cpp")
        files.push_back(entry.path());
  REQUIRE(files.size() >= 5);
  return files;
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST_CASE("every string of the table has both languages, with the same conversions and ids", "[ui][text]") {
  const auto& table = session::translations();
  REQUIRE(table.size() > 50);
  std::set<std::string> keys;
  for (const raycam::Translation& t : table) {
    INFO(t.english());
    REQUIRE(t.english() != nullptr);
    REQUIRE(t[Language::fr] != nullptr);
    CHECK(std::string(t.english()).size() > 0);
    CHECK(std::string(t[Language::fr]).size() > 0);
    CHECK(keys.insert(t.english()).second);  // no key twice
    CHECK(conversions(t.english()) == conversions(t[Language::fr]));
    CHECK(imgui_id(t.english()) == imgui_id(t[Language::fr]));
  }
  // Every French entry differs from its English, but for an explicit list of what reads the same in both
  // (key names, formulas, numbers, the languages' own names): a French entry left in English fails here.
  const std::set<std::string> same_in_both = {
      "English", "Français", "%d × %d###image", "M_d = T(ΩP)·R(α)·H(1, d_f), α = φᵥ + ψ₀ = %.1f°", "F", "k = 0", "float",
      "double", "long double", "intersection###intersection", "stable (Ray Tracing Gems)", "figure###figure_path", "format###figure_format",
      "F1", "F9", "F11", "F12", "P", "← / →", "θ −/+ 5°", "↑ / ↓", "φ −/+ 5° (3D)", "+ / −", "[ / ]", "Tab", "2D / 3D",
      "1 / 2 / 3", "%.0f ms · %.1f ms"};
  for (const raycam::Translation& t : table)
    if (!same_in_both.count(t.english())) {
      INFO(t.english());
      CHECK(std::string(t.english()) != std::string(t[Language::fr]));
    }
  // One decimal separator in each language: the point, as the sliders and tables print numbers (printf in
  // the C locale); a French "0,05" beside a slider's "0.5000" read as two conventions.
  const std::regex decimal_comma(R"(\d,\d)");
  for (const raycam::Translation& t : table) {
    INFO(t[Language::fr]);
    CHECK_FALSE(std::regex_search(std::string(t[Language::fr]), decimal_comma));
  }
  // The handout's words are there (a French table that kept the English would pass the checks above).
  std::string all_french;
  for (const raycam::Translation& t : table) all_french += std::string(t[Language::fr]) + "\n";
  for (const char* word : {"distance focale", "cible C", "œil", "écran", "résolution", "carte des couleurs",
                           "barre de couleurs", "homothétie"})
    CHECK_THAT(all_french, Catch::Contains(word));
}

// Every text raycam shows, in every table that holds one: the window's, the checker's, the error reasons'
// patterns and the classic mistakes' labels and explanations. Adding a language to Language is then caught
// here until each of them has its column.
TEST_CASE("every text of every table has every language", "[ui][text][language]") {
  std::vector<std::pair<std::string, const LocalText*>> texts;
  for (const Translation& t : session::translations()) texts.push_back({"window", &t});
  for (const Translation& t : check::check_translations()) texts.push_back({"check", &t});
  for (const ReasonPattern& p : reason_patterns()) texts.push_back({"reason", &p});
  for (const Translation& t : demo_object_name_texts()) texts.push_back({"demo names", &t});
  for (const MistakeInfo& info : kClassicMistakes) {
    texts.push_back({std::string("mistake ") + info.id, &info.label});
    texts.push_back({std::string("mistake ") + info.id, &info.explanation});
  }
  REQUIRE(texts.size() > 300);
  for (const auto& [table, text] : texts)
    for (Language language : kLanguages) {
      INFO(table << ": " << (text->english() ? text->english() : "(no English)") << " in "
                 << kLanguageCodes[std::size_t(language)]);
      REQUIRE((*text)[language] != nullptr);
      CHECK(std::string((*text)[language]).size() > 0);
    }
}

TEST_CASE("every string the window shows is in the table", "[ui][text]") {
  std::set<std::string> keys;
  for (const raycam::Translation& t : session::translations()) keys.insert(t.english());
  // tr(language, "..."), trf(language, "...", ...), tr_later("..."), with adjacent literals joined.
  const std::regex marked(R"re(\b(?:tr|trf|tr_later)\(\s*(?:[\w.:>()-]+,\s*)?((?:"(?:[^"\\]|\\.)*"\s*)+))re");
  // Widgets whose first argument is shown: a raw English literal there bypasses the table.
  const std::regex widget(
      R"re(ImGui::(?:Text|TextUnformatted|TextWrapped|TextColored\([^,]+,|Button|Checkbox|RadioButton|CollapsingHeader|TreeNode|Selectable|Begin|BeginCombo|MenuItem|SetTooltip|Slider\w*|Drag\w*|Input\w*)\(\s*("(?:[^"\\]|\\.)*"))re");
  const std::regex english_word(R"re([A-Za-z]{3,})re");
  const std::set<std::string> notation{"raycam", "arccos", "atan2", "panel", "status", "keys"};
  int marked_count = 0;
  for (const auto& file : ui_sources()) {
    const std::string text = read(file);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), marked); it != std::sregex_iterator();
         ++it) {
      const std::string key = unescape(joined_literals((*it)[1].str()));
      INFO(file.filename().string() << ": " << key);
      CHECK(keys.count(key) == 1);
      ++marked_count;
    }
    for (auto it = std::sregex_iterator(text.begin(), text.end(), widget); it != std::sregex_iterator();
         ++it) {
      std::string literal = joined_literals((*it)[1].str());
      literal = literal.substr(0, literal.find("##"));  // "##id" and "###id" are not shown
      for (auto w = std::sregex_iterator(literal.begin(), literal.end(), english_word);
           w != std::sregex_iterator(); ++w) {
        INFO(file.filename().string() << ": widget shows the untranslated literal \"" << literal << "\"");
        CHECK(notation.count(w->str()) == 1);
      }
    }
  }
  CHECK(marked_count > 50);
  // Names the core gives and the window shows.
  for (const CastMethod method : kCastMethods) CHECK(keys.count(cast_method_name(method)) == 1);
}

TEST_CASE("tr shows French when the language is French, and trf formats after translating", "[ui][text]") {
  CHECK(std::string(session::tr(raycam::Language::fr, "Camera###camera")) == "Caméra###camera");
  CHECK(session::trf(raycam::Language::fr, "opened %s", "a.json") == "ouvert\u00a0: a.json");  // a no-break space before the colon
  CHECK(std::string(session::tr(raycam::Language::en, "Camera###camera")) == "Camera###camera");
  CHECK(session::trf(raycam::Language::en, "opened %s", "a.json") == "opened a.json");
}

TEST_CASE("the language comes from --lang, else LANGUAGE, LC_ALL, LC_MESSAGES, LANG", "[ui][text]") {
  CHECK(raycam::parse_language_flag("fr") == raycam::Language::fr);
  CHECK(raycam::parse_language_flag("en") == raycam::Language::en);
  CHECK_THROWS_WITH(raycam::parse_language_flag("de"), "--lang: expected en or fr, got 'de'");
  CHECK(raycam::language_from_code("fr_FR.UTF-8") == raycam::Language::fr);
  CHECK(raycam::language_from_code("fr:en") == raycam::Language::fr);
  CHECK(raycam::language_from_code("en_GB") == raycam::Language::en);
  CHECK_FALSE(raycam::language_from_code("C").has_value());
  CHECK_FALSE(raycam::language_from_code("french").has_value());

  for (const char* name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) unsetenv(name);
  CHECK(raycam::language_from_environment() == raycam::Language::en);
  setenv("LANG", "fr_FR.UTF-8", 1);
  CHECK(raycam::language_from_environment() == raycam::Language::fr);
  setenv("LC_ALL", "en_US.UTF-8", 1);  // LC_ALL overrides LANG
  CHECK(raycam::language_from_environment() == raycam::Language::en);
  setenv("LANGUAGE", "fr", 1);  // LANGUAGE first, as gettext
  CHECK(raycam::language_from_environment() == raycam::Language::fr);
  setenv("LANGUAGE", "", 1);  // empty: not set
  CHECK(raycam::language_from_environment() == raycam::Language::en);
  for (const char* name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) unsetenv(name);
}

TEST_CASE("each state shows its own language, whichever was made last (no language global)", "[ui][text]") {
  const session::AppState french = test::state_for({"--view", "2d", "--lang", "fr"});
  const session::AppState english = test::state_for({"--view", "2d", "--lang", "en"});
  CHECK(session::window_title(french) == "raycam — 2D — scène de démonstration");
  CHECK(session::window_title(english) == "raycam — 2D — demo scene");
  CHECK_THAT(session::cannot_open_message(french.language, "a.json", "no such file"),
             Catch::StartsWith("impossible d'ouvrir a.json"));
}
