// Everything the window shows, as plain data. Panels are functions of this state; the orbit parameters
// here are the source of truth and the cameras are derived from them (place_cameras), so that a mistake
// toggle or the arccos route can be switched on and off without losing the student's settings.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/mat4x4.hpp>
#include <optional>
#include <string>

#include "raycam/accuracy_options.h"
#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/colour_map.h"
#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "raycam/view_setup.h"
#include "session/host_capabilities.h"
#include "session/host_requests.h"
#include "session/text.h"
#include "session/view.h"

namespace raycam::session {

struct PixelIndex {
  int row = 0;
  int column = 0;
};

// The observer's own orbit around the camera's target in the 3D observer view (degrees; zoom multiplies a
// distance fitted to the camera).
struct ObserverOrbit {
  float yaw_deg = -60.0f;
  float pitch_deg = 30.0f;
  float zoom = 1.0f;
};

// A view made to fill the views' area (keys 1, 2, 3 or a double-click on its title bar; the same again gives
// the others back). The observer exists in 3D only: maximised in 2D, the views keep their places.
enum class ShownView { all, image, overhead, observer };

// Where a message came from: it is shown in that panel section (or above the status line when the section
// is closed).
enum class MessageSource { general, camera, files, caster, construction };

// The session's state, split by what each part is. Functions take the part they use (const where they only
// read it); AppState is the whole, and converts to any of its parts.

// The lesson's model: what the student and the teacher set. Everything else is derived from it or about
// showing it.
struct Lesson {
  // The view on screen, and the other dimension's, kept as it was left: switching 2D/3D swaps the two, so
  // coming back finds its scene, its file and its camera again (view.h).
  View view{View3D{}};
  View other_view{View2D{}};
  double res = 1.0;         // one res for both views: switching keeps it
  double preset_res = 1.0;  // the res the scene file and the command line opened with
  // 3D, "non-square" on: the rows' res (res is then the columns'), and the preset's.
  std::optional<double> res_rows, preset_res_rows;
  ClassicMistakes mistakes;
  bool arccos_route = false;  // free placement through the handout's arccos (the mistake near a pole)
  std::string mistake_look_at;  // after a mistake's "show me": what to look at (empty: nothing shown)
  int construction_step = -1;  // -1: the final camera; 0..steps: the handout's frames a → d
  // How much of step `construction_step`'s own factor is applied (a recording's in-between poses: a rotation
  // by that part of its angle, a translation along that part of its vector, H by that part of its scale);
  // 1: the step itself, all the app's panels ever set.
  double construction_fraction = 1.0;
  std::optional<PixelIndex> pinned_pixel;   // clicked, or --inspect
  std::optional<glm::dvec2> pin_point;      // its canonical point as a fraction of the image (follows res)
  PixelIndex pin_placed;                    // the pixel the last image pinned for that point
  std::optional<PixelIndex> hovered_pixel;  // under the mouse this frame
  CastOptions cast_options;  // the caster's method (the app's "Caster" combo); same ids whatever it is
  AccuracyFlags accuracy;    // the accuracy knobs; at their defaults the fast caster runs
  Language language = Language::en;  // --lang, else the environment; the frame applies it (text.h)
  // What changed since the last cast: the cast cache is rebuilt from the model when these say so.
  bool cameras_dirty = true;
  std::uint64_t scene_version = 1;  // bumped when the objects change
  // Bumped only when a scene is opened, not by Tab's switch of views (which bumps scene_version for the
  // packed and uploaded copies): the check's case key, so Tab there and back is the same case again.
  std::uint64_t opened_version = 1;
  std::uint64_t scene_opens = 0;    // scene files opened by open_scene: the panels follow each (the Open box)
};

// The cast cache: rebuilt from the lesson by recast_if_needed, never edited by the panels.
struct CastCache {
  // The 3D scene packed for the caster (raycam/scene.h), repacked when scene_version moves past packed_version.
  PackedScene3D packed3d;
  std::uint64_t packed_version = 0;
  ColourMap map;
  std::uint64_t map_version = 0;  // bumped at every cast
  CastStats stats;
  double cast_ms = 0.0;
  long long cast_count = 0;
  double ns_per_ray = 20.0;     // measured at every full cast; predicts the next cast's cost
  bool refine_pending = false;  // the map on screen is a coarse preview cast while the user drags
};

// How the window shows the lesson: the lecture settings and the views' own framing.
struct Display {
  float font_scale = 1.0f;  // the font is rasterised at this scale (fonts.h), not stretched
  bool high_contrast = false;
  bool show_help = false;
  bool panel_hidden = false;  // P: the views take the panel's width (its button is in the status line then)
  ShownView maximised = ShownView::all;
  ObserverOrbit observer;
  // The overhead view's world rectangle (x, y). Fitted to the scene and the camera when a scene is loaded,
  // the camera reset or "fit" asked for (button, F key), not every frame: fixed objects hold still while the
  // camera moves.
  glm::dvec2 overhead_low{-1.0}, overhead_high{1.0};
  bool overhead_fit_pending = true;
};

// Messages: one at a time, shown beside the views (never on them) next to what caused it. An error stays
// until dismissed or replaced; a confirmation goes away by itself kConfirmationSeconds after it was first shown.
struct Messages {
  std::string message;
  bool message_is_error = false;
  MessageSource message_source = MessageSource::general;
  long long message_shown_frame = -1;  // the frame in which a panel section showed it (else the frame does)
  double message_since = -1.0;         // the frame clock (s) when it was first drawn; -1: not yet
};

// Long enough to read a path at 3× in front of a class, short enough not to linger over the next action.
inline constexpr double kConfirmationSeconds = 5.0;

// The host: what it can do (set once by the executable), what the session asks of it, and the frame clock.
struct HostLink {
  HostCapabilities host = kDesktopHost;
  HostRequests requests;  // only the executable knows about windows and files of pixels
  std::string window_title = "raycam";  // "raycam — 3D — many3d.json": the frame sets it, the host applies it
  long long frame_count = 0;
  double frame_ms = 0.0;
  // A recording of the window under way (the host records; the panel and the status line show it).
  bool recording = false;
  double recording_seconds = 0.0;
  // In full screen now (the host says so before each frame): the panel's button then offers to leave it.
  bool in_fullscreen = false;
};

// The session's whole state. The panels' own widget state is not in it: the frame keeps it (ui/panel_state.h).
struct AppState : Lesson, CastCache, Display, Messages, HostLink {};

// Makes `view` fill the views' area, or, when it already does, gives the other views back.
void toggle_maximised(Display& display, ShownView view);

// Sets the one message on screen (replacing any other).
void set_message(Messages& messages, MessageSource source, bool is_error, std::string text);
// At frame clock `now` (seconds): starts the shown message's clock, and clears a confirmation shown for
// kConfirmationSeconds (errors stay until read). Returns whether a confirmation is still counting down
// (the window keeps drawing until it goes).
bool age_message(Messages& messages, double now);

// Asks the host for a screenshot at the next free raycam-screenshot-NNN.png (in French raycam-capture-NNN.png)
// in the current directory.
void request_screenshot(HostLink& host, Language language);
// "cannot open PATH: REASON", without the path twice when the reason already names it.
std::string cannot_open_message(Language language, const std::string& path, const std::string& reason);
// The first raycam-screenshot-NNN.png (NNN from 001; its French name in French) not in `directory`.
std::string next_screenshot_path(Language language, const std::string& directory = ".");

// "raycam — 3D — many3d.json" (the demo scene: its translated name).
std::string window_title(const Lesson& state);

// Takes the scene, the file's path and the camera parameters of a view setup (keeps the display settings).
void adopt_view_setup(Lesson& state, Display& display, const ViewSetup& setup);
// Builds cameras from the parameters (and the mistakes); throws std::invalid_argument on bad parameters.
void place_cameras(Lesson& state);
// Re-casts the primary rays if anything changed since the last cast. Returns true if it cast. While the
// user is interacting, a cast predicted to take longer than kInteractiveBudgetMs is done at a coarser res
// (a preview), and refined to full resolution once the interaction stops: the UI never freezes.
inline constexpr double kInteractiveBudgetMs = 25.0;
bool recast_if_needed(AppState& state, bool interacting = false);
// Loads a scene file; on error keeps the current scene and sets an error message. Returns success (and
// counts it in scene_opens).
bool open_scene(AppState& state, const std::string& path);
// The same with the file's scene from `read` (the file at `path` parsed elsewhere, e.g. over several frames
// in the page; its exception is the file's error, shown as open_scene shows it).
bool open_scene(AppState& state, const std::string& path, const std::function<SceneFile()>& read);
// Saves the current camera as the scene file's preset (written atomically). Returns success.
bool save_preset(AppState& state, const std::string& path);
// What Save as did: saved, wrote nothing because `path` exists and the user has not said yes to replacing
// it (the caller asks, then calls again with `overwrite`), or failed (the message says why).
enum class SaveAsOutcome { saved, needs_yes, failed };
// Save as: an existing file is replaced only when `overwrite` is true (a download never replaces anything).
SaveAsOutcome save_preset_as(AppState& state, const std::string& path, bool overwrite);

// True when the accuracy knobs ask for more than the fast caster gives (another precision, samples per
// pixel, camera-relative rays, or the exact 2D bar): the reference caster then draws the image.
bool uses_reference_caster(const Lesson& state);

// Back to the camera the scene opened with (the file's preset and the command line), and a fresh fit of
// the overhead view.
void reset_camera(Lesson& state, Display& display);

// Switches between the 2D and 3D cameras; a scene file holds one kind of scene, so the other kind is the
// built-in demo scene.
void switch_dimension(AppState& state, int dimension);

// ---- the views: the one on screen and each dimension's ----
int dimension(const Lesson& state);  // of the view on screen
// Each dimension's view, on screen or kept aside.
View2D& view2d(Lesson& state);
const View2D& view2d(const Lesson& state);
View3D& view3d(Lesson& state);
const View3D& view3d(const Lesson& state);
// The file the scene on screen came from (empty: the built-in demo).
const std::string& scene_path(const Lesson& state);

// The orbit parameters the 2D and 3D cameras share (Number: double, or const double to read them).
template <class Number>
struct SharedOrbit {
  Number& theta;
  Number& d;
  Number& df;
};
SharedOrbit<double> active_orbit(Lesson& state);
SharedOrbit<const double> active_orbit(const Lesson& state);
// The target C seen from above (3D: its x and y).
glm::dvec2 active_target_xy(const Lesson& state);
// The longest side the camera may use: N in 2D, max(W, H) in 3D.
int active_max_side(const Lesson& state);
// The objects of the scene on screen (circles or spheres).
std::size_t active_object_count(const Lesson& state);
// The camera's current parameters as a scene file's preset.
CameraPreset active_preset(const Lesson& state);

// Number of construction steps of the current mode (3 in 2D, 5 in 3D).
int construction_steps(const Lesson& state);

}  // namespace raycam::session
