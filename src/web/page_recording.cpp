#include "web/page_recording.h"

#include <emscripten.h>

#include <string>

#include "session/shown_files.h"
#include "session/text.h"

namespace {
double started_ms = 0.0;
std::string recording_name;
}  // namespace

// 1: recording; 0: this browser cannot record a canvas. The chunks are kept in the page until the stop, as
// one Blob: the download is the whole video or nothing. VP9 where the browser has it (sharper text at the
// same size), else VP8. (EM_JS: the script's commas are its own, not a macro's arguments.)
EM_JS(int, raycam_start_canvas_recorder, (const char* name_pointer), {
  if (typeof MediaRecorder === "undefined" || !Module.canvas.captureStream) return 0;
  const name = UTF8ToString(name_pointer);
  const type = ["video/webm;codecs=vp9", "video/webm;codecs=vp8", "video/webm"].find(function(t) {
    return MediaRecorder.isTypeSupported(t);
  });
  let recorder;
  try {
    recorder = new MediaRecorder(Module.canvas.captureStream(30), type ? {mimeType: type, videoBitsPerSecond: 8000000} : {});
  } catch (error) {
    return 0;
  }
  const chunks = [];
  recorder.ondataavailable = function(event) { if (event.data.size > 0) chunks.push(event.data); };
  recorder.onstop = function() {
    const blob = new Blob(chunks, {type: "video/webm"});
    const link = document.createElement("a");
    link.href = URL.createObjectURL(blob);
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(function() { URL.revokeObjectURL(link.href); }, 60000);
    Module.raycam_recorded_bytes = blob.size;
  };
  recorder.start(1000);  // a chunk a second: a long lecture is not held as one growing buffer
  Module.raycam_recorder = recorder;
  return 1;
});

EM_JS(void, raycam_stop_canvas_recorder, (), {
  if (Module.raycam_recorder) Module.raycam_recorder.stop();
  Module.raycam_recorder = null;
});

namespace raycam::web {

void toggle_page_recording(session::AppState& state) {
  if (state.recording) {
    raycam_stop_canvas_recorder();
    state.recording = false;
    const int seconds = int((emscripten_get_now() - started_ms) / 1000.0);
    session::set_message(state, session::MessageSource::files, false,
                         session::trf(state.language, "asked the browser to save %s (%d:%02d)", recording_name.c_str(),
                                 seconds / 60, seconds % 60));
    return;
  }
  recording_name = session::named_after_scene(state, std::string(session::tr(state.language, "-recording")) + ".webm");
  if (!raycam_start_canvas_recorder(recording_name.c_str())) {
    session::set_message(state, session::MessageSource::files, true,
                         session::tr(state.language, "this browser cannot record the page (no MediaRecorder)"));
    return;
  }
  started_ms = emscripten_get_now();
  state.recording = true;
  state.recording_seconds = 0.0;
  session::set_message(state, session::MessageSource::files, false,
                       session::trf(state.language, "recording the window to %s (F9 stops)", recording_name.c_str()));
}

void update_page_recording(session::AppState& state) {
  if (state.recording) state.recording_seconds = (emscripten_get_now() - started_ms) / 1000.0;
}

}  // namespace raycam::web
