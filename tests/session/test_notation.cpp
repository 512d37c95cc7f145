// One notation from the window to the figures (docs/conventions.md): each construction step's caption in
// the window names the same points and rotations as the figure's frame for that step (Ω the origin and the
// canonical screen's centre, C the target, P the placed screen's centre, E0 and E the eye, α = φv + ψ0).
#include <catch2/catch.hpp>
#include <filesystem>
#include <set>
#include <string>

#include "app_state_for.h"
#include "figure/construction_figure.h"
#include "session/construction_view.h"
#include "session/text.h"

using namespace raycam;

namespace {
// The construction's symbols a caption names, the figure's markup ("$\vec{ΩP}$", "$ψ_0$") read as the
// window writes them ("ΩP", "ψ₀"), both read as plain ("ψ0"); a vector names its two points.
std::set<std::string> named_symbols(std::string text) {
  for (const char* markup : {"\\vec", "$", "{", "}", "_"})
    for (std::size_t at = text.find(markup); at != std::string::npos; at = text.find(markup, at))
      text.erase(at, std::string(markup).size());
  for (const auto& [typeset, plain] : {std::pair<std::string, std::string>{"₀", "0"}, {"ᵥ", "v"}})
    for (std::size_t at = text.find(typeset); at != std::string::npos; at = text.find(typeset, at))
      text.replace(at, typeset.size(), plain);
  static const char* const kSymbols[] = {"E0", "φv", "ψ0", "Ω", "O", "C", "P", "E", "α"};
  std::set<std::string> found;
  auto lower = [](char c) { return c >= 'a' && c <= 'z'; };
  for (std::size_t at = 0; at < text.size();) {
    bool matched = false;
    for (const std::string symbol : kSymbols)
      if (text.compare(at, symbol.size(), symbol) == 0 && (at == 0 || !lower(text[at - 1])) &&
          (at + symbol.size() >= text.size() || !lower(text[at + symbol.size()]))) {
        found.insert(symbol);
        at += symbol.size();
        matched = true;
        break;
      }
    if (!matched) ++at;
  }
  return found;
}
}  // namespace

TEST_CASE("the symbol scan reads both notations alike", "[session][notation]") {
  CHECK(named_symbols("translation $T(\\vec{ΩP})$, $ψ_0 = +π/2$, eye $E_0$") ==
        std::set<std::string>{"Ω", "P", "ψ0", "E0"});
  CHECK(named_symbols("d: T(OP) moves the screen to P") == std::set<std::string>{"O", "P"});
  CHECK(named_symbols("l'œil recule en E, M_d = I") == std::set<std::string>{"E"});
  CHECK(named_symbols("R(α) = R(φᵥ)·R(ψ₀), œil E₀") == std::set<std::string>{"α", "φv", "ψ0", "E0"});
}

TEST_CASE("the window's construction captions name the figure's points and rotations, step by step",
          "[session][notation]") {
  for (Language language : kLanguages)
    for (const char* view : {"2d", "3d"}) {
      session::AppState state = test::state_for({"--view", view});
      const figure::FigureOptions options{language, 5};
      const figure::Figure figure = std::visit(
          [&](const auto& v) { return figure::construction_figure(session::scene_as_shown(language, v), v.camera, options); },
          state.view);
      for (std::size_t step = 0; step < figure.frames.size(); ++step) {
        const std::string window = session::tr(language, session::construction_caption(view[0] == '2' ? 2 : 3, int(step)));
        INFO(view << " step " << step << ": window \"" << window << "\", figure \"" << figure.frames[step].caption
                  << "\"");
        CHECK(named_symbols(window) == named_symbols(figure.frames[step].caption));
        CHECK_FALSE(named_symbols(window).count("O"));  // the origin is Ω, as in the handout
      }
    }
}

TEST_CASE("in French no shipped scene's object is shown with an English name", "[session][notation][text]") {
  std::size_t objects = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    session::AppState state = test::state_for({"--lang", "fr"});
    REQUIRE(session::open_scene(state, entry.path().string()));
    const std::size_t count = std::visit([](const auto& v) { return objects_of(v.scene).size(); }, state.view);
    for (std::size_t id = 0; id < count; ++id) {
      const std::string english =
          std::visit([&](const auto& v) { return objects_of(v.scene).at(id).name; }, state.view);
      const std::string shown = session::shown_object_name(Language::fr, state.view, id);
      INFO(entry.path().filename().string() << ": object " << id << " \"" << english << "\" shown \"" << shown << "\"");
      if (!english.empty()) CHECK(shown != english);
      CHECK(session::shown_object_name(Language::en, state.view, id) == english);
      ++objects;
    }
  }
  CHECK(objects >= 20);
}
