// The stress cases (see the header). Sections: scenes; 2D cases; 3D cases; references and measurement.
#include "raycam/stress_cases.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "raycam/exact_bar.h"
#include "raycam/standard_scenes.h"

namespace raycam {

namespace {

std::string label(const char* key, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%s=%.17g", key, value);
  return text;
}

// ---- Scenes: the demo scene's objects around the target (one definition: raycam/standard_scenes.h) ----
Scene2D cluster_2d(glm::dvec2 target, double rotation = 0.0) {
  return testkit::demo_cluster_2d(target, rotation);
}
Scene3D cluster_3d(glm::dvec3 target, double rotation_z = 0.0) {
  return testkit::demo_cluster_3d(target, rotation_z);
}

// Orbit zoomed so that a scene of half-size ~4 around the target fills the view at any distance:
// the screen's half-width 1 at focal distance d_f sees a half-width d/d_f at the target.
double zoomed_df(double d, double minimum) { return std::max(minimum, d / 4.0); }

// ---- 2D ------------------------------------------------------------------------------------------------
Camera2D camera_of(int side, const Orbit2D& orbit) { return Camera2D(side, orbit); }
Camera3D camera_of(int side, const Orbit3D& orbit) { return Camera3D(side, side, orbit); }

// Collects the cases of one dimension, each camera `side` pixels wide (and high, in 3D).
template <class Case, class Orbit, class Scene>
struct Builder {
  int side;
  std::vector<Case> cases;
  void add(std::string group, std::string name, const Orbit& orbit, Scene scene, double res = 1.0) {
    auto camera = camera_of(side, orbit);
    camera.set_res(res);
    cases.push_back(Case{std::move(group), std::move(name), camera, std::move(scene)});
  }
};
using Builder2D = Builder<StressCase2D, Orbit2D, Scene2D>;
using Builder3D = Builder<StressCase3D, Orbit3D, Scene3D>;
}  // namespace

std::vector<StressCase2D> stress_cases_2d(bool long_sweep) {
  Builder2D b{long_sweep ? 1024 : 128, {}};
  const glm::dvec2 origin(0.0);
  const Orbit2D base{origin, 6.0, glm::half_pi<double>(), 1.5};

  const std::vector<double> distances =
      long_sweep ? std::vector<double>{1e-3, 1e-2, 0.1, 1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7}
                 : std::vector<double>{1e-3, 1, 1e3, 1e5, 1e7};
  for (double d : distances)
    b.add("d", label("d", d), Orbit2D{origin, d, glm::half_pi<double>(), zoomed_df(d, 1.5)},
          cluster_2d(origin));

  const std::vector<double> focals =
      long_sweep ? std::vector<double>{1e-3, 1e-2, 0.1, 1, 10, 100, 1e3} : std::vector<double>{1e-3, 1, 1e3};
  for (double df : focals)
    b.add("df", label("df", df), Orbit2D{origin, 6.0, glm::half_pi<double>(), df}, cluster_2d(origin));

  std::vector<double> thetas = {glm::pi<double>(), -glm::pi<double>(), std::nextafter(glm::pi<double>(), 4.0),
                                std::nextafter(-glm::pi<double>(), -4.0), glm::two_pi<double>()};
  if (long_sweep)
    thetas.insert(thetas.end(), {3 * glm::pi<double>(), -5 * glm::pi<double>(), 1e6,
                                 std::nextafter(glm::two_pi<double>(), 0.0)});
  for (double theta : thetas)
    b.add("theta", label("theta", theta), Orbit2D{origin, 6.0, theta, 1.5}, cluster_2d(origin));

  const double n = b.side;
  for (double res : {1.0 / n, 2.0 / n, 0.1}) b.add("res", label("res", res), base, cluster_2d(origin), res);

  const std::vector<double> shifts =
      long_sweep ? std::vector<double>{1e2, 1e3, 1e4, 1e5, 1e6, 1e7} : std::vector<double>{1e3, 1e5, 1e7};
  for (double shift : shifts) {
    const glm::dvec2 target(shift, -0.7 * shift);
    b.add("translate", label("shift", shift), Orbit2D{target, 6.0, glm::half_pi<double>(), 1.5},
          cluster_2d(target));
  }
  for (double angle : long_sweep ? std::vector<double>{0.3, 1.0, 2.5, -2.0} : std::vector<double>{1.0, 2.5}) {
    b.add("rotate", label("angle", angle), Orbit2D{origin, 6.0, glm::half_pi<double>() + angle, 1.5},
          cluster_2d(origin, angle));
    const glm::dvec2 far(1e6, 1e6);
    b.add("rotate", label("angle@1e6", angle), Orbit2D{far, 6.0, glm::half_pi<double>() + angle, 1.5},
          cluster_2d(far, angle));
  }

  {  // Grazing: circles exactly tangent (to rounding) to two pixel-centre rays.
    Camera2D camera(b.side);
    camera.set_orbit(base);
    Scene2D scene;
    for (int k : {b.side / 3, (2 * b.side) / 3 + 1}) {
      const Ray2D ray = camera.primary_ray(k);
      const glm::dvec2 side(-ray.direction.y, ray.direction.x);
      const double r = 0.5 + 0.1 * k / n;
      scene.circles.push_back(Circle{ray.origin + 5.0 * ray.direction + r * side, r, Rgb8{200, 200, 40}, ""});
    }
    b.cases.push_back(StressCase2D{"grazing", "tangent to 2 pixel rays", camera, scene});
  }
  {  // The screen cuts through a circle centred on the screen centre, in front of the cluster.
    Camera2D camera(b.side);
    camera.set_orbit(base);
    Scene2D scene = cluster_2d(origin);
    scene.circles.insert(scene.circles.begin(), Circle{camera.screen_centre(), 0.6, Rgb8{250, 250, 250}, ""});
    b.cases.push_back(StressCase2D{"screen cut", "circle on the screen", camera, scene});
  }
  {  // Equal depth: two identical circles (the lower index must win), and two circles whose front
     // intersection point lies on the view axis, hit by the centre ray of an odd-sized bar.
    Scene2D scene;
    scene.circles.push_back(Circle{{0, 0}, 1.0, Rgb8{255, 0, 0}, ""});
    scene.circles.push_back(Circle{{0, 0}, 1.0, Rgb8{0, 255, 0}, ""});
    scene.circles.push_back(Circle{{-0.5, -2.0}, 1.5, Rgb8{0, 0, 255}, ""});
    scene.circles.push_back(Circle{{0.5, -2.0}, 1.5, Rgb8{0, 255, 255}, ""});
    Builder2D odd{b.side + 1, {}};
    odd.add("equal depth", "identical + crossing on axis", Orbit2D{{0, 0}, 6.0, glm::half_pi<double>(), 1.5},
            scene);
    odd.add("equal depth", "crossing pair only", Orbit2D{{0, 0}, 6.0, glm::half_pi<double>(), 1.5},
            Scene2D{kDefaultBackground, {scene.circles[2], scene.circles[3]}});
    for (auto& c : odd.cases) b.cases.push_back(std::move(c));
  }
  return b.cases;
}

// ---- 3D ------------------------------------------------------------------------------------------------
std::vector<StressCase3D> stress_cases_3d(bool long_sweep) {
  Builder3D b{long_sweep ? 128 : 32, {}};
  const glm::dvec3 origin(0.0);
  const Orbit3D base{origin, 8.0, 0.5, 1.0, 2.0};

  const std::vector<double> distances = long_sweep
                                            ? std::vector<double>{1e-3, 0.1, 1, 10, 1e3, 1e4, 1e5, 1e6, 1e7}
                                            : std::vector<double>{1e-3, 1e3, 1e5, 1e7};
  for (double d : distances)
    b.add("d", label("d", d), Orbit3D{origin, d, 0.5, 1.0, zoomed_df(d, 2.0)}, cluster_3d(origin));

  for (double df :
       long_sweep ? std::vector<double>{1e-3, 1e-2, 0.1, 1, 10, 100, 1e3} : std::vector<double>{1e-3, 1e3})
    b.add("df", label("df", df), Orbit3D{origin, 8.0, 0.5, 1.0, df}, cluster_3d(origin));

  const double tiny = std::nextafter(0.0, 1.0);
  std::vector<double> phis = {0.0,
                              glm::pi<double>(),
                              std::nextafter(glm::pi<double>(), 0.0),
                              std::nextafter(glm::pi<double>(), 4.0),
                              4 * tiny,
                              -4 * tiny};
  if (long_sweep)
    phis.insert(phis.end(), {1e-300, 1e-16, 1e-8, -1e-8, glm::pi<double>() - 1e-8, glm::pi<double>() + 1e-8});
  for (double phi : phis)
    b.add("phi", label("phi", phi), Orbit3D{origin, 8.0, 0.5, phi, 2.0}, cluster_3d(origin));

  std::vector<double> thetas = {glm::pi<double>(), -glm::pi<double>(), std::nextafter(glm::pi<double>(), 4.0),
                                std::nextafter(-glm::pi<double>(), -4.0)};
  if (long_sweep) thetas.insert(thetas.end(), {glm::two_pi<double>(), 3 * glm::pi<double>(), 1e6});
  for (double theta : thetas)
    b.add("theta", label("theta", theta), Orbit3D{origin, 8.0, theta, 1.0, 2.0}, cluster_3d(origin));

  for (double res : {1.0 / b.side, 2.0 / b.side})
    b.add("res", label("res", res), base, cluster_3d(origin), res);

  for (double shift :
       long_sweep ? std::vector<double>{1e3, 1e4, 1e5, 1e6, 1e7} : std::vector<double>{1e3, 1e5, 1e7}) {
    const glm::dvec3 target(shift, -0.7 * shift, 0.3 * shift);
    b.add("translate", label("shift", shift), Orbit3D{target, 8.0, 0.5, 1.0, 2.0}, cluster_3d(target));
  }
  for (double angle : {1.0, 2.5}) {
    b.add("rotate", label("angle", angle), Orbit3D{origin, 8.0, 0.5 + angle, 1.0, 2.0},
          cluster_3d(origin, angle));
    const glm::dvec3 far(1e6, 1e6, -1e6);
    b.add("rotate", label("angle@1e6", angle), Orbit3D{far, 8.0, 0.5 + angle, 1.0, 2.0},
          cluster_3d(far, angle));
  }
  {  // Grazing: a sphere tangent to one pixel-centre ray.
    Camera3D camera(b.side, b.side);
    camera.set_orbit(base);
    const Ray3D ray = camera.primary_ray(b.side / 3, b.side / 2);
    const glm::dvec3 side = glm::normalize(glm::cross(ray.direction, glm::dvec3(0, 0, 1)));
    Scene3D scene;
    scene.spheres.push_back(
        Sphere{ray.origin + 6.0 * ray.direction + 0.7 * side, 0.7, Rgb8{200, 200, 40}, ""});
    b.cases.push_back(StressCase3D{"grazing", "tangent to a pixel ray", camera, scene});
  }
  {  // The screen cuts through a sphere centred on the screen centre.
    Camera3D camera(b.side, b.side);
    camera.set_orbit(base);
    Scene3D scene = cluster_3d(origin);
    scene.spheres.insert(scene.spheres.begin(), Sphere{camera.screen_centre(), 0.6, Rgb8{250, 250, 250}, ""});
    b.cases.push_back(StressCase3D{"screen cut", "sphere on the screen", camera, scene});
  }
  {  // Equal depth: identical spheres, and a pair whose intersection circle crosses the view axis.
    Scene3D scene;
    scene.spheres.push_back(Sphere{{0, 0, 0}, 1.0, Rgb8{255, 0, 0}, ""});
    scene.spheres.push_back(Sphere{{0, 0, 0}, 1.0, Rgb8{0, 255, 0}, ""});
    b.add("equal depth", "identical spheres", base, scene);
    Builder3D odd{b.side + 1, {}};
    odd.add("equal depth", "crossing pair", Orbit3D{origin, 8.0, 0.0, glm::half_pi<double>(), 2.0},
            Scene3D{kDefaultBackground,
                    {Sphere{{0, -0.5, 0}, 1.5, Rgb8{0, 0, 255}, ""},
                     Sphere{{0, 0.5, 0}, 1.5, Rgb8{0, 255, 255}, ""}},
                    {}});
    for (auto& c : odd.cases) b.cases.push_back(std::move(c));
  }
  return b.cases;
}

// ---- References and measurement -------------------------------------------------------------------------
CoverageImage stress_reference(const StressCase2D& stress_case) {
  return exact_bar_image(exact_bar(stress_case.camera, stress_case.scene), stress_case.scene);
}

CoverageImage stress_reference(const StressCase3D& stress_case) {
  return reference_cast(stress_case.camera, stress_case.scene,
                        ReferenceOptions{Scalar::extended, IntersectFormula::stable, 1, true});
}

namespace {
template <int D>
bool finite(const glm::vec<D, double>& v) {
  for (int i = 0; i < D; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

template <class Matrix>
bool finite_matrix(const Matrix& m) {
  for (int c = 0; c < Matrix::length(); ++c)
    for (int r = 0; r < Matrix::length(); ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

bool image_valid(const CoverageImage& image, std::size_t objects) {
  for (int id : image.ids)
    if (id < -1 || id >= int(objects)) return false;
  for (const glm::dvec3& c : image.colours)
    if (!finite<3>(c)) return false;
  return true;
}
}  // namespace

namespace {
bool rays_finite(const Camera2D& camera) {
  for (int k = 0; k < camera.pixel_count(); ++k) {
    const Ray2D ray = camera.primary_ray(k);
    if (!finite<2>(ray.origin) || !finite<2>(ray.direction)) return false;
  }
  return true;
}

bool rays_finite(const Camera3D& camera) {
  for (int row = 0; row < camera.rows(); ++row)
    for (int column = 0; column < camera.columns(); ++column) {
      const Ray3D ray = camera.primary_ray(row, column);
      if (!finite<3>(ray.origin) || !finite<3>(ray.direction)) return false;
    }
  return true;
}

std::size_t object_count(const Scene2D& scene) { return scene.circles.size(); }
std::size_t object_count(const Scene3D& scene) { return scene.spheres.size(); }

template <class Case>
StressResult measure_case(const Case& stress_case, const CoverageImage& reference,
                          const ReferenceOptions& options) {
  const auto& camera = stress_case.camera;
  const CoverageImage image = reference_cast(camera, stress_case.scene, options);
  StressResult result;
  result.id_error = id_disagreement(image, reference);
  result.all_finite = finite_matrix(camera.world_from_camera()) && finite(camera.eye()) &&
                      image_valid(image, object_count(stress_case.scene)) && rays_finite(camera);
  return result;
}
}  // namespace

StressResult measure(const StressCase2D& stress_case, const CoverageImage& reference,
                     const ReferenceOptions& options) {
  return measure_case(stress_case, reference, options);
}

StressResult measure(const StressCase3D& stress_case, const CoverageImage& reference,
                     const ReferenceOptions& options) {
  return measure_case(stress_case, reference, options);
}

}  // namespace raycam
