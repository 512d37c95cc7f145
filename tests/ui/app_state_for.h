// The app's state built from command-line options, as the app builds it, for the UI tests.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "app_options.h"

namespace raycam::test {

inline ui::AppState state_for(const std::vector<std::string>& args) {
  ui::AppOptions options;
  for (std::size_t i = 0; i < args.size();)
    if (!ui::parse_app_option(args, i, options)) throw std::logic_error("not an app option: " + args[i]);
  return ui::make_app_state(options);
}

}  // namespace raycam::test
