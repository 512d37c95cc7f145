#include "web/downloads.h"

#include <emscripten.h>

#include <filesystem>

namespace raycam::web {

namespace {
void offer(const std::string& path, const std::string& name) {
  // A Blob of the file's bytes behind a temporary link: the browser's own download, with its usual prompt.
  EM_ASM(
      {
        const bytes = FS.readFile(UTF8ToString($0));
        const link = document.createElement('a');
        link.href = URL.createObjectURL(new Blob([bytes]));
        link.download = UTF8ToString($1);
        document.body.appendChild(link);
        link.click();
        setTimeout(() => { URL.revokeObjectURL(link.href); link.remove(); }, 1000);
      },
      path.c_str(), name.c_str());
}

template <class Visit>
void each_file(Visit&& visit) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(".", error)) {
    if (!entry.is_regular_file(error)) continue;
    const auto written = entry.last_write_time(error).time_since_epoch().count();
    visit(entry.path().filename().string(), std::pair<long long, long long>(written, entry.file_size(error)));
  }
}
}  // namespace

Downloads::Downloads() {
  each_file([this](const std::string& name, auto stamp) { seen_[name] = stamp; });
}

void Downloads::offer_new_files() {
  each_file([this](const std::string& name, auto stamp) {
    auto found = seen_.find(name);
    if (found != seen_.end() && found->second == stamp) return;
    seen_[name] = stamp;
    offer("./" + name, name);
  });
}

}  // namespace raycam::web
