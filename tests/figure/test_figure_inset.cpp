// The inset of the final frame (2D (d), 3D step 5): on a scene much larger than the zoom on the camera, a
// framed overview shows every object, and its zoom rectangle holds the camera; on a small scene there is
// none; no label covers it; the TikZ that draws it compiles.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <random>
#include <stb_image.h>  // implementation provided by Debian's libstb (test_construction_figure.cpp)

#include "../scratch_dir.h"
#include "figure/construction_figure.h"
#include "figure/figure_files.h"
#include "figure/figure_layout.h"
#include "figure_test_support.h"

using namespace raycam;
using namespace raycam::figure;
using namespace raycam::figure_tests;

namespace {

bool holds(const Box& b, glm::dvec2 p) { return p.x >= b.left && p.x <= b.right && p.y >= b.top && p.y <= b.bottom; }

// The small test scene and a far object, 60 units away from a camera 5 units from its target.
Scene2D far_scene_2d() {
  Scene2D s = scene_2d();
  s.circles.push_back({{60.0, 40.0}, 3.0, {120, 60, 200}, "far"});
  return s;
}

Scene3D far_scene_3d() {
  Scene3D s = scene_3d();
  s.spheres.push_back({{60.0, 40.0, 5.0}, 3.0, {120, 60, 200}, "far"});
  return s;
}

// 2000 small objects spread over 400 × 400 units around the target.
Scene2D crowd_2d() {
  Scene2D s;
  std::mt19937 random(36);
  std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
  for (int i = 0; i < 2000; ++i)
    s.circles.push_back({{2.0 + coordinate(random), -1.0 + coordinate(random)}, 0.5, {200, 100, 50}, ""});
  return s;
}

Camera3D camera_3d() {
  Orbit3D orbit;
  orbit.target = {0.5, 0.2, 0.0};
  orbit.d = 6.0;
  orbit.theta = 0.6;
  orbit.phi = 1.1;
  orbit.df = 1.5;
  return Camera3D(32, 24, orbit);
}

// The inset of the final frame shows every object's centre (through the inset's own transform), and its
// zoom rectangle holds the camera's eye; no label covers it.
void require_inset_of_the_whole_scene(const Figure& figure, const std::string& what) {
  INFO(what);
  const int last = int(figure.frames.size()) - 1;
  const Frame& frame = figure.frames[std::size_t(last)];
  const PageFrame page = lay_out_frame(figure, last, FigureOutput{});
  REQUIRE(page.inset.shown());
  const PageInset& inset = page.inset;
  CHECK(holds(page.area, {inset.box.left, inset.box.top}));
  CHECK(holds(page.area, {inset.box.right, inset.box.bottom}));
  int outside = 0;
  for (const Disc& disc : frame.objects) outside += !holds(inset.box, inset.to_inset(disc.centre));
  CHECK(outside == 0);
  CHECK(inset.discs.size() == frame.objects.size());
  for (const Marker& m : frame.markers)
    if (m.point == Point::eye || m.point == Point::target) {
      INFO("point " << int(m.point));
      CHECK(holds(inset.zoom, inset.to_inset(m.at)));
    }
  for (const PlacedText& label : page.labels) {
    INFO("label '" << label.markup << "'");
    CHECK(overlap_area(label.box, inset.box) == 0.0);
  }
  for (int f = 0; f < last; ++f) CHECK_FALSE(lay_out_frame(figure, f, FigureOutput{}).inset.shown());
}

}  // namespace

TEST_CASE("on a large scene the final frame has an inset of the whole scene holding the camera", "[figure]") {
  for (const Camera2D& camera : cameras_2d()) {
    require_inset_of_the_whole_scene(construction_figure_2d(far_scene_2d(), camera, {}), "far object, 2D");
    require_inset_of_the_whole_scene(construction_figure_2d(crowd_2d(), camera, {}), "2000 objects, 2D");
  }
  require_inset_of_the_whole_scene(construction_figure_3d(far_scene_3d(), camera_3d(), {}), "far object, 3D");
}

TEST_CASE("on a small scene no frame has an inset", "[figure]") {
  for (const Camera2D& camera : cameras_2d()) {
    const Figure figure = construction_figure_2d(scene_2d(), camera, {});
    for (int f = 0; f < int(figure.frames.size()); ++f) CHECK_FALSE(lay_out_frame(figure, f, FigureOutput{}).inset.shown());
  }
  const Figure figure = construction_figure_3d(scene_3d(), camera_3d(), {});
  for (int f = 0; f < int(figure.frames.size()); ++f) CHECK_FALSE(lay_out_frame(figure, f, FigureOutput{}).inset.shown());
}

TEST_CASE("the TikZ of a frame with an inset compiles with pdflatex and draws the inset", "[figure]") {
  const test::ScratchDir scratch("figure-inset-tikz");
  FigureOutput output;
  output.format = Format::tikz;
  output.standalone = true;
  const Figure figures[] = {construction_figure_2d(far_scene_2d(), cameras_2d()[0], {}),
                            construction_figure_3d(far_scene_3d(), camera_3d(), {})};
  for (const Figure& figure : figures) {
    const int last = int(figure.frames.size()) - 1;
    REQUIRE(lay_out_frame(figure, last, output).inset.shown());
    write_figure(figure, {last}, output, scratch.path("inset.tex"));
    const std::string tex = read_text(scratch.path("inset.tex"));
    CHECK(tex.find("fill={rgb,255:red,245;green,245;blue,237}") != std::string::npos);  // the inset's box
    const std::string compile = "cd '" + scratch.dir.string() +
                                "' && pdflatex -interaction=nonstopmode -halt-on-error inset.tex > /dev/null 2>&1";
    CHECK(std::system(compile.c_str()) == 0);
  }
}

TEST_CASE("the PNG paints the inset's light box where the layout puts it", "[figure]") {
  const test::ScratchDir scratch("figure-inset-png");
  FigureOutput output;
  output.format = Format::png;
  output.page = page_in_mm(160.0, 120.0, 72.0);  // 1 px a point
  const Figure figure = construction_figure_2d(far_scene_2d(), cameras_2d()[0], {});
  const PageFrame page = lay_out_frame(figure, 3, output);
  REQUIRE(page.inset.shown());
  const auto written = write_figure(figure, {3}, output, scratch.path("inset.png"));
  REQUIRE(written.files.size() == 1);
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(written.files[0].c_str(), &width, &height, &channels, 3);
  REQUIRE(pixels != nullptr);
  const auto light = [&](int x, int y) {
    const unsigned char* p = pixels + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
    return std::abs(p[0] - int(255 * kInsetBackground[0] + 0.5)) <= 2 && std::abs(p[1] - int(255 * kInsetBackground[1] + 0.5)) <= 2 &&
           std::abs(p[2] - int(255 * kInsetBackground[2] + 0.5)) <= 2;
  };
  int in_box = 0, elsewhere = 0, box_pixels = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool in = holds(page.inset.box, {x + 0.5, y + 0.5});
      box_pixels += in;
      (in ? in_box : elsewhere) += light(x, y);
    }
  stbi_image_free(pixels);
  CHECK(in_box > box_pixels / 2);  // the objects, the screen and the zoom rectangle cover the rest
  CHECK(elsewhere == 0);
}
