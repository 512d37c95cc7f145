// The check command's language follows the window's rule (raycam/language.h): --lang first, else the
// first of LANGUAGE, LC_ALL, LC_MESSAGES, LANG that is set, French only when it names French.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <optional>
#include <string>

#include "check/check_texts.h"
#include "raycam/language.h"

using namespace raycam;

namespace {
// Sets the locale variables for one scope and puts back what was there.
class LocaleEnvironment {
 public:
  LocaleEnvironment() {
    for (int i = 0; i < 4; ++i) {
      const char* value = std::getenv(kNames[i]);
      if (value) saved_[i] = value;
      ::unsetenv(kNames[i]);
    }
  }
  ~LocaleEnvironment() {
    for (int i = 0; i < 4; ++i)
      if (saved_[i]) ::setenv(kNames[i], saved_[i]->c_str(), 1);
      else ::unsetenv(kNames[i]);
  }

 private:
  static constexpr const char* kNames[4] = {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"};
  std::optional<std::string> saved_[4];
};
}  // namespace

TEST_CASE("check's language: --lang, else the environment by the window's rule", "[check][language]") {
  LocaleEnvironment scope;
  CHECK(check::check_language(std::nullopt) == Language::en);  // nothing set
  ::setenv("LANG", "fr_FR.UTF-8", 1);
  CHECK(check::check_language(std::nullopt) == Language::fr);
  CHECK(check::check_language(Language::en) == Language::en);  // the flag wins
  ::setenv("LC_ALL", "C", 1);  // the first one set decides, even when it names no language
  CHECK(check::check_language(std::nullopt) == Language::en);
  ::setenv("LANGUAGE", "fr:en", 1);
  CHECK(check::check_language(std::nullopt) == Language::fr);
  ::setenv("LANGUAGE", "french", 1);  // not a language code: English, as the window decides
  CHECK(check::check_language(std::nullopt) == Language::en);
  CHECK(check::check_language(std::nullopt) == language_from_environment());
}

TEST_CASE("check's texts: French by English key, English when asked or when the key is unknown",
          "[check][language]") {
  const std::string french = check::text(Language::fr, "wrong pixels");
  CHECK(!french.empty());
  CHECK(french != "wrong pixels");
  CHECK(std::string(check::text(Language::en, "wrong pixels")) == "wrong pixels");
  CHECK(std::string(check::text(Language::fr, "no such key")) == "no such key");
  // The formatter fills the French format.
  const std::string format = check::text(Language::fr, "warning: %s\n");
  REQUIRE(format.find("%s") != std::string::npos);
  std::string expected = format;
  expected.replace(expected.find("%s"), 2, "x");
  CHECK(check::textf(Language::fr, "warning: %s\n", "x") == expected);
}

TEST_CASE("check's counts: one is singular, in both languages (\"on 1 thread\", not \"1 threads\")",
          "[check][language]") {
  // The plural groups of the one formatter (format_text); French: 0 and 1 singular.
  CHECK(check::textf(Language::en, "%zu {{thread|threads}}", std::size_t(1)) == "1 thread");
  CHECK(check::textf(Language::en, "%zu {{thread|threads}}", std::size_t(0)) == "0 threads");
  CHECK(check::textf(Language::en, "%zu {{submission|submissions}}", std::size_t(2)) == "2 submissions");
  CHECK(check::textf(Language::fr, "%zu {{thread|threads}}", std::size_t(1)) == "1 exécution à la fois");
  CHECK(check::textf(Language::fr, "%zu {{thread|threads}}", std::size_t(3)) == "3 exécutions à la fois");
  CHECK(check::textf(Language::fr, "%zu {{submission|submissions}}", std::size_t(1)) == "1 rendu");
  CHECK(check::textf(Language::fr, "%zu {{submission|submissions}}", std::size_t(0)) == "0 rendu");
}

TEST_CASE("a batch's time left: the pace so far, rounded up, in the language, none before or after",
          "[check][language][progress]") {
  using raycam::check::time_left;
  // 10 of 40 runs in 20 s: 2 s a run, 30 runs left, 60 s (+1 rounding up).
  CHECK(time_left(Language::en, 10, 40, 20.0) == "about 1 min 01 s left");
  CHECK(time_left(Language::fr, 10, 40, 20.0) == "encore 1 min 01 s environ");
  CHECK(time_left(Language::en, 1, 2, 0.5) == "about 1 s left");
  CHECK(time_left(Language::en, 1, 1000, 10.0) == "about 2 h 46 min left");  // 9990 s + 1
  CHECK(time_left(Language::en, 0, 40, 5.0).empty());   // no pace yet
  CHECK(time_left(Language::en, 40, 40, 80.0).empty());  // done
}
