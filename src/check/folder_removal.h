// Removing a run's temporary folder whatever the run did to it: a program may leave a sub-folder of mode 500
// (or 000), which a checker that is not root cannot empty until it gives itself the rights back.
#pragma once

#include <string>

namespace raycam::check {

// Removes `folder` and everything in it (links are removed, never followed); true when it is gone.
bool remove_folder_whatever_modes(const std::string& folder);

}  // namespace raycam::check
