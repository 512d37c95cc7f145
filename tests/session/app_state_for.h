// The app's state built from command-line options, as the app builds it, for the UI tests.
#pragma once

#include <string>
#include <vector>

#include "flags/app/app_flags.h"
#include "session/app_options.h"

namespace raycam::test {

inline session::AppState state_for(const std::vector<std::string>& args) {
  return session::make_app_state(flags::parse_app_options(args));
}

}  // namespace raycam::test
