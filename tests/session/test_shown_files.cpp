// Files as a student knows them (shown_files.h): in the page, a message names a file by its name alone (the
// page's folders are not the student's), downloads are named after the scene, and a download never asks to
// replace anything; on the desktop, paths stay whole and Save as still asks.
#include <catch2/catch.hpp>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "../scratch_dir.h"
#include "session/app_options.h"
#include "session/shown_files.h"

using namespace raycam;
using namespace raycam::session;

TEST_CASE("the page names files by their names, the desktop by their paths", "[files][host]") {
  CHECK(shown_file_name(kPageHost, "/picked/my scene.json") == "my scene.json");
  CHECK(shown_file_name(kPageHost, "/home/web_user/raycam-screenshot-001.png") == "raycam-screenshot-001.png");
  CHECK(shown_file_name(kDesktopHost, "/home/me/my scene.json") == "/home/me/my scene.json");
  CHECK(with_file_shown(kPageHost, "cannot open: /picked/a.json: /picked/a.json is empty", "/picked/a.json") ==
        "cannot open: a.json: a.json is empty");
  CHECK(with_file_shown(kDesktopHost, "cannot open: /home/me/a.json", "/home/me/a.json") ==
        "cannot open: /home/me/a.json");
}

TEST_CASE("a file the page cannot open is named alone in its error, the desktop names the path",
          "[files][host]") {
  const test::ScratchDir scratch("page-open-names");
  const std::string bad = scratch.path("notes.json");
  std::ofstream(bad) << "this is not a scene";
  for (const bool page : {true, false}) {
    AppState state = make_app_state(AppOptions{});
    state.host = page ? kPageHost : kDesktopHost;
    CHECK_FALSE(open_scene(state, bad));
    CHECK(state.message.find("notes.json") != std::string::npos);
    CHECK((state.message.find(scratch.dir.string()) != std::string::npos) == !page);
  }
}

TEST_CASE("downloads are named after the scene and never ask to replace", "[files][host]") {
  AppOptions options;
  options.view.scene_path = std::string(SCENES_DIR) + "/many3d.json";
  AppState state = make_app_state(options);
  CHECK(named_after_scene(state, ".json") == "many3d.json");
  CHECK(named_after_scene(state, "-figure.tex") == "many3d-figure.tex");
  CHECK(named_after_scene(make_app_state(AppOptions{}), ".json") == "raycam-demo-3d.json");

  const test::ScratchDir scratch("page-downloads");
  const std::string path = scratch.path("many3d.json");
  for (const bool page : {true, false}) {
    state.host = page ? kPageHost : kDesktopHost;
    std::filesystem::remove(path);
    CHECK(save_preset_as(state, path, false) == SaveAsOutcome::saved);
    // Saved again: the page's download asks nothing (the browser keeps both); the desktop asks first.
    CHECK(save_preset_as(state, path, false) == (page ? SaveAsOutcome::saved : SaveAsOutcome::needs_yes));
    CHECK((state.message.find(scratch.dir.string()) != std::string::npos) == !page);
  }
}

TEST_CASE("the page says what it asked the browser to save, the desktop what it wrote", "[files][host]") {
  CHECK(written_message(kPageHost, Language::en, "/home/web_user/many3d.png") == "asked the browser to save many3d.png");
  CHECK(written_message(kPageHost, Language::fr, "/home/web_user/many3d.png") ==
        "téléchargement de many3d.png demandé au navigateur");
  CHECK(written_message(kDesktopHost, Language::en, "/home/me/many3d.png") == "wrote /home/me/many3d.png");
  for (const Language language : {Language::en, Language::fr}) {
    const std::string page = written_message(kPageHost, language, "a.png");
    CHECK(page.find("wrote") == std::string::npos);
    CHECK(page.find("écrit") == std::string::npos);
  }
}

TEST_CASE("several files become one zip archive that unzip gives back whole", "[files][host][zip]") {
  const test::ScratchDir scratch("one-download");
  std::vector<std::string> files;
  for (const char* name : {"many3d-figure-a.tex", "many3d-figure-b.tex", "many3d-figure-c.tex"}) {
    files.push_back(scratch.path(name));
    std::ofstream(files.back()) << "% the figure " << name << "\n\\begin{tikzpicture}\\end{tikzpicture}\n";
  }
  const std::string archive = as_one_download(files, "many3d-steps.zip");
  CHECK(archive == scratch.path("many3d-steps.zip"));
  for (const std::string& file : files) CHECK_FALSE(std::filesystem::exists(file));  // only the archive is offered
  const std::string out = scratch.path("out");
  REQUIRE(std::system(("unzip -tq " + archive + " >/dev/null && unzip -q " + archive + " -d " + out).c_str()) == 0);
  for (const char* name : {"many3d-figure-a.tex", "many3d-figure-b.tex", "many3d-figure-c.tex"}) {
    std::ifstream in(out + "/" + name);
    std::string first;
    std::getline(in, first);
    CHECK(first == std::string("% the figure ") + name);
  }
  CHECK_THROWS_AS(as_one_download({scratch.path("missing.tex")}, "x.zip"), std::runtime_error);
}
