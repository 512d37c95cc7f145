// "Export figure…": the construction panel writes the figures of the camera on screen, in the window's
// language, the step shown or every step.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "../scratch_dir.h"
#include "app_state_for.h"
#include "session/figure_export.h"
#include "raycam/transform.h"
#include "session/text.h"

using namespace raycam;

namespace {
std::string pdf_text(const std::string& file) {
  std::string out;
  if (FILE* pipe = popen(("pdftotext -layout '" + file + "' -").c_str(), "r")) {
    char buffer[4096];
    std::size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    pclose(pipe);
  }
  return out;
}
}  // namespace

TEST_CASE("Export figure writes the step shown, or every step, in the window's language", "[ui][figure]") {
  const test::ScratchDir scratch("figure-export");
  session::AppState state = test::state_for({"--view", "2d"});

  state.language = raycam::Language::fr;
  state.construction_step = 1;  // the second frame: (b)
  auto files = session::export_construction_figure(state, {}, scratch.path("b.pdf"), false);
  REQUIRE(files == std::vector<std::string>{scratch.path("b.pdf")});
  std::string text = pdf_text(files[0]);
  CHECK(text.find("cadre (b)") != std::string::npos);
  CHECK(text.find("cadre (a)") == std::string::npos);

  state.construction_step = -1;  // M_d itself: frame (d)
  CHECK(pdf_text(session::export_construction_figure(state, {}, scratch.path("d.pdf"), false)[0]).find("cadre (d)") !=
        std::string::npos);

  state.language = raycam::Language::en;
  files = session::export_construction_figure(state, {}, scratch.path("all.pdf"), true);
  REQUIRE(files.size() == 1);
  text = pdf_text(files[0]);
  for (const char* title : {"frame (a)", "frame (b)", "frame (c)", "frame (d)"})
    CHECK(text.find(title) != std::string::npos);

  files = session::export_construction_figure(state, {}, scratch.path("all.svg"), true);
  CHECK(files.size() == 4);
  for (const std::string& file : files) CHECK(std::filesystem::file_size(file) > 1000);

  CHECK_THROWS_AS(session::export_construction_figure(state, {}, scratch.path("figure.gif"), false), std::invalid_argument);
}

TEST_CASE("Export figure in 3D writes the six steps", "[ui][figure]") {
  const test::ScratchDir scratch("figure-export-3d");
  session::AppState state = test::state_for({"--view", "3d"});
  const auto files = session::export_construction_figure(state, {}, scratch.path("steps.png"), true);
  REQUIRE(files.size() == 6);
  CHECK(files.back() == scratch.path("steps-5.png"));
}

TEST_CASE("Export figure draws the matrix on screen, with the panel's format, rays and matrix choice", "[ui][figure]") {
  const test::ScratchDir scratch("figure-export-panel");
  session::AppState state = test::state_for({"--view", "2d", "--df", "1.25"});
  state.language = raycam::Language::en;
  // The format chosen in the panel sets the name's extension.
  CHECK(session::with_figure_extension("notes/fig.svg", 3) == "notes/fig.tex");
  CHECK(session::with_figure_extension("notes/fig", 1) == "notes/fig.pdf");
  CHECK(session::figure_format_of("a.png") == 2);

  state.construction_step = 1;  // on screen: construction_step(1) = H(1, d_f)
  session::FigureContent content;  // the panel's rays and matrix choice
  content.rays = 3;
  const std::string path = scratch.path("sub/../step.tex");
  std::filesystem::create_directories(scratch.path("sub"));
  CHECK(session::existing_figure_files(state, content, path, false).empty());
  const auto files = session::export_construction_figure(state, content, path, false);
  REQUIRE(files == std::vector<std::string>{scratch.path("step.tex")});  // the full path, normalised
  CHECK(session::existing_figure_files(state, content, path, false) == files);
  std::ifstream in(files[0]);
  const std::string tex((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(tex.find("frame (b)") != std::string::npos);
  // The matrix the panel shows for step 1 (H: d_f on the diagonal), and as many rays as chosen.
  const glm::dmat3 shown = construction_step(session::view2d(state).camera.placement(), 1);
  CHECK(shown[1][1] == Approx(1.25));
  CHECK(tex.find("\\begin{pmatrix} 1.000 & 0.000 & 0.000 \\\\ 0.000 & 1.250 & 0.000 \\\\ 0.000 & 0.000 & 1.000 "
                 "\\end{pmatrix}") != std::string::npos);
  std::size_t rays = 0;
  for (std::size_t at = 0; (at = tex.find("\\draw[ray]", at)) != std::string::npos; ++at) ++rays;
  CHECK(rays == 3);
  content.matrix = false;
  CHECK(session::export_construction_figure(state, content, path, false) == files);
  std::ifstream again(files[0]);
  const std::string without((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
  CHECK(without.find("pmatrix") == std::string::npos);
}

TEST_CASE("Export figure's messages name the full path, and several files briefly", "[ui][figure]") {
  struct Restore {
    std::filesystem::path folder = std::filesystem::current_path();
    ~Restore() { std::filesystem::current_path(folder); }
  } restore;
  const test::ScratchDir scratch("figure-export-message");
  session::AppState state = test::state_for({"--view", "3d"});
  std::filesystem::current_path(scratch.path("."));
  for (const raycam::Language language : {raycam::Language::en, raycam::Language::fr}) {
    state.language = language;
    // A relative name is written in the working folder: the message says which, in full.
    const auto one = session::export_construction_figure(state, {}, "raycam-figure.svg", false);
    REQUIRE(one.size() == 1);
    const std::string folder = std::filesystem::canonical(scratch.path(".")).string();
    const std::string said = session::figure_files_message(language, one);
    INFO(said);
    CHECK(said.find(folder + "/raycam-figure.svg") != std::string::npos);
    // Six files: one full path that spans them, not six paths (at 3× a message above the status line that
    // long covered half the views).
    const auto six = session::export_construction_figure(state, {}, "steps.svg", true);
    REQUIRE(six == (std::vector<std::string>{folder + "/steps-0.svg", folder + "/steps-1.svg", folder + "/steps-2.svg",
                                             folder + "/steps-3.svg", folder + "/steps-4.svg", folder + "/steps-5.svg"}));
    const std::string brief = session::figure_files_message(language, six);
    INFO(brief);
    CHECK(brief.find("6 ") != std::string::npos);  // how many
    CHECK(brief.find(folder + "/steps-0…5.svg") != std::string::npos);
    CHECK(brief.size() < folder.size() + 40);  // one path and a few words
    // The question before replacing them says as much, as briefly.
    const std::string question = session::figure_replace_question(language, session::existing_figure_files(state, {}, "steps.svg", true));
    INFO(question);
    CHECK(question.find(folder + "/steps-0…5.svg") != std::string::npos);
    CHECK(question.size() < folder.size() + 70);
  }
}

TEST_CASE("Export figure names the demo's objects in the window's language", "[ui][figure]") {
  const test::ScratchDir scratch("figure-export-names");
  session::AppState state = test::state_for({"--view", "2d"});
  const auto tex_of = [&](raycam::Language language) {
    state.language = language;
    const auto files = session::export_construction_figure(state, {}, scratch.path("names.tex"), false);
    std::ifstream in(files.at(0));
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const std::string french = tex_of(raycam::Language::fr), english = tex_of(raycam::Language::en);
  for (const auto& [en, fr] : {std::pair{"{red}", "{rouge}"}, std::pair{"{green}", "{vert}"}}) {
    CHECK(french.find(fr) != std::string::npos);
    CHECK(french.find(en) == std::string::npos);
    CHECK(english.find(en) != std::string::npos);
  }
}

TEST_CASE("Export figure refuses a page its objects' names do not fit, with the size that names them all", "[ui][figure]") {
  // Forty small discs with long names in a clump: no place by the discs, no leader, and a key taller than the
  // 160 × 120 mm page. raycam-cli figure refuses the page; the window's export did write it, names missing.
  const test::ScratchDir scratch("figure-names-refused");
  std::string objects;
  for (int i = 0; i < 40; ++i) {
    char object[256];
    std::snprintf(object, sizeof object,
                  "%s{\"type\": \"circle\", \"center\": [%.3f, %.3f], \"radius\": 0.05, \"color\": [%d, 90, 120], "
                  "\"name\": \"un objet au nom vraiment très long numéro %d\"}",
                  i ? ", " : "", -0.5 + 0.025 * (i % 40), -0.5 + 0.61 * ((i * 7) % 13) / 13.0, 6 * i, i);
    objects += object;
  }
  const std::string scene = scratch.path("crowd.json");
  std::ofstream(scene) << "{\"dimension\": 2, \"background\": [0, 0, 0], \"objects\": [" << objects
                       << "], \"camera\": {\"target\": [0, 0], \"d\": 6, \"theta\": 70, \"df\": 1.5, \"size\": 64}}";
  session::AppState state = test::state_for({"--scene", scene});
  state.construction_step = -1;
  try {
    session::export_construction_figure(state, {}, scratch.path("crowd.tex"), false);
    FAIL("exported a figure whose names do not fit");
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    INFO(message);
    CHECK(message.find("160 × 120 mm") != std::string::npos);
    int width = 0, height = 0;
    REQUIRE(std::sscanf(message.c_str() + message.find("--size ") + 7, "%dx%dmm", &width, &height) == 2);
    CHECK(width > 160);
    CHECK(height > 120);
  }
  CHECK_FALSE(std::filesystem::exists(scratch.path("crowd.tex")));
  // The classic scene's names fit: its export is written.
  session::AppState classic = test::state_for({"--view", "2d"});
  CHECK(session::export_construction_figure(classic, {}, scratch.path("classic.tex"), false).size() == 1);
}
