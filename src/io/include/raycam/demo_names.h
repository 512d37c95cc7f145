// The built-in demo scenes' object names in the reader's language ("red" → "rouge"), for everything that
// shows them: the window's inspector and exported figures, and `raycam-cli figure --lang`. A scene file's
// names are its author's and are shown as written.
#pragma once

#include <string>
#include <vector>

#include "raycam/language.h"
#include "raycam/view_setup.h"

namespace raycam {

// The table: {"red", "rouge"}, ... (checked with every other table for every language).
const std::vector<Translation>& demo_object_name_texts();
// A demo object's name in `language`; any other name as it is.
std::string demo_object_name(Language language, const std::string& english);
// Names the setup's objects in `language` when its scene is the built-in demo (scene_path empty).
void name_demo_objects(ViewSetup& setup, Language language);

}  // namespace raycam
