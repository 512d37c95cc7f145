// Counts and numbers in the window's language: one formatter (format_text) picks a count's singular or
// plural by each language's rule and writes decimals with the language's mark; every table's count texts go
// through its plural groups. The expected texts are written here by hand, in each language's grammar.
#include <catch2/catch.hpp>
#include <regex>
#include <set>
#include <string>

#include "check/check_texts.h"
#include "figure/figure_texts.h"
#include "raycam/language.h"
#include "session/text.h"

using namespace raycam;

namespace {
// French typography's no-break space before ':' read as a space: the texts compared are the words.
std::string spaced(std::string text) {
  for (std::size_t at = text.find("\u00a0"); at != std::string::npos; at = text.find("\u00a0", at))
    text.replace(at, 2, " ");
  return text;
}
const std::string nbsp = " ";
}

TEST_CASE("a count picks the singular or the plural by each language's rule", "[ui][text][plural]") {
  // French: 0 and 1 singular, 2 and more plural; English: 1 singular, else plural.
  CHECK_FALSE(takes_plural(Language::fr, 0));
  CHECK_FALSE(takes_plural(Language::fr, 1));
  CHECK(takes_plural(Language::fr, 2));
  CHECK(takes_plural(Language::fr, 1000000));
  CHECK(takes_plural(Language::en, 0));
  CHECK_FALSE(takes_plural(Language::en, 1));
  CHECK(takes_plural(Language::en, 2));
  CHECK(takes_plural(Language::en, 1000000));
}

TEST_CASE("the window's count texts over 0, 1, 2 and large counts, in both languages", "[ui][text][plural]") {
  using session::trf;
  const char* check = "CHECK: %lld {{pixel|pixels}} wrong";
  CHECK(trf(Language::en, check, 0LL) == "CHECK: 0 pixels wrong");
  CHECK(trf(Language::en, check, 1LL) == "CHECK: 1 pixel wrong");
  CHECK(trf(Language::en, check, 2LL) == "CHECK: 2 pixels wrong");
  CHECK(trf(Language::en, check, 27932LL) == "CHECK: 27932 pixels wrong");
  CHECK(spaced(trf(Language::fr, check, 0LL)) == "VÉRIFICATION" + nbsp + ": 0 pixel faux");
  CHECK(spaced(trf(Language::fr, check, 1LL)) == "VÉRIFICATION" + nbsp + ": 1 pixel faux");
  CHECK(spaced(trf(Language::fr, check, 2LL)) == "VÉRIFICATION" + nbsp + ": 2 pixels faux");
  CHECK(spaced(trf(Language::fr, check, 27932LL)) == "VÉRIFICATION" + nbsp + ": 27932 pixels faux");
  const char* wrote = "wrote %d {{file|files}}: %s";
  CHECK(trf(Language::en, wrote, 1, "a.svg") == "wrote 1 file: a.svg");
  CHECK(trf(Language::en, wrote, 6, "a.svg … f.svg") == "wrote 6 files: a.svg … f.svg");
  CHECK(spaced(trf(Language::fr, wrote, 1, "a.svg")) == "1 fichier écrit" + nbsp + ": a.svg");
  CHECK(spaced(trf(Language::fr, wrote, 6, "a.svg")) == "6 fichiers écrits" + nbsp + ": a.svg");
  // Two counts, each with its own noun.
  const char* casts = "%lld {{cast|casts}} in %lld {{frame|frames}}";
  CHECK(trf(Language::en, casts, 1LL, 2LL) == "1 cast in 2 frames");
  CHECK(trf(Language::en, casts, 3LL, 1LL) == "3 casts in 1 frame");
  CHECK(trf(Language::fr, casts, 0LL, 1LL) == "0 lancer en 1 image");
  CHECK(trf(Language::fr, casts, 2LL, 100000LL) == "2 lancers en 100000 images");
  const char* opened = "opened %s (%zu {{object|objects}}) in %.1f s";
  CHECK(trf(Language::en, opened, "s.json", std::size_t(1), 0.4) == "opened s.json (1 object) in 0.4 s");
  CHECK(trf(Language::fr, opened, "s.json", std::size_t(100000), 15.4) == "s.json ouvert (100000 objets) en 15,4 s");
}

TEST_CASE("the checker's count texts over 0, 1, 2 and large counts, in both languages", "[check][text][plural]") {
  using check::textf;
  CHECK(textf(Language::en, "%zu {{thread|threads}}", std::size_t(1)) == "1 thread");
  CHECK(textf(Language::en, "%zu {{thread|threads}}", std::size_t(0)) == "0 threads");
  CHECK(textf(Language::fr, "%zu {{thread|threads}}", std::size_t(0)) == "0 exécution à la fois");
  CHECK(textf(Language::fr, "%zu {{thread|threads}}", std::size_t(2)) == "2 exécutions à la fois");
  const char* score = "score: %d / %d {{case|cases}} passed (%.0f %%)\n";
  CHECK(textf(Language::en, score, 1, 1, 100.0) == "score: 1 / 1 case passed (100 %)\n");
  CHECK(textf(Language::en, score, 0, 12, 0.0) == "score: 0 / 12 cases passed (0 %)\n");
  CHECK(textf(Language::fr, score, 1, 1, 100.0) == "score : 1 / 1 cas réussi (100 %)\n");
  CHECK(textf(Language::fr, score, 3, 12, 25.0) == "score : 3 / 12 cas réussis (25 %)\n");
  CHECK(textf(Language::fr, "runs: %.2f s, %.2f s of CPU in all; peak memory %.1f MiB (case %d)\n", 0.5, 0.25, 3.5,
              2) == "exécutions : 0,50 s, dont 0,25 s de calcul en tout ; mémoire au plus haut 3,5 Mio (cas 2)\n");
}

TEST_CASE("one number formatter per language: French decimal comma, English point", "[ui][text][numbers]") {
  CHECK(formatted(Language::fr, "en %.1f s", 0.4) == "en 0,4 s");
  CHECK(formatted(Language::en, "in %.1f s", 0.4) == "in 0.4 s");
  CHECK(formatted(Language::fr, "θ = %.1f°", 50.0) == "θ = 50,0°");
  CHECK(formatted(Language::fr, "%.3g / %.1e / %5.2f", 0.125, 1.5e-8, -3.25) == "0,125 / 1,5e-08 / -3,25");
  CHECK(formatted(Language::fr, "%s %d %.0f%%", "a.b", 3, 12.0) == "a.b 3 12%");  // a string keeps its points
  CHECK(formatted(Language::fr, "%02d:%02d", 1, 5) == "01:05");
  CHECK(session::trf(Language::fr, "running… (%.1f s)", 2.25) == "en cours… (2,2 s)");
  // A '*' takes its int from the arguments before the value (the M_d tables' "%.*f"): read as the value, it
  // took a double from an int's place, a precision of millions in some runs.
  CHECK(formatted(Language::fr, "%.*f", 2, 3.14159) == "3,14");
  CHECK(formatted(Language::en, "%.*f|%*d|%-*d|", 0, 2.5, 4, 7, 3, 8) == "2|   7|8  |");
  CHECK(formatted(Language::en, "%.*f", -1, 0.5) == formatted(Language::en, "%f", 0.5));  // no precision
  for (int decimals = 0; decimals <= 4; ++decimals)
    CHECK(formatted(Language::fr, "%.*f %d", decimals, -0.123456, 9).size() == std::size_t(decimals + 4 + (decimals > 0)));
}

namespace {
// The words that may follow a count without a plural group: units, nouns the same in both numbers, and the
// words between two counts or after a count that do not agree with it ("%lld of %lld {{pixel|pixels}}",
// "✗ %lld wrong").
const std::set<std::string> kNotAgreeing = {"s",  "ms",  "min", "h",   "MB",    "Mo",  "MiB", "Mio", "mm",
                                            "px", "cas", "of",  "des", "sur",   "wrong", "faux", "to", "à"};

// Where a count ("%d", "%lld", "%zu"...) is followed by a word that agrees with it, with no plural group
// before the next conversion: "%d files".
std::vector<std::string> bare_counts(const std::string& text) {
  static const std::regex count(R"(%[-+ #0]*[0-9]*(hh|h|ll|l|z|j|t)?[diu])");
  static const std::regex word(R"(^ ([^ {}\d%()×/=:,.;+−-][^ ,.;:)]*))");
  std::vector<std::string> found;
  for (std::sregex_iterator it(text.begin(), text.end(), count), end; it != end; ++it) {
    const std::size_t after = std::size_t(it->position() + it->length());
    const std::string rest = text.substr(after, text.find('%', after) - after);
    std::smatch first;
    if (rest.find("{{") == std::string::npos && std::regex_search(rest, first, word) &&
        !kNotAgreeing.count(first[1].str()))
      found.push_back(it->str() + first[0].str());
  }
  return found;
}
}  // namespace

TEST_CASE("no count text of any table is left without its plural form", "[ui][text][plural]") {
  std::vector<const Translation*> rows;
  for (const Translation& t : session::translations()) rows.push_back(&t);
  for (const Translation& t : check::check_translations()) rows.push_back(&t);
  for (const LocalText& t : figure::figure_translations()) rows.push_back(&t);
  // The scan catches a bare count (seen failing on "%d files").
  CHECK(bare_counts("wrote %d files: %s") == std::vector<std::string>{"%d files"});
  CHECK(bare_counts("wrote %d {{file|files}}: %s").empty());
  for (const Translation* t : rows)
    for (Language language : kLanguages) {
      const std::string text = (*t)[language];
      INFO(text);
      CHECK(bare_counts(text).empty());
      // Each plural group is whole ({{one|many}}), holds no conversion and follows an integer conversion.
      for (std::size_t at = text.find("{{"); at != std::string::npos; at = text.find("{{", at + 2)) {
        const std::size_t bar = text.find('|', at), end = text.find("}}", at);
        REQUIRE(end != std::string::npos);
        CHECK(bar < end);
        CHECK(text.substr(at, end - at).find('%') == std::string::npos);
        CHECK(std::regex_search(text.substr(0, at), std::regex(R"(%[-+ #0]*[0-9]*(hh|h|ll|l|z|j|t)?[diu])")));
      }
    }
}

namespace {
// In an error reason's pattern, where a count's placeholder ({count}, {rows}, {columns}, {max}: the names the
// table gives a number of things) is followed by a word rather than a plural group: "{count} columns". Units
// keep their form.
std::vector<std::string> bare_reason_counts(const std::string& pattern) {
  static const std::regex count(R"(\{(count|rows|columns|max)\})");
  static const std::regex word(R"(^ ([^ {}\d%()×/=:,.;+−-][^ ,.;:)]*))");
  static const std::set<std::string> units = {"MiB", "Mio", "rad"};
  std::vector<std::string> found;
  for (std::sregex_iterator it(pattern.begin(), pattern.end(), count), end; it != end; ++it) {
    const std::size_t after = std::size_t(it->position() + it->length());
    const std::string rest = pattern.substr(after);
    std::smatch first;  // (a plural group right after the count is no word: '{' does not start one)
    if (std::regex_search(rest, first, word) && !units.count(first[1].str()))
      found.push_back(it->str() + first[0].str());
  }
  return found;
}
}  // namespace

TEST_CASE("no count of an error reason's pattern is left without its plural form",
          "[ui][text][plural][reasons]") {
  // The scan catches a bare count (seen failing on "{count} columns").
  CHECK(bare_reason_counts("ids[{row}]: {count} columns where row 0 has {columns}") ==
        std::vector<std::string>{"{count} columns"});
  CHECK(bare_reason_counts("ids[{row}]: {count} {{column|columns}} where row 0 has {columns}").empty());
  CHECK(bare_reason_counts("more than {size} MiB").empty());
  CHECK(bare_reason_counts("at most {max} rad").empty());
  for (const ReasonPattern& pattern : reason_patterns())
    for (Language language : kLanguages) {
      const std::string text = pattern[language];
      INFO(text);
      CHECK(bare_reason_counts(text).empty());
      // Each plural group is whole and follows a placeholder, whose number picks its form.
      for (std::size_t at = text.find("{{"); at != std::string::npos; at = text.find("{{", at + 2)) {
        const std::size_t bar = text.find('|', at), end = text.find("}}", at);
        REQUIRE(end != std::string::npos);
        CHECK(bar < end);
        CHECK(std::regex_search(text.substr(0, at), std::regex(R"(\{[a-z_]+\} $)")));
      }
    }
}

TEST_CASE("no text of the window's or the checker's table sends to a file the page's user does not have",
          "[ui][text]") {
  std::vector<const Translation*> rows;
  for (const Translation& t : session::translations()) rows.push_back(&t);
  for (const Translation& t : check::check_translations()) rows.push_back(&t);
  for (const Translation* t : rows)
    for (Language language : kLanguages) {
      const std::string text = (*t)[language];
      INFO(text);
      CHECK(text.find("docs/") == std::string::npos);
      CHECK(text.find("README") == std::string::npos);
      CHECK(text.find(".md") == std::string::npos);
    }
}
