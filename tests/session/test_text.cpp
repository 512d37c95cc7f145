// French and English: every string of the window's table has both languages with the same printf conversions
// and ImGui ids; every table's texts have every language; every text call in src/ (the window's tr()/trf()/
// tr_later(), the checker's text()/textf(), the figures' figure_text(), a tr_reason() of a literal) has its
// key in the table it looks in; no widget shows an English literal that bypasses the table; and the language
// comes from --lang or the environment.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

#include "app_state_for.h"
#include "check/check_texts.h"
#include "figure/figure_texts.h"
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

// Every text raycam shows, in every table that holds one: the window's, the checker's, the figures', the
// error reasons' patterns, the demo scenes' object names and the classic mistakes' labels and explanations.
// Adding a language to Language is then caught here until each of them has its column.
TEST_CASE("every text of every table has every language", "[ui][text][language]") {
  std::vector<std::pair<std::string, const LocalText*>> texts;
  for (const Translation& t : session::translations()) texts.push_back({"window", &t});
  for (const Translation& t : check::check_translations()) texts.push_back({"check", &t});
  for (const ReasonPattern& p : reason_patterns()) texts.push_back({"reason", &p});
  for (const Translation& t : demo_object_name_texts()) texts.push_back({"demo names", &t});
  for (const LocalText& t : figure::figure_translations()) texts.push_back({"figure", &t});
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

namespace {
// Every .cpp and .h under src/, whatever its folder: a text call in a new folder is scanned as well.
std::vector<std::filesystem::path> all_sources() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(std::filesystem::path(RAYCAM_SOURCE_DIR) / "src"))
    if (entry.path().extension() == ".cpp" || entry.path().extension() == ".h") files.push_back(entry.path());
  REQUIRE(files.size() >= 100);
  return files;
}

// `code` with its comments and raw strings blanked (newlines kept, so that offsets keep their line): a
// comment's example call, tr(language, "English text"), is no call, nor a regular expression's text. Other
// string literals are kept whole: they are the keys.
std::string without_comments(const std::string& code) {
  std::string out = code;
  for (std::size_t i = 0; i < out.size();) {
    if (out.compare(i, 2, "//") == 0) {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
    } else if (out.compare(i, 2, "/*") == 0) {
      const std::size_t end = std::min(out.find("*/", i + 2), out.size() - 2) + 2;
      for (; i < end; ++i)
        if (out[i] != '\n') out[i] = ' ';
    } else if (out.compare(i, 2, "R\"") == 0 &&
               (i == 0 || !(std::isalnum((unsigned char)out[i - 1]) || out[i - 1] == '_'))) {
      const std::size_t open = std::min(out.find('(', i), out.size());
      const std::string close = ")" + out.substr(i + 2, open - i - 2) + "\"";
      const std::size_t end = std::min(out.find(close, open), out.size() - close.size()) + close.size();
      for (; i < end; ++i)
        if (out[i] != '\n') out[i] = ' ';
    } else if (out[i] == '"' || out[i] == '\'') {
      const char quote = out[i++];
      while (i < out.size() && out[i] != quote && out[i] != '\n') i += out[i] == '\\' ? 2 : 1;
      ++i;
    } else {
      ++i;
    }
  }
  return out;
}

std::size_t line_of(const std::string& text, std::size_t offset) {
  return std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(offset), '\n')) + 1;
}

// A kind of text call: the functions that look a literal English key up, and the table they look in.
struct TextCall {
  std::string table;
  std::regex call;  // submatch 1: the key's literals ("a" "b" joined)
  std::function<bool(const std::string&)> has;
  int least;  // calls expected at least: a regex that no longer matches anything fails here, not silently
};

// The language argument (state.language, header.language, Language::fr, lang...) then the key's literals.
const std::string kLanguageArgument = R"re((?:[\w.:>()\[\]-]+,\s*))re";
const std::string kLiterals = R"re(((?:"(?:[^"\\]|\\.)*"\s*)+))re";

std::set<std::string> keys_of(const std::vector<LocalText>& table) {
  std::set<std::string> keys;
  for (const LocalText& t : table) keys.insert(t.english());
  return keys;
}

std::vector<TextCall> text_calls() {
  static const std::set<std::string> window = keys_of(session::translations());
  static const std::set<std::string> checker = keys_of(check::check_translations());
  static const std::set<std::string> figure = keys_of(figure::figure_translations());
  return {
      // The window and the page (session/text.h; ui's words.h takes the same names): tr, trf, tr_later.
      {"the window's (src/session/text_table.cpp)",
       std::regex(R"re(\b(?:tr|trf|tr_later)\(\s*)re" + kLanguageArgument + "?" + kLiterals),
       [](const std::string& key) { return window.count(key) == 1; }, 250},
      // The checker (check/check_texts.h), in src/check and src/cli: text, textf.
      {"the checker's (src/check/check_texts.cpp)",
       std::regex(R"re(\b(?:text|textf)\(\s*)re" + kLanguageArgument + kLiterals),
       [](const std::string& key) { return checker.count(key) == 1; }, 20},
      // The construction figures (figure/figure_texts.h).
      {"the figure's (src/figure/figure_texts.cpp)",
       std::regex(R"re(\bfigure_text\(\s*)re" + kLanguageArgument + kLiterals),
       [](const std::string& key) { return figure.count(key) == 1; }, 15},
      // An error reason written in place: one of the reason table's patterns must read it.
      {"the error reasons' patterns (src/io/reason_table.cpp)",
       std::regex(R"re(\btr_reason\(\s*)re" + kLanguageArgument + kLiterals),
       [](const std::string& key) {
         std::vector<std::size_t> used;
         translate_reason(Language::fr, key, &used);
         return !used.empty();
       },
       0},
  };
}

// "file:line: key (table)" for each text call of `code` whose literal key is missing from its table; `counts`
// receives the calls found per kind.
std::vector<std::string> missing_keys(const std::string& name, const std::string& code,
                                      std::vector<int>& counts) {
  const std::string bare = without_comments(code);
  const std::vector<TextCall> calls = text_calls();
  counts.assign(calls.size(), 0);
  std::vector<std::string> missing;
  for (std::size_t c = 0; c < calls.size(); ++c)
    for (auto it = std::sregex_iterator(bare.begin(), bare.end(), calls[c].call);
         it != std::sregex_iterator(); ++it) {
      ++counts[c];
      const std::string key = unescape(joined_literals((*it)[1].str()));
      if (!calls[c].has(key))
        missing.push_back(name + ":" + std::to_string(line_of(bare, std::size_t(it->position()))) + ": \"" +
                          key + "\" is not in " + calls[c].table + " table");
    }
  return missing;
}
}  // namespace

TEST_CASE("every text call in src/ has its key in the table it looks in", "[ui][text][language]") {
  // The scan sees each kind of call, in a comment-free text, and names the place of a missing key.
  std::vector<int> counts;
  CHECK(missing_keys("a.cpp",
                     "x = tr(state.language, \"Camera###camera\");\n"
                     "y = check::textf(lang,\n    \"score: %d / %d {{case|cases}} \"\n"
                     "    \"passed (%.0f %%)\\n\", 1, 2, 50.0);\n"
                     "z = figure_text(lang, \"up\");  // tr(language, \"English text\")\n",
                     counts)
            .empty());
  CHECK(counts == std::vector<int>{1, 1, 1, 0});
  CHECK(missing_keys("b.cpp", "\n  a = figure_text(lang, \"upward\");", counts) ==
        std::vector<std::string>{
            "b.cpp:2: \"upward\" is not in the figure's (src/figure/figure_texts.cpp) table"});
  CHECK(missing_keys("c.cpp", "f(R\"(tr(l, \"no such key\"))\");", counts).empty());  // inside a raw string
  CHECK(missing_keys("d.cpp", "text(h.language, \"no such key\")", counts).size() == 1);
  CHECK(missing_keys("e.cpp", "tr_reason(lang, \"no answer within the timeout\")", counts).empty());
  CHECK(missing_keys("e.cpp", "tr_reason(lang, \"no such reason\")", counts).size() == 1);

  std::vector<int> total(text_calls().size(), 0);
  for (const auto& file : all_sources()) {
    const std::string name = std::filesystem::relative(file, RAYCAM_SOURCE_DIR).string();
    for (const std::string& missing : missing_keys(name, read(file), counts)) FAIL_CHECK(missing);
    for (std::size_t c = 0; c < counts.size(); ++c) total[c] += counts[c];
  }
  const std::vector<TextCall> calls = text_calls();
  for (std::size_t c = 0; c < calls.size(); ++c) {
    INFO(calls[c].table << ": " << total[c] << " calls");
    CHECK(total[c] >= calls[c].least);
  }
  // Names the core gives and the window shows.
  std::set<std::string> keys = keys_of(session::translations());
  for (const CastMethod method : kCastMethods) CHECK(keys.count(cast_method_name(method)) == 1);
}

TEST_CASE("no widget shows an English literal that bypasses the window's table", "[ui][text]") {
  // Widgets whose first argument is shown: a raw English literal there bypasses the table.
  const std::regex widget(
      R"re(ImGui::(?:Text|TextUnformatted|TextWrapped|TextColored\([^,]+,|Button|Checkbox|RadioButton|CollapsingHeader|TreeNode|Selectable|Begin|BeginCombo|MenuItem|SetTooltip|Slider\w*|Drag\w*|Input\w*)\(\s*("(?:[^"\\]|\\.)*"))re");
  const std::regex english_word(R"re([A-Za-z]{3,})re");
  const std::set<std::string> notation{"raycam", "arccos", "atan2", "panel", "status", "keys"};
  for (const auto& file : ui_sources()) {
    const std::string text = read(file);
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
