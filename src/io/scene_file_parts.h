// parse_scene_json's two halves (scene_file.cpp), shared with the resumable reader (scene_file_reader.cpp) so
// that both check a file by the same code: the file's fields, then each object of "objects" by itself.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "raycam/scene_file.h"

namespace raycam::scene_file_parts {

// The scene of a parsed file: every field checked, "objects" read with read_scene_object. Throws
// std::invalid_argument naming `source`, the field and what was expected.
SceneFile read_scene(const nlohmann::json& root, const std::string& source);

// Appends objects[index] (its JSON `item`) to the file's scene of its dimension, checked.
void read_scene_object(SceneFile& file, const nlohmann::json& item, std::size_t index, const std::string& source);

}  // namespace raycam::scene_file_parts
