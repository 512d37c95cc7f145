// What the 2D overhead view says, drawn headless: each screen-end label beside the end it names, at every font
// scale, on both projector sizes, in both languages, after every show-me — its anchor computed here from the
// camera's own pixel positions (Camera2D::primary_ray, not the view's drawing code); and the 2D demo's
// construction steps, each a picture of its own.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "headless/headless_renderer.h"
#include "image_compare.h"
#include "session/mistake_lessons.h"
#include "raycam/transform.h"

using namespace raycam;

namespace {
struct Box {
  float x0, y0, x1, y1;
};
Box box_of(const ui::WidgetRect& r) { return {r.x0, r.y0, r.x1, r.y1}; }

// The distance from a point to a box (0 inside).
double distance(ImVec2 p, const Box& b) {
  const double dx = std::max({double(b.x0) - p.x, 0.0, double(p.x) - b.x1});
  const double dy = std::max({double(b.y0) - p.y, 0.0, double(p.y) - b.y1});
  return std::hypot(dx, dy);
}
bool overlap(const Box& a, const Box& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

// Everything wrong with the two labels of one drawn frame, as lines of text (empty: all true).
std::string label_faults(const session::AppState& state, const ui::FrameLayout& layout,
                         const ui::WidgetRects& rects) {
  std::string faults;
  const auto fault = [&](const std::string& what) { faults += "\n    " + what; };
  const auto k0 = rects.find("###label_k0"), column0 = rects.find("###label_column0");
  if (k0 == rects.end() || column0 == rects.end()) return "\n    a label was not drawn";
  const Camera2D& camera = session::view2d(state).camera;
  const ui::OverheadMapping& m = layout.overhead_mapping;
  // The anchors: pixel k = 0 and the bar's column 0 on the screen, P_k = M_d·P_k^0 (not the rays' origins:
  // under the eye_origin mistake every ray leaves from the eye).
  const auto on_screen = [&](int k) {
    return m.to_screen(transform_point(camera.world_from_camera(), camera.canonical_pixel(k)));
  };
  const ImVec2 at_k0 = on_screen(0), at_column0 = on_screen(camera.pixel_of_column(0));
  struct Label {
    const char* name;
    Box box;
    ImVec2 own, other;
  };
  const Label labels[] = {{"k = 0", box_of(k0->second), at_k0, at_column0},
                          {"column 0", box_of(column0->second), at_column0, at_k0}};
  for (const Label& label : labels) {
    const double line = label.box.y1 - label.box.y0;  // the label's own line height
    const double own = distance(label.own, label.box), other = distance(label.other, label.box);
    if (own > 3.0 * line + 4.0)  // the view's rings: 4 px, then half a line at a time
      fault(std::string(label.name) + ": " + std::to_string(own) + " px from its end (line " + std::to_string(line) + ")");
    if (!(own < other))
      fault(std::string(label.name) + ": nearer the other end (" + std::to_string(own) + " vs " + std::to_string(other) + " px)");
    const ui::Rect& view = layout.overhead;
    if (label.box.x0 < view.x || label.box.y0 < view.y || label.box.x1 > view.x + view.w || label.box.y1 > view.y + view.h)
      fault(std::string(label.name) + ": outside the view");
    for (const Circle& circle : session::view2d(state).scene.circles) {
      const ImVec2 c = m.to_screen(circle.centre);
      if (distance(c, label.box) < circle.radius * m.scale)
        fault(std::string(label.name) + ": on the disc of " + circle.name);
    }
  }
  if (overlap(labels[0].box, labels[1].box)) fault("the labels overlap");
  return faults;
}
}  // namespace

TEST_CASE("the 2D overhead labels sit beside the ends they name, off the discs and each other, at any scale",
          "[render][lecture][overhead]") {
  struct Screen {
    int width, height;
  };
  // The demo as it opens, at the old default θ = 90°, and after every 2D show-me (the camera moves).
  std::vector<std::pair<std::string, std::vector<std::string>>> setups = {{"demo", {}}, {"theta 90", {"--theta", "90"}}};
  for (const session::MistakeLesson& lesson : session::mistake_lessons())
    if (lesson.show_me && lesson.info && lesson.info->in_2d) setups.push_back({std::string("show me ") + lesson.id, {}});
  int checked = 0;
  std::string faults;
  for (const Screen screen : {Screen{1024, 768}, Screen{1280, 800}})
    for (const float scale : {1.0f, 2.0f, 3.0f})
      for (const char* language : {"fr", "en"})
        for (const auto& [name, extra] : setups) {
          std::vector<std::string> args = {"--view", "2d", "--lang", language};
          args.insert(args.end(), extra.begin(), extra.end());
          session::AppState state = session::make_app_state(flags::parse_app_options(args));
          state.font_scale = scale;
          if (name.rfind("show me ", 0) == 0) session::show_mistake(state, *session::find_lesson(name.substr(8).c_str()));
          if (session::dimension(state) != 2) continue;  // a show-me that goes to 3D
          ui::WidgetRects rects;
          headless::HeadlessRenderer renderer(screen.width, screen.height);
          renderer.panels().widget_rects = &rects;
          renderer.render_settled(state, 2);
          const gl::RgbaImage image = renderer.render_settled(state, 2);
          const std::string found = label_faults(state, renderer.layout(), rects);
          if (!found.empty()) {
            const std::string shot = "overhead-labels-" + std::to_string(screen.width) + "-" +
                                     std::to_string(int(scale)) + "-" + language + "-" + std::to_string(checked) + ".png";
            gl::write_png(image, shot);  // beside the build, as the reference screenshots' diffs
            faults += "\n  " + std::to_string(screen.width) + "x" + std::to_string(screen.height) + " at " +
                      std::to_string(scale) + "x, " + language + ", " + name + " (" + shot + "):" + found;
          }
          ++checked;
        }
  INFO(faults);
  CHECK(faults.empty());
  CHECK(checked >= 24);
}

// The demo's default camera: each construction step draws another picture of the overhead view (at θ = 90°
// the rotation R(θ − 90°) was the identity and step c drew step b again, pixel for pixel).
TEST_CASE("the 2D demo's construction steps draw pictures that differ pairwise", "[render][overhead]") {
  session::AppState state = session::make_app_state(flags::parse_app_options({"--view", "2d"}));
  headless::HeadlessRenderer renderer(1280, 800);
  std::vector<gl::RgbaImage> views;
  const int steps = session::construction_steps(state);
  for (int step = 0; step <= steps; ++step) {
    state.construction_step = step == steps ? -1 : step;
    const gl::RgbaImage frame = renderer.render_settled(state, 3);
    const ui::Rect& v = renderer.layout().overhead;
    gl::RgbaImage view;
    view.width = int(v.w);
    view.height = int(v.h);
    for (int y = 0; y < view.height; ++y)
      for (int x = 0; x < view.width; ++x) {
        const std::uint8_t* p = frame.at(int(v.x) + x, int(v.y) + y);
        view.pixels.insert(view.pixels.end(), p, p + 4);
      }
    views.push_back(view);
  }
  for (std::size_t a = 0; a < views.size(); ++a)
    for (std::size_t b = a + 1; b < views.size(); ++b) {
      const test::Difference d = test::compare(views[a], views[b], 8);
      INFO("steps " << a << " and " << b << ": " << d.differing << " of " << d.compared << " pixels differ");
      CHECK(d.differing >= 200);  // a visible change: more than a few glyphs' worth
    }
}
