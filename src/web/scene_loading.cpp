#include "scene_loading.h"

#include <emscripten.h>

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "raycam/scene_file.h"
#include "shown_files.h"
#include "text.h"
#include "web_host.h"

namespace raycam::web {

namespace {
// announce: a frame says what is parsed; parse: the parse, the check, then (same frame) the packing and first
// image; report: how long it took.
enum class Step { idle, announce, parse, report };

struct Loading {
  Step step = Step::idle;
  std::string path;
  double started_ms = 0.0;
};
Loading loading;

double megabytes(double bytes) { return bytes / (1024.0 * 1024.0); }
}  // namespace

void install_scene_reader() {
  // 8 MiB slices: a 90 MB file in a dozen awaits, each a few milliseconds of copying on the page's thread.
  EM_ASM({
    Module.raycamReadFile = async function(file, path) {
      const slice = 8 * 1024 * 1024;
      const stream = FS.open(path, 'w');
      try {
        for (let at = 0; at < file.size; at += slice) {
          const bytes = new Uint8Array(await file.slice(at, at + slice).arrayBuffer());
          FS.write(stream, bytes, 0, bytes.length);
          Module.ccall('raycam_scene_read_progress', null, ['string', 'number', 'number'],
                       [file.name, at + bytes.length, file.size]);
          await new Promise(requestAnimationFrame);  // the frame showing the bytes read is drawn
        }
      } finally {
        FS.close(stream);
      }
      Module.ccall('raycam_open_file', null, ['string'], [path]);
    };
    // A dropped file takes the same route (emscripten's GLFW would read it whole first, with no progress).
    Module.canvas.removeEventListener('drop', GLFW.onDrop, true);
    Module.canvas.addEventListener('drop', (event) => {
      const files = event.dataTransfer && event.dataTransfer.files;
      if (!files || files.length === 0) return;
      event.preventDefault();
      FS.mkdirTree('/dropped');
      Module.raycamReadFile(files[0], '/dropped/' + files[0].name.split('/').join('_'));
    }, true);
  });
}

void open_scene_in_steps(session::AppState& state, const std::string& path) {
  std::error_code error;
  const auto bytes = std::filesystem::file_size(path, error);
  loading = Loading{Step::announce, path, emscripten_get_now()};
  if (!error)
    session::set_message(state, session::MessageSource::files, false,
                         ui::trf(state.language, "opening %s: reading the objects of %.1f MB, then packing them…",
                                 session::shown_file_name(state.host, path).c_str(),
                                 megabytes(double(bytes))));
  wake_page();
}

bool scene_loading_step(session::AppState& state) {
  switch (loading.step) {
    case Step::idle:
      return false;
    case Step::announce:
      loading.step = Step::parse;
      return true;
    case Step::parse:
      // The desktop's Open: its checks, its messages; a bad file keeps the scene.
      loading.step = session::open_scene(state, loading.path) ? Step::report : Step::idle;
      return true;
    case Step::report:
      loading.step = Step::idle;
      session::set_message(state, session::MessageSource::files, false,
                           ui::trf(state.language, "opened %s (%zu objects) in %.1f s",
                                   session::shown_file_name(state.host, loading.path).c_str(),
                                   session::active_object_count(state),
                                   (emscripten_get_now() - loading.started_ms) / 1000.0));
      return true;
  }
  return false;
}

}  // namespace raycam::web

// The page's reader (install_scene_reader): a slice of `name` read, `done` of `total` bytes.
extern "C" EMSCRIPTEN_KEEPALIVE void raycam_scene_read_progress(const char* name, double done, double total) {
  using namespace raycam;
  session::set_message(web::page_state(), session::MessageSource::files, false,
                       ui::trf(web::page_state().language, "opening %s: read %.1f of %.1f MB", name, web::megabytes(done),
                               web::megabytes(total)));
  web::wake_page();
}
