// libFuzzer target: cameras and the caster fed raw doubles (NaN, infinities, denormals, huge and tiny
// values). Every input is either refused with std::invalid_argument or gives finite rays, a finite M_d and
// valid ids; and every accelerated caster gives the plain loop's ids (their bounds must hold whatever the
// numbers).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "raycam/ray_caster.h"

namespace {
struct Bytes {
  const std::uint8_t* data;
  std::size_t size;
  double next_double() {
    double value = 0.0;
    if (size >= sizeof value) {
      std::memcpy(&value, data, sizeof value);
      data += sizeof value;
      size -= sizeof value;
    }
    return value;
  }
  int next_small(int modulus) {
    if (size == 0) return 0;
    --size;
    return *data++ % modulus;
  }
};

void check(bool condition) {
  if (!condition) std::abort();
}

// Every method, both formulas, against the plain loop.
template <class Camera, class Scene>
void check_casters(const Camera& camera, const Scene& scene) {
  using namespace raycam;
  for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
    CastOptions options;
    options.formula = formula;
    options.method = CastMethod::plain;
    const ColourMap plain = cast_primary_rays(camera, scene, options);
    for (int id : plain.ids) check(id >= -1 && id < 3);
    for (CastMethod method : {CastMethod::culled, CastMethod::footprint, CastMethod::binned}) {
      options.method = method;
      options.threads = 1;
      check(cast_primary_rays(camera, scene, options).ids == plain.ids);
    }
  }
}

template <class Ray>
void check_ray(const Ray& ray) {
  for (int i = 0; i < ray.origin.length(); ++i)
    check(std::isfinite(ray.origin[i]) && std::isfinite(ray.direction[i]));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace raycam;
  Bytes in{data, size};
  const bool three_d = in.next_small(2);
  const int columns = 1 + in.next_small(12), rows = 1 + in.next_small(12);
  const ClassicMistakes mistakes{bool(in.next_small(2)), bool(in.next_small(2)), false};
  try {
    if (three_d) {
      Camera3D camera(columns, rows);
      camera.set_mistakes(mistakes);
      camera.set_res(in.next_double(), in.next_double());
      Orbit3D orbit{{in.next_double(), in.next_double(), in.next_double()},
                    in.next_double(),
                    in.next_double(),
                    in.next_double(),
                    in.next_double()};
      if (in.next_small(2))
        camera.set_free(orbit.target + glm::dvec3(orbit.d, orbit.theta, orbit.phi), orbit.target, orbit.df,
                        in.next_small(2) ? AngleRoute::stable : AngleRoute::handout_arccos);
      else
        camera.set_orbit(orbit);
      Scene3D scene;
      for (int i = 0; i < 3; ++i)
        scene.spheres.push_back(
            {{in.next_double(), in.next_double(), in.next_double()}, in.next_double(), {}, ""});
      validate(scene);
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) check(std::isfinite(camera.world_from_camera()[c][r]));
      for (int r = 0; r < camera.rows(); ++r)
        for (int c = 0; c < camera.columns(); ++c) check_ray(camera.primary_ray(r, c));
      check_casters(camera, scene);
    } else {
      Camera2D camera(columns * rows);
      camera.set_mistakes(mistakes);
      camera.set_res(in.next_double());
      Orbit2D orbit{
          {in.next_double(), in.next_double()}, in.next_double(), in.next_double(), in.next_double()};
      if (in.next_small(2))
        camera.set_free(orbit.target + glm::dvec2(orbit.d, orbit.theta), orbit.target, orbit.df,
                        in.next_small(2) ? AngleRoute::stable : AngleRoute::handout_arccos);
      else
        camera.set_orbit(orbit);
      Scene2D scene;
      for (int i = 0; i < 3; ++i)
        scene.circles.push_back({{in.next_double(), in.next_double()}, in.next_double(), {}, ""});
      validate(scene);
      for (int k = 0; k < camera.pixel_count(); ++k) check_ray(camera.primary_ray(k));
      check_casters(camera, scene);
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
