// Scene files: JSON, one scene per file, angles in degrees, colours 0–255 (docs/cli.md, "Scene files").
//   { "dimension": 3, "background": [20,20,30],
//     "objects": [ {"type": "sphere", "center": [0,0,0], "radius": 1, "color": [230,60,50], "name": "red"} ],
//     "camera": {"target": [0,0,0], "d": 8, "theta": 30, "phi": 60, "df": 2, "res": 1, "size": [256,256]} }
// 2D: "dimension": 2, "circle" objects with 2-component centres, "size": N. 3D's "res" is one number or two,
// [columns, rows] (the handout's "une (ou deux) variables de résolution").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "raycam/scene.h"

namespace raycam {

// The optional camera preset; every field may be absent. Angles in DEGREES, as in the file.
struct CameraPreset {
  std::optional<std::vector<double>> target;  // 2 or 3 components
  std::optional<double> d, theta_deg, phi_deg, df, res;
  std::optional<std::vector<int>> size;  // [N] in 2D, [columns, rows] in 3D
  // 3D, when the image's two sides have their own resolution: the rows' (res is then the columns'). Set only
  // with res; absent, the rows take res.
  std::optional<double> res_rows;
};

struct SceneFile {
  int dimension = 3;
  Scene2D scene2d;  // the scene of a 2D file
  Scene3D scene3d;  // of a 3D file (the other stays empty)
  CameraPreset camera;
  // The version of `raycam-cli check`'s protocol a case file follows (docs/check.md, "Protocol versions"):
  // written by check --write-cases and on a program's stdin, read so a case file stays a scene file; the
  // renderer ignores it.
  std::optional<int> protocol;
};

// Calls function(scene) with the scene the file's dimension holds, Scene2D or Scene3D, as std::visit does on a
// variant: what is the same in both dimensions is written once, over overloads (objects_of, …).
template <class File, class Function>
decltype(auto) visit_scene(File& file, Function&& function) {
  if (file.dimension == 2) return function(file.scene2d);
  return function(file.scene3d);
}

// Errors throw std::invalid_argument with "<source>: <field>: <what was expected>" (and line/column for
// JSON syntax errors). `source` names the file in messages.
SceneFile parse_scene_json(const std::string& text, const std::string& source);
SceneFile load_scene_file(const std::string& path);
// load_scene_file's first half: the file's text, with its errors (a folder, too big, unreadable).
std::string read_scene_text(const std::string& path);
std::string scene_to_json(const SceneFile& file);
// Writes to a temporary file beside `path`, then renames: an existing file is never left truncated.
void save_scene_file(const SceneFile& file, const std::string& path);

}  // namespace raycam
