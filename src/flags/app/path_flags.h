// `raycam-cli record`'s camera path on the command line: --sweep SLIDER=FROM:TO (repeatable, one after the
// other), --path FILE (key cameras), --construction, --ease. Each sweep is checked against its slider's range
// with the one message format (flag_values.h); the path is built by session::camera_path once the scene is
// known (a φ sweep needs a 3D camera).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "session/camera_path.h"
#include "flags/flag_values.h"

namespace raycam::flags {

struct PathFlags {
  std::vector<session::Sweep> sweeps;
  std::optional<std::string> key_file;  // --path
  bool construction = false;
  bool ease = false;
};

// --sweep's rule: NAME=FROM:TO with NAME a path slider and both ends in its range.
ValueRule<session::Sweep> sweep_rule();

// Adds the "Path" option group.
CLI::Option_group* add_path_options(CLI::App& command, PathFlags& path);

// The path for these flags from the state's camera (`seconds`: the sweeps' or the construction's total;
// a key file gives its own). Throws std::invalid_argument naming the flag.
session::CameraPath make_camera_path(const PathFlags& flags, const session::Lesson& state, double seconds);

}  // namespace raycam::flags
