// The construction figures are right: each frame's matrix is the product of the handout's factors so far (and
// the last one is the camera's M_d), the points drawn in the SVG are where the core puts them, the PDF holds
// the pages and the words of the language asked for, the PNG has the size asked for, and every object of a
// big scene is drawn.
#include <stb_image.h>  // implementation provided by Debian's libstb

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "../scratch_dir.h"
#include "figure_test_support.h"
#include "figure/construction_figure.h"
#include "figure/figure_files.h"
#include "raycam/ray_caster.h"
#include "raycam/transform.h"

using namespace raycam;
using namespace raycam::figure;
using namespace raycam::figure_tests;

namespace {

// Each "<path …>" element's stroke colour (the text inside "rgb(…)") and the first segment of its path data,
// "M x0 y0 L x1 y1 " (more follows). Parsed by hand: std::regex recurses once per character and overflows
// the stack on cairo's long glyph paths under the sanitizers.
struct SvgSegment {
  std::string stroke;
  glm::dvec2 from{0.0}, to{0.0};
};
std::vector<SvgSegment> segments_in_svg(const std::string& svg) {
  std::vector<SvgSegment> segments;
  for (std::size_t at = svg.find("<path "); at != std::string::npos; at = svg.find("<path ", at + 1)) {
    const std::string element = svg.substr(at, svg.find('>', at) - at);
    const std::size_t stroke = element.find("stroke:rgb("), data = element.find("d=\"M ");
    if (stroke == std::string::npos || data == std::string::npos) continue;
    SvgSegment segment;
    const std::size_t colour = stroke + std::string("stroke:rgb(").size();
    segment.stroke = element.substr(colour, element.find(')', colour) - colour);
    std::istringstream path(element.substr(data + 5));
    std::string line_to;
    if (path >> segment.from.x >> segment.from.y >> line_to >> segment.to.x >> segment.to.y && line_to == "L" &&
        path.peek() == ' ')
      segments.push_back(segment);
  }
  return segments;
}

// The crosses of the SVG by kind (figure_files.h: kind k stroked rgb(0, 0, k+1)): page position of each
// cross's centre, the middle of its horizontal arm "M x0 y L x1 y".
std::map<int, std::vector<glm::dvec2>> crosses_in_svg(const std::string& svg) {
  std::map<int, std::vector<glm::dvec2>> crosses;
  for (const SvgSegment& s : segments_in_svg(svg)) {
    if (s.stroke.rfind("0%,0%,", 0) != 0 || s.stroke.back() != '%') continue;
    const double blue = std::stod(s.stroke.substr(6)) / 100.0 * 255.0;
    const int kind = int(std::lround(blue)) - 1;
    if (kind < 0 || std::abs(blue - std::round(blue)) > 1e-3) continue;
    crosses[kind].push_back({0.5 * (s.from.x + s.to.x), s.from.y});
  }
  return crosses;
}

// What the core says each marked point of a frame is, in the plane the figure draws.
struct Expected {
  Point point;
  glm::dvec2 at;
};

void require_svg_points(const Figure& figure, int index, const std::vector<Expected>& expected,
                        const FigureOutput& output, const test::ScratchDir& scratch) {
  const std::string file = scratch.path("frame.svg");
  write_figure(figure, {index}, output, file);
  const auto crosses = crosses_in_svg(read_text(file));
  const PageTransform to_page = lay_out_frame(figure, index, output).to_page;
  for (const Expected& e : expected) {
    INFO("frame " << index << ", point kind " << int(e.point));
    REQUIRE(crosses.count(int(e.point)) == 1);
    REQUIRE(crosses.at(int(e.point)).size() == 1);
    const glm::dvec2 drawn = crosses.at(int(e.point))[0];
    CHECK(drawn.x == Approx(to_page.x(e.at.x)).margin(0.01));  // SVG numbers carry ~6 digits
    CHECK(drawn.y == Approx(to_page.y(e.at.y)).margin(0.01));
  }
}

}  // namespace

TEST_CASE("each 2D frame is the handout's factors so far, (c) and (d) the core's", "[figure]") {
  for (const Camera2D& camera : cameras_2d()) {
    const Placement2D& p = camera.placement();
    INFO("theta " << glm::degrees(camera.orbit().theta));
    // (a) the identity.
    CHECK(frame_matrix_2d(camera, 0) == glm::dmat3(1.0));
    // (b) H(1, d_f): u0 = (0, -1) is scaled to length d_f (the app's step 1, the core's construction_step(1)).
    const glm::dvec2 u_b = transform_vector(frame_matrix_2d(camera, 1), kCanonicalView2D);
    CHECK(u_b.x == Approx(0.0).margin(1e-12));
    CHECK(u_b.y == Approx(-camera.orbit().df));
    // The first rotation R(ψ0) turns u0 onto +x, the direction from which R(φ_v) measures v's angle: φ_v,
    // printed in (c)'s caption, is v's angle θ + π.
    const double phi_v = view_angle_phi_v(camera);
    CHECK(std::cos(phi_v) == Approx(std::cos(camera.orbit().theta + glm::pi<double>())).margin(1e-12));
    CHECK(std::sin(phi_v) == Approx(std::sin(camera.orbit().theta + glm::pi<double>())).margin(1e-12));
    // (c) the camera looks along v = PC/‖PC‖, and the product is the core's R(α)·H.
    const glm::dmat3 c = frame_matrix_2d(camera, 2);
    const glm::dvec2 v = glm::normalize(camera.orbit().target - camera.screen_centre());
    CHECK(glm::length(glm::normalize(transform_vector(c, kCanonicalView2D)) - v) < 1e-12);
    const glm::dmat3 core_c = construction_step(p, 2);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(c[i][j] == Approx(core_c[i][j]).margin(1e-12));
    // (d) M_d itself.
    const glm::dmat3 d = frame_matrix_2d(camera, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(d[i][j] == Approx(camera.world_from_camera()[i][j]).margin(1e-12));
    // The frames carry those matrices.
    const Figure figure = construction_figure_2d(scene_2d(), camera, {});
    REQUIRE(figure.frames.size() == 4);
    for (int f = 0; f < 4; ++f)
      for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col)
          CHECK(figure.frames[std::size_t(f)].matrix[std::size_t(r)][std::size_t(col)] ==
                frame_matrix_2d(camera, f)[col][r]);
  }
}

TEST_CASE("the 2D SVG draws E, the screen's ends, Ω or P and C where the core puts them", "[figure]") {
  const test::ScratchDir scratch("figure-svg2d");
  FigureOutput output;
  output.format = Format::svg;
  for (const Camera2D& camera : cameras_2d()) {
    const Figure figure = construction_figure_2d(scene_2d(), camera, {});
    for (int f = 0; f < kFrames2D; ++f) {
      const glm::dmat3 m = frame_matrix_2d(camera, f);
      const auto ends = screen_corners_of(m);
      std::vector<Expected> expected{{Point::eye, eye_of(m)},
                                     {Point::screen_first_end, ends[0]},
                                     {Point::screen_last_end, ends[1]},
                                     {Point::screen_centre, transform_point(m, glm::dvec2(0.0))},
                                     {Point::target, camera.orbit().target}};
      if (f == 3) {  // the placed camera: the core's own eye and screen centre P
        expected[0].at = camera.eye();
        expected[3].at = camera.screen_centre();
      }
      require_svg_points(figure, f, expected, output, scratch);
    }
  }
}

namespace {
// The figure's numbers against the core's: a plane point to 1e-9 of the frame's size.
bool near(glm::dvec2 a, glm::dvec2 b, double size) { return glm::length(a - b) <= 1e-9 * (1.0 + size); }

// The ray paths of an SVG (the ray stroke's colour, figure_files.cpp), as "M x0 y0 L x1 y1" page points.
std::vector<std::pair<glm::dvec2, glm::dvec2>> rays_in_svg(const std::string& svg) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> rays;
  for (const SvgSegment& s : segments_in_svg(svg))
    if (s.stroke == "80%,30%,5%") rays.push_back({s.from, s.to});
  return rays;
}
}  // namespace

TEST_CASE("every 2D frame's rays leave the core's pixels along its rays and stop at its hits, ticks at its pixels",
          "[figure]") {
  const test::ScratchDir scratch("figure-rays");
  std::mt19937 random(38);
  const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  const auto integer = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  for (int trial = 0; trial < 60; ++trial) {
    Orbit2D orbit;
    orbit.target = {uniform(-5.0, 5.0), uniform(-5.0, 5.0)};
    orbit.d = uniform(2.0, 10.0);
    orbit.theta = uniform(-glm::pi<double>(), glm::pi<double>());
    orbit.df = uniform(0.3, 3.0);
    const int n = integer(2, 140);
    const Camera2D camera(n, orbit);
    Scene2D scene;  // circles around the target: some rays hit, some miss
    for (int i = 0, count = integer(1, 6); i < count; ++i)
      scene.circles.push_back({orbit.target + glm::dvec2(uniform(-2.5, 2.5), uniform(-2.5, 2.5)), uniform(0.2, 1.5),
                               {200, 80, 40}, ""});
    FigureOptions options;
    options.rays = integer(2, std::min(n, 9));
    const Figure figure = construction_figure_2d(scene, camera, options);
    INFO("trial " << trial << ": " << n << " pixels, " << options.rays << " rays");
    for (int f = 0; f < kFrames2D; ++f) {
      INFO("frame " << f);
      const Frame& frame = figure.frames[std::size_t(f)];
      const glm::dmat3 m = frame_matrix_2d(camera, f);
      const double size = glm::length(orbit.target) + orbit.d + orbit.df;
      const auto ends = screen_corners_of(m);
      std::vector<Segment> rays, ticks;
      for (const Segment& s : frame.segments) {
        if (s.stroke == Stroke::ray) rays.push_back(s);
        if (s.stroke == Stroke::tick) ticks.push_back(s);
      }
      // The rays: evenly spread over the pixels, both ends included, each from P_k along u_k.
      REQUIRE(int(rays.size()) == options.rays);
      for (int i = 0; i < options.rays; ++i) {
        const int k = int(std::lround(double(i) * (n - 1) / (options.rays - 1)));
        const Ray2D ray = camera.primary_ray(k);
        const glm::dvec2 from = f == 3 ? ray.origin : transform_point(m, camera.canonical_pixel(k));
        const glm::dvec2 along =
            f == 3 ? ray.direction : glm::normalize(transform_vector(m, camera.canonical_pixel(k) - kCanonicalEye2D));
        const Segment& drawn = rays[std::size_t(i)];
        INFO("ray " << i << ", pixel " << k);
        CHECK(near(drawn.from, from, size));
        CHECK(glm::length(glm::normalize(drawn.to - drawn.from) - along) < 1e-9);
        if (f != 3) continue;
        // Placed: the ray stops where the core's caster says this pixel's ray hits, or goes past every object.
        const Hit hit = nearest_hit(scene.circles, ray, IntersectFormula::stable);
        if (hit.id >= 0) {
          CHECK(near(drawn.to, ray.origin + hit.t * ray.direction, size));
        } else {
          for (const Circle& circle : scene.circles)
            CHECK(glm::length(drawn.to - drawn.from) > glm::length(circle.centre - from) + circle.radius);
        }
      }
      // The ticks: each at a pixel centre, across the screen; the first and last pixels ticked; every pixel
      // up to 64.
      std::vector<int> ticked;
      for (const Segment& tick : ticks) {
        int k = 0;  // a tick starts at its pixel (the page draws it at a fixed length across the screen)
        while (k < n && !near(tick.from, transform_point(m, camera.canonical_pixel(k)), size)) ++k;
        CHECK(k < n);
        ticked.push_back(k);
        CHECK(std::abs(glm::dot(glm::normalize(tick.to - tick.from), glm::normalize(ends[1] - ends[0]))) < 1e-9);
      }
      CHECK(std::count(ticked.begin(), ticked.end(), 0) == 1);
      CHECK(std::count(ticked.begin(), ticked.end(), n - 1) == 1);
      if (n <= 64) CHECK(int(ticked.size()) == n);
    }
    // The placed frame's SVG draws those rays where its page transform puts them: each drawn ray is the
    // plane's ray moved to the page, cut near the drawing area (the clip does the rest): its ends lie on the moved
    // ray, between its ends.
    FigureOutput output;
    const std::string file = scratch.path("rays.svg");
    write_figure(figure, {3}, output, file);
    const auto drawn = rays_in_svg(read_text(file));
    const Frame& placed = figure.frames[3];
    const PageFrame laid_out = lay_out_frame(figure, 3, output);
    std::vector<Segment> rays;
    for (const Segment& s : placed.segments)
      if (s.stroke == Stroke::ray) rays.push_back(s);
    REQUIRE(drawn.size() == rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const glm::dvec2 a = laid_out.to_page(rays[i].from), b = laid_out.to_page(rays[i].to);
      const double length = glm::length(b - a);
      REQUIRE(length > 0.0);
      const glm::dvec2 along = (b - a) / length;
      for (const glm::dvec2 page : {drawn[i].first, drawn[i].second}) {
        const glm::dvec2 rel = page - a;
        CHECK(std::abs(rel.x * along.y - rel.y * along.x) < 0.01);  // on the moved ray's line (SVG: 2 decimals)
        CHECK(glm::dot(rel, along) > -0.01);
        CHECK(glm::dot(rel, along) < length + 0.01);
      }
    }
  }
}

TEST_CASE("a PNG figure fills each object in the scene's colour (red, green and blue in their places)", "[figure]") {
  const test::ScratchDir scratch("figure-png-colours");
  Scene2D scene;  // apart from each other, around the target of cameras_2d()
  scene.circles = {{{1.0, -2.5}, 0.7, {230, 40, 30}, ""}, {{3.0, -0.5}, 0.6, {40, 200, 60}, ""},
                   {{2.2, 1.5}, 0.6, {30, 60, 235}, ""}};
  for (const Camera2D& camera : cameras_2d()) {
    const Figure figure = construction_figure_2d(scene, camera, {});
    const Frame& placed = figure.frames[3];  // the placed camera: objects in their colours
    REQUIRE_FALSE(placed.objects_faded);
    FigureOutput output;
    output.format = Format::png;
    output.page = page_in_px(900, 700);
    const std::string file = scratch.path("colours.png");
    write_figure(figure, {3}, output, file);
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(file.c_str(), &width, &height, &channels, 3);
    REQUIRE(pixels);
    const PageTransform to_page = lay_out_frame(figure, 3, output).to_page;
    const double px_per_pt = double(output.page.width_px()) / output.page.width_pt;
    auto at = [&](double x, double y) {
      const std::size_t i = (std::size_t(std::lround(y)) * std::size_t(width) + std::size_t(std::lround(x))) * 3;
      return glm::ivec3(pixels[i], pixels[i + 1], pixels[i + 2]);
    };
    CHECK(at(2, 2) == glm::ivec3(255));  // the page is white
    for (const Disc& disc : placed.objects) {
      // Filled at 80 % opacity over white; sampled on a grid inside half its radius (a ray or a line drawn
      // over it changes a few samples, never most).
      const glm::ivec3 expected = glm::ivec3(glm::round(0.8 * glm::dvec3(disc.colour.r, disc.colour.g, disc.colour.b) + 0.2 * 255.0));
      const double cx = to_page.x(disc.centre.x) * px_per_pt, cy = to_page.y(disc.centre.y) * px_per_pt;
      const double r = to_page.scale * disc.radius * px_per_pt;
      REQUIRE(r > 8.0);
      int samples = 0, matching = 0;
      for (int i = -4; i <= 4; ++i)
        for (int j = -4; j <= 4; ++j) {
          if (i * i + j * j > 16) continue;
          const glm::ivec3 got = at(cx + 0.125 * r * i, cy + 0.125 * r * j);
          ++samples;
          matching += glm::all(glm::lessThanEqual(glm::abs(got - expected), glm::ivec3(3)));
        }
      INFO("object coloured " << int(disc.colour.r) << ", " << int(disc.colour.g) << ", " << int(disc.colour.b));
      CHECK(matching >= samples * 3 / 4);
    }
    stbi_image_free(pixels);
  }
}

TEST_CASE("the 3D SVG draws each step's eye, screen and centre as the core's construction", "[figure]") {
  const test::ScratchDir scratch("figure-svg3d");
  Orbit3D orbit;
  orbit.target = {1.0, -2.0, 0.5};
  orbit.d = 7.0;
  orbit.theta = glm::radians(40.0);
  orbit.phi = glm::radians(65.0);
  orbit.df = 1.8;
  const Camera3D camera(32, 24, orbit);
  const Figure figure = construction_figure_3d(scene_3d(), camera, {});
  REQUIRE(figure.frames.size() == std::size_t(kSteps3D));
  FigureOutput output;
  for (int s = 0; s < kSteps3D; ++s) {
    const glm::dmat4 m = construction_step(camera.placement(), s);
    const auto corners = screen_corners_of(m);
    require_svg_points(figure, s,
                       {{Point::eye, oblique_projection(eye_of(m))},
                        {Point::screen_first_end, oblique_projection(corners[0])},
                        {Point::screen_last_end, oblique_projection(corners[2])},
                        {Point::screen_centre, oblique_projection(transform_point(m, glm::dvec3(0.0)))},
                        {Point::target, oblique_projection(orbit.target)}},
                       output, scratch);
  }
  // The last step is the camera: its eye is Camera3D's.
  const glm::dvec3 eye = eye_of(construction_step(camera.placement(), kSteps3D - 1));
  CHECK(glm::length(eye - camera.eye()) < 1e-12);
}

TEST_CASE("a PDF of pages holds one page per frame, the language's titles and the matrices", "[figure]") {
  const test::ScratchDir scratch("figure-pdf");
  const Camera2D camera = cameras_2d()[2];
  for (Language language : {Language::fr, Language::en}) {
    FigureOptions options;
    options.language = language;
    const Figure figure = construction_figure_2d(scene_2d(), camera, options);
    FigureOutput output;
    output.format = Format::pdf;
    output.pages = true;
    const std::string file = scratch.path("frames.pdf");
    REQUIRE(write_figure(figure, {0, 1, 2, 3}, output, file).files.size() == 1);
    CHECK(run_output("pdfinfo '" + file + "'").find("Pages:           4") != std::string::npos);
    const std::string text = run_output("pdftotext -layout '" + file + "' -");
    const bool fr = language == Language::fr;
    for (const char* letter : {"a", "b", "c", "d"}) {
      CHECK(text.find(std::string(fr ? "cadre (" : "frame (") + letter + ")") != std::string::npos);
      CHECK(text.find(std::string(fr ? "frame (" : "cadre (") + letter + ")") == std::string::npos);
    }
    CHECK(text.find(fr ? "homothétie" : "scaling") != std::string::npos);
    // Every frame's matrix, row by row, with 3 decimals, the language's decimal separator and the minus sign.
    for (int f = 0; f < 4; ++f) {
      const glm::dmat3 m = frame_matrix_2d(camera, f);
      for (int r = 0; r < 3; ++r) {
        // The numbers in order, any spacing between them (the layout's).
        std::string pattern;
        for (int c = 0; c < 3; ++c) {
          char number[32];
          std::snprintf(number, sizeof number, "%.3f", std::abs(m[c][r]) < 5e-4 ? 0.0 : m[c][r]);
          std::string expected = std::regex_replace(number, std::regex("[.]"), fr ? "," : "\\.");
          expected = std::regex_replace(expected, std::regex("-"), "\xe2\x88\x92");  // U+2212
          pattern += (c == 0 ? "" : " +") + expected;
        }
        INFO("frame " << f << " row " << r << ": " << pattern);
        CHECK(std::regex_search(text, std::regex(pattern)));
      }
    }
  }
}

TEST_CASE("a PNG has the size asked for, in pixels or in millimetres at 300 dpi", "[figure]") {
  const test::ScratchDir scratch("figure-png");
  const Figure figure = construction_figure_2d(scene_2d(), cameras_2d()[0], {});
  const std::pair<PageSize, std::pair<int, int>> cases[] = {
      {page_in_px(640, 480), {640, 480}},
      {page_in_px(333, 777), {333, 777}},
      {page_in_mm(100.0, 50.0), {int(std::lround(100.0 / 25.4 * 300.0)), int(std::lround(50.0 / 25.4 * 300.0))}}};
  for (const auto& [page, size] : cases) {
    FigureOutput output;
    output.format = Format::png;
    output.page = page;
    const std::string file = scratch.path("frame.png");
    write_figure(figure, {1}, output, file);
    int width = 0, height = 0, channels = 0;
    REQUIRE(stbi_info(file.c_str(), &width, &height, &channels) == 1);
    CHECK(width == size.first);
    CHECK(height == size.second);
  }
}

TEST_CASE("several frames go to one file each, named after the frame", "[figure]") {
  const test::ScratchDir scratch("figure-files");
  const Figure figure = construction_figure_2d(scene_2d(), cameras_2d()[0], {});
  FigureOutput output;
  const auto written = write_figure(figure, {0, 3}, output, scratch.path("course.svg"));
  REQUIRE(written.files == std::vector<std::string>{scratch.path("course-a.svg"), scratch.path("course-d.svg")});
  for (const std::string& file : written.files) CHECK(read_text(file).rfind("<?xml", 0) == 0);
}

TEST_CASE("a scene of 2000 objects has every object that reaches the drawing drawn", "[figure]") {
  const test::ScratchDir scratch("figure-many");
  Scene2D scene;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
  for (int i = 0; i < 2000; ++i)  // around the target: all in (d)'s view, some out of (a)'s
    scene.circles.push_back({{2.0 + 0.1 * coordinate(random), -1.0 + 0.1 * coordinate(random)}, 0.02, {200, 100, 50}, ""});
  const Figure figure = construction_figure_2d(scene, cameras_2d()[0], {});
  FigureOutput output;
  const auto written = write_figure(figure, {0, 3}, output, scratch.path("many.svg"));
  REQUIRE(written.objects_drawn.size() == 2);
  CHECK(written.objects_drawn[1] == 2000);
  // (a): at least every object inside the drawing area, at most those within 20 pt of it (stroke ends).
  const PageFrame a = lay_out_frame(figure, 0, output);
  int inside = 0, near = 0;
  for (const Circle& c : scene.circles) {
    const glm::dvec2 p = a.to_page(c.centre);
    const double r = a.to_page.scale * c.radius;
    const double dx = std::max({a.area.left - p.x, 0.0, p.x - a.area.right});
    const double dy = std::max({a.area.top - p.y, 0.0, p.y - a.area.bottom});
    inside += std::hypot(dx, dy) <= r;
    near += std::hypot(std::max(dx - 20.0, 0.0), std::max(dy - 20.0, 0.0)) <= r;
  }
  CHECK(inside > 100);
  CHECK(inside < 2000);
  CHECK(written.objects_drawn[0] >= inside);
  CHECK(written.objects_drawn[0] <= near);
  // Counted again in the file: the placed frame fills each object in its colour.
  const std::string svg = read_text(written.files[1]);
  std::size_t filled = 0;
  for (std::size_t at = 0; (at = svg.find("fill:rgb(78.431373%,39.215686%,19.607843%)", at)) != std::string::npos; ++at)
    ++filled;
  CHECK(filled == 2000);
}

TEST_CASE("numbers in French take the decimal comma and no minus zero", "[figure]") {
  CHECK(decimal(1.5, 3, Language::fr) == "1,500");
  CHECK(decimal(1.5, 3, Language::en) == "1.500");
  CHECK(decimal(-1e-9, 3, Language::en) == "0.000");
  CHECK(decimal(-0.0, 1, Language::fr) == "0,0");
  CHECK(decimal(-2.25, 2, Language::fr) == "\xe2\x88\x92" "2,25");  // U+2212, not the hyphen
}

TEST_CASE("a far C or O is pointed at and named, never a dashed line running off the page", "[figure]") {
  // The target at (5000, 3000): in (d) the translation OP ran from P off the page unnamed (O is 5800 away).
  Orbit2D orbit;
  orbit.target = {5000.0, 3000.0};
  orbit.d = 6.0;
  orbit.theta = glm::half_pi<double>();
  const Figure figure = construction_figure_2d(scene_2d(), Camera2D(64, orbit), {});
  for (const Frame& frame : figure.frames) {
    const bool placed = frame.id == "d";
    std::vector<std::string> named;  // the labels at a pointer's tip
    for (const Segment& s : frame.segments) {
      if (s.stroke == Stroke::pointer)
        for (const Label& l : frame.labels)
          if (l.at == s.to) named.push_back(l.text);
      if (s.stroke != Stroke::construction) continue;
      INFO("frame " << frame.id << ": a dashed line from (" << s.from.x << ", " << s.from.y << ") to (" << s.to.x
                    << ", " << s.to.y << ")");
      const glm::dvec2 far = placed ? glm::dvec2(0.0) : orbit.target;  // Ω in (d), C in (a)–(c)
      CHECK((s.from != far && s.to != far));
    }
    INFO("frame " << frame.id);
    if (!placed) CHECK(named == std::vector<std::string>{"$C$"});  // (d): C is 6 from P, in view
    if (placed) CHECK(named == std::vector<std::string>{"$Ω$"});
  }
}

TEST_CASE("an eye far off the page (d_f = 50) is pointed at and named, from the screen's centre", "[figure]") {
  // (b) says "the eye moves back to E = (0, d_f)": at d_f = 50 E was neither drawn nor named.
  Orbit2D orbit;
  orbit.d = 6.0;
  orbit.theta = glm::half_pi<double>();
  orbit.df = 50.0;
  const Figure f2 = construction_figure_2d(scene_2d(), Camera2D(64, orbit), {});
  Orbit3D orbit3;
  orbit3.df = 50.0;
  const Figure f3 = construction_figure_3d(scene_3d(), Camera3D(16, 12, orbit3), {});
  for (const Figure* figure : {&f2, &f3})
    for (const Frame& frame : figure->frames) {
      const bool canonical = &frame == &figure->frames.front();  // E₀ at distance 1: in view
      glm::dvec2 screen_centre(0.0), eye(0.0);
      for (const Marker& m : frame.markers) {
        if (m.point == Point::screen_centre) screen_centre = m.at;
        if (m.point == Point::eye) eye = m.at;
      }
      int pointers_to_eye = 0;
      for (const Segment& s : frame.segments) {
        if (s.stroke != Stroke::pointer) continue;
        INFO("frame " << frame.id);
        CHECK(s.from == screen_centre);  // not the middle of the camera's extent
        const glm::dvec2 along = glm::normalize(s.to - s.from), towards = glm::normalize(eye - s.from);
        for (const Label& l : frame.labels)
          if (l.at == s.to && (l.text == "$E$") && glm::dot(along, towards) > 1.0 - 1e-9) ++pointers_to_eye;
      }
      INFO("frame " << frame.id << " of " << figure->frames.size());
      CHECK(pointers_to_eye == (canonical ? 0 : 1));
    }
}
