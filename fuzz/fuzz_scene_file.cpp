// libFuzzer target: the scene-file parser, then a small render of whatever it accepts.
// Anything may be refused with std::invalid_argument; nothing may crash, hang, or produce an id out of range.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "raycam/view_setup.h"

namespace {
void check(bool condition) {
  if (!condition) std::abort();  // a broken guarantee: libFuzzer saves the input
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace raycam;
  SceneFile file;
  try {
    file = parse_scene_json(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const std::invalid_argument&) {
    return 0;
  }
  // Round trip: what we write, we read back.
  const SceneFile again = parse_scene_json(scene_to_json(file), "again.json");
  check(again.dimension == file.dimension);
  check(again.scene2d.circles.size() == file.scene2d.circles.size());
  check(again.scene3d.spheres.size() == file.scene3d.spheres.size());
  if (file.scene2d.circles.size() + file.scene3d.spheres.size() > 64) return 0;  // keep each run fast

  // Render the scene with its preset, at a tiny size.
  file.camera.size.reset();
  ViewFlags flags;
  flags.dimension = file.dimension;
  flags.camera = file.camera;
  flags.camera.size = file.dimension == 2 ? std::vector<int>{8} : std::vector<int>{8, 8};
  try {
    ViewSetup setup = make_view_setup(flags);  // the demo scene; then swap in the fuzzed one
    setup.file = file;
    const ColourMap map = file.dimension == 2 ? cast_primary_rays(setup.camera2d, file.scene2d)
                                              : cast_primary_rays(setup.camera3d, file.scene3d);
    const int count = int(file.dimension == 2 ? file.scene2d.circles.size() : file.scene3d.spheres.size());
    for (int id : map.ids) check(id >= -1 && id < count);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
