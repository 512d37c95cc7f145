// Layouts that fit a lecture hall's projector: at 1×, 2× and 3× fonts on 1024×768, 1280×800 and 1920×1080, in
// both languages and both views, with every section of the panel open, a mistake shown and a ray pinned, no
// window of the frame has content wider than what it shows without a horizontal scroll bar (a text, a button
// or a box that extends past its window's clip rectangle is cut) and no window title is wider than its
// window. ImGui measures every item it lays out into its window's content size, so this reads what the frame
// itself measured, item by item; a combo's shown choice fits beside its arrow. Text drawn straight into a draw list (the views' labels) is checked glyph by
// glyph against the clip rectangle it is drawn in; the picture keeps its size whatever its header says (a
// mistake, a check's verdict); and no table scrolls sideways (M_d's translation column shows whole).
#include <algorithm>
#include <imgui.h>
#include <imgui_internal.h>

#include <catch2/catch.hpp>
#include <cfloat>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <functional>

#include "flags/app/app_flags.h"
#include "session/construction_view.h"
#include "session/app_options.h"
#include "ui/check_panel.h"
#include "ui/frame_host.h"
#include "headless/headless_renderer.h"
#include "session/mistake_lessons.h"
#include "ui/overhead_view.h"
#include "ui/panels.h"
#include "raycam/scene_file.h"
#include "check/answer.h"
#include "check/case_image.h"
#include <fstream>

using namespace raycam;

namespace {
session::AppState lecture_state(const char* view, const char* language) {
  session::AppOptions options;
  return session::make_app_state(
      flags::parse_app_options({"--view", view, "--lang", language, "--inspect", "3,0"}, options));
}

// Opens every section of the panel, as an instructor preparing a lecture would (ImGui keeps a header's
// open state in its window's storage, under the header's id).
void open_every_section() {
  ImGuiWindow* panel = ImGui::FindWindowByName("raycam###panel");
  REQUIRE(panel);
  for (const char* id : {"###camera", "###mistakes", "###caster", "###files", "###lecture", "###construction",
                         "###inspector", "###check"})
    panel->StateStorage.SetInt(panel->GetID(id), 1);
}

// Window titles cut: a title wider than its window's title bar.
std::vector<std::string> cut_titles() {
  std::vector<std::string> cut;
  for (ImGuiWindow* window : GImGui->Windows) {
    if (!window->WasActive || window->Hidden || (window->Flags & ImGuiWindowFlags_NoTitleBar)) continue;
    const char* end = ImGui::FindRenderedTextEnd(window->Name);
    const float title = ImGui::CalcTextSize(window->Name, end).x + 2 * GImGui->Style.FramePadding.x;
    if (title > window->Size.x + 1.0f) cut.push_back("title '" + std::string(window->Name, std::size_t(end - window->Name)) + "'");
  }
  return cut;
}

// Every visible window whose laid-out content is wider than its inner width while it has no horizontal
// scroll bar, with by how much.
std::vector<std::string> cut_windows() {
  std::vector<std::string> cut;
  for (ImGuiWindow* window : GImGui->Windows) {
    if (!window->WasActive || window->Hidden || window->ScrollbarX) continue;
    const float shown = window->InnerRect.GetWidth(), content = window->ContentSize.x + window->WindowPadding.x;
    if (content > shown + 1.0f) {
      std::ostringstream out;
      out << "'" << window->Name << "' content " << content << " px in " << shown << " px";
      cut.push_back(out.str());
    }
  }
  return cut;
}

// Windows that scroll sideways: a table or panel whose last columns hide behind a scroll bar (M_d's
// translation column at 3×).
std::vector<std::string> sideways_scrolling() {
  std::vector<std::string> found;
  for (ImGuiWindow* window : GImGui->Windows)
    if (window->WasActive && !window->Hidden && window->ScrollbarX) found.push_back("'" + std::string(window->Name) + "' scrolls sideways");
  return found;
}

// Text drawn cut: a glyph of a window's draw list that crosses the clip rectangle it is drawn in. ImGui
// drops the glyphs wholly outside that rectangle and keeps the others whole (draw-list text is not clipped
// finely), so a label that runs past a view's edge leaves a glyph across it ("vue de côt|é"). Sideways in
// every window; up and down too in windows that do not scroll (a scrolled panel cuts its top and bottom
// lines by design). A glyph is a vertex textured from the font atlas, neither its white pixel nor its baked
// thick lines.
std::vector<std::string> cut_drawn_text() {
  const ImFontAtlas* atlas = ImGui::GetIO().Fonts;
  const ImVec2 white = atlas->TexUvWhitePixel;
  ImVec4 lines = atlas->TexUvLines[0];
  for (const ImVec4& uv : atlas->TexUvLines)
    lines = {std::min(lines.x, uv.x), std::min(lines.y, uv.y), std::max(lines.z, uv.z), std::max(lines.w, uv.w)};
  auto is_glyph = [&](ImVec2 uv) {
    const bool on_white = std::abs(uv.x - white.x) < 1e-6f && std::abs(uv.y - white.y) < 1e-6f;
    const bool on_lines = uv.x >= lines.x && uv.x <= lines.z && uv.y >= lines.y && uv.y <= lines.w;
    return !on_white && !on_lines;
  };
  std::vector<std::string> cut;
  for (ImGuiWindow* window : GImGui->Windows) {
    if (!window->WasActive || window->Hidden) continue;
    const bool scrolls = window->ScrollMax.y > 0;
    const ImDrawList* list = window->DrawList;
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback || cmd.TextureId != atlas->TexID) continue;
      const ImVec4 clip = cmd.ClipRect;
      for (unsigned i = cmd.IdxOffset; i < cmd.IdxOffset + cmd.ElemCount; ++i) {
        const ImDrawVert& v = list->VtxBuffer[int(cmd.VtxOffset + list->IdxBuffer[int(i)])];
        if (!is_glyph(v.uv)) continue;
        const bool across = v.pos.x < clip.x - 0.5f || v.pos.x > clip.z + 0.5f ||
                            (!scrolls && (v.pos.y < clip.y - 0.5f || v.pos.y > clip.w + 0.5f));
        if (!across) continue;
        std::ostringstream out;
        out << "'" << window->Name << "': a glyph at " << v.pos.x << "," << v.pos.y << " across its clip "
            << clip.x << "," << clip.y << " - " << clip.z << "," << clip.w;
        cut.push_back(out.str());
        break;  // one a draw command says it
      }
    }
  }
  return cut;
}

// The image window's title as drawn, when it is wider than its title bar: cut.
std::vector<std::string> cut_image_title(const ui::FrameLayout& layout) {
  const float title = ImGui::CalcTextSize(layout.image_title.c_str()).x + 2 * GImGui->Style.FramePadding.x;
  if (title <= layout.image_header.w + 1.0f) return {};
  return {"the image's title '" + layout.image_title + "'"};
}

// Combos whose shown choice is wider than the combo leaves it beside its arrow ("stable (Ray Tra" at 3×):
// the panel records each combo's rectangle and its preview's width (the panels' test hook).
std::vector<std::string> cut_combos(const ui::WidgetRects& rects) {
  std::vector<std::string> cut;
  for (const auto& [id, preview] : rects) {
    const std::size_t slash = id.find("/preview");
    if (slash == std::string::npos) continue;
    const ui::WidgetRect& combo = rects.at(id.substr(0, slash));
    const float room = combo.x1 - combo.x0 - ImGui::GetFrameHeight() - 2 * GImGui->Style.FramePadding.x;
    if (preview.x1 > room + 1.0f) cut.push_back("combo '" + id.substr(0, slash) + "' shows its choice cut");
  }
  return cut;
}

// Everything the layout test finds cut or hidden in the frame just drawn, a line each.
std::string everything_cut(const ui::FrameLayout& layout) {
  std::vector<std::string> cut = cut_windows();
  for (auto found : {cut_titles(), cut_image_title(layout), sideways_scrolling(), cut_drawn_text()})
    for (const std::string& c : found) cut.push_back(c);
  std::string all;
  for (const std::string& c : cut) all += "\n  " + c;
  return all;
}

struct Screen {
  int width, height;
};
constexpr Screen kScreens[] = {{1024, 768}, {1280, 800}, {1920, 1080}};

}  // namespace

TEST_CASE("at 1x to 3x on 1024x768 to 1920x1080, in both languages, no window's content is cut",
          "[render][lecture][layout]") {
  int checked = 0;
  for (const Screen screen : kScreens)
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* language : {"fr", "en"})
        for (const char* view : {"2d", "3d"}) {
          session::AppState state = lecture_state(view, language);
          state.font_scale = scale;
          session::show_mistake(state, *session::find_lesson("pixel_edges"));
          if (std::string(view) == "3d") state.res_rows = 0.5;  // non-square: the res_c and res_l sliders
          ui::WidgetRects rects;
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          renderer.panels().widget_rects = &rects;
          renderer.run_frame(state);
          open_every_section();
          renderer.render_settled(state, 4);
          std::string cut = everything_cut(renderer.layout());
          for (const std::string& c : cut_combos(rects)) cut += "\n  " + c;
          CHECK(rects.count("###intersection/preview") == 1);  // the caster's combos were laid out
          INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << language << ", " << view << ":"
                            << cut);
          CHECK(cut.empty());
          ++checked;
        }
  CHECK(checked == 36);
}

// The overhead view's landmark labels never print over each other, however big the font and however close
// their anchors ("k = 0" over "eye's left (column 0)" at 3× in a narrow view), and stay inside the view.
TEST_CASE("a label placed beside others moves off them and stays in the view", "[render][lecture][layout]") {
  const ImVec2 low{0, 0}, high{400, 300}, size{180, 45};
  std::vector<std::pair<ImVec2, ImVec2>> placed = {{{100, 100}, {200, 45}}};
  for (const ImVec2 wanted : {ImVec2{110, 100}, ImVec2{250, 120}, ImVec2{390, 290}, ImVec2{-50, -50}}) {
    const ImVec2 at = ui::place_label(wanted, size, low, high, placed);
    INFO(wanted.x << "," << wanted.y << " -> " << at.x << "," << at.y);
    for (const auto& [q, s] : placed)
      CHECK_FALSE((at.x < q.x + s.x && q.x < at.x + size.x && at.y < q.y + s.y && q.y < at.y + size.y));
    CHECK((at.x >= low.x && at.y >= low.y && at.x + size.x <= high.x && at.y + size.y <= high.y));
    placed.push_back({at, size});
  }
}

// Every step of the construction, where the views draw their own labels ("eye E: z = …", the side view's
// title, the axes' names) and M_d's tables change: nothing runs past its window's edge, at any font scale,
// on any screen. Each screen is also laid out 4000 px tall (the panel as wide, every section in sight: a
// glyph below the panel's fold is not drawn at all, cut or not).
TEST_CASE("at 1x to 3x, every construction step's drawn labels show whole", "[render][lecture][layout]") {
  int checked = 0;
  for (const Screen screen : {kScreens[0], kScreens[1], kScreens[2], Screen{1024, 4000}, Screen{1280, 4000}})
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* view : {"2d", "3d"})
        for (int step = 0; step <= (std::string(view) == "2d" ? 3 : 5); ++step) {
          session::AppState state = lecture_state(view, "fr");  // the longer words
          state.font_scale = scale;
          state.construction_step = step;
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          renderer.render_settled(state, 3);
          const std::string cut = everything_cut(renderer.layout());
          INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << view << ", step " << step << ":"
                            << cut);
          CHECK(cut.empty());
          ++checked;
        }
  CHECK(checked == 5 * 3 * (4 + 6));
}

namespace {
// Runs frames until the check's verdict is in (the quiet time is counted on the frames' 60 Hz clock, the
// program runs on a thread of its own) and then only as long as the app's idle loop would
// (frame_needs_redraw): what is left on screen is what an idle window shows. No fixed count of frames after
// the verdict: extra frames would do the scrolling an idle window never does. At most 60 s.
void until_verdict(headless::HeadlessRenderer& renderer, session::AppState& state) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  do {
    renderer.run_frame(state);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  } while ((renderer.check().status().empty() || ui::frame_needs_redraw(state, renderer.panels())) &&
           std::chrono::steady_clock::now() < deadline);
}

// A folder of the test's own under the temporary directory (its name and the process id), removed at the end.
struct ScratchFolder {
  explicit ScratchFolder(const std::string& name)
      : path((std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))).string()) {
    std::filesystem::create_directories(path);
  }
  ~ScratchFolder() { std::filesystem::remove_all(path); }
  const std::string path;
};

// The page's round trip: the check's case downloaded into `folder`, `program` run on it as a student would;
// returns the answer file it wrote (given back by the caller, after whatever the student does in between).
std::string answer_of(const std::string& program, headless::HeadlessRenderer& renderer, const session::AppState& state,
                      const std::string& folder) {
  const std::string case_path = folder + "/case.json", answer = folder + "/answer.json";
  save_scene_file(renderer.check().case_for_download(state), case_path);
  REQUIRE(std::system((program + " < " + case_path + " > " + answer).c_str()) == 0);
  return answer;
}
}  // namespace

// What the header says never takes the picture's height: the picture is drawn as big with a mistake on, with
// a failing and with a passing check as with nothing to say; the header stays one line that fits, the
// verdict whole in it; and the verdict, in the panel, is scrolled into sight when it arrives.
TEST_CASE("the picture keeps its size whatever its header says and the check's verdict is in sight",
          "[render][lecture][layout]") {
  const std::string student = EXAMPLE_STUDENT_CPP, mistaken = std::string(MISTAKEN_STUDENT) + " --mistake mirrored";
  for (const Screen screen : kScreens)
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* view : {"2d", "3d"}) {
        auto picture = [&](const char* what, const char* mistake, const std::string& program) {
          session::AppState state = lecture_state(view, "fr");
          state.font_scale = scale;
          if (mistake) {
            session::show_mistake(state, *session::find_lesson(mistake));
            state.mistakes.mirrored = true;  // two names: the longest header
          }
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          renderer.panels().check_command = program;
          renderer.run_frame(state);
          open_every_section();
          if (program.empty()) renderer.render_settled(state, 4);
          else until_verdict(renderer, state);
          const std::string& title = renderer.layout().image_title;
          const std::string cut = everything_cut(renderer.layout());
          INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << view << ", " << what
                            << ": header '" << title << "'" << cut);
          CHECK(cut.empty());
          if (!program.empty()) {  // the verdict whole in the header, and in the panel's view
            const bool failing = program == mistaken;  // its long form, or its short one, whole
            CHECK((title.find("VÉRIFICATION : ") != std::string::npos || title.find(failing ? "✗ " : "✓ ") == 0));
            CHECK(title.find(failing ? " faux" : "réussie") != std::string::npos);
            const ImGuiWindow* panel = ImGui::FindWindowByName("raycam###panel");
            const ImVec4 verdict = ui::drawn_verdict_rect();
            INFO("verdict at y " << verdict.y << " - " << verdict.w << ", the panel shows y " << panel->InnerClipRect.Min.y
                                 << " - " << panel->InnerClipRect.Max.y);
            CHECK(verdict.y >= panel->InnerClipRect.Min.y);
            CHECK(verdict.w <= panel->InnerClipRect.Max.y + 0.5f);
          }
          return renderer.layout().image;
        };
        const ui::Rect plain = picture("nothing to say", nullptr, "");
        for (const auto& [what, mistake, program] :
             {std::tuple<const char*, const char*, std::string>{"two mistakes", "pixel_edges", ""},
              {"a failing check", nullptr, mistaken},
              {"a passing check", nullptr, student}}) {
          if (scale == 2.0f && !std::string(program).empty()) continue;  // checks at 1× and 3× (each runs a program)
          const ui::Rect shown = picture(what, mistake, program);
          INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << view << ", " << what << ": "
                            << shown.w << "x" << shown.h << " instead of " << plain.w << "x" << plain.h);
          CHECK(shown.w == plain.w);
          CHECK(shown.h == plain.h);
        }
      }
}

namespace {
// The panel's view and the verdict down to its next step (check_panel.h): the verdict's top in the view, and
// the next step too unless the two are taller than the view.
void check_next_step_in_sight(const char* where) {
  const ImGuiWindow* panel = ImGui::FindWindowByName("raycam###panel");
  REQUIRE(panel);
  const ImVec4 shown = ui::drawn_next_step_rect();
  const ImRect view = panel->InnerClipRect;
  INFO(where << ": the verdict and its next step at y " << shown.y << " - " << shown.w << ", the panel shows y "
             << view.Min.y << " - " << view.Max.y);
  CHECK(shown.w > shown.y);  // drawn
  CHECK(shown.y >= view.Min.y - 0.5f);
  CHECK((shown.w <= view.Max.y + 0.5f || shown.w - shown.y > view.GetHeight()));
}
}  // namespace

// Issue 45: after an answer, the verdict's first lines and the next step (what the diagnosis says, else the
// clear button) are in the panel's view at every screen and scale, in both languages: in the page, whose
// answer file comes back while the mouse still rests on the panel where its button was (QA: at 1024×768 in
// English the verdict stayed below the fold and "Give the answer file…" cut; at 1280×800 in French the
// verdict was cut at the bottom), and on the desktop, where the program's verdict arrives by itself.
TEST_CASE("after an answer the verdict and its next step are in sight, in the page and the window, both languages",
          "[render][lecture][layout]") {
  const std::string mistaken = std::string(MISTAKEN_STUDENT) + " --mistake mirrored";
  const ScratchFolder folder("raycam-verdict");
  for (const Screen screen : kScreens)
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* language : {"en", "fr"})
        for (const bool page : {true, false}) {
          std::ostringstream where;
          where << screen.width << "x" << screen.height << " at " << scale << "x, " << language << ", "
                << (page ? "the page" : "the window");
          session::AppState state = lecture_state("3d", language);
          state.font_scale = scale;
          if (page) state.host = session::kPageHost;
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          if (!page) renderer.panels().check_command = mistaken;
          renderer.run_frame(state);
          open_every_section();
          renderer.run_frame(state);
          if (page) {  // the case out, the student's program run on it, its answer file back
            const ImGuiWindow* panel = ImGui::FindWindowByName("raycam###panel");
            REQUIRE(panel);
            renderer.move_mouse(panel->InnerClipRect.GetCenter().x, panel->InnerClipRect.GetCenter().y);
            renderer.run_frame(state);
            renderer.check().give_answer(answer_of(mistaken, renderer, state, folder.path));
          }
          until_verdict(renderer, state);
          REQUIRE(renderer.check().status() == "fail");
          check_next_step_in_sight(where.str().c_str());
        }
}

// Issue 45: with a classic mistake on, the page grades the case's camera (the case never carries the mistake)
// and the header says so plainly, naming the mistake the image shows: never a pass inside a red "MISTAKE ON"
// header (QA: "✓ réussie | ERREUR ACTIVE : image en miroir").
TEST_CASE("with a mistake on, the header says the verdict is the downloaded case's and the image shows the mistake",
          "[render][layout][check]") {
  const ScratchFolder folder("raycam-graded");
  for (const char* language : {"en", "fr"})
    for (const bool right : {true, false}) {
      session::AppState state = lecture_state("3d", language);
      state.host = session::kPageHost;
      headless::HeadlessRenderer renderer(1920, 1080);
      renderer.run_frame(state);
      const std::string program = right ? std::string(EXAMPLE_STUDENT_CPP) : std::string(MISTAKEN_STUDENT) + " --mistake mirrored";
      const std::string answer = answer_of(program, renderer, state, folder.path);
      session::show_mistake(state, *session::find_lesson("mirrored"));
      renderer.check().give_answer(answer);
      until_verdict(renderer, state);
      const std::string& title = renderer.layout().image_title;
      INFO(language << (right ? ", the right answer" : ", a mirrored answer") << ": header '" << title << "'");
      REQUIRE(renderer.check().status() == (right ? "pass" : "fail"));
      const bool french = std::string(language) == "fr";
      CHECK(title.find(french ? "ERREUR ACTIVE" : "MISTAKE ON") == std::string::npos);
      // The header's line as wide as the image (its longest form: in the tooltip, and in the header where wide).
      CHECK(title.find(french ? "cas" : "case") != std::string::npos);
      CHECK(title.find(french ? "l'image montre « image en miroir »" : "the image shows « mirrored image »") != std::string::npos);
      CHECK(title.find(right ? (french ? "réussi" : "passed") : (french ? "faux" : "wrong")) != std::string::npos);
      const session::CheckHeader header =
          session::check_header(french ? Language::fr : Language::en, renderer.check().progress(), session::mistakes_on(state), true);
      CHECK(header.forms.front().find(french ? (right ? "réussie pour le cas téléchargé — l'image affichée montre l'erreur « image en miroir »"
                                                      : "faux pour le cas téléchargé — l'image affichée montre l'erreur « image en miroir »")
                                             : (right ? "passed for the downloaded case — the image shown shows the mistake « mirrored image »"
                                                      : "wrong for the downloaded case — the image shown shows the mistake « mirrored image »")) !=
            std::string::npos);
    }
}

// Issue 45: one wrong pixel can be found: the verdict names it as (row, column) of the answer's ids, and the
// image frames it in black and white, one of which stands out on whatever lies under it (QA: its red tint
// vanished on a red sphere). The wrong pixel is put on a sphere, in both languages.
TEST_CASE("a wrong pixel is named as (row, column) and framed in colours that stand out from it",
          "[render][layout][check]") {
  const ScratchFolder folder("raycam-wrong-pixel");
  for (const char* language : {"en", "fr"}) {
    session::AppState state = lecture_state("3d", language);
    state.host = session::kPageHost;
    headless::HeadlessRenderer renderer(1280, 800);
    renderer.run_frame(state);
    const check::CaseImage right = check::render_case(renderer.check().case_for_download(state));
    // A pixel on an object, away from the edges: its id changed to the background's (the corner's).
    int row = right.rows / 2, column = -1;
    for (int c = right.columns / 3; c < right.columns && column < 0; ++c)
      if (right.ids[std::size_t(row * right.columns + c)] != right.ids[0]) column = c + 2;
    REQUIRE(column > 0);
    check::Answer answer;
    answer.rows = right.rows;
    answer.columns = right.columns;
    answer.ids = right.ids;
    answer.ids[std::size_t(row * right.columns + column)] = right.ids[0];
    const std::string path = folder.path + "/one-wrong.json";
    std::ofstream(path) << check::answer_to_json(answer, right.dimension);
    renderer.check().give_answer(path);
    until_verdict(renderer, state);
    REQUIRE(renderer.check().status() == "fail");
    REQUIRE(renderer.check().wrong_pixels() == 1);
    // Named: the pixel changed, as the answer's own comparison finds it.
    const auto verdict = renderer.check().progress().latest;
    CHECK(session::wrong_pixels_named(verdict->verdict) ==
          "(" + std::to_string(row) + ", " + std::to_string(column) + ")");
    // Framed: around the pixel's place on screen, a near-black and a near-white ring, and the pixel itself
    // neither (a frame of its own colour would not stand out).
    const gl::RgbaImage shot = renderer.render_settled(state, 3);
    const ui::Rect image = renderer.layout().image;
    const float cw = image.w / float(right.columns), ch = image.h / float(right.rows);
    const int cx = int(image.x + (column + 0.5f) * cw), cy = int(image.y + (row + 0.5f) * ch);
    bool black = false, white = false;
    for (int dx = 0; dx < int(cw) + 12; ++dx) {
      const std::uint8_t* p = shot.at(cx + dx, cy);
      black = black || (p[0] < 40 && p[1] < 40 && p[2] < 40);
      white = white || (p[0] > 215 && p[1] > 215 && p[2] > 215);
    }
    const std::uint8_t* under = shot.at(cx, cy);
    const int black_distance = under[0] + under[1] + under[2], white_distance = 3 * 255 - black_distance;
    INFO(language << ": pixel (" << row << ", " << column << ") at " << cx << "," << cy << " shows " << int(under[0]) << ","
                  << int(under[1]) << "," << int(under[2]));
    CHECK(black);
    CHECK(white);
    CHECK(std::max(black_distance, white_distance) > 300);  // one of the two frames stands out strongly
  }
}

// Issue 45: the diagnosis's bullets have a heading saying what they are, and an answer of the wrong size is not
// told "no classic mistake reproduces this image" (no image of that size was compared), in both languages.
TEST_CASE("the diagnosis has a heading and a bad-size answer is not said to be no classic mistake",
          "[render][layout][check]") {
  const ScratchFolder folder("raycam-diagnosis");
  for (const char* language : {"en", "fr"})
    for (const bool bad_size : {true, false}) {
      session::AppState state = lecture_state("3d", language);
      state.host = session::kPageHost;
      headless::HeadlessRenderer renderer(1920, 1080);
      renderer.run_frame(state);
      open_every_section();
      const std::string bad_answer = folder.path + "/bad-size.json";
      if (bad_size) std::ofstream(bad_answer) << "{\"ids\": [[0, 1, 2], [0, 1, 2]]}\n";
      renderer.check().give_answer(bad_size ? bad_answer
                                            : answer_of(std::string(MISTAKEN_STUDENT) + " --mistake mirrored", renderer, state, folder.path));
      until_verdict(renderer, state);
      const std::vector<std::string> lines = ui::drawn_diagnosis_lines();
      std::string said;
      for (const std::string& line : lines) said += "\n  " + line;
      INFO(language << (bad_size ? ", a bad-size answer" : ", a mirrored answer") << " (" << renderer.check().status()
                    << "), under the verdict:" << said);
      const bool french = std::string(language) == "fr";
      const std::string none = french ? "aucune erreur classique" : "no classic mistake";
      const std::string heading = french ? "Erreurs classiques qui donnent cette même image :" : "Classic mistakes that make this same image:";
      if (bad_size) {
        CHECK(renderer.check().status() == "bad-output");
        CHECK(said.find(none) == std::string::npos);
      } else {
        REQUIRE(renderer.check().status() == "fail");
        REQUIRE(lines.size() >= 2);
        CHECK(lines[0] == heading);
        CHECK(lines[1].find(french ? "image en miroir" : "mirrored image") == 0);
      }
    }
}

// Issue 45: the camera's sliders read as one column, their labels all beside them or all above (QA at 2× on
// 1024×768: θ's label sat beside its slider while the others sat above theirs): the same step from one
// slider to the next, at every screen and scale, in both languages and both views.
TEST_CASE("the camera's slider labels are all beside or all above their sliders", "[render][lecture][layout]") {
  for (const Screen screen : kScreens)
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* language : {"en", "fr"})
        for (const char* view : {"2d", "3d"}) {
          session::AppState state = lecture_state(view, language);
          state.font_scale = scale;
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          ui::WidgetRects rects;
          renderer.panels().widget_rects = &rects;
          renderer.render_settled(state, 3);
          renderer.panels().widget_rects = nullptr;
          std::vector<const char*> ids = {"###df", "###d", "###theta"};
          if (std::string(view) == "3d") ids.push_back("###phi");
          std::ostringstream steps;
          std::vector<float> step;
          for (std::size_t i = 1; i < ids.size(); ++i) {
            REQUIRE(rects.count(ids[i]) == 1);
            step.push_back(rects.at(ids[i]).y0 - rects.at(ids[i - 1]).y0);
            steps << " " << ids[i - 1] << "→" << ids[i] << " " << step.back();
          }
          INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << language << ", " << view << ":" << steps.str());
          // A step of more than one and a half sliders holds a label line above the slider (two where a long
          // label wraps): all steps of one kind.
          const float frame = rects.at("###d").y1 - rects.at("###d").y0;
          for (const float s : step) CHECK((s > 1.5f * frame) == (step.front() > 1.5f * frame));
        }
}

// The verdict's scroll never moves the panel under the mouse (QA: with automatic checks on, every Open brought
// a verdict that scrolled the panel, and the next click landed on another control): while the mouse is over
// the panel the verdict waits below the fold; once the mouse leaves, it is scrolled into sight.
TEST_CASE("a verdict arriving while the mouse is over the panel waits for it to leave before scrolling",
          "[render][lecture][layout]") {
  const std::string mistaken = std::string(MISTAKEN_STUDENT) + " --mistake mirrored";
  session::AppState state = lecture_state("3d", "fr");
  state.font_scale = 3.0f;
  headless::HeadlessRenderer renderer(1280, 800);
  renderer.panels().check_command = mistaken;
  renderer.run_frame(state);
  open_every_section();
  const ImGuiWindow* panel = ImGui::FindWindowByName("raycam###panel");
  REQUIRE(panel);
  const ImVec2 over_panel{panel->InnerClipRect.Min.x + 20, panel->InnerClipRect.Min.y + 100};
  renderer.move_mouse(over_panel.x, over_panel.y);
  renderer.run_frame(state);
  const float scroll_before = panel->Scroll.y;
  until_verdict(renderer, state);
  REQUIRE(renderer.layout().image_title.find("faux") != std::string::npos);  // the verdict is in
  CHECK(panel->Scroll.y == scroll_before);                // the panel did not move under the mouse
  const ImVec4 waiting = ui::drawn_verdict_rect();
  CHECK(waiting.w > panel->InnerClipRect.Max.y);          // so the verdict is still below the fold
  // A click on a control in sight (QA: ImGui counts the panel as not hovered while a control it holds is
  // active, so the click itself let the scroll through and the text typed next went to the camera).
  ui::WidgetRects rects;
  renderer.panels().widget_rects = &rects;
  renderer.run_frame(state);
  renderer.panels().widget_rects = nullptr;
  const auto in_sight = std::find_if(rects.begin(), rects.end(), [&](const auto& entry) {
    const ui::WidgetRect& r = entry.second;
    return r.x0 > panel->InnerClipRect.Min.x && r.x1 < panel->InnerClipRect.Max.x &&  // in the panel, not a view's label
           r.y0 > panel->InnerClipRect.Min.y + 10 &&
           r.y1 < panel->InnerClipRect.Max.y - 10 && r.x1 - r.x0 > 20;
  });
  REQUIRE(in_sight != rects.end());
  INFO("clicking " << in_sight->first);
  const ImVec2 on_control{(in_sight->second.x0 + in_sight->second.x1) / 2, (in_sight->second.y0 + in_sight->second.y1) / 2};
  renderer.move_mouse(on_control.x, on_control.y);
  renderer.run_frame(state);
  for (bool down : {true, true, false}) {
    renderer.set_mouse_button(0, down);
    renderer.run_frame(state);
    CHECK(panel->Scroll.y == scroll_before);
  }
  renderer.move_mouse(-FLT_MAX, -FLT_MAX);                // the mouse leaves the window
  until_verdict(renderer, state);
  const ImVec4 shown = ui::drawn_verdict_rect();
  INFO("verdict at y " << shown.y << " - " << shown.w << ", the panel shows y " << panel->InnerClipRect.Min.y << " - "
                       << panel->InnerClipRect.Max.y);
  CHECK(shown.y >= panel->InnerClipRect.Min.y);
  CHECK(shown.w <= panel->InnerClipRect.Max.y + 0.5f);
}

namespace {
// The window rectangle ImGui gave a view this frame (title bar included), or an empty one.
ui::Rect window_rect(const char* name) {
  const ImGuiWindow* window = ImGui::FindWindowByName(name);
  if (!window || !window->WasActive) return {};
  return {window->Pos.x, window->Pos.y, window->Size.x, window->Size.y};
}

bool same_rect(const ui::Rect& a, const ui::Rect& b) { return a.x == b.x && a.y == b.y && a.w == b.w && a.h == b.h; }

// The pixels of `r` that differ between two frames (what a message drawn over a view would change).
int changed_pixels(const gl::RgbaImage& a, const gl::RgbaImage& b, const ui::Rect& r) {
  int changed = 0;
  for (int y = int(r.y); y < int(r.y + r.h); ++y)
    for (int x = int(r.x); x < int(r.x + r.w); ++x) {
      const std::uint8_t *p = a.at(x, y), *q = b.at(x, y);
      changed += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
    }
  return changed;
}
}  // namespace

// A message (a start-up file that does not open, a screenshot's confirmation) is read beside the views, never
// on them: each view's window, title bar included, has the same rectangle and the same pixels with the message
// on screen as without it (QA at 3× on 1280×800: the message box hid the observer's title and a third of the
// image), and the message is shown whole somewhere.
TEST_CASE("a message never takes a view's room: each view's rectangle and pixels are the same without it",
          "[render][lecture][layout][messages]") {
  int checked = 0;
  for (const Screen screen : {kScreens[0], kScreens[1], kScreens[2]})
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* language : {"fr", "en"})
        for (const char* view : {"2d", "3d"})
          for (const bool error : {true, false})
            for (const bool hidden : {false, true}) {  // the panel hidden (P): the status line says it
            if (hidden && scale != 3.0f) continue;     // the lecture's case

            session::AppOptions options;
            options.demo_on_bad_scene = true;  // as the app starts
            session::AppState state = session::make_app_state(flags::parse_app_options(
                {"no/such/folder/for/the/lecture/scene_file_that_does_not_open.json", "--view", view, "--lang",
                 language},
                options));
            REQUIRE(state.message_is_error);
            if (!error)  // a confirmation no section shows (as F12's), with a long path
              session::set_message(state, session::MessageSource::general, false,
                                   "wrote /home/instructor/lectures/chapter-3/raycam-screenshot-001.png");
            state.font_scale = scale;
            state.panel_hidden = hidden;
            headless::HeadlessRenderer renderer(screen.width, screen.height);
            const gl::RgbaImage with = renderer.render_settled(state, 3);
            const ui::FrameLayout shown = renderer.layout();
            const bool in_section = ui::message_shown_this_frame(state, state) || shown.message.w > 0;
            const ui::Rect views[] = {window_rect("###image"), window_rect("###overhead"), window_rect("###observer")};
            const std::string cut = everything_cut(shown);  // the message's frame: whole, and cutting nothing
            state.message.clear();
            const gl::RgbaImage without = renderer.render_settled(state, 3);
            const ui::FrameLayout plain = renderer.layout();
            INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << language << ", " << view
                              << (error ? ", an error" : ", a confirmation") << (hidden ? ", panel hidden" : ""));
            CHECK(in_section);  // the message was on screen
            INFO(cut);
            CHECK(cut.empty());
            CHECK(same_rect(shown.image, plain.image));
            CHECK(same_rect(shown.overhead, plain.overhead));
            CHECK(same_rect(shown.observer, plain.observer));
            int view_index = 0;
            for (const char* name : {"###image", "###overhead", "###observer"}) {
              const ui::Rect r = window_rect(name);
              CHECK(same_rect(r, views[view_index++]));
              INFO(name << " at " << r.x << "," << r.y << " " << r.w << "x" << r.h);
              if (r.w > 0) CHECK(changed_pixels(with, without, r) == 0);
            }
            ++checked;
          }
  CHECK(checked == 3 * 3 * 2 * 2 * 2 + 3 * 2 * 2 * 2);
}

namespace {
// The ground sphere's height in the observer view, in window pixels: every point of a sphere projects inside
// its silhouette, so the extent of its projected surface points is the silhouette's (clipped to the view).
float observer_ground_height(const ui::FrameLayout& layout, const Sphere& ground) {
  const ui::Rect& view = layout.observer;
  const session::ObserverCamera& observer = layout.observer_camera;
  double top = view.y + view.h, bottom = view.y;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j <= 32; ++j) {
      const double azimuth = 2 * glm::pi<double>() * i / 64, polar = glm::pi<double>() * j / 32;
      const glm::dvec3 p = ground.centre + ground.radius * glm::dvec3(std::sin(polar) * std::cos(azimuth),
                                                                      std::sin(polar) * std::sin(azimuth), std::cos(polar));
      const glm::vec4 clip = observer.projection * observer.view * glm::vec4(glm::vec3(p), 1.0f);
      const double y = view.y + (1.0 - clip.y / clip.w) * 0.5 * view.h;  // NDC y up, window y down
      top = std::min(top, std::max(y, double(view.y))), bottom = std::max(bottom, std::min(y, double(view.y + view.h)));
    }
  return float(std::max(0.0, bottom - top));
}
}  // namespace

// In a lecture the 3D construction is read from the back row: at 3× on a projector and a laptop, with the panel
// hidden (P), the observer view shows the default scene's ground sphere at least 15% of the window's height
// (QA: a 100 px strip with a 25 px ground). docs/app.md gives the figures this prints.
TEST_CASE("at 3x with the panel hidden, the observer's ground sphere is at least 15% of the window's height",
          "[render][lecture][layout][views]") {
  for (const Screen screen : {kScreens[0], kScreens[1]})
    for (const int mode : {0, 1, 2}) {  // the panel shown, hidden, shown with the observer maximised (3)
      const bool hidden = mode == 1;
      session::AppState state = lecture_state("3d", "fr");
      state.font_scale = 3.0f;
      state.panel_hidden = hidden;
      if (mode == 2) state.maximised = session::ShownView::observer;
      headless::HeadlessRenderer renderer(screen.width, screen.height);
      renderer.render_settled(state, 3);
      const auto& spheres = view3d(state).scene.spheres;
      const Sphere ground = *std::max_element(spheres.begin(), spheres.end(),
                                              [](const Sphere& a, const Sphere& b) { return a.radius < b.radius; });
      const float height = observer_ground_height(renderer.layout(), ground);
      const ui::Rect& view = renderer.layout().observer;
      WARN(screen.width << "x" << screen.height << " at 3x, panel " << (hidden ? "hidden" : "shown")
                        << (mode == 2 ? ", observer maximised" : "") << ": observer "
                        << view.w << "x" << view.h << " px, ground " << height << " px = "
                        << 100.0f * height / float(screen.height) << "% of the window's height; overhead "
                        << renderer.layout().overhead.w << "x" << renderer.layout().overhead.h << " px");
      if (mode == 0) continue;
      CHECK(height >= 0.15f * float(screen.height));
      if (mode == 2) continue;
      CHECK(renderer.layout().image.h >= 0.5f * float(screen.height));  // the image keeps half the window
      CHECK(renderer.layout().overhead.h >= 0.15f * float(screen.height));  // and the overhead view a usable height
    }
}

namespace {
const char* const kViewWindows[] = {"###image", "###overhead", "###observer"};

// Equal to within ImGui's rounding of a window to whole pixels.
bool rect_equals(const ui::Rect& a, const ui::Rect& b) {
  return std::abs(a.x - b.x) < 1.0f && std::abs(a.y - b.y) < 1.0f && std::abs(a.w - b.w) < 1.0f &&
         std::abs(a.h - b.h) < 1.0f;
}
}  // namespace

// In a lecture any one view can be shown as big as the views' room allows and then put back: its key (1 image,
// 2 overhead, 3 observer) or a double-click on its title bar makes its window the whole views' area, the others
// go; the same again gives every view its rectangle of before. 2D has no observer: 3 changes nothing there.
TEST_CASE("a view's key or a double-click on its title makes it fill the views' room, and back",
          "[render][lecture][layout][views]") {
  int checked = 0;
  for (const Screen screen : {kScreens[0], kScreens[1]})
    for (const float scale : {1.0f, 3.0f})
      for (const char* view : {"2d", "3d"})
        for (const bool hidden : {false, true})
          for (const bool double_click : {false, true}) {
            session::AppState state = lecture_state(view, "fr");
            state.font_scale = scale;
            state.panel_hidden = hidden;
            headless::HeadlessRenderer renderer(screen.width, screen.height);
            renderer.render_settled(state, 3);
            std::vector<ui::Rect> before;
            for (const char* name : kViewWindows) before.push_back(window_rect(name));
            const ui::Rect views = renderer.layout().views;
            for (int index = 0; index < 3; ++index) {
              INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << view
                                << (hidden ? ", panel hidden" : "") << (double_click ? ", double-click" : ", key")
                                << ": view " << kViewWindows[index]);
              const bool exists = before[std::size_t(index)].w > 0;
              auto toggle = [&] {
                if (double_click) {
                  if (!exists) return;
                  const ui::Rect title = window_rect(kViewWindows[index]);
                  renderer.move_mouse(title.x + 0.5f * title.w, title.y + 0.5f * ImGui::GetFrameHeight());
                  renderer.run_frame(state);
                  for (const bool down : {true, false, true, false}) {
                    renderer.set_mouse_button(0, down);
                    renderer.run_frame(state);
                  }
                  renderer.move_mouse(-FLT_MAX, -FLT_MAX);
                  for (int frame = 0; frame < 24; ++frame) renderer.run_frame(state);  // the next click, no double
                } else {
                  renderer.type_text(std::to_string(index + 1).c_str());
                }
                renderer.render_settled(state, 3);
              };
              toggle();
              for (int other = 0; other < 3; ++other) {
                const ui::Rect r = window_rect(kViewWindows[other]);
                INFO("then " << kViewWindows[other] << " at " << r.x << "," << r.y << " " << r.w << "x" << r.h
                             << ", the views' room " << views.x << "," << views.y << " " << views.w << "x" << views.h);
                if (!exists) CHECK(rect_equals(r, before[std::size_t(other)]));  // 3 in 2D: nothing moves
                else if (other == index) CHECK(rect_equals(r, views));
                else CHECK(r.w == 0.0f);  // not drawn
              }
              toggle();
              for (int other = 0; other < 3; ++other)
                CHECK(rect_equals(window_rect(kViewWindows[other]), before[std::size_t(other)]));
              ++checked;
            }
          }
  CHECK(checked == 2 * 2 * 2 * 2 * 2 * 3);
}

namespace {
// A mark on screen a label must leave in sight: a point of a camera's drawing, the target, a disc.
struct Mark {
  ImVec2 centre;
  float radius;
  std::string what;
};

void mark_line(std::vector<Mark>& marks, ImVec2 a, ImVec2 b, const std::string& what) {
  const int steps = std::max(1, int(std::hypot(b.x - a.x, b.y - a.y) / 2.0f));
  for (int i = 0; i <= steps; ++i)
    marks.push_back({{a.x + (b.x - a.x) * i / steps, a.y + (b.y - a.y) * i / steps}, 1.5f, what});
}

// What the overhead view draws that its labels must not cover, computed from the state: each camera's screen
// and eye (the final one; the construction's, its axes too, in 3D), the target's cross, and in 2D every disc.
std::vector<Mark> overhead_content(const session::AppState& state, const ui::OverheadMapping& m) {
  std::vector<Mark> marks;
  auto to_screen = [&](auto p) { return m.to_screen(glm::dvec2(p.x, p.y)); };
  auto camera = [&](const auto& world_from_camera, const std::string& what) {
    const auto corners = screen_corners_of(world_from_camera);
    for (std::size_t i = 0; i < corners.size(); ++i)
      if (corners.size() > 2 || i == 0)
        mark_line(marks, to_screen(corners[i]), to_screen(corners[(i + 1) % corners.size()]), what + "'s screen");
    marks.push_back({to_screen(eye_of(world_from_camera)), 5.0f, what + "'s eye"});
  };
  const bool constructing = state.construction_step >= 0;
  std::visit(session::overloaded{[&](const session::View2D& view) {
                          camera(view.camera.world_from_camera(), "the camera");
                          if (constructing)
                            camera(session::construction_pose(view.camera.placement(), state.construction_step, 1.0),
                                   "the construction's camera");
                          for (const Circle& c : view.scene.circles)
                            marks.push_back({to_screen(c.centre), float(c.radius) * m.scale, "a disc"});
                        },
                        [&](const session::View3D& view) {
                          camera(view.camera.world_from_camera(), "the camera");
                          if (!constructing) return;
                          const glm::dmat4 pose =
                              session::construction_pose(view.camera.placement(), state.construction_step, 1.0);
                          camera(pose, "the construction's camera");
                          for (const session::ConstructionSegment& s : session::construction_camera(pose, 1.5))
                            if (s.part != session::ConstructionPart::field_edge)
                              mark_line(marks, to_screen(s.from), to_screen(s.to), "the construction camera's axes");
                        }},
             state.view);
  marks.push_back({to_screen(session::active_target_xy(state)), 7.0f, "the target"});
  return marks;
}

bool rect_meets_mark(const ui::WidgetRect& r, const Mark& mark) {
  const float x = std::clamp(mark.centre.x, r.x0, r.x1), y = std::clamp(mark.centre.y, r.y0, r.y1);
  return std::hypot(x - mark.centre.x, y - mark.centre.y) < mark.radius;
}
bool rects_meet(const ui::WidgetRect& a, const ui::WidgetRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}
}  // namespace

// The overhead view's labels never lie on what they label (QA at 3×: the 3D side view's box over the canonical
// camera, the target and the "x" axis name; in 2D "k = 0" over the "y"): the side view with its title, the
// eye's height, "k = 0" and "column 0" cover no camera, no target, no axis name and in 2D no disc, over the
// construction's steps, every show-me and random cameras, at 1× to 3× on a projector and a laptop.
TEST_CASE("the overhead view's labels cover no camera, target, disc or axis name", "[render][lecture][layout]") {
  std::srand(3);
  auto uniform = [](double low, double high) { return low + (high - low) * double(std::rand()) / RAND_MAX; };
  int checked = 0, side_views = 0, k_labels = 0;
  for (const Screen screen : {kScreens[0], kScreens[1]})
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* view : {"2d", "3d"}) {
        const bool is_2d = std::string(view) == "2d";
        std::vector<std::function<void(session::AppState&)>> cases;
        for (int step = 0; step < (is_2d ? 3 : 5); ++step)
          cases.push_back([step](session::AppState& s) { s.construction_step = step; });
        for (const session::MistakeLesson& lesson : session::mistake_lessons())
          cases.push_back([&lesson](session::AppState& s) { session::show_mistake(s, lesson); });
        for (int trial = 0; trial < 4; ++trial) {
          const double theta = uniform(-3.1, 3.1), phi = uniform(0.2, 2.9), d = uniform(3.0, 20.0);
          const int step = trial % 2 ? int(uniform(0.0, is_2d ? 2.99 : 4.99)) : -1;
          cases.push_back([=](session::AppState& s) {
            session::active_orbit(s).theta = theta;
            session::active_orbit(s).d = d;
            if (auto* v = std::get_if<session::View3D>(&s.view)) v->orbit.phi = phi;
            s.construction_step = step;
            s.cameras_dirty = true;
          });
        }
        int index = 0;
        for (const auto& set_up : cases) {
          session::AppState state = lecture_state(view, "fr");
          state.font_scale = scale;
          set_up(state);
          if (dimension(state) != (is_2d ? 2 : 3)) continue;  // a show-me that goes to the other dimension
          ui::WidgetRects rects;
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          renderer.panels().widget_rects = &rects;
          renderer.render_settled(state, 3);
          const std::vector<Mark> marks = overhead_content(state, renderer.layout().overhead_mapping);
          for (const char* label : {"###label_side_view", "###label_eye_height", "###label_k0", "###label_column0"}) {
            if (!rects.count(label)) continue;
            const ui::WidgetRect r = rects.at(label);
            side_views += std::string(label) == "###label_side_view";
            k_labels += std::string(label) == "###label_k0";
            INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << view << ", case " << index
                              << " (step " << state.construction_step << "): " << label << " at " << r.x0 << ","
                              << r.y0 << " - " << r.x1 << "," << r.y1);
            for (const Mark& mark : marks) {
              if (!is_2d && mark.what == "a disc") continue;
              INFO("over " << mark.what << " at " << mark.centre.x << "," << mark.centre.y);
              CHECK_FALSE(rect_meets_mark(r, mark));
            }
            for (const char* name : {"###axis_x", "###axis_y"})
              if (rects.count(name)) {
                INFO("over the axis name " << name);
                CHECK_FALSE(rects_meet(r, rects.at(name)));
              }
            // The side view and its title take one corner: the title is broken and made smaller to the
            // frame's width (at least 160 px, its lines' narrowest), never one line running out across the
            // view. The frame is square and the title sits above it, so the box is no wider than it is tall.
            if (std::string(label) == "###label_side_view") CHECK(r.x1 - r.x0 <= std::max(r.y1 - r.y0, 160.0f) + 8.0f);
          }
          ++checked;
          ++index;
        }
      }
  CHECK(checked > 100);
  CHECK(side_views > 40);  // the 3D steps drew their side view
  CHECK(k_labels > 40);    // and the 2D screen its ends' labels
}

// Where to look after a show-me is read next to what the instructor just pressed: the orange "Look:" line
// right under the show-me button (after the explanation, it was two screens below at 3×), at 1× to 3×, on
// a projector and a laptop, for every show-me.
TEST_CASE("after a show-me, what to look at is right under its button", "[render][lecture][layout]") {
  int checked = 0;
  for (const Screen screen : {kScreens[0], kScreens[1]})
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const session::MistakeLesson& lesson : session::mistake_lessons()) {
        if (!lesson.show_me) continue;
        session::AppState state = lecture_state("3d", "fr");
        state.font_scale = scale;
        session::show_mistake(state, lesson);
        ui::WidgetRects rects;
        headless::HeadlessRenderer renderer(screen.width, screen.height);
        renderer.panels().widget_rects = &rects;
        renderer.run_frame(state);
        open_every_section();
        renderer.render_settled(state, 3);
        INFO(screen.width << "x" << screen.height << " at " << scale << "x, show me: " << lesson.id);
        const std::string button = std::string("###show_me/") + lesson.id;
        REQUIRE(rects.count(button) == 1);
        REQUIRE(rects.count("###look_at") == 1);
        const float gap = rects.at("###look_at").y0 - rects.at(button).y1;
        INFO("the line starts " << gap << " px under the button");
        CHECK(gap >= 0.0f);
        CHECK(gap <= ImGui::GetFrameHeightWithSpacing());  // the button's row is a checkbox's: at most a line
        ++checked;
      }
  CHECK(checked >= 2 * 3 * 5);
}

// The construction's M_d table is read at the panel's font at every scale (a 4×4 at 3× was drawn at about
// half of it to fit the panel's width: its last column now goes under the others instead).
TEST_CASE("M_d's table is drawn at the panel's font at 1x to 3x", "[render][lecture][layout]") {
  int checked = 0;
  for (const Screen screen : kScreens)
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* view : {"2d", "3d"}) {
        session::AppState state = lecture_state(view, "fr");
        state.font_scale = scale;
        state.construction_step = 2;
        ui::WidgetRects rects;
        headless::HeadlessRenderer renderer(screen.width, screen.height);
        renderer.panels().widget_rects = &rects;
        renderer.run_frame(state);
        open_every_section();
        renderer.render_settled(state, 3);
        REQUIRE(rects.count("###matrix/M") == 1);
        const ui::WidgetRect& table = rects.at("###matrix/M");
        const float font = table.x1 - table.x0;  // the hook's font size
        INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << view << ": the table's font "
                          << font << " px, the panel's " << ImGui::GetFontSize() << " px");
        CHECK(font >= ImGui::GetFontSize() - 0.5f);
        const std::string cut = everything_cut(renderer.layout());
        INFO(cut);
        CHECK(cut.empty());
        ++checked;
      }
  CHECK(checked == 18);
}

// The pinned pixel is marked as big as the font at least, drawn as thick as a tenth of it: a 3D pixel is a few
// screen pixels wide (its outline alone was 4 px at 3×).
TEST_CASE("the pinned pixel's marker is scaled with the font", "[render][lecture][layout]") {
  for (const Screen screen : {kScreens[0], kScreens[1]})
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* view : {"2d", "3d"}) {
        session::AppState state = lecture_state(view, "fr");  // --inspect 3,0: a pinned pixel
        state.font_scale = scale;
        ui::WidgetRects rects;
        headless::HeadlessRenderer renderer(screen.width, screen.height);
        renderer.panels().widget_rects = &rects;
        renderer.render_settled(state, 3);
        REQUIRE(rects.count("###pinned_marker") == 1);
        const ui::WidgetRect& marker = rects.at("###pinned_marker");
        INFO(screen.width << "x" << screen.height << " at " << scale << "x, " << view << ": marker "
                          << marker.x1 - marker.x0 << "x" << marker.y1 - marker.y0 << " px, font "
                          << ImGui::GetFontSize());
        CHECK(marker.x1 - marker.x0 >= ImGui::GetFontSize());
        CHECK(marker.y1 - marker.y0 >= ImGui::GetFontSize());
      }
}
