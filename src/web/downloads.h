// Files the app writes (Save as, the colour map PNG, screenshots, check cases) land in the page's in-memory
// file system, in its working folder; each new or rewritten file there is handed to the browser as a
// download, under its own name. The app's code for writing them is the desktop's, unchanged.
#pragma once

#include <map>
#include <string>
#include <utility>

namespace raycam::web {

class Downloads {
 public:
  Downloads();  // remembers what the folder already holds: only later writes are offered
  void offer_new_files();

 private:
  std::map<std::string, std::pair<long long, long long>> seen_;  // name -> (modification time, size)
};

}  // namespace raycam::web
