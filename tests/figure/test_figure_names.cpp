// A name by its own object, at any size (issue 48): in the placed frame (2D (d), 3D step 5) every named object
// in view is named once, and each name's box lies on no other object (disc, camera, cross, label, leader) and
// nearer to its own object than to any other; a name that has no such place hangs on a leader from a free
// place, ending in a dot on its object, crossing no other object. Checked on the pure layout (no pixels) for
// the demo scenes (scenes/classic2d.json, classic3d.json) with their cameras, the docs' example and seeded
// random cameras, at sizes from 60 × 45 mm to 200 × 150 mm, in English and French. A name with no place in
// the drawing goes to a key beside it; with no room for the key, the page is refused and a bigger one of the
// same shape names them all. Both writers draw the leaders' dots and the key.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <random>
#include <sstream>

#include "../scratch_dir.h"
#include "figure/construction_figure.h"
#include "figure/figure_files.h"
#include "figure/figure_layout.h"
#include "figure_test_support.h"
#include "figure/math_text.h"
#include "raycam/demo_names.h"
#include "figure/tikz_file.h"

using namespace raycam;
using namespace raycam::figure;

namespace {

// ---- geometry on the page ------------------------------------------------------------------------------

double box_to_point(const Box& b, glm::dvec2 p) {
  return glm::length(p - glm::dvec2(std::clamp(p.x, b.left, b.right), std::clamp(p.y, b.top, b.bottom)));
}

// The gap between a box and a disc (0 when they meet).
double box_to_disc(const Box& b, const PageDisc& d) { return std::max(0.0, box_to_point(b, d.centre) - d.radius); }

// The length of segment a-b inside the box (Liang–Barsky).
double length_inside(glm::dvec2 a, glm::dvec2 b, const Box& box) {
  double t0 = 0.0, t1 = 1.0;
  const glm::dvec2 d = b - a;
  const double p[] = {-d.x, d.x, -d.y, d.y};
  const double q[] = {a.x - box.left, box.right - a.x, a.y - box.top, box.bottom - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return 0.0;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return 0.0;
  }
  return (t1 - t0) * glm::length(d);
}

double segment_to_point(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const glm::dvec2 d = b - a;
  const double t = glm::dot(d, d) > 0.0 ? std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
  return glm::length(a + t * d - p);
}

bool segments_cross(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
  auto side = [](glm::dvec2 o, glm::dvec2 p, glm::dvec2 q) {
    const glm::dvec2 u = p - o, v = q - o;
    return u.x * v.y - u.y * v.x;
  };
  return side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0;
}

glm::dvec2 leader_end(const PlacedText& label) {
  return {std::clamp(label.anchor.x, label.box.left, label.box.right),
          std::clamp(label.anchor.y, label.box.top, label.box.bottom)};
}

bool camera_stroke(Stroke s) { return s == Stroke::camera || s == Stroke::arrow || s == Stroke::tick; }

// ---- the cases ------------------------------------------------------------------------------------------

struct Case {
  std::string what;
  Figure figure;
  FigureOutput output;
};

constexpr double kMinShare = kLeastDrawingShare;

// As an instructor would make it fit: the title and the caption left out where they leave the drawing too
// little room (the command refuses those pages), then the matrix.
FigureOutput output_for(const Figure& figure, double w, double h) {
  FigureOutput output;
  output.page = page_in_mm(w, h);
  if (room_for_drawing_pt(figure, output) < kMinShare * output.page.height_pt) output.title = output.caption = false;
  if (room_for_drawing_pt(figure, output) < kMinShare * output.page.height_pt) output.matrix = false;
  return output;
}

template <class Scene>
Scene named_in(Scene scene, Language language) {
  for (auto& object : objects_of(scene)) object.name = demo_object_name(language, object.name);
  return scene;
}

std::vector<Case> cases() {
  const double kSizes[][2] = {{60, 45}, {70, 52.5}, {80, 60}, {100, 75}, {120, 90}, {160, 120}, {200, 150}};
  std::vector<std::pair<std::string, Figure>> figures;
  for (Language language : {Language::en, Language::fr}) {
    const std::string lang = language == Language::en ? "en" : "fr";
    const Scene2D scene2 = named_in(demo_scene_2d(), language);
    const Scene3D scene3 = named_in(demo_scene_3d(), language);
    Orbit2D classic2;  // scenes/classic2d.json's camera
    classic2.theta = glm::radians(70.0);
    figures.push_back({"classic2d " + lang, construction_figure_2d(scene2, Camera2D(256, classic2), {language})});
    Orbit2D docs;  // docs/figures.md: --mode 2d --theta 30 --df 2
    docs.theta = glm::radians(30.0);
    docs.df = 2.0;
    figures.push_back({"docs' example " + lang, construction_figure_2d(scene2, Camera2D(256, docs), {language})});
    figures.push_back({"classic3d " + lang, construction_figure_3d(scene3, Camera3D(256, 256, Orbit3D{}), {language})});
    std::mt19937 random(48);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 6; ++i) {
      Orbit2D orbit;
      orbit.target = {4.0 * unit(random) - 2.0, 4.0 * unit(random) - 2.0};
      orbit.d = 3.0 + 9.0 * unit(random);
      orbit.theta = glm::two_pi<double>() * unit(random);
      orbit.df = 0.8 + 2.2 * unit(random);
      figures.push_back({"2D camera " + std::to_string(i) + " " + lang,
                         construction_figure_2d(scene2, Camera2D(256, orbit), {language})});
    }
    for (int i = 0; i < 6; ++i) {
      Orbit3D orbit;
      orbit.target = {3.0 * unit(random) - 1.5, 3.0 * unit(random) - 1.5, 2.0 * unit(random) - 1.0};
      orbit.d = 5.0 + 9.0 * unit(random);
      orbit.theta = glm::two_pi<double>() * unit(random);
      orbit.phi = 0.3 + (glm::pi<double>() - 0.6) * unit(random);
      orbit.df = 1.0 + 2.0 * unit(random);
      figures.push_back({"3D camera " + std::to_string(i) + " " + lang,
                         construction_figure_3d(scene3, Camera3D(64, 48, orbit), {language})});
    }
  }
  // Scenes of their own: five to eight objects of every size around the target, some overlapping.
  std::mt19937 random(4848);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const char* kNames[] = {"red", "green", "blue", "yellow", "cyan", "magenta", "orange", "grey"};
  for (int i = 0; i < 4; ++i) {
    const int count = 5 + int(4.0 * unit(random));
    Orbit2D orbit2;
    orbit2.theta = glm::two_pi<double>() * unit(random);
    Scene2D scene2;
    for (int k = 0; k < count; ++k)
      scene2.circles.push_back({{8.0 * unit(random) - 4.0, 8.0 * unit(random) - 4.0}, 0.1 + 0.9 * unit(random),
                                Rgb8{std::uint8_t(40 * k), 120, std::uint8_t(255 - 30 * k)}, kNames[k]});
    figures.push_back({"2D scene " + std::to_string(i), construction_figure_2d(scene2, Camera2D(128, orbit2), {})});
    Orbit3D orbit3;
    orbit3.theta = glm::two_pi<double>() * unit(random);
    Scene3D scene3;
    for (int k = 0; k < count; ++k)
      scene3.spheres.push_back({{6.0 * unit(random) - 3.0, 6.0 * unit(random) - 3.0, 6.0 * unit(random) - 3.0},
                                0.1 + 0.9 * unit(random), Rgb8{std::uint8_t(40 * k), 120, std::uint8_t(255 - 30 * k)},
                                kNames[k]});
    figures.push_back({"3D scene " + std::to_string(i), construction_figure_3d(scene3, Camera3D(64, 48, orbit3), {})});
  }
  std::vector<Case> all;
  for (const auto& [what, figure] : figures)
    for (const auto& size : kSizes) {
      std::ostringstream name;
      name << what << " at " << size[0] << "x" << size[1] << "mm";
      all.push_back({name.str(), figure, output_for(figure, size[0], size[1])});
    }
  return all;
}

// ---- the rules ------------------------------------------------------------------------------------------

constexpr double kReach = 1.0;  // font sizes: a name without a leader lies within this of its own object

struct Counts {
  int by_object = 0, on_leader = 0, keyed = 0, refused = 0;
};

// What is wrong with the names of the case's placed frame, one line per bad name added to `bad`; a refused
// page is checked again at the size the refusal offers.
void bad_names(const Case& c, Counts& counts, std::vector<std::string>& bad) {
  const Frame& frame = c.figure.frames.back();
  const PageFrame page = lay_out_frame(c.figure, int(c.figure.frames.size()) - 1, c.output);
  if (!page.names_fit) {  // refused: then a bigger page of the same shape names them all
    ++counts.refused;
    const std::vector<int> placed{int(c.figure.frames.size()) - 1};
    FigureOutput bigger = c.output;
    bigger.page = smallest_page_for_names(c.figure, placed, c.output, 72.0 / 25.4, 2000.0 * 72.0 / 25.4);
    if (!(bigger.page.width_pt > c.output.page.width_pt) || !names_fit(c.figure, placed, bigger))
      bad.push_back(c.what + ": refused, and no bigger page found");
    else
      bad_names({c.what + " made bigger", c.figure, bigger}, counts, bad);
    return;
  }
  // The objects as drawn, and their names.
  std::vector<PageDisc> discs;
  std::vector<std::string> names;
  for (const Disc& disc : frame.objects) {
    discs.push_back({page.to_page(disc.centre), page.to_page.scale * disc.radius, disc.colour, {}});
    names.push_back(escape_markup(disc.name));
  }
  const Box& area = page.area;
  for (std::size_t i = 0; i < discs.size(); ++i) {
    if (names[i].empty()) continue;
    const PageDisc& own = discs[i];
    const bool in_view = own.centre.x > area.left && own.centre.x < area.right && own.centre.y > area.top &&
                         own.centre.y < area.bottom;
    const PlacedText* name = nullptr;
    for (const PlacedText& label : page.labels)
      if (label.markup == names[i]) name = &label;
    const std::string who = c.what + ": '" + names[i] + "'";
    const KeyEntry* keyed = nullptr;
    for (const KeyEntry& entry : page.key)
      if (entry.text.markup == names[i]) keyed = &entry;
    if (keyed) {
      ++counts.keyed;
      if (name) bad.push_back(who + " is both in the drawing and in the key");
      std::string why;
      const Box& box = keyed->text.box;
      if (box.left < area.right || box.right > c.output.page.width_pt || box.top < area.top || box.bottom > area.bottom)
        why += " lies off the key's column beside the drawing";
      if (keyed->colour.r != frame.objects[i].colour.r || keyed->colour.g != frame.objects[i].colour.g ||
          keyed->colour.b != frame.objects[i].colour.b)
        why += " has another object's colour";
      for (const KeyEntry& other : page.key)
        if (&other != keyed && overlap_area(other.text.box, box) > 0.0) why += " lies on '" + other.text.markup + "'";
      if (!why.empty()) bad.push_back(who + " in the key" + why);
      continue;
    }
    if (!name) {
      if (in_view) bad.push_back(who + " is missing");
      continue;
    }
    ++(name->leader ? counts.on_leader : counts.by_object);
    if (name->leader && !name->dot) bad.push_back(who + " has a leader without a dot");
    std::string why;
    const Box& box = name->box;
    for (std::size_t j = 0; j < discs.size(); ++j)
      if (j != i && box_to_disc(box, discs[j]) <= 0.0) why += " lies on '" + names[j] + "'";
    for (const Segment& s : page.segments)
      if (camera_stroke(s.stroke) && length_inside(s.from, s.to, box) > 0.0) why += " lies on the camera";
    for (const PageMarker& m : page.markers)
      if (length_inside(m.at - glm::dvec2(page.arm, 0.0), m.at + glm::dvec2(page.arm, 0.0), box) > 0.0 ||
          length_inside(m.at - glm::dvec2(0.0, page.arm), m.at + glm::dvec2(0.0, page.arm), box) > 0.0)
        why += " lies on a point's cross";
    for (const PlacedText& other : page.labels) {
      if (&other == name) continue;
      if (overlap_area(other.box, box) > 0.0) why += " lies on the label '" + other.markup + "'";
      if (other.leader && length_inside(other.anchor, leader_end(other), box) > 0.0)
        why += " lies on the leader of '" + other.markup + "'";
    }
    if (!name->leader) {
      const double mine = box_to_disc(box, own);
      if (mine > kReach * c.output.font_size_pt) why += " is far from its object";
      for (std::size_t j = 0; j < discs.size(); ++j)
        if (j != i && box_to_disc(box, discs[j]) <= mine) why += " is nearer to '" + names[j] + "'";
    } else {
      const glm::dvec2 dot = name->anchor, end = leader_end(*name);
      if (glm::length(dot - own.centre) > own.radius) why += ": its leader ends off its object";
      if (box_to_point(area, dot) > 0.0) why += ": its leader ends out of view";
      for (std::size_t j = 0; j < discs.size(); ++j)
        if (j != i && segment_to_point(dot, end, discs[j].centre) < discs[j].radius)
          why += ": its leader crosses '" + names[j] + "'";
      for (const PlacedText& other : page.labels) {
        if (&other == name) continue;
        if (length_inside(dot, end, other.box) > 0.0) why += ": its leader crosses the label '" + other.markup + "'";
        if (other.leader && segments_cross(dot, end, other.anchor, leader_end(other)))
          why += ": its leader crosses the leader of '" + other.markup + "'";
      }
    }
    if (!why.empty()) bad.push_back(who + why);
  }
}

}  // namespace

TEST_CASE("every name by its own object: on no other object, nearest its own, or on a leader to a dot, at "
          "60x45mm to 200x150mm, 2D and 3D, en and fr", "[figure][names]") {
  int figures = 0, bad_figures = 0, bad_count = 0;
  Counts counts;
  std::vector<std::string> all_bad;
  for (const Case& c : cases()) {
    ++figures;
    std::vector<std::string> bad;
    bad_names(c, counts, bad);
    bad_figures += !bad.empty();
    bad_count += int(bad.size());
    all_bad.insert(all_bad.end(), bad.begin(), bad.end());
  }
  std::ostringstream report;
  report << bad_count << " bad names over " << bad_figures << " of " << figures << " figures";
  for (std::size_t i = 0; i < all_bad.size() && i < 40; ++i) report << "\n  " << all_bad[i];
  INFO(report.str());
  std::printf("names: %d bad names over %d of %d figures; %d by their object, %d on a leader, %d in a key; %d "
              "figures refused\n", bad_count, bad_figures, figures, counts.by_object, counts.on_leader, counts.keyed,
              counts.refused);
  CHECK(bad_count == 0);
}

namespace {

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

// The same layout serves cairo and TikZ: a figure with leaders and a key draws a dot per leader in TikZ and
// the key's names as words in the PDF.
TEST_CASE("both writers draw the names' leaders with their dots and the key", "[figure][names]") {
  const test::ScratchDir scratch("figure-names");
  int leaders = 0, keys = 0;
  for (const Case& c : cases()) {
    const int placed = int(c.figure.frames.size()) - 1;
    const PageFrame page = lay_out_frame(c.figure, placed, c.output);
    if (!page.names_fit) continue;
    std::size_t dots = 0;
    for (const PlacedText& label : page.labels) dots += label.dot;
    if (dots == 0 && page.key.empty()) continue;
    if ((dots > 0 && leaders >= 3) || (!page.key.empty() && keys >= 3)) continue;
    leaders += dots > 0;
    keys += !page.key.empty();
    INFO(c.what);
    const std::string tikz = tikz_document(c.figure, {placed}, c.output);
    CHECK(occurrences(tikz, "\\filldraw[name dot]") == dots);
    CHECK(occurrences(tikz, "\\draw[name leader]") == dots);
    FigureOutput pdf = c.output;
    pdf.format = Format::pdf;
    write_figure(c.figure, {placed}, pdf, scratch.path("names.pdf"));
    const std::string words = figure_tests::run_output("pdftotext '" + scratch.path("names.pdf") + "' -");
    for (const KeyEntry& entry : page.key) {
      CHECK(occurrences(tikz, "{" + latex_of(entry.text.markup) + "}") >= 1);
      CHECK(words.find(entry.text.markup) != std::string::npos);
    }
  }
  CHECK(leaders == 3);
  CHECK(keys == 3);
}
