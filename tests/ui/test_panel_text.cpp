// The numbers the panels print, read back as text (Dear ImGui's log capture: no window, no GL) and checked
// against the core, computed here from the app state's camera: the ray inspector's P_k^0, u_k^0, P_k, u_k,
// hit id and t, and the status line's work counts. Pixels are a poor witness for numbers (printing 1.5·t
// changed 74 pixels of a 1280×720 screenshot); text is exact. Labels may be reworded or translated: the test
// reads the numeric tuples in order, the integer after "object"/"objet" and the number after "t =".
#include <imgui.h>
#include <imgui_internal.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <set>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../scratch_dir.h"
#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "session/mistake_lessons.h"
#include "ui/panel_widgets.h"  // labelled: the rule every labelled widget of the panel follows
#include "ui/panels.h"

using namespace raycam;

namespace {
// An ImGui context with a built font atlas and no renderer: enough to run panel functions and log their text.
class TextCapture {
 public:
  TextCapture() : context_(ImGui::CreateContext()) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = {1600, 1200};
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ~TextCapture() { ImGui::DestroyContext(context_); }
  template <class Draw>
  std::string capture(Draw draw) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({1600, 1200});
    ImGui::Begin("capture");
    ImGui::LogToBuffer();
    draw();
    const std::string text = GImGui->LogBuffer.c_str();
    ImGui::LogFinish();
    ImGui::End();
    ImGui::EndFrame();
    return text;
  }

 private:
  ImGuiContext* context_;
};

session::AppState state_for(const std::vector<std::string>& args) {
  session::AppState state = session::make_app_state(flags::parse_app_options(args));
  session::recast_if_needed(state);
  return state;
}

const char* const kNumber = R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)";

// Every parenthesised group whose members are all numbers, in order: "(0.1234, -1.0000)".
std::vector<std::vector<double>> numeric_tuples(const std::string& text) {
  std::vector<std::vector<double>> tuples;
  const std::regex group(R"(\(([^()]*)\))"), member(std::string(R"(^\s*()") + kNumber + R"()\s*$)");
  for (std::sregex_iterator it(text.begin(), text.end(), group), end; it != end; ++it) {
    std::vector<double> values;
    bool numeric = true;
    std::string inside = (*it)[1];
    std::size_t start = 0;
    while (numeric) {
      const std::size_t comma = inside.find(',', start);
      const std::string part =
          inside.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      std::smatch m;
      if (std::regex_match(part, m, member))
        values.push_back(std::stod(m[1]));
      else
        numeric = false;
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (numeric && values.size() >= 2) tuples.push_back(values);
  }
  return tuples;
}

std::optional<double> number_after(const std::string& text, const std::string& label_regex) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(label_regex + R"(\s*()" + kNumber + ")"))) return std::nullopt;
  return std::stod(m[1]);
}

// Nearest hit computed here in long double, independently of intersect.h: smallest t ≥ 0 of
// |o + t·u − c|² = r², ties to the lower index.
template <class Vec, class Object>
std::pair<int, long double> nearest(const std::vector<Object>& objects, const Vec& origin,
                                    const Vec& direction) {
  int id = -1;
  long double best = INFINITY;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    long double b = 0, c = 0;
    for (int a = 0; a < Vec::length(); ++a) {
      const long double f = (long double)origin[a] - objects[i].centre[a];
      b += f * direction[a];
      c += f * f;
    }
    c -= (long double)objects[i].radius * objects[i].radius;
    const long double disc = b * b - c;
    if (disc < 0) continue;
    for (long double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)})
      if (t >= 0) {
        if (t < best) best = t, id = int(i);
        break;
      }
  }
  return {id, best};
}

// %.4f in the panel: half a unit of the last digit, plus double's rounding of large values.
void check_close(double printed, double expected) {
  CHECK(std::abs(printed - expected) <= 5.001e-5 + 1e-12 * std::abs(expected));
}
void check_tuple(const std::vector<double>& printed, const glm::dvec3& expected, int dimensions) {
  REQUIRE(int(printed.size()) == dimensions);
  for (int a = 0; a < dimensions; ++a) check_close(printed[std::size_t(a)], expected[a]);
}
}  // namespace

TEST_CASE("the ray inspector prints the core's P_k, u_k, hit and t (2D)", "[ui][inspector]") {
  TextCapture text;
  for (int column : {100, 17, 200}) {
    session::AppState state = state_for({"--view", "2d", "--inspect", std::to_string(column) + ",0"});
    const std::string shown = text.capture([&] { ui::inspector_section(state); });
    INFO("column " << column << ", the panel says:\n" << shown);
    const Camera2D& camera = view2d(state).camera;
    const int n = camera.pixel_count(), k = n - 1 - column;  // column 0 is the eye's left: k = n-1
    const glm::dvec2 p0(-1.0 + (2.0 * k + 1.0) / n, 0.0), u0 = p0 - glm::dvec2(0, 1);
    const glm::dmat3& m = camera.world_from_camera();  // M_d from the app's state
    const glm::dvec2 p = glm::dvec2(m * glm::dvec3(p0, 1.0)),
                     u = glm::normalize(glm::dvec2(m * glm::dvec3(u0, 0.0)));
    const auto tuples = numeric_tuples(shown);
    REQUIRE(tuples.size() == 4);
    check_tuple(tuples[0], {p0, 0}, 2);
    check_tuple(tuples[1], {u0, 0}, 2);
    check_tuple(tuples[2], {p, 0}, 2);
    check_tuple(tuples[3], {u, 0}, 2);
    CHECK(number_after(shown, R"(k\s*=)") == Approx(k));
    const auto [id, t] = nearest(view2d(state).scene.circles, p, u);
    CHECK(id == state.map.id_at(0, column));
    if (id >= 0) {
      CHECK(number_after(shown, "obje[ct]+") == Approx(id));
      REQUIRE(number_after(shown, R"(t\s*=)"));
      check_close(*number_after(shown, R"(t\s*=)"), double(t));
    } else {
      CHECK_FALSE(number_after(shown, R"(t\s*=)"));
    }
  }
}

TEST_CASE("the ray inspector prints the core's P, u, hit and t (3D)", "[ui][inspector]") {
  TextCapture text;
  for (const char* pixel : {"120,140", "10,10", "200,60"}) {
    session::AppState state = state_for({"--inspect", pixel, "--theta", "40", "--phi", "65"});
    const std::string shown = text.capture([&] { ui::inspector_section(state); });
    INFO(pixel << ", the panel says:\n" << shown);
    const int column = std::stoi(pixel),
              row = std::stoi(std::string(pixel).substr(std::string(pixel).find(',') + 1));
    const Camera3D& camera = view3d(state).camera;
    const glm::dvec3 p0(-1.0 + (2.0 * column + 1.0) / camera.columns(),
                        1.0 - (2.0 * row + 1.0) / camera.rows(), 0.0);
    const glm::dvec3 u0 = p0 - glm::dvec3(0, 0, 1);
    const glm::dmat4& m = camera.world_from_camera();
    const glm::dvec3 p = glm::dvec3(m * glm::dvec4(p0, 1.0)),
                     u = glm::normalize(glm::dvec3(m * glm::dvec4(u0, 0.0)));
    // The pixel it names is the one inspected (rows and columns from 0, as the image's).
    REQUIRE(number_after(shown, "(?:row|ligne)"));
    CHECK(*number_after(shown, "(?:row|ligne)") == row);
    REQUIRE(number_after(shown, "(?:column|colonne)"));
    CHECK(*number_after(shown, "(?:column|colonne)") == column);
    const auto tuples = numeric_tuples(shown);
    REQUIRE(tuples.size() == 4);
    check_tuple(tuples[0], p0, 3);
    check_tuple(tuples[1], u0, 3);
    check_tuple(tuples[2], p, 3);
    check_tuple(tuples[3], u, 3);
    const auto [id, t] = nearest(view3d(state).scene.spheres, p, u);
    CHECK(id == state.map.id_at(row, column));
    if (id >= 0) {
      CHECK(number_after(shown, "obje[ct]+") == Approx(id));
      REQUIRE(number_after(shown, R"(t\s*=)"));
      check_close(*number_after(shown, R"(t\s*=)"), double(t));
    }
  }
}

TEST_CASE("the status line prints the cast's work counts", "[ui][status]") {
  TextCapture text;
  for (const char* view : {"2d", "3d"}) {
    session::AppState state = state_for({"--view", view});
    const std::string shown = text.capture([&] { ui::status_counters(state); });  // the status line's tooltip
    INFO(shown);
    const CastStats& w = state.stats;
    CHECK(w.rays == std::int64_t(state.map.width) * state.map.height);  // one answer per pixel
    // Each count appears as a whole number (the timings, which vary, are not checked).
    for (long long count : {w.rays, w.pixels_skipped, w.intersection_tests, w.objects_culled}) {
      INFO("count " << count);
      CHECK(std::regex_search(shown, std::regex("(^|[^0-9.])" + std::to_string(count) + "($|[^0-9.])")));
    }
  }
}

// Lecture sizes wrap the panel's text at its edge, between words only: never inside a number ("67." then
// "4°", as ImGui's own wrapping breaks after a '.') and never past the edge.
TEST_CASE("panel text wraps between words, never inside a number, and never past the edge", "[ui][lecture]") {
  TextCapture capture;
  const float width = 150.0f;
  const std::string text = "n = 256 × 256, field of view 67.4°, half a pixel 0.00391 wide, at t = 12.3456";
  const std::string logged = capture.capture([&] {
    ImGui::BeginChild("narrow", {width, 400});
    ui::wrapped_between_words(text);
    ImGui::EndChild();
  });
  std::vector<std::string> lines;
  std::istringstream in(logged);
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(' ') != std::string::npos) lines.push_back(line.substr(line.find_first_not_of(' ')));
  INFO(logged);
  CHECK(lines.size() >= 3);  // it did wrap
  std::string joined;
  for (const std::string& line : lines) {
    CHECK(ImGui::CalcTextSize(line.c_str()).x <= width);
    for (const char* number : {"67.4°", "0.00391", "12.3456"})  // each number whole on one line, or absent
      if (line.find(std::string(number).substr(0, 3)) != std::string::npos) CHECK(line.find(number) != std::string::npos);
    joined += (joined.empty() ? "" : " ") + line;
  }
  CHECK(joined == text);  // nothing lost, words in order
}

// A label sits beside its widget only where the widget keeps the room it asks for (the target C's fields each
// show -10.00 whole): where beside would leave it less, the label goes above and the widget takes the whole
// line. The widget reports the width it is given (ImGui's next item width, which labelled sets).
TEST_CASE("a labelled widget keeps the width it asks for: its label goes above rather than squeeze it",
          "[ui][lecture]") {
  TextCapture capture;
  ui::PanelState panels;
  const char* text = "a label of some length";
  for (const float short_by : {10.0f, -10.0f}) {  // beside would leave the widget 10 px too little, or 10 px more
    float avail = 0.0f, label = 0.0f, asked = 0.0f, given = 0.0f;
    capture.capture([&] {
      label = ImGui::CalcTextSize(text).x + ImGui::GetStyle().ItemInnerSpacing.x;
      ImGui::BeginChild("panel", {3.0f * label, 400});  // the label a third of the line: short enough to sit beside
      avail = ImGui::GetContentRegionAvail().x;
      asked = avail - label + short_by;
      ui::labelled(panels, (std::string(text) + "###field").c_str(), [&](const char*) {
        given = ImGui::CalcItemWidth();
        return false;
      }, asked);
      ImGui::EndChild();
    });
    INFO("line " << avail << " px, label " << label << " px, the widget asks " << asked << " px and is given " << given);
    REQUIRE(label <= 0.45f * avail);
    CHECK(given >= asked);
    if (short_by > 0) CHECK(given == Approx(avail));          // the label above, the widget the whole line
    else CHECK(given == Approx(avail - label));               // the label beside
  }
}

// Where not even one of M_d's columns fits the panel's width at its font, the table is drawn in a smaller font
// (down to about half the panel's) rather than at the panel's font in a strip that scrolls sideways.
TEST_CASE("M_d's table shrinks its font where not one column fits the panel", "[ui][lecture]") {
  TextCapture capture;
  for (const char* view : {"2d", "3d"}) {
    session::AppState state = state_for({"--view", view});
    ui::PanelState panels;
    ui::WidgetRects rects;
    panels.widget_rects = &rects;
    float panel_font = 0.0f, column = 0.0f;
    capture.capture([&] {
      panel_font = ImGui::GetFontSize();
      column = ImGui::CalcTextSize("0.00").x;  // narrower than any column of the table (none is shorter)
      ImGui::BeginChild("narrow", {column, 4000});
      ui::construction_section(state, panels);
      ImGui::EndChild();
    });
    REQUIRE(rects.count("###matrix/M") == 1);
    const ui::WidgetRect& table = rects.at("###matrix/M");
    const float font = table.x1 - table.x0;  // the hook's font size
    INFO(view << ": a panel " << column << " px wide, the table's font " << font << " px, the panel's " << panel_font);
    CHECK(font < panel_font);
    CHECK(font >= 0.5f * panel_font);
  }
}

// The French window is French: every section open (a mistake shown, a ray pinned, a file that failed to
// open), its text read back, and no word of a list of English-only words in it. The list holds words a
// translation left behind would show (not words French shares: image, pixel, distance, rotation…).
TEST_CASE("the French window shows no English word", "[ui][text]") {
  TextCapture text;
  for (const char* view : {"2d", "3d"}) {
    session::AppState state = state_for({"--view", view, "--lang", "fr", "--inspect", "3,0"});
    session::show_mistake(state, *session::find_lesson("pixel_edges"));
    session::open_scene(state, "/inexistant/fichier.json");  // a red message, in French
    session::recast_if_needed(state);
    const std::string shown = text.capture([&] {
      ImGuiWindow* window = ImGui::GetCurrentWindow();
      for (const char* id : {"###camera", "###mistakes", "###caster", "###files", "###lecture", "###construction",
                             "###inspector"})
        window->StateStorage.SetInt(window->GetID(id), 1);
      ui::PanelState panels = ui::panel_state_for({}, state);  // as the hosts start it: the export's name in French
      ui::camera_section(state, panels);
      ui::mistakes_section(state, panels);
      ui::caster_section(state, panels);
      ui::files_section(state, panels);
      ui::lecture_section(state, panels);
      ui::construction_section(state, panels);
      ui::inspector_section(state);
      ui::status_line(state, panels);
    });
    INFO(view << ":\n" << shown);
    CHECK(shown.find("Caméra") != std::string::npos);  // it is the French window
    for (const char* word : {"the", "and", "of", "with", "from", "cannot", "error", "mistake", "show", "step",
                             "expected", "colour", "color", "field", "view", "open", "save", "check", "rows",
                             "columns", "file", "wheel", "drag", "focal", "scene", "preset", "export", "help",
                             "fullscreen", "screenshot", "caster", "frame", "cast", "hit", "nothing", "object",
                             "background", "route", "psi0", "theta", "phi", "colmap", "oeil"}) {
      const std::regex english(std::string("(^|[^A-Za-zÀ-ÿ_])") + word + "($|[^A-Za-zÀ-ÿ_])", std::regex::icase);
      INFO("English word: " << word);
      CHECK_FALSE(std::regex_search(shown, english));
    }
  }
}

TEST_CASE("Export figure's replace question is not shown beside the last export's 'wrote'", "[ui][figure]") {
  // Exporting twice: the second click asks before replacing. The first export's "wrote …" stayed under the
  // question, so the panel said both "… already exists. Replace it?" and "wrote …" at once.
  TextCapture text;
  session::AppState state = state_for({"--view", "2d"});
  ui::PanelState panels;
  panels.figure_path = "raycam-figure.svg";
  panels.figure_replace_pending = 1;
  session::set_message(state, session::MessageSource::construction, false, "wrote /somewhere/raycam-figure.svg");
  const std::string asking = text.capture([&] { ui::construction_section(state, panels); });
  CHECK(asking.find("already exists. Replace it?") != std::string::npos);
  CHECK(asking.find("wrote") == std::string::npos);
  CHECK(state.message.empty());  // nor on the line above the status (lecture sizes): the question replaced it
  // Another panel's message stays.
  session::set_message(state, session::MessageSource::files, false, "saved scene.json");
  text.capture([&] { ui::construction_section(state, panels); });
  CHECK(state.message == "saved scene.json");
}

TEST_CASE("Export figure's replace question shows the files found when asked, without drawing them again",
          "[ui][figure]") {
  // The question is drawn every frame: from the list found at the click, not by building the figure again
  // to look for the files (a whole figure per frame; and a name no longer a figure's threw out of the frame).
  TextCapture text;
  session::AppState state = state_for({"--view", "2d"});
  ui::PanelState panels;
  panels.figure_replace_pending = 2;
  panels.figure_replace_files = {"/home/ada/figs/steps-a.svg", "/home/ada/figs/steps-b.svg",
                                "/home/ada/figs/steps-c.svg", "/home/ada/figs/steps-d.svg"};
  panels.figure_path = "notes.gif";  // no figure's name: building the figure for it throws
  std::string asking;
  REQUIRE_NOTHROW(asking = text.capture([&] { ui::construction_section(state, panels); }));
  CHECK(asking.find("4 files already exist: /home/ada/figs/steps-a…d.svg. Replace them?") != std::string::npos);
}

TEST_CASE("Export figure's ray count is offered in 2D only: the 3D steps draw no rays", "[ui][figure]") {
  TextCapture text;
  for (const char* view : {"2d", "3d"}) {
    session::AppState state = state_for({"--view", view});
    ui::PanelState panels;
    const std::string shown = text.capture([&] { ui::construction_section(state, panels); });
    INFO(view);
    CHECK(shown.find("Export figure") != std::string::npos);
    CHECK((shown.find("rays") != std::string::npos) == (std::string(view) == "2d"));
  }
}

// The shipped scenes' objects are named in the window's language (the test's own French words, not the
// table's), where the inspector names the object a ray hit: the demo's, and the demo saved as a file.
TEST_CASE("the inspector names the shipped objects in the window's language, the demo's and a saved file's",
          "[ui][text]") {
  const std::map<std::string, std::string> kFrench = {
      {"red", "rouge"}, {"green", "vert"}, {"blue", "bleu"}, {"yellow", "jaune"}, {"ground", "sol"}};
  const test::ScratchDir scratch("demo-names");
  TextCapture text;
  for (const char* view : {"2d", "3d"})
    for (const char* language : {"fr", "en"})
      for (const bool from_file : {false, true}) {
        session::AppState state = state_for({"--view", view, "--lang", language});
        if (from_file) {  // the demo saved as a file, opened again: the names the table knows are translated
          const std::string file = scratch.path(std::string("demo") + view + ".json");
          REQUIRE(session::save_preset(state, file));
          REQUIRE(session::open_scene(state, file));
          session::recast_if_needed(state);
        }
        const auto& names = std::visit(
            [](const auto& v) {
              std::vector<std::string> out;
              for (const auto& object : objects_of(v.scene)) out.push_back(object.name);
              return out;
            },
            state.view);
        std::set<int> seen;
        for (int row = 0; row < state.map.height; ++row)
          for (int column = 0; column < state.map.width; ++column) {
            const int id = state.map.id_at(row, column);
            if (id < 0 || !seen.insert(id).second) continue;
            state.pinned_pixel = session::PixelIndex{row, column};
            const std::string shown = text.capture([&] { ui::inspector_section(state); });
            const std::string& name = names[std::size_t(id)];
            const bool french = std::string(language) == "fr";
            const std::string expected = french ? kFrench.at(name) : name;
            INFO(view << " " << language << (from_file ? " file" : " demo") << ": " << shown);
            CHECK(shown.find(" " + std::to_string(id) + " " + expected + " ") != std::string::npos);
          }
        CHECK(seen.size() >= 4);  // every demo object in sight
      }
}

TEST_CASE("the French window writes its numbers with a decimal comma, sliders and tables included", "[ui][text]") {
  TextCapture text;
  for (const char* view : {"2d", "3d"}) {
    session::AppState state = state_for({"--view", view, "--lang", "fr", "--inspect", "3,0", "--theta", "50"});
    session::recast_if_needed(state);
    const std::string shown = text.capture([&] {
      ImGuiWindow* window = ImGui::GetCurrentWindow();
      for (const char* id : {"###camera", "###caster", "###lecture", "###construction", "###inspector"})
        window->StateStorage.SetInt(window->GetID(id), 1);
      ui::PanelState panels = ui::panel_state_for({}, state);
      ui::camera_section(state, panels);
      ui::caster_section(state, panels);
      ui::lecture_section(state, panels);
      ui::construction_section(state, panels);
      ui::inspector_section(state);
      ui::status_line(state, panels);
    });
    INFO(view << ":\n" << shown);
    CHECK(std::regex_search(shown, std::regex(R"(50,0°)")));  // θ's slider, written by the panel
    CHECK(std::regex_search(shown, std::regex(R"(\d,\d{4})")));  // the inspector's coordinates
    CHECK_FALSE(std::regex_search(shown, std::regex(R"(\d\.\d)")));
  }
}
