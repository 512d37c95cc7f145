#include "web/scene_loading.h"

#include <emscripten.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

#include "raycam/scene_file.h"
#include "raycam/scene_file_reader.h"
#include "session/shown_files.h"
#include "session/text.h"
#include "web/web_host.h"

namespace raycam::web {

namespace {
// announce: a frame says what comes; start: the file's text, out of the page's file system; parse: a slice of
// the parse (SceneFileReader, kParseSliceMs) per frame, the frame showing the count; pack: a frame says the
// packing comes; open: the desktop's Open with the parsed scene, then (the same frame) the packing, the first
// image and the views' copies of the objects, one step; report: how long it took.
enum class Step { idle, announce, start, parse, pack, open, report };

// A frame's share of the parse: with the frame's own drawing (10-30 ms in software WebGL) the page answers
// about ten times a second; a larger slice opens faster but answers slower (docs/web.md, "Big files").
constexpr double kParseSliceMs = 50.0;

struct Loading {
  Step step = Step::idle;
  std::string path;
  double started_ms = 0.0;
  std::unique_ptr<SceneFileReader> reader;
};
Loading loading;

double megabytes(double bytes) { return bytes / (1024.0 * 1024.0); }

std::string shown_name(const session::AppState& state) { return session::shown_file_name(state.host, loading.path); }

// The status line while the parse goes on: the bytes looked through, then the objects read of those found.
void show_parse_progress(session::AppState& state) {
  const SceneFileReader& reader = *loading.reader;
  const std::string text =
      reader.phase() == SceneFileReader::Phase::finding
          ? session::trf(state.language, "opening %s: finding the objects (%.1f of %.1f MB)", shown_name(state).c_str(),
                    megabytes(double(reader.bytes_scanned())), megabytes(double(reader.bytes())))
          : session::trf(state.language, "opening %s: objects read %zu of %zu", shown_name(state).c_str(),
                    reader.objects_read(), reader.objects_found());
  session::set_message(state, session::MessageSource::files, false, text);
}
}  // namespace

void install_scene_reader() {
  // 8 MiB slices: a 90 MB file in a dozen awaits, each a few milliseconds of copying on the page's thread.
  EM_ASM({
    Module.raycamReadFile = async function(file, path) {
      const slice = 8 * 1024 * 1024;
      const stream = FS.open(path, 'w');
      try {
        // The whole size at once: grown slice by slice, the file's storage was copied whole at each doubling
        // (up to 64 MB in one frame for a 97 MB file).
        FS.ftruncate(stream.fd, file.size);
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
  loading = Loading{Step::announce, path, emscripten_get_now(), nullptr};
  if (!error)
    session::set_message(state, session::MessageSource::files, false,
                         session::trf(state.language, "opening %s: reading the objects of %.1f MB, then packing them…",
                                 session::shown_file_name(state.host, path).c_str(),
                                 megabytes(double(bytes))));
  wake_page();
}

bool scene_loading_step(session::AppState& state) {
  switch (loading.step) {
    case Step::idle:
      return false;
    case Step::announce:
      loading.step = Step::start;
      return true;
    case Step::start:
      try {
        loading.reader = std::make_unique<SceneFileReader>(read_scene_text(loading.path), loading.path);
        loading.step = Step::parse;
      } catch (const std::exception&) {  // unreadable: the desktop's Open says why, in its words
        session::open_scene(state, loading.path);
        loading.step = Step::idle;
      }
      return true;
    case Step::parse:
      if (loading.reader->step(kParseSliceMs)) {
        show_parse_progress(state);
      } else if (loading.reader->failed()) {
        loading.step = Step::open;  // its error, at once
      } else {
        loading.step = Step::pack;
        session::set_message(state, session::MessageSource::files, false,
                             session::trf(state.language, "opening %s: packing %zu {{object|objects}}…", shown_name(state).c_str(),
                                     loading.reader->objects()));
      }
      return true;
    case Step::pack:
      loading.step = Step::open;
      return true;
    case Step::open: {
      // The desktop's Open with the parsed scene (or the parse's error): its checks, its messages; a bad file
      // keeps the scene.
      SceneFileReader& reader = *loading.reader;
      const bool opened = session::open_scene(state, loading.path, [&] { return reader.take(); });
      loading.reader.reset();
      loading.step = opened ? Step::report : Step::idle;
      return true;
    }
    case Step::report:
      loading.step = Step::idle;
      session::set_message(state, session::MessageSource::files, false,
                           session::trf(state.language, "opened %s (%zu {{object|objects}}) in %.1f s", shown_name(state).c_str(),
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
                       session::trf(web::page_state().language, "opening %s: read %.1f of %.1f MB", name, web::megabytes(done),
                               web::megabytes(total)));
  web::wake_page();
}
