#include "session/view.h"

#include "raycam/demo_names.h"
#include "session/text.h"

namespace raycam::session {

namespace {
View2D view_of(const ViewSetup& setup, const Camera2D& camera) {
  View2D view;
  view.scene = setup.file.scene2d;
  view.orbit = view.preset = camera.orbit();
  view.max_pixels = camera.max_pixels();
  view.camera = camera;
  return view;
}
View3D view_of(const ViewSetup& setup, const Camera3D& camera) {
  View3D view;
  view.scene = setup.file.scene3d;
  view.orbit = view.preset = camera.orbit();
  view.max_columns = camera.max_columns();
  view.max_rows = camera.max_rows();
  view.camera = camera;
  return view;
}
}  // namespace

OpenedViews views_from_setup(const ViewSetup& setup) {
  // ViewSetup (raycam_io) holds both cameras and says which is meant: the one place that reads it.
  OpenedViews views{view_of(setup, setup.camera3d), view_of(setup, setup.camera2d)};
  if (setup.dimension == 2) std::swap(views.on_screen, views.other);
  std::visit([&](auto& view) { view.scene_path = setup.scene_path; }, views.on_screen);
  return views;
}

void pack_scene(const View& view, PackedScene3D& packed) {
  std::visit(overloaded{[](const View2D&) {},  // 2D casts its circles as they are
                        [&](const View3D& v) { packed.pack(v.scene); }},
             view);
}

void cast_view(const View& view, const PackedScene3D& packed, ColourMap& map, const CastOptions& options,
               CastStats* stats) {
  std::visit(overloaded{[&](const View2D& v) { cast_primary_rays(v.camera, v.scene, map, options, stats); },
                        [&](const View3D& v) { cast_primary_rays(v.camera, packed, map, options, stats); }},
             view);
}

void validate(const View& view) {
  std::visit([](const auto& v) { raycam::validate(v.scene); }, view);
}

SceneFile scene_file_of(const View& view, const CameraPreset& camera) {
  SceneFile file;
  file.camera = camera;
  file.dimension = dimension_of(view);
  std::visit(overloaded{[&](const View2D& v) { file.scene2d = v.scene; }, [&](const View3D& v) { file.scene3d = v.scene; }},
             view);
  return file;
}

namespace {
template <class AnyView>
std::string name_as_shown(Language language, const AnyView&, const std::string& name) {
  return demo_object_name(language, name);  // the shipped scenes' names translated (raycam/demo_names.h)
}
template <class AnyView>
auto with_names_as_shown(Language language, const AnyView& view) {
  auto scene = view.scene;
  for (auto& object : objects_of(scene)) object.name = name_as_shown(language, view, object.name);
  return scene;
}
}  // namespace

std::string shown_object_name(Language language, const View& view, std::size_t id) {
  return std::visit([&](const auto& v) { return name_as_shown(language, v, objects_of(v.scene).at(id).name); }, view);
}
Scene2D scene_as_shown(Language language, const View2D& view) { return with_names_as_shown(language, view); }
Scene3D scene_as_shown(Language language, const View3D& view) { return with_names_as_shown(language, view); }

}  // namespace raycam::session
