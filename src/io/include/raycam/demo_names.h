// The shipped scenes' object names (the built-in demos and scenes/*.json) in the reader's language ("red" →
// "rouge", "left twin" → "jumeau gauche"), for everything that shows them: the window's inspector and
// exported figures, and `raycam-cli figure --lang`. They are translated wherever the scene comes from (the
// demo saved as a file and opened again keeps its French names); a name the table does not know is its
// author's and is shown as written.
#pragma once

#include <string>
#include <vector>

#include "raycam/language.h"
#include "raycam/view_setup.h"

namespace raycam {

// The table: {"red", "rouge"}, ... (checked with every other table for every language; a test checks that
// every shipped scene's names are in it).
const std::vector<Translation>& demo_object_name_texts();
// A shipped object's name in `language`; any other name as it is.
std::string demo_object_name(Language language, const std::string& english);
// Names the setup's objects in `language` (the names the table knows).
void name_demo_objects(ViewSetup& setup, Language language);

}  // namespace raycam
