// The fast paths of the views (docs/speed.md) draw what the plain ones draw: the observer's spheres cast on
// the CPU against the GL impostors, and the overhead view's disc layer against the geometry of its discs.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "gl/disc_layer.h"
#include "gl/gl.h"
#include "headless/headless_renderer.h"
#include "gl/observer_renderer.h"

using namespace raycam;

namespace {
std::vector<std::uint8_t> render_observer(gl::ObserverRenderer& renderer, gl::SphereDrawing drawing,
                                          const gl::ObserverFrame& frame, int width, int height) {
  renderer.set_sphere_drawing(drawing);
  const GLuint texture = renderer.render(frame, width, height);
  std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());

  return rgba;
}

struct Agreement {
  int differing = 0, covered = 0, pixels = 0;
};

Agreement compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, Rgb8 background) {
  Agreement result;
  for (std::size_t p = 0; p < a.size(); p += 4) {
    ++result.pixels;
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[p + c]) - int(b[p + c])));
    result.differing += worst > 24;
    result.covered += a[p] != background.r || a[p + 1] != background.g || a[p + 2] != background.b;
  }
  return result;
}

gl::ObserverFrame observer_looking_at_origin(glm::vec3 eye, int width, int height) {
  gl::ObserverFrame frame;
  const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 0, 1));
  const float distance = glm::length(eye);
  frame.view_projection = glm::perspective(glm::radians(45.0f), float(width) / float(height),
                                           distance * 0.01f, distance * 50.0f) *
                          view;
  frame.observer_eye = eye;
  frame.background = Rgb8{20, 20, 30};
  frame.lines.push_back({glm::vec3(-30, 0, 0), glm::vec3(30, 0, 0),
                         glm::vec4(1, 0, 0, 1)});  // hidden where spheres are in front
  return frame;
}
}  // namespace

TEST_CASE("the observer's spheres cast on the CPU look like the GL impostors", "[render][observer][speed]") {
  const int width = 480, height = 320;
  headless::HeadlessRenderer context(width, height);  // a current GL context
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(-6.0, 6.0), size(0.1, 0.9);
  std::uniform_int_distribution<int> channel(60, 255);
  std::vector<Sphere> spheres;
  for (int i = 0; i < 400; ++i)
    spheres.push_back(
        {{position(random), position(random), position(random)},
         size(random),
         Rgb8{std::uint8_t(channel(random)), std::uint8_t(channel(random)), std::uint8_t(channel(random))},
         ""});

  // The same spheres drawn both ways from `eye`, looking at the origin, compared pixel by pixel.
  auto impostors_against_layer = [&](const std::vector<Sphere>& drawn, glm::vec3 eye) {
    gl::ObserverRenderer renderer;
    renderer.set_spheres(drawn);
    const gl::ObserverFrame frame = observer_looking_at_origin(eye, width, height);
    const std::vector<std::uint8_t> impostors =
        render_observer(renderer, gl::SphereDrawing::impostors, frame, width, height);
    const std::vector<std::uint8_t> layer =
        render_observer(renderer, gl::SphereDrawing::cpu_layer, frame, width, height);
    return compare(impostors, layer, frame.background);
  };
  SECTION("from outside, with a sphere reaching behind the observer") {
    spheres.push_back({{22.0, 0.0, 8.0}, 3.0, Rgb8{250, 250, 250}, ""});
    const Agreement d = impostors_against_layer(spheres, {24.0f, 6.0f, 9.0f});
    INFO(d.differing << " of " << d.pixels << " pixels differ; " << d.covered << " covered");
    CHECK(d.covered > d.pixels / 20);      // the picture is not empty
    CHECK(d.differing <= d.pixels / 200);  // silhouettes may round differently: ≤ 0.5 %
  }
  SECTION("from inside a sphere that holds everything") {
    spheres.insert(spheres.begin(), Sphere{{0.0, 0.0, 0.0}, 60.0, Rgb8{90, 140, 90}, ""});
    const Agreement d = impostors_against_layer(spheres, {20.0f, 10.0f, 8.0f});
    INFO(d.differing << " of " << d.pixels << " pixels differ; " << d.covered << " covered");
    CHECK(d.covered == d.pixels);  // the inside of the big sphere is everywhere behind the others
    CHECK(d.differing <= d.pixels / 200);
  }
}

TEST_CASE("the observer's CPU layer is cast again only when its view, its size or the spheres change",
          "[render][observer][speed]") {
  const int width = 160, height = 120;
  headless::HeadlessRenderer context(width, height);
  std::vector<Sphere> spheres;
  for (int i = 0; i < 30; ++i) spheres.push_back({{i * 0.4 - 6.0, std::sin(i), std::cos(i)}, 0.5, Rgb8{200, 90, 40}, ""});
  gl::ObserverRenderer renderer;
  renderer.set_spheres(spheres);
  gl::ObserverFrame frame = observer_looking_at_origin({14.0f, 5.0f, 6.0f}, width, height);
  const std::vector<std::uint8_t> first = render_observer(renderer, gl::SphereDrawing::cpu_layer, frame, width, height);
  CHECK(renderer.sphere_layer_casts() == 1);
  // A frame that changes only the lines (a camera drag, a hovered pixel): the layer is drawn as it was.
  frame.lines.push_back({glm::vec3(0, -30, 0), glm::vec3(0, 30, 0), glm::vec4(0, 1, 0, 1)});
  const std::vector<std::uint8_t> again = render_observer(renderer, gl::SphereDrawing::cpu_layer, frame, width, height);
  CHECK(renderer.sphere_layer_casts() == 1);
  // The kept layer is the one a fresh renderer casts for the same frame.
  gl::ObserverRenderer fresh;
  fresh.set_spheres(spheres);
  CHECK(render_observer(fresh, gl::SphereDrawing::cpu_layer, frame, width, height) == again);
  CHECK(again != first);  // the new line shows
  // The observer turns, the size changes, the spheres change: cast again, each time.
  frame = observer_looking_at_origin({10.0f, -8.0f, 6.0f}, width, height);
  render_observer(renderer, gl::SphereDrawing::cpu_layer, frame, width, height);
  CHECK(renderer.sphere_layer_casts() == 2);
  render_observer(renderer, gl::SphereDrawing::cpu_layer, frame, width / 2, height / 2);
  CHECK(renderer.sphere_layer_casts() == 3);
  spheres.pop_back();
  renderer.set_spheres(spheres);
  render_observer(renderer, gl::SphereDrawing::cpu_layer, frame, width / 2, height / 2);
  CHECK(renderer.sphere_layer_casts() == 4);
}

TEST_CASE("the overhead disc layer puts each disc where the mapping says, later ones on top",
          "[render][overhead][speed]") {
  gl::DiscPlacement placement;
  placement.origin = {50.0f, 40.0f};  // world (0, 0) at layer pixel (50, 40); y up
  placement.scale = 10.0f;
  placement.width = 100;
  placement.height = 80;
  const Rgb8 red{255, 0, 0}, blue{0, 0, 255}, green{0, 255, 0};
  const std::vector<gl::Disc> discs = {{{0.0, 0.0}, 1.0, red},       // pixels 40..60, 30..50
                                       {{1.0, 0.0}, 1.0, blue},      // overlaps the red one from x = 50
                                       {{-3.0, 2.0}, 0.01, green}};  // a tenth of a pixel: drawn with one
  std::vector<std::uint8_t> rgba;
  gl::rasterise_discs(discs, placement, rgba);
  REQUIRE(rgba.size() == 100u * 80u * 4u);
  const auto at = [&](int x, int y) { return &rgba[(std::size_t(y) * 100 + std::size_t(x)) * 4]; };
  // Pixel centres are at (i + ½, j + ½): world (x, y) is at layer (50 + 10x, 40 − 10y).
  CHECK(at(44, 40)[0] == 255);  // inside red only
  CHECK(at(44, 40)[3] == 255);
  CHECK(at(55, 40)[2] == 255);  // red and blue overlap: blue, later, on top
  CHECK(at(55, 40)[0] == 0);
  CHECK(at(80, 40)[3] == 0);    // beyond both: transparent
  CHECK(at(39, 40)[3] == 0);    // red's edge is at x = 40, this pixel's centre 0.5 + 1 pixel away... none
  CHECK(at(20, 20)[1] == 255);  // the tiny green disc at layer (20, 20) still shows
  CHECK(at(20, 20)[3] > 0);
  // A pixel whose centre is on the red circle (x = 40.5 is 9.5 from 50; the circle is at 10): partly covered.
  CHECK(at(40, 40)[3] > 0);
  CHECK(at(40, 40)[3] < 255);
}
