#!/usr/bin/env bash
# Mutation testing, by hand-picked mutants (not run in CI): each mutant is ONE deliberate bug that a test
# must catch. For each, the script edits a scratch copy of the tree (never your checkout), rebuilds only the
# targets that matter, runs the relevant part of the suite, and prints caught / missed.
#   scripts/mutate.sh                 every mutant
#   scripts/mutate.sh NAME...         only these (names as printed by --list)
#   scripts/mutate.sh --list
#   scripts/mutate.sh --check [NAME...]   which mutants still apply (nothing built; seconds)
# Environment: MUTATE_DIR (scratch, default /tmp/raycam-mutate), JOBS (default 2).
# Exit status: 0 when every mutant was caught; 1 when one was missed or did not apply (the code it edits moved).
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SCRATCH=${MUTATE_DIR:-/tmp/raycam-mutate}
JOBS=${JOBS:-2}
TREE=$SCRATCH/tree
BUILD=$TREE/build   # inside the tree, as in a checkout: ccache then hits on every untouched file
WEB_BUILD=$TREE/build-web  # the web page (emcmake), built only for mutants whose targets say web:TARGET
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"  # emscripten's JavaScript optimiser (scripts/web.sh)
# ccache when installed (rebuilds then take seconds), with ccache's own cache unless CCACHE_DIR says otherwise.
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=$SCRATCH
fi

names=() files=() edits=() targets=() tests=()
# mutant NAME FILE SED-SCRIPT TARGETS CTEST-REGEX   (a target web:NAME is built in the web page's build)
# FILE may be FILE@FUNCTION: the edit then applies only inside that function's definition (from the line at
# column 0 that names it followed by "(" to the next "}" at column 0), so the same text elsewhere in the file
# is never touched and a mutant names the code it means; --check says when the function is gone.
mutant() { names+=("$1"); files+=("$2"); edits+=("$3"); targets+=("$4"); tests+=("$5"); }

# apply_edit PATH EDIT FUNCTION: sed EDIT on PATH in place, within FUNCTION when one is given. Returns 3 when
# the function is not found, sed's status otherwise.
apply_edit() {
  local path=$1 edit=$2 function=$3 first last
  if [ -z "$function" ]; then
    sed -i -e "$edit" "$path"
    return
  fi
  first=$(grep -nE "^[A-Za-z_].*[^A-Za-z0-9_:]${function}\(" "$path" | grep -v ';$' | head -1 | cut -d: -f1)
  [ -n "$first" ] || return 3
  # A one-line definition ends on its own line; a longer one at the next "}" at column 0.
  last=$(awk -v from="$first" 'NR == from && /}$/ { print NR; exit } NR > from && /^}/ { print NR; exit }' "$path")
  [ -n "$last" ] || return 3
  sed -i -e "${first},${last}{" -e "$edit" -e "}" "$path"
}

CORE="raycam_core_tests"
CORE_TESTS="^core:"

# --- bugs the suite caught from the start ---
mutant roll-flipped include/raycam/camera3d.h 's/kRollPsi0 = \([^;]*\);/kRollPsi0 = -(\1);/' "$CORE" "$CORE_TESTS"
mutant pixel-edges src/core/camera3d.cpp 's/mistakes_.pixel_edges ? column : column + 0.5/column/' "$CORE" "$CORE_TESTS"
mutant no-renormalise src/core/primary_ray.h 's/if (renormalise) direction \*=/if (false) direction *=/' "$CORE" "$CORE_TESTS"
mutant printed-rotation-2d src/core/camera2d.cpp 's/placement.alpha = view_angle - \(.*\);/placement.alpha = view_angle + \1;/' "$CORE" "$CORE_TESTS"
mutant negative-t-hits include/raycam/intersect.h 's/const bool moving_away = c > T(0) \&\& b > T(0);/const bool moving_away = false;/; s/T t = t_near >= T(0) ? t_near :/T t = true ? t_near :/' "$CORE" "$CORE_TESTS"
mutant mirrored-bar include/raycam/camera2d.h 's/int column_of_pixel(int k) const { return pixel_count_ - 1 - k; }/int column_of_pixel(int k) const { return k; }/' "$CORE" "$CORE_TESTS"
mutant footprint-shrunk-by-a-pixel src/core/screen_footprint.cpp 's/d.bounded ? higher(k.zero, ceil_a) : 0.0/d.bounded ? higher(k.zero, ceil_a + 1.0) : 0.0/' "$CORE" "$CORE_TESTS"
# The exact 2D bar's three kinds of breakpoint, one dropped at a time: silhouettes, the screen line
# entering or leaving a circle, two circles crossing.
mutant exact-bar-no-silhouettes src/core/exact_bar.cpp '/add_direction(Vec(cos_beta \* u.x [+-] sin_beta/d' "$CORE" "$CORE_TESTS"
mutant exact-bar-no-screen-crossings src/core/exact_bar.cpp 's/^\( *\)if (s > -1 \&\& s < 1) points.push_back(s);$/\1(void)s;/' "$CORE" "$CORE_TESTS"
mutant exact-bar-no-circle-crossings src/core/exact_bar.cpp '/add_direction(base [+-] h \* normal - frame.eye);/d' "$CORE" "$CORE_TESTS"
# --- holes an outside mutation run found ---
mutant footprint-no-rounding-slack src/core/screen_footprint.cpp 's/slack = 64 \* kEpsilon/slack = 0 * kEpsilon/; s/slack += 16 \* kEpsilon/slack += 0 * kEpsilon/; s/kRelativeSlack = 1e-9;/kRelativeSlack = 0;/; s/kIndexSlack = 1e-6;/kIndexSlack = 0;/' "$CORE" "$CORE_TESTS"
mutant plain-ties-to-higher-index src/core/ray_caster.cpp 's/if (t < hit.t) hit/if (t <= hit.t) hit/' "$CORE" "$CORE_TESTS"
mutant fast-ties-to-higher-index-2d src/core/footprint_caster.cpp 's/if (t < depth\[p\])/if (t <= depth[p])/' "$CORE" "$CORE_TESTS"
mutant fast-ties-to-higher-index-3d src/core/band_kernels.h 's/return (t < depth) | ((t == depth) \& (object < id));/return t <= depth;/' "$CORE" "$CORE_TESTS"
mutant radius-0-accepted src/core/validation.cpp 's/value > 0.0 \&\& value <= kMaxCoordinate/value >= 0.0 \&\& value <= kMaxCoordinate/' "$CORE" "$CORE_TESTS"
mutant res-0-accepted src/core/validation.cpp 's/if (!(value > 0.0 \&\& value <= 1.0))/if (!(value >= 0.0 \&\& value <= 1.0))/' "$CORE" "$CORE_TESTS"
mutant roll-left-out-of-the-product src/core/camera3d.cpp 's/const glm::dmat4 factors\[\] = {placement.scale, placement.roll,/const glm::dmat4 factors[] = {placement.scale, glm::dmat4(1.0),/' "$CORE" "$CORE_TESTS"
mutant placement-knob-ignored src/io/view_setup.cpp 's/if (flags.placement != PlacementRoute::orbit) {/if (false) {/g' "$CORE" "$CORE_TESTS"
mutant embree-build-time-not-measured src/bench/embree_caster.cpp 's/build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();/build_ms_ = 0.0;/' "raycam_bench_tests" "^bench:"
mutant scene-preset-df-ignored src/io/view_setup.cpp '/if (preset.df) orbit.df = \*preset.df;/d' "raycam-cli raycam_cli_tests" "^cli:"
mutant cli-error-exits-0 src/flags/flag_values.cpp 's/return fail(usage_error_message(app, error), 2);/return fail(usage_error_message(app, error), 0);/' "raycam-cli" "^cli rejects:"
# --- the loops rewritten for speed ---
mutant tangent-at-origin-dropped include/raycam/intersect.h 's/  t = tangent_at_origin ? T(0) : t;//' "$CORE" "$CORE_TESTS"
mutant band-rays-not-renormalised src/core/band_kernels.cpp 's/column_x\[i\], true, origin, direction/column_x[i], false, origin, direction/' "$CORE" "$CORE_TESTS"
mutant band-rays-missing-past-a-box-first-block src/core/footprint_caster.cpp 's/std::size_t(c.box.columns.last \/ kRayBlock)\] + 1, 1);/std::size_t(c.box.columns.first \/ kRayBlock)] + 1, 1);/' "$CORE" "$CORE_TESTS"
mutant dense-band-without-rays src/core/footprint_caster.cpp 's/every_ray ? 1 : 0);/0);/' "$CORE" "$CORE_TESTS"
mutant compaction-keeps-culled src/core/footprint_caster.cpp 's/survivors += (box_rows > 0) & (box_columns > 0);/survivors += 1;/' "$CORE" "$CORE_TESTS"
UI="raycam_ui_tests raycam_render_tests"
mutant inspector-prints-1.5t src/ui/inspector_section.cpp 's/ray.hit.id, name.c_str(), ray.hit.t));/ray.hit.id, name.c_str(), 1.5 * ray.hit.t));/' "$UI" "^(ui|render):"
mutant packed-scene-not-repacked src/session/app_state.cpp 's/^  ++state.scene_version;  \/\/ new objects/  \/\/ new objects/' "raycam_session_tests raycam_render_tests" "^(session|render):"
# --- structure and hygiene ---
# Each caught by the direct test named in its regex (not only through the stress suite's error bounds).
mutant scene-reader-radius-bound-1e300 src/io/scene_file.cpp 's/^\( *\)kMaxCoordinate, true, "\]0, 1e12\]");/\11e300, true, "]0, 1e12]");/' "$CORE" "^core: ?scene files refuse the open bounds"
mutant reference-ties-to-later-object src/core/reference_caster.cpp 's/if (t < best) {  \/\/ strict: ties keep the lower index/if (t <= best) {  \/\/ strict: ties keep the lower index/' "$CORE" "^core: ?ties go to the lower index through the accuracy knobs"
# --- course figures ---
FIGURE="raycam_figure_tests raycam-cli"
mutant figure-first-rotation-as-printed src/figure/construction_figure.cpp 's/^constexpr double kFirstRotation2D = glm::half_pi<double>();/constexpr double kFirstRotation2D = -glm::half_pi<double>();/' "$FIGURE" "^figure:"
mutant figure-matrix-transposed src/figure/construction_figure.cpp 's/rows\[r\]\[c\] = m\[c\]\[r\];/rows[r][c] = m[r][c];/' "$FIGURE" "^figure:"
mutant figure-3d-target-at-origin src/figure/construction_figure.cpp 's/frame.markers.push_back({Point::target, oblique_projection(orbit.target), "$C$"});/frame.markers.push_back({Point::target, oblique_projection(glm::dvec3(0.0)), "$C$"});/' "$FIGURE" "^figure:"
mutant figure-eye-before-scaling src/figure/construction_figure.cpp 's/const glm::dvec2 eye = transform_point(m, kCanonicalEye2D);/const glm::dvec2 eye = transform_point(m, kCanonicalEye2D) - transform_vector(m, {0.0, 0.0});/; s/const glm::dvec2 eye = transform_point(m, kCanonicalEye2D) - transform_vector(m, {0.0, 0.0});/const glm::dvec2 eye = transform_point(m * glm::inverse(camera.placement().scale), kCanonicalEye2D);/' "$FIGURE" "^figure:"
mutant figure-png-pixel-size src/figure/figure_layout.cpp 's/return {0.75 \* width, 0.75 \* height, 1.0 \/ 0.75};/return {0.75 * width, 0.75 * height, 1.0 \/ 0.8};/' "$FIGURE" "^figure:"
mutant figure-objects-culled src/figure/figure_files.cpp 's/^  for (const PageDisc\& disc : page.discs) {$/  for (const PageDisc\& disc : page.discs) { if (\&disc - page.discs.data() >= 1000) break;/' "$FIGURE" "^figure:"
mutant figure-export-ignores-the-step src/session/figure_export.cpp 's/state.construction_step < 0 ? count - 1 : std::min(state.construction_step, count - 1)/count - 1/' "raycam_session_tests" "^session:.*Export figure"
mutant figure-french-titles-in-english src/figure/construction_figure.cpp 's/std::string(figure_text(lang, "frame ("))/std::string("frame (")/' "$FIGURE" "^figure:"
# --- checker safety ---
CHECK="raycam_check_tests raycam-cli"
mutant grading-one-wrong-pixel-passes src/check/grading.cpp 's/result.status = result.wrong_pixels == 0 ? CaseStatus::pass/result.status = result.wrong_pixels <= 1 ? CaseStatus::pass/' "$CHECK" "^check:"
mutant sandbox-writable-host src/check/sandbox_policy.cpp 's/  add(words, {"--remount-ro", "\/tmp",/  add(words, {"--bind", "\/var", "\/var", "--remount-ro", "\/tmp",/' "$CHECK" "^check:"
mutant no-deadline-after-stdout-closes src/check/student_process.cpp 's/    if ((facts.stopped = over_a_bound(Clock::now())) == Stop::none) usleep(2000);/    if ((facts.stopped = Stop::none) == Stop::none) usleep(2000);/' "$CHECK" "^check:"
mutant score-line-counts-failures src/check/check_report.cpp 's/^               report.passed(), n,$/               n - report.passed(), n,/' "$CHECK" "^check:"
mutant answer-ids-not-capped src/check/answer.cpp 's/    if (flat_ ? int(answer.ids.size()) >= columns_ : row_length_ >= columns_) return too_many();//' "$CHECK" "^check:"
mutant square-pixels-ignored src/core/camera3d.cpp 's/return mistakes_.square_pixels ? x \* double(columns_) \/ double(rows_) : x;/return x;/' "$CHECK raycam_core_tests" "^(check|core):"
mutant diff-image-written-through-links src/check/check_report.cpp 's/    write_replacing(path, \[\&\](const std::string\& temporary) { write_png(canvas, temporary, scale_x, scale_y); });/    write_png(canvas, path, scale_x, scale_y);/' "$CHECK" "^check:"
mutant french-details-left-english src/check/check_report.cpp 's/own != detail ? own : translate_reason(lang, detail)/own != detail ? own : detail/' "$CHECK" "^check:"
mutant detached-child-holds-the-answer src/check/student_process.cpp 's/^    if (exited \&\& now >= drained_by) break;/    (void)drained_by;/' "$CHECK" "^check:"
mutant run-uid-kept-root src/check/student_process.cpp 's/  const uid_t run_uid = unprivileged ? next_run_uid() : 0;/  const uid_t run_uid = 0;/' "$CHECK" "^check:"
# The sandbox one can audit (sandbox_policy.h, classify_run, syscall_filter.cpp): each fact and each part.
SANDBOX="^check: ?(sandbox|run facts|bounds: a submission that leads|a killed check)"
mutant checkpoint-ignored src/check/run_facts.cpp 's/  const bool program_started = f.sandboxed ? !f.checkpoint.empty() : f.exec_errno == 0;/  const bool program_started = f.sandboxed ? true : f.exec_errno == 0;/' "$CHECK" "$SANDBOX"
mutant exec-errno-ignored src/check/run_facts.cpp 's/  if (exec_errno != 0) {  \/\/ the program itself cannot be exec/  if (false) {  \/\/ the program itself cannot be exec/' "$CHECK" "$SANDBOX"
mutant opt-shown-again src/check/sandbox_policy.cpp 's/^const char\* const kSystemFolders\[\] = {"\/usr"};/const char* const kSystemFolders[] = {"\/usr", "\/opt"};/' "$CHECK" "$SANDBOX"
mutant filter-lets-keyctl src/check/syscall_filter.cpp 's/^      "keyctl", "add_key", "request_key",/      "add_key", "request_key",/' "$CHECK" "$SANDBOX"
mutant filter-not-passed src/check/sandbox_policy.cpp 's/  if (policy.filtered) add(words, {"--seccomp"/  if (false) add(words, {"--seccomp"/' "$CHECK" "$SANDBOX"
mutant filter-clone-flags-ignored src/check/syscall_filter.cpp 's/SCMP_A0(SCMP_CMP_MASKED_EQ, flag, flag)/SCMP_A0(SCMP_CMP_EQ, flag)/' "$CHECK" "$SANDBOX"
mutant run-files-unbounded src/check/student_process.cpp '/    if (files_in(disk) > max_files) return Stop::files;/d' "$CHECK" "$SANDBOX"
mutant bwrap-processes-counted src/check/student_process.cpp 's/^constexpr int kSandboxProcesses = 2;/constexpr int kSandboxProcesses = 0;/' "$CHECK" "$SANDBOX"
mutant raw-paths-bound src/check/sandbox_policy.cpp 's/    if (!seen) policy.shown.push_back(real);/    if (!seen) policy.shown.push_back(dir);/' "$CHECK" "$SANDBOX"
mutant submission-links-followed src/cli/check_command.cpp 's/      s.refusal = submission_refusal(folder, root.string(), s.argv);/      s.refusal.clear();/' "$CHECK" "$SANDBOX"
mutant stale-folders-kept src/check/student_process.cpp 's/    if (pid <= 0 || pid == getpid() || kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;/    continue;/' "$CHECK" "$SANDBOX"
mutant stale-groups-kept src/check/run_group.cpp 's/^      for (const std::string\& parent : h.parents) sweep_stale_groups(parent);/      (void)0;/' "$CHECK" "^check: ?bounds: a killed check's control groups"
mutant checkpoint-fd-inherited src/check/exec_checkpoint.cpp 's/  if (fcntl(fd, F_SETFD, FD_CLOEXEC) != 0 || write(fd, "S", 1) != 1) return 126;/  if (write(fd, "S", 1) != 1) return 126;/' "$CHECK raycam-exec" "$SANDBOX"
# --- projector and state ---
SESSION="raycam_session_tests"
mutant save-straight-to-target src/io/scene_file.cpp 's/^  const std::string temporary = path + ".tmp";/  const std::string temporary = path;/' "$SESSION" "^session:"
mutant pin-stays-in-image-cells src/session/app_state.cpp 's/^  place_pin(state);$/  (void)place_pin;/' "$SESSION" "^session:"
mutant saved-degrees-round-tripped src/io/view_setup.cpp 's/  return std::abs(rounded - degrees) <= 1e-9 ? rounded : degrees;/  return degrees;/' "$SESSION" "^session:"
mutant key-changes-not-spread src/ui/key_queue.h 's/    if (held_.empty() \&\& !must_wait(e)) {/    if (true) {/' "raycam_ui_tests" "^ui:"
mutant characters-overtake-keys src/ui/key_queue.h 's/  bool arrive_character(unsigned int character) { return arrive(Event{-1, false, character}); }/  bool arrive_character(unsigned int) { return true; }/' "raycam_ui_tests" "^ui:"
mutant inspector-row-plus-one src/ui/inspector_section.cpp 's/wrapped_between_words(trf(state.language, "row %d, column %d", pixel->row, pixel->column));/wrapped_between_words(trf(state.language, "row %d, column %d", pixel->row + 1, pixel->column));/' "raycam_ui_tests" "^ui: ?the ray inspector"
mutant checkbox-label-not-wrapped src/ui/panel_widgets.cpp 's/  if (box + ImGui::CalcTextSize(label, nullptr, true).x <= ImGui::GetContentRegionAvail().x)/  if (true)/' "raycam_render_tests" "^render: ?at 1x to 3x"
mutant words-broken-anywhere src/ui/panel_widgets.cpp 's/  for (const std::string\& line : lines_between_words(text, width)) {/  for (const std::string\& line : {text}) {/' "raycam_ui_tests" "^ui: ?panel text wraps"
mutant labels-printed-over-each-other src/ui/overhead_view.cpp 's/    if (!overlaps(p)) return p;/    return p;/' "raycam_render_tests" "^render: ?a label placed beside"
mutant french-label-left-in-english src/core/classic_mistakes.cpp 's/{"θ and φ swapped", "θ et φ inversés"}/{"θ and φ swapped", "θ and φ swapped"}/' "raycam_ui_tests" "^ui: ?the French window shows no English"
mutant overhead-never-refits src/ui/frame.cpp 's/      if (state.overhead_fit_pending || !camera_and_target_in_view(state, state, top_left, size)) fit_overhead(state, state);/      if (state.overhead_fit_pending) fit_overhead(state, state);/' "raycam_render_tests" "^render: ?the overhead view holds still"
mutant message-below-the-fold-counts-as-shown src/ui/messages.cpp 's/^  if (top < inside.Min.y || top + height > inside.Max.y) {/  if (top < inside.Min.y) {/' "raycam_render_tests" "^render: ?a message stays on screen"
mutant font-rebuild-keeps-buffer-sizes src/ui/fonts.cpp 's/^  restart_renderer_backend();/  ImGui_ImplOpenGL3_DestroyDeviceObjects();/; s/^#include "ui\/renderer_backend.h"/#include "ui\/renderer_backend.h"\n#include <imgui_impl_opengl3.h>/' "raycam_render_tests" "^render:lecture mode: a font scale changed"
mutant window-bigger-than-the-screen src/app/glfw_host.cpp 's/  if (area_width > 0 && area_height > 0) {/  if (false) {/' "raycam raycam_app_tests" "^app: ?the window fits"
mutant font-scale-slider-left-out-of-view src/ui/lecture_section.cpp 's/^  if (scale_changed) panels.font_scale_scroll_frames = 2;/  if (scale_changed) panels.font_scale_scroll_frames = 0;/' "raycam_render_tests" "^render: ?lecture mode: after a change"
# The target's fields cut, in two halves since the split put them in two files: the fields never one a line
# (target_fields), and a label put beside a widget with less than its minimum width (labelled: the layout
# test measures the row with its label, which hides that half, so a ui test asks labelled itself).
mutant target-fields-cut src/ui/camera_section.cpp 's/  if (ImGui::GetContentRegionAvail().x >= needed)/  if (true)/' "raycam_render_tests" "^render: ?lecture mode: at 1"
mutant labelled-ignores-widget-min-width src/ui/panel_widgets.cpp 's/  if (deciding_width <= avail \* 0.45f \&\& avail - deciding_width >= widget_min_width) {/  if (deciding_width <= avail * 0.45f) {/' "raycam_ui_tests" "^ui: ?a labelled widget keeps the width it asks for"
mutant idle-loop-polls src/app/glfw_host.cpp 's/^    glfwWaitEventsTimeout(std::max(wait, 0.001));/    glfwPollEvents();/' "raycam raycam_app_tests" "^app:an idle window"
mutant french-entry-left-english src/session/text_table.cpp 's|      {"Export colour map PNG", "[^"]*"},|      {"Export colour map PNG", "Export colour map PNG"},|' "$SESSION" "^session:"
mutant show-me-focal-left-at-2 src/session/mistake_lessons.cpp 's/^void focal_scale_show(AppState\& state) { focal(state) = 3.0; }/void focal_scale_show(AppState\& state) { if (focal(state) < 1.5) focal(state) = 3.0; }/' "$SESSION" "^session:"
mutant show-me-object-centred src/session/mistake_lessons.cpp 's/  const Vector screen_centre = nearest->centre + view \* depth - side \* r;/  const Vector screen_centre = nearest->centre + view * depth;/' "$SESSION" "^session:"
# --- fast on scenes it has never seen ---
mutant near-to-far-tie-to-first src/core/band_kernels.h 's/return (t < depth) | ((t == depth) \& (object < id));/return t < depth;/' "$CORE" "$CORE_TESTS"
mutant near-bound-from-the-eye src/core/footprint_caster.cpp 's/out\[i\] = distance - radius\[i\] - corner_distance - 1e-6/out[i] = distance - radius[i] - 1e-6/' "$CORE" "$CORE_TESTS"
mutant pending-tests-left-in-the-queue src/core/footprint_caster.cpp 's/^    run_pending_tests(options.formula, s.pixels);/    (void)0;/' "$CORE" "$CORE_TESTS"
mutant band-sort-reads-one-candidate src/core/footprint_caster.cpp 's/for (const Candidate\& c : s.sorted) use(c);/for (const Candidate\& c : s.sorted) { use(c); break; }/' "$CORE" "$CORE_TESTS"
mutant cluster-culled-by-half-its-radius src/core/screen_footprint.cpp 's/const double grown = r \* (1.0 + 1e-3)/const double grown = 0.5 * r * (1.0 + 1e-3)/' "$CORE" "$CORE_TESTS"
mutant cluster-side-plane-sign-lost src/core/screen_footprint.cpp 's/(-df \* a - c > beyond)/(-df * a + c > beyond)/' "$CORE" "$CORE_TESTS"
mutant clusters-far-to-near src/core/sphere_clusters.cpp 's/const bool first_nearer = eye\[s.axis\] < s.at;/const bool first_nearer = eye[s.axis] >= s.at;/' "$CORE" "$CORE_TESTS"
mutant clusters-split-along-x-only src/core/sphere_clusters.cpp 's/if (high\[a\] - low\[a\] > high\[axis\] - low\[axis\]) axis = a;/(void)a;/' "$CORE" "$CORE_TESTS"
mutant cluster-bound-without-member-radius src/core/sphere_clusters.cpp 's/std::sqrt(d.x \* d.x + d.y \* d.y + d.z \* d.z) + radius\[j\]/std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z)/' "$CORE" "$CORE_TESTS"
mutant bound-float-rounded-to-nearest src/core/band_kernels.h 's/return float(d - std::abs(d) \* 0x1p-22 - 0x1p-126);/return float(d);/' "$CORE" "$CORE_TESTS"
mutant near-to-far-never-skips src/core/band_kernels.h 's/  for (int i = 0; i < count; ++i) open |= depth\[i\] >= nearest_t;/  open = true;/' "$CORE" "$CORE_TESTS"
# --- one language for error reasons ---
mutant reason-template-in-english src/io/reason_table.cpp 's/"{path} : impossible d'\''ouvrir le fichier de scène"/"{path}: cannot open scene file"/' "$SESSION" "^session: ?error reasons"
mutant nested-reason-left-english src/io/reason_translation.cpp 's/p.nested\[k\] ? translated(/false ? translated(/' "$SESSION" "^session: ?error reasons"
mutant window-shows-reasons-in-english src/session/text.cpp 's/const std::string shown = translate_reason(language, english);/const std::string shown = english;/' "$SESSION" "^session: ?error reasons"
# --- tests that catch what they claim ---
# Nine bugs the suite once let through (issue 38), each caught by the test written for its class of hole.
mutant sandbox-shown-folders-writable src/check/sandbox_policy.cpp 's/{"--ro-bind", dir, dir}/{"--bind", dir, dir}/' "raycam-cli" "^check: ?the sandbox shows a student's folders"
mutant deadline-whole-seconds src/check/student_process.cpp 's/  const auto deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.timeout_seconds));/  const auto deadline = start + std::chrono::seconds(int(limits.timeout_seconds));/' "$CHECK" "^check: ?deadlines"
mutant timeout-flag-rounded src/cli/check_command.cpp 's/\[\&\](double t) { flags.timeout = t; }/[\&](double t) { flags.timeout = double(long(t + 0.5)); }/' "$CHECK" "^check: ?deadlines"
mutant depth-map-skips-row-0 src/check/grading.cpp 's/for (int r = rows - 1; r >= 0; --r)/for (int r = rows - 1; r > 0; --r)/' "$CHECK" "^check: ?the worst pixel"
mutant battery-keeps-last-draw src/check/battery.cpp 's/^    if (all) break;$/    (void)all;/' "$CHECK" "^check: ?a seed's designed cases"
mutant cluster-split-at-wrong-centre src/core/sphere_clusters.cpp 's/splits.push_back({axis, centres\[std::size_t(middle)\].at\[axis\], 0, 0});/splits.push_back({axis, centres[std::size_t(middle - 1)].at[axis], 0, 0});/' "$CORE" "^core: ?every split keeps"
mutant figure-ray-hit-from-the-eye src/figure/construction_figure.cpp 's/nearest_hit_t<2, double>(pixel, u,/nearest_hit_t<2, double>(eye, u,/' "$FIGURE" "^figure: ?every 2D frame's rays"
mutant figure-png-red-blue-swapped src/figure/figure_files.cpp 's/row\[std::size_t(x) \* 3 + 0\] = (pixel\[x\] >> 16) \& 0xff;/row[std::size_t(x) * 3 + 0] = pixel[x] \& 0xff;/; s/row\[std::size_t(x) \* 3 + 2\] = pixel\[x\] \& 0xff;/row[std::size_t(x) * 3 + 2] = (pixel[x] >> 16) \& 0xff;/' "$FIGURE" "^figure: ?a PNG figure fills"
mutant french-reason-parts-swapped src/io/reason_table.cpp 's/"{source} : {field} : on attend {what} ; reçu : {value}"/"{source} : {field} : on attend {value} ; reçu : {what}"/' "$SESSION" "^session: ?error reasons: a sample"
mutant open-keeps-save-as-path src/ui/panel_state.cpp 's/^  if (opened) panels.save_path.clear();  \/\/ Save as starts empty.*$/  \/\/ (Save as kept)/' "raycam_ui_tests" "^ui: ?(the panels follow an opened scene|a scene opened outside the panel)"
# --- a large course: shards, merge, grade books ---
SHARDS="^check:.*(slice|shard|--shard|csv records|merge|Gradescope|gradescope|CSV's last column)|^check: (GNU parallel|Gradescope)"
mutant shard-hash-not-fnv src/check/shards.cpp 's/    hash \*= 1099511628211ull;/    hash *= 1099511628213ull;/' "$CHECK" "$SHARDS"
mutant shard-keeps-every-student src/cli/check_command.cpp 's/\[\&\](const Submission\& s) { return shard_of(s.name, shard.count) != shard.index; }/[\&](const Submission\&) { return false; }/' "$CHECK" "$SHARDS"
mutant shard-exit-1-when-a-student-fails src/cli/check_command.cpp 's/    if (report.count(CaseStatus::checker_error) > 0) return 1;/    if (report.passed() < int(report.results.size())) return 1;/' "$CHECK" "$SHARDS"
mutant merge-key-ignores-quotes src/check/csv_merge.cpp "s/    if (record\[i\] == '\"') quoted = !quoted;/    if (false) quoted = !quoted;/" "$CHECK" "$SHARDS"
mutant merge-ignores-the-seed src/check/batch_record.cpp 's/differs("seed", seed, other.seed)/differs("seed", seed, seed)/' "$CHECK" "$SHARDS"
mutant merge-allows-overlaps src/check/csv_merge.cpp 's/} else if (const auto seen = file_of_key.find(key); seen != file_of_key.end()) {/} else if (const auto seen = file_of_key.find(key); false \&\& seen != file_of_key.end()) {/' "$CHECK" "$SHARDS"
mutant merge-forgets-missing-students src/check/csv_merge.cpp 's/      missing.push_back(escaped_control(student) + " (" +/      (void)(escaped_control(student) + " (" +/' "$CHECK" "$SHARDS"
mutant gradescope-status-pass-fail src/check/lms_grades.cpp 's/{"status", passed ? "passed" : "failed"}/{"status", passed ? "pass" : "fail"}/' "$CHECK" "$SHARDS"
mutant grade-out-of-100-whatever-the-scale src/check/lms_grades.cpp 's/  return n ? scale \* report.passed() \/ double(n) : 0.0;/  return n ? 100.0 * report.passed() \/ double(n) : 0.0;/' "$CHECK" "$SHARDS"
mutant autograder-ignores-the-points examples/gradescope/run_autograder 's/ --scale "\$scale"//' "$CHECK" "$SHARDS"
mutant autograder-build-failure-graded examples/gradescope/run_autograder 's/ 2> build.log ||$/ 2> build.log; true ||/' "$CHECK" "$SHARDS"
mutant shard-slices-from-zero src/check/shards.cpp 's/return int(fnv1a_64(name) % std::uint64_t(count)) + 1; }/return int(fnv1a_64(name) % std::uint64_t(count)); }/' "$CHECK" "$SHARDS"
mutant shard-index-above-count-accepted src/check/shards.cpp 's/ || shard.index > shard.count)/)/' "$CHECK" "$SHARDS"
mutant shard-without-batch-accepted src/cli/check_command.cpp 's/  if (!flags.shard.empty() \&\& !batch) throw/  if (false) throw/' "$CHECK" "$SHARDS"
mutant csv-record-split-inside-quotes src/check/csv_merge.cpp 's/    if (text\[i\] == .".) quoted = !quoted;  \/\/ "" inside/    if (false) quoted = !quoted;  \/\/ "" inside/' "$CHECK" "$SHARDS"
mutant merged-record-keeps-the-shard src/check/csv_merge.cpp 's/  merged.record.shard = Shard{1, 1};/  (void)0;/' "$CHECK" "$SHARDS"
mutant merge-batch-of-the-first-shard src/check/csv_merge.cpp 's/  merged.record.students.assign(batch.begin(), batch.end());/  merged.record.students = first.students;/' "$CHECK" "$SHARDS"
mutant autograder-no-fallback-without-sandbox examples/gradescope/run_autograder 's/^  "\${grade\[@\]}" --no-sandbox$/  true/' "$CHECK" "$SHARDS"
# --- contest-grade bounds per run (issue 32) ---
BOUNDS="^check: ?(bounds|run bounds)"
mutant run-not-in-a-group src/check/student_process.cpp 's/  if (limits.use_run_groups \&\& run_groups_available(no_group)) {/  if (false) {/' "$CHECK" "$BOUNDS"
mutant run-processes-unbounded src/check/run_group.cpp 's/write_text(group->folders_\[1\] + "\/pids.max", processes)/write_text(group->folders_[1] + "\/pids.max", "max")/' "$CHECK" "$BOUNDS"
mutant run-disk-on-the-host src/check/sandbox_policy.cpp 's/{"--size", std::to_string(policy.disk_bytes), "--tmpfs", policy.work}/{"--bind", policy.work, policy.work}/' "$CHECK" "$BOUNDS"
mutant run-status-cpu-dropped src/check/check_run.cpp '/  result.cpu_seconds = run.cpu_seconds;/d' "$CHECK" "$BOUNDS"
mutant keyring-shared src/check/student_process.cpp '/  if (syscall(SYS_keyctl, KEYCTL_JOIN_SESSION_KEYRING, nullptr) < 0) fail_in_child(c.report, kSetupStep);/d' "$CHECK" "$BOUNDS"
mutant home-shown src/check/shown_folders.cpp 's/else if (!home.empty() \&\& inside/else if (false \&\& inside/' "$CHECK" "$BOUNDS"
mutant class-under-usr-shown src/check/sandbox_policy.cpp '/  for (const std::string\& dir : policy.hidden) add(words, {"--tmpfs", dir});/d' "$CHECK" "$BOUNDS"
mutant modes-500-left-behind src/check/folder_removal.cpp 's/^  make_folders_ours(folder);$/  (void)make_folders_ours;/' "$CHECK" "$BOUNDS"
mutant hangup-leaves-folders src/cli/check_command.cpp '/  sigaddset(\&signals, SIGHUP);/d' "$CHECK" "$BOUNDS"
mutant unreadable-submission-crashes src/cli/check_command.cpp 's/        if (geteuid() == 0) s.setup_error = unreadable_by_others/        if (false) s.setup_error = unreadable_by_others/' "$CHECK" "$BOUNDS"
mutant no-sandbox-by-default src/cli/check_command.cpp 's/^    throw std::invalid_argument(textf(header.language, "the sandbox cannot start (%s)/    if (false) throw std::invalid_argument(textf(header.language, "the sandbox cannot start (%s)/' "$CHECK" "$BOUNDS"
mutant dir-substituted-again src/cli/check_command.cpp 's/^      out += dir;/      out += word.substr(at, 5);/' "$CHECK" "$BOUNDS"
mutant stderr-unescaped src/check/check_report.cpp 's/escaped_control(err.substr(start, std::min<std::size_t>(end - start, 160)))/err.substr(start, std::min<std::size_t>(end - start, 160))/' "$CHECK" "$BOUNDS"
mutant cpu-time-not-polled src/check/student_process.cpp '/    if (group \&\& group->cpu_seconds() > cpu_limit) return Stop::cpu_time;/d' "$CHECK" "$BOUNDS"
# Text a student controls, inert (issue 44): bytes that are not UTF-8 shown raw; a folder named =HYPERLINK(...)
# written as a live formula.
TEXT="^check: ?(escaping|csv: (a name|check merge)|json and text|batch: hostile)"
mutant invalid-utf8-shown-raw src/check/escaped_text.cpp 's/^      append_hex(out, byte);$/      out += text[i];/' "$CHECK" "$TEXT"
mutant csv-formula-unguarded src/check/check_report.cpp 's/  const bool formula = !text.empty() \&\& /  const bool formula = false \&\& /' "$CHECK" "$TEXT"
mutant limits-fallback-runs-anyway src/cli/check_command.cpp 's/  if (flags.require_limits) throw/  if (false) throw/' "$CHECK" "$BOUNDS"
# --- one view model, one language, one mistake row, two resolutions, docs that cannot go stale (issue 33) ---
STRUCTURE="raycam_core"  # the structure checks are scripts: any built target will do
mutant doc-names-a-moved-test docs/app.md 's#`tests/session/test_files.cpp`#`tests/ui/test_files.cpp`#' "$STRUCTURE" "^structure: the README"
mutant architecture-row-misses-a-link docs/architecture.md 's/(`camera_path.h`) | core, io, check, figure |/(`camera_path.h`) | core, io, check |/' "$STRUCTURE" "^structure: docs/architecture"
mutant preset-takes-one-res src/io/view_setup.cpp 's/  if (preset.res) camera.set_res(\*preset.res, preset.res_rows.value_or(\*preset.res));/  if (preset.res) camera.set_res(*preset.res);/' "raycam_flags_tests" "^flags: ?.*(nbc|resolution)"
mutant window-drops-the-rows-res src/session/app_state.cpp 's/        set_res_of(camera, state.res, state.res_rows);/        set_res_of(camera, state.res, std::nullopt);/' "raycam_session_tests" "^session: ?the window's two resolutions"
mutant preview-squares-two-res src/session/app_state.cpp 's/std::max(\*state.res_rows \* factor, least)/std::max(state.res * factor, least)/' "raycam_session_tests" "^session: ?the window's two resolutions"
mutant battery-has-one-res-only src/check/battery.cpp 's/fractional_res(j, 44, 25, 35), fractional_res(j, 32, 8, 14));/fractional_res(j, 44, 25, 35));/' "raycam_check_tests" "^check: ?with --two-res a 3D case has two resolutions"
mutant example-student-reads-one-res examples/student/camera.py 's/        rows = useful_size(res_rows, camera\["size"\]\[1\])/        rows = useful_size(res_columns, camera["size"][1])/' "raycam_check_tests raycam-cli" "^check: ?(the example students|a program that reads both resolutions)"
mutant mistake-row-wrong-hook src/core/classic_mistakes.cpp 's/MistakeHook::hit_rule, false,/MistakeHook::pixel, false,/' "$CORE" "^core: ?each mistake's row"
mutant mirrored-claims-only-camera src/core/classic_mistakes.cpp 's/MistakeHook::pixel, false, "a scene not symmetric left to right"/MistakeHook::pixel, true, "a scene not symmetric left to right"/' "$CORE" "^core: ?(each mistake's row|accelerated casters equal)"
mutant check-text-without-french src/check/check_texts.cpp 's/      {"none", "aucun"},/      {"none"},/' "raycam_session_tests" "^session: ?every text of every table has every language"
mutant mistake-label-without-french src/core/classic_mistakes.cpp 's/{"mirrored image", "image en miroir"},/{"mirrored image"},/' "raycam_session_tests" "^session: ?every text of every table has every language"
# --- figures an instructor pastes ---
mutant figure-labels-not-placed src/figure/figure_layout.cpp 's/^        if (cost < best_cost) {/        if (cost < best_cost \&\& d == 0 \&\& ring == 0) {/' "$FIGURE" "^figure:"
mutant figure-text-scales-with-page src/figure/figure_layout.cpp 's/^  b.font = output.font_size_pt;/  b.font = output.font_size_pt * output.page.height_pt \/ 340.0;/' "$FIGURE" "^figure:"
mutant figure-png-without-dpi src/figure/figure_files.cpp 's/^  png_set_pHYs(png, info, per_metre, per_metre, PNG_RESOLUTION_METER);/  (void)per_metre;/' "$FIGURE" "^figure:"
mutant figure-ticks-not-thinned src/figure/figure_layout.cpp 's/^constexpr double kMinTickGap = 2.0; /constexpr double kMinTickGap = 0.0; /' "$FIGURE" "^figure:"
mutant figure-wide-entries-fixed src/figure/construction_figure.cpp 's/^  if (std::strlen(text) <= kWidest) return decimal(value, 3, language);/  return decimal(value, 3, language);/' "$FIGURE" "^figure:"
mutant figure-written-in-place src/figure/figure_writing.cpp 's/^    return temporary;/    return path;/' "$FIGURE" "^figure:"
mutant figure-hyphen-minus src/figure/construction_figure.cpp 's/^      out += kMinus;/      out += "-";/' "$FIGURE" "^figure:"
mutant figure-caption-hides-mistakes src/figure/construction_figure.cpp 's/caption_2d(camera, index, lang) + mistakes_said(camera.mistakes(), 2, lang);/caption_2d(camera, index, lang);/' "$FIGURE" "^figure:"
mutant figure-tikz-y-down src/figure/tikz_file.cpp 's/p.x \* kCmPerPoint, (page_height - p.y) \* kCmPerPoint);/p.x * kCmPerPoint, p.y * kCmPerPoint);/' "$FIGURE" "^figure:"
mutant figure-tikz-short-arrow-over-pc src/figure/math_text.cpp 's/(char_count(run.text) > 1 ? "\\\\overrightarrow{" : "\\\\vec{")/("\\\\vec{")/' "$FIGURE" "^figure:"
mutant figure-huge-disc-as-circle src/figure/figure_layout.cpp 's/^  constexpr double kHugeRadius = 1e4; /  constexpr double kHugeRadius = 1e300; /' "$FIGURE" "^figure:"
mutant figure-export-five-rays src/session/figure_export.cpp 's/^  const figure::FigureOptions options{state.language, content.rays};/  const figure::FigureOptions options{state.language, 5};/' "$SESSION" "^session:.*Export figure"
mutant figure-export-matrix-always src/session/figure_export.cpp 's/^  e.output.matrix = content.matrix;/  e.output.matrix = true;/' "$SESSION" "^session:.*Export figure"
mutant figure-labels-over-objects src/figure/figure_layout.cpp 's/^constexpr double kOverObjectWeight = 150.0;/constexpr double kOverObjectWeight = 1.0;/' "$FIGURE" "^figure:"
mutant figure-docs-slide-too-wide docs/figures.md 's/--pages --size 105x72mm --out cadres.tex/--pages --size 110x72mm --out cadres.tex/' "$FIGURE" "^figure: the docs"
mutant figure-export-stale-wrote src/ui/construction_section.cpp 's/^    if (state.message_source == MessageSource::construction) state.message.clear();/    (void)0;/' "$UI" "^ui: ?Export figure"
mutant figure-far-origin-unnamed src/figure/construction_figure.cpp 's/m.point == Point::target || m.point == Point::origin || m.point == Point::eye/m.point == Point::target || m.point == Point::eye/' "$FIGURE" "^figure:"
mutant figure-far-eye-unnamed src/figure/construction_figure.cpp 's/ || m.point == Point::eye) \&\& !near(m.at)) {/) \&\& !near(m.at)) {/' "$FIGURE" "^figure:"
mutant figure-beamer-standalone-cut src/figure/tikz_file.cpp 's/(output.pages ? slide_of_the_picture(output.page) : "")/std::string()/' "$FIGURE" "^figure:"
mutant figure-page-without-room src/cli/figure_command.cpp 's/^  if (room < figure::kLeastDrawingShare \* output.page.height_pt) {/  if (false) {/' "$FIGURE" "cli rejects: figure a page with no room"
mutant figure-export-rays-in-3d src/ui/construction_section.cpp 's/^  if (dimension(state) == 2)  \/\/ the 3D steps draw no rays/  if (true)  \/\/ the 3D steps draw no rays/' "$UI" "^ui: ?Export figure"
mutant figure-inset-never src/figure/figure_layout.cpp 's/^  if (!cut \&\& !small) return;/  return;/' "$FIGURE" "^figure:"
mutant figure-inset-always src/figure/figure_layout.cpp 's/^  if (!cut \&\& !small) return;/  (void)0;/' "$FIGURE" "^figure:"
mutant figure-inset-under-labels src/figure/figure_layout.cpp 's/^    if (page_.inset.shown()) cost += /    if (false) cost += /' "$FIGURE" "^figure:"
mutant figure-inset-zoom-off-camera src/figure/figure_layout.cpp 's/^  const glm::dvec2 a = to(view.lo), b = to(view.hi), c/  const glm::dvec2 a = to(scene.lo), b = to(scene.lo), c/' "$FIGURE" "^figure:"
mutant figure-inset-main-scale src/figure/figure_layout.cpp 's/^  inset.to_inset.scale = std::min(inner.width() \/ extent.x, inner.height() \/ extent.y);/  inset.to_inset.scale = page.to_page.scale;/' "$FIGURE" "^figure:"
# A name by its own object (issue 48): nearer to another object, its leader without a dot, no refusal.
mutant figure-name-nearer-another src/figure/figure_layout.cpp 's/^          nearest = j == own || box_to_disc(b, page_.discs\[j\]) >= std::max(mine + kNameMargin \* font_, 2.0 \* mine);/          nearest = true;/' "$FIGURE" "^figure: ?every name by its own object"
mutant figure-name-leader-without-dot src/figure/tikz_file.cpp 's/^        t += "\\\\filldraw\[name dot\] "/        if (false) t += "\\\\filldraw[name dot] "/' "$FIGURE" "^figure: ?both writers draw the names"
mutant figure-names-never-refused src/cli/figure_command.cpp 's/^  if (!figure::names_fit(drawn, frames, output)) {/  if (false) {/' "$FIGURE" "cli rejects: figure a page with no room for the names"
mutant figure-inset-not-in-tikz src/figure/tikz_file.cpp 's/^  t += inset_commands(page.inset, at);/  (void)0;/' "$FIGURE" "^figure:"
mutant figure-inset-tikz-scope-open src/figure/tikz_file.cpp 's/^  return t + "\\\\end{scope}\\n";/  return t;/' "$FIGURE" "^figure:"
mutant figure-inset-not-painted src/figure/figure_files.cpp 's/^  draw_inset(cr, page);/  (void)0;/' "$FIGURE" "^figure:"
mutant figure-missing-folder-unnamed src/figure/figure_writing.cpp 's/    if (!folder.empty() \&\& !std::filesystem::is_directory(folder))/    if (false)/' "$FIGURE" "^figure:"
# --- one view model, host capabilities ---
mutant page-grades-in-background src/session/camera_check.cpp 's/if (!link.host.grades_in_background) {/if (false) {/' "$SESSION" "^session: ?a host without a thread"
mutant page-without-picker src/ui/status_line.cpp 's/const bool picker = state.host.picks_files;/const bool picker = false;/' "raycam_render_tests" "^render: ?the page's host offers"
mutant null-host-frame-skips-the-cast src/ui/frame.cpp 's/  recast_if_needed(state, ImGui::IsAnyMouseDown());/  (void)0;/' "raycam_ui_tests" "^ui: ?the null host runs"
# --- grader QA ---
# An instructor's run of docs/check.md found these (a QA pass over issues 32, 37 and 38).
mutant output-folder-trailing-slash-refused src/cli/check_command.cpp 's/^  while (!target.has_filename() \&\& target.has_relative_path()) target = target.parent_path();$/  (void)0;/' "$CHECK" "^check: ?bad outputs, a folder"
mutant env-crlf-without-hint src/check/student_process.cpp 's/result.end == RunResult::End::exited \&\& result.exit_code == 127 \&\&/false \&\&/' "$CHECK" "^check: ?bounds: set-up errors"
mutant fallback-cpu-unsaid src/cli/check_command.cpp 's/^  if (header.sandboxed) header.limits_note += /  if (false) header.limits_note += /' "$CHECK" "^check: run bounds as an ordinary user"
# --- the merged app, driven ---
# A student's and an instructor's walk through the merged window (Tab, non-square, files, figures) found these.
mutant demo-note-stays-over-the-file src/session/app_state.cpp 's/^  if (!state.message_is_error \&\& state.message == demo_note) state.message.clear();/  (void)demo_note;/' "$SESSION" "^session: ?the note that the other dimension"
mutant show-me-res-columns-only src/session/mistake_lessons.cpp 's/^  if (state.res_rows) state.res_rows = res;$/  (void)0;/' "$SESSION" "^session: ?with non-square on, a show-me"
# --- #34 page host ---
# The page's canvas, full screen, idle loop and keys (tests/web/test_host.py, headless Chromium).
WEB_HOST_TEST="^web: the page's host"
mutant page-canvas-not-resized src/web/web_host.cpp 's/new ResizeObserver(fit)/new ResizeObserver(function() {})/g' "web:raycam_web" "$WEB_HOST_TEST"
mutant page-pixel-ratio-ignored src/web/web_host.cpp 's/const ratio = window.devicePixelRatio || 1;/const ratio = 1;/' "web:raycam_web" "$WEB_HOST_TEST"
mutant page-idle-loop-spins src/web/web_host.cpp 's/^  emscripten_pause_main_loop();/  (void)0;/' "web:raycam_web" "$WEB_HOST_TEST"
mutant page-key-taps-unqueued src/glfw_host/glfw_host_base.cpp 's/host.keys_.arrive(key, action == GLFW_PRESS, modifier)/true/' "web:raycam_web" "$WEB_HOST_TEST"
mutant page-f-keys-to-the-browser src/web/web_host.cpp "s/event.key === 'F11' || event.key === 'F12') event.preventDefault();/event.key === 'F11') event.preventDefault();/" "web:raycam_web" "$WEB_HOST_TEST"
mutant page-fullscreen-ignored src/web/web_host.cpp 's/toggle_fullscreen)) toggle_fullscreen();/toggle_fullscreen)) {}/' "web:raycam_web" "$WEB_HOST_TEST"
# --- #35 lecture words ---
# The lecture-hall walk at 3x in French (issue 35 items 2, 5, 6, 8): what a typed path, an export and a label say.
mutant open-failure-empties-box src/ui/panel_state.cpp 's/^  if (!opened && !switched) return;$/  (void)0;/' "raycam_ui_tests" "^ui: ?the panels follow an opened scene"
mutant open-keeps-look-at src/session/app_state.cpp '/^    state.mistake_look_at.clear();  \/\/ a "show me" pointed at the old scene/d' "$SESSION" "^session: ?Open resets every field"
mutant clicks-not-spread src/ui/key_queue.h 's/  static bool changes_a_key(const Event\& e) { return e.key >= 0 || e.button >= 0; }/  static bool changes_a_key(const Event\& e) { return e.key >= 0; }/' "raycam_ui_tests" "^ui: ?Ctrl\+A, Home and a double-click"
mutant chord-split-by-its-modifier src/ui/key_queue.h 's/    return (changes_a_key(e) \&\& changed(id_of(e))) || (e.modifier \&\& pressed_key_);/    return changes_a_key(e) \&\& changed(id_of(e));/' "raycam_ui_tests" "^ui: ?a chord whose modifier"
mutant figure-message-first-file-only src/session/figure_export_text.cpp 's/^  return (first.parent_path() \/ range).string();$/  return files.front();/' "$SESSION" "^session: ?Export figure's messages"
mutant figure-question-rebuilt-every-frame src/ui/construction_section.cpp 's/^    const bool all = panels.figure_replace_pending == 2;$/&\n    panels.figure_replace_files = existing_figure_files(state, panels.figure, panels.figure_path, all);/' "raycam_ui_tests" "^ui: ?Export figure's replace question shows"
mutant overhead-label-at-the-other-end src/ui/overhead_view.cpp 's/^  label(minus, -along,/  label(plus, -along,/' "raycam_render_tests" "^render: ?the 2D overhead labels"
mutant overhead-label-on-a-disc src/ui/overhead_view.cpp 's/^      if (std::any_of(avoid.begin(), avoid.end(), \[\&\](const ScreenDisc\& d) { return box_meets_disc(box, d); })) continue;$/      (void)avoid;/' "raycam_render_tests" "^render: ?the 2D overhead labels"
mutant overhead-label-past-the-view src/ui/overhead_view.cpp 's/^      if (!inside) continue;$/      (void)inside;/' "raycam_render_tests" "^render: ?the 2D overhead labels"
mutant demo-names-in-english src/session/view.cpp 's/^  return demo_object_name(language, name);.*/  return name;/' "raycam_ui_tests raycam_session_tests" "^(ui|session): ?(the inspector names|Export figure names|in French no shipped)"
mutant demo-theta-90 src/io/include/raycam/view_setup.h 's/^inline constexpr double kDemoTheta2DDegrees = 70.0;/inline constexpr double kDemoTheta2DDegrees = 90.0;/' "raycam_render_tests" "^render: ?the 2D demo's construction steps"
# --- #35 lecture layout ---
# The picture keeps its size under a mistake's or a check's header, the verdict whole and in sight, M_d whole,
# the views' drawn labels whole at 3× (tests/render/test_layout_fit.cpp).
mutant header-line-steals-picture src/ui/frame.cpp 's/^  layout.image_title = header.title;$/&\n  if (!header.tooltip.empty()) ImGui::TextUnformatted("MISTAKE ON");/' "raycam_render_tests" "^render: ?the picture keeps its size"
mutant header-verdict-without-short-form src/session/camera_check.cpp 's/^             trf(language, "✗ %lld wrong", r.wrong_pixels)}};$/             }};/' "raycam_render_tests" "^render: ?the picture keeps its size"
mutant verdict-not-scrolled-into-view src/ui/check_panel.cpp 's/^    ImGui::ScrollToRect(ImGui::GetCurrentWindow(), ImRect(low, {high.x, next_step_bottom}));/    (void)0;/' "raycam_render_tests" "^render: ?the picture keeps its size"
mutant md-table-scrolls-sideways src/ui/construction_section.cpp 's/kMinTableFontScale, 1.0f);/1.0f, 1.0f);/' "raycam_ui_tests" "^ui: ?M_d.s table shrinks its font"
mutant overhead-x-at-fixed-offset src/ui/overhead_view.cpp 's/const ImVec2 at{clip_max.x - std::max(14.0f, x_size.x + 5),/const ImVec2 at{clip_max.x - 14,/' "raycam_render_tests" "^render: ?at 1x to 3x on 1024x768"
mutant view-labels-not-fitted src/ui/overhead_view.cpp 's/^  if (measure(text, full).x <= width) return {text, full, measure(text, full)};$/  return {text, full, measure(text, full)};/' "raycam_render_tests" "^render: ?the overhead view's labels cover"
mutant fonts-kept-for-a-new-context src/ui/fonts.cpp 's/ \&\& atlas_is_ours \&\& / \&\& /' "raycam_render_tests" "^render: ?the picture keeps its size"
mutant combo-choice-cut src/ui/panel_widgets.cpp 's/ImGui::CalcTextSize(name).x <= room ? whole :/true ? whole :/' "raycam_render_tests" "^render: ?at 1x to 3x on 1024x768"
mutant idle-window-leaves-verdict-below src/ui/frame.cpp 's/^    panels_.check_waiting |= panel->ScrollTarget.x < FLT_MAX || panel->ScrollTarget.y < FLT_MAX;$/    (void)panel;/' "raycam_render_tests" "^render: ?the picture keeps its size"
mutant verdict-scrolls-under-the-mouse src/ui/check_panel.cpp 's/^  if (in_view.scroll_pending \&\& (in_view.asked || (!mouse_on_panel \&\& !ImGui::IsAnyMouseDown()))) {/  if (in_view.scroll_pending) {/' "raycam_render_tests" "^render: ?a verdict arriving while the mouse"
mutant missing-answer-file-a-crash src/check/check_run.cpp 's/^  if (run.end == RunResult::End::could_not_start) result.status = CaseStatus::bad_output;$/  (void)0;/' "raycam_check_tests" "^check: ?grade_case reads an answer file"
# --- #33 view model leftovers ---
mutant dimension-branch-written-again src/io/view_setup.cpp 's/^  preset = merged(preset, flags.camera);$/&\n  const bool is_2d = setup.dimension == 2;\n  if (is_2d \&\& flags.camera.phi_deg) throw std::invalid_argument("--phi: 3D only");\n  if (is_2d \&\& flags.camera.res_rows) throw std::invalid_argument("--res: one in 2D");\n  if (is_2d \&\& preset.size \&\& preset.size->size() != 1) throw std::invalid_argument("--size: N in 2D");\n  if (!is_2d \&\& preset.size \&\& preset.size->empty()) throw std::invalid_argument("--size: WxH in 3D");\n  if (is_2d) setup.camera2d = camera2d_from_preset(preset);/' "raycam_io" "^structure: at most 30 dimension branches"
# (the six branches make_view_setup had before visit_view_setup: 25 + 6 > 30)
mutant merge-says-shards-is-required src/cli/check_merge_command.cpp 's/^  app.add_option("shards", shards, \(.*\));$/  app.add_option("shards", shards, \1)->required();/' "raycam-cli" "^check: merge without shards"
mutant tr-ignores-the-language src/session/text.cpp 's/return table().lookup(language, english);/return table().lookup(Language::en, english);/' "raycam_session_tests" "^session: ?(each state shows its own language|tr shows French)"
# --- #34 page verdicts and files ---
mutant page-regrades-a-moved-answer src/session/camera_check.cpp 's/  const bool automatic = request_.automatic \&\& link.host.runs_programs;/  const bool automatic = request_.automatic;/' "$SESSION" "^session: ?the page never re-grades"
mutant page-answer-graded-on-screen src/session/camera_check.cpp 's/  const bool for_download = request_.is_file \&\& downloaded_;/  const bool for_download = false;/' "$SESSION" "^session: ?the page grades an answer for the case downloaded"
mutant page-verdict-always-current src/session/camera_check.cpp 's/  return verdict->key == last_key_ ? VerdictState::for_camera_shown/  return true ? VerdictState::for_camera_shown/' "$SESSION" "^session: ?the page (grades|never)"
mutant page-messages-show-folders src/session/shown_files.cpp 's/  if (!host.files_are_downloads) return path;/  return path;/' "$SESSION" "^session: ?(the page names|a file the page|downloads are named)"
mutant page-download-asks-to-replace src/session/app_state.cpp 's/  if (!overwrite \&\& !state.host.files_are_downloads \&\& std::filesystem::exists(path))$/  if (!overwrite \&\& std::filesystem::exists(path))/' "$SESSION" "^session: ?downloads are named"
mutant page-text-advances-unrounded src/figure/text_metrics_font.cpp 's/    m.x_advance += std::round(advance \* scale);/    m.x_advance += advance * scale;/' "$FIGURE" "^figure: ?the page's text metrics"
# --- #34 page speed and big files ---
# The page's mutants rebuild the page (raycam_web_page: scripts/web.sh --build-only in the scratch tree).
mutant big-file-open-unannounced src/web/scene_loading.cpp 's/loading = Loading{Step::announce, path,/loading = Loading{Step::parse, path,/' "raycam_web_page" "^web: a big scene file opens"
# --- raycam-cli figure's demo names ---
mutant cli-figure-demo-names-english src/cli/figure_command.cpp '/^  name_demo_objects(setup, options.language);/d' "raycam-cli" "^cli: figure (--lang fr names|names a scene file)"
# --- #33 panel state in ui ---
mutant session-keeps-a-panel-field src/session/app_state.h 's/^  std::uint64_t scene_opens = 0; .*$/&\n  std::string path_input;  \/\/ the Open box/' "$STRUCTURE" "^structure: src/session reads no panel state"
mutant save-as-forgets-the-question src/ui/panel_state.cpp 's/^    panels.overwrite_pending = asked;$/    (void)asked;/' "raycam_ui_tests" "^ui: ?Save as from the panel"
mutant check-command-not-handed-over src/ui/panel_state.cpp '/^  panels.check_command = options.check_command;$/d' "raycam_ui_tests" "^ui: ?the start-up options reach the panels"
mutant dropped-scene-not-followed src/ui/frame.cpp 's/^  follow_scene_shown(state, panels_);$/  (void)0;/' "raycam_ui_tests" "^ui: ?a scene opened outside the panel"
mutant big-file-size-unannounced src/web/scene_loading.cpp 's/^  if (!error)$/  if (false)/' "raycam_web_page" "^web: a big scene file opens"
mutant big-file-parsed-in-one-go src/web/scene_loading.cpp 's/constexpr double kParseSliceMs = 50.0;/constexpr double kParseSliceMs = 1e9;/' "raycam_web_page" "^web: a big scene file opens"
# --- #34 big files parsed in steps ---
# The resumable scene reader (src/io/scene_file_reader.cpp) against parse_scene_json (test_scene_file_reader.cpp).
READER_TESTS="^core: ?the resumable reader"
mutant reader-drops-a-steps-last-object src/io/scene_file_reader.cpp 's/^      if (milliseconds_since(start) >= budget_ms) break;$/      if (milliseconds_since(start) >= budget_ms) { if (phase_ == Phase::reading \&\& next_object_ > 0) visit_scene(file_, [](auto\& s) { objects_of(s).pop_back(); }); break; }/' "$CORE" "$READER_TESTS"
mutant reader-comma-optional src/io/scene_file_reader.cpp "s/^    if (text_\[at_\] != ',') return false;$/    if (text_[at_] != ',') --at_;/" "$CORE" "$READER_TESTS"
mutant reader-escapes-ignored src/io/scene_file_reader.cpp 's/^    if (text\[at\] == .\\\\.)$/    if (false)/' "$CORE" "$READER_TESTS"
mutant reader-always-in-one-go src/io/scene_file_reader.cpp 's/^      if (!regular) fall_back();/      fall_back();/' "$CORE" "$READER_TESTS"
mutant reader-text-after-the-end src/io/scene_file_reader.cpp 's/^      return at_ == text_.size();/      return true;/' "$CORE" "$READER_TESTS"
# --- #34 page speed: writing the band (item 8) ---
mutant background-group-one-id-a-word src/core/footprint_caster.cpp 's/constexpr std::uint64_t kSigns = 0x8000000080000000u;/constexpr std::uint64_t kSigns = 0x80000000u;/' "$CORE" "$CORE_TESTS"
mutant covered-count-one-byte-a-word src/core/footprint_caster.cpp 's/covered += std::uint32_t((w \* 0x0101010101010101u) >> 56);/covered += std::uint32_t(w \& 1u);/' "$CORE" "$CORE_TESTS"
# --- QA after the panel move: questions follow the scene on screen ---
mutant questions-survive-tab src/ui/panel_state.cpp 's/^  const bool switched = panels.dimension_seen != shown_dimension;/  const bool switched = false;/' "raycam_ui_tests" "^ui: ?a Replace question is withdrawn"
mutant figure-question-survives-open src/ui/panel_state.cpp '/^  panels.figure_replace_pending = 0;$/d' "raycam_ui_tests" "^ui: ?a Replace question is withdrawn"
mutant verdict-scrolls-on-a-click src/ui/check_panel.cpp 's/^  if (in_view.scroll_pending \&\& (in_view.asked || (!mouse_on_panel \&\& !ImGui::IsAnyMouseDown()))) {/  if (in_view.scroll_pending \&\& (in_view.asked || !ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows))) {/' "raycam_render_tests" "^render: ?a verdict arriving while the mouse"
mutant save-question-beside-saved src/ui/panel_state.cpp '/^    if (state.message_source == MessageSource::files) state.message.clear();$/d' "raycam_ui_tests" "^ui: ?Save as from the panel asks"
mutant bad-start-scene-empties-box src/ui/panel_state.cpp '/^  if (panels.path_input.empty() \&\& options.view.scene_path) panels.path_input = \*options.view.scene_path;$/d' "raycam_ui_tests" "^ui: ?the start-up options reach the panels"
# --- QA: a newer check stops a stale run ---
mutant stale-check-run-kept src/session/camera_check.cpp '/^  if (shared_->running) shared_->cancel_running = true;  \/\/ and stops one still running$/d' "raycam_session_tests" "^session: ?a newer check stops a run"
mutant case-cancel-not-passed src/check/case_verdict.cpp '/^    limits.cancel = source.cancel;$/d' "raycam_session_tests" "^session: ?a newer check stops a run"
mutant run-ignores-cancel src/check/student_process.cpp 's/^  auto cancelled = \[\&\] { return limits.cancel \&\& limits.cancel->load(); };/  auto cancelled = [] { return false; };/' "raycam_session_tests" "^session: ?a newer check stops a run"
mutant colour-map-message-relative src/ui/panel_state.cpp 's/written_message(state.host, state.language, whole)/written_message(state.host, state.language, asked)/' "raycam_render_tests" "^render: ?Export colour map names the file"
# --- #34 page speed: the float culling pass (item 8) ---
FLOAT_TESTS="^core: ?(the float pass|casts with and without the float pass)"
# A growth of one float rounding: the float centre's error alone then drops spheres. (Rows mapped upside
# down is not a mutant: the pixel centres are symmetric, so the test cannot tell, and neither can the ids.)
mutant float-culling-growth-too-small src/core/float_culling.cpp 's/^constexpr float kGrowth = 0x1p-15f;/constexpr float kGrowth = 0x1p-24f;/' "$CORE" "$FLOAT_TESTS"
mutant float-culling-rows-counted-as-columns src/core/float_culling.cpp 's/-f.df, f.rows);/-f.df, f.columns);/' "$CORE" "$FLOAT_TESTS"
mutant float-culling-half-width-centre-only src/core/float_culling.cpp 's/spread \* (std::abs(a) \* far + c2)/spread * c2/' "$CORE" "$FLOAT_TESTS"
mutant float-culling-behind-by-the-near-side src/core/float_culling.cpp 's/const bool behind = far < f.df \* (1.0f - kGrowth);/const bool behind = near < f.df;/' "$CORE" "$FLOAT_TESTS"
mutant float-culling-gathers-the-wrong-radius src/core/footprint_caster.cpp 's/gathered\[3\]\[j\] = spheres.radius\[i\];/gathered[3][j] = spheres.radius[at + std::size_t(j)];/' "$CORE" "$FLOAT_TESTS"
mutant float-culling-keeps-everything src/core/float_culling.cpp 's/^    unseen\[i\] = behind | (bounded \& (off_columns | off_rows));/    unseen[i] = behind \& !behind;/' "$CORE" "$FLOAT_TESTS"
# --- QA leftovers: the colour map's name follows the language; a message in one place ---
mutant colour-map-name-keeps-start-language src/ui/frame.cpp '/^  follow_default_names(state, panels_);$/d' "raycam_ui_tests" "^ui: ?the colour map's default file name follows"
mutant colour-map-typed-name-translated src/ui/panel_state.cpp 's/^    if (panels.export_path == panels.export_default) {  \/\/ never typed over: the new default$/    if (true) {/' "raycam_ui_tests" "^ui: ?the colour map's default file name follows"
mutant message-cut-in-section-too src/ui/messages.cpp 's|^    ImGui::Dummy(ImVec2(wrap, height));  // its room kept.*$|    draw_message(state, panels, "###message/section");|' "raycam_render_tests" "^render: ?a section's message shows in one place"
mutant message-under-the-title-bar src/ui/messages.cpp 's/^  if (top < inside.Min.y || top + height > inside.Max.y) {/  if (top < ImGui::GetWindowPos().y || top + height > inside.Max.y) {/' "raycam_render_tests" "^render: ?a section's message shows in one place"
# --- #49 the lecture hall: messages beside the views, exports that ask ---
mutant message-over-the-views src/ui/frame.cpp 's/^    layout.message = {layout.panel.x, layout.panel.y + layout.panel.h, layout.panel.w, message_h};/    layout.message = {status_area.x, status_area.y - message_h, status_area.w, message_h};/' "raycam_render_tests" "^render: ?a message never takes a view's room"
mutant confirmation-never-goes src/session/app_state.cpp 's/^  if (now - messages.message_since < kConfirmationSeconds) return true;/  return true;/' "raycam_session_tests" "^session: ?a confirmation goes by itself"
mutant colour-map-replaced-without-asking src/ui/panel_state.cpp 's/^  if (!overwrite \&\& !state.host.files_are_downloads \&\& std::filesystem::exists(asked, ignored)) {/  if (false) {/' "raycam_render_tests" "^render: ?Export colour map asks before replacing"
mutant export-names-without-the-dimension src/session/shown_files.cpp 's/^    base += "-" + dimension;.*$/    (void)dimension;/' "raycam_ui_tests" "^ui: ?the colour map's default file name follows"
mutant screenshot-named-in-english src/session/app_state.cpp 's/tr(language, "raycam-screenshot"), i);/"raycam-screenshot", i);/' "raycam_session_tests" "^session: ?screenshots are numbered"
# --- #49 the lecture hall: the views get the room ---
mutant observer-frames-a-bounding-sphere src/session/observer_view.cpp 's/^  const double eye_depth = std::max({across.depth, upwards.depth, front + 1e-3 \* extent});.*$/  const double eye_depth = middle + 0.5 * std::sqrt(3.0) * extent \/ std::sin(0.5 * kObserverFovY * std::min(1.0, aspect));/' "raycam_session_tests" "^session: ?the observer frames the camera, the target"
mutant observer-fit-off-centre src/session/observer_view.cpp 's/^    return Fit{0.5 \* k \* (a - b), 0.5 \* (a + b)};/    return Fit{0.0, std::max(a, b)};/' "raycam_session_tests" "^session: ?the observer frames the camera, the target"
mutant maximised-view-keeps-its-place src/ui/frame.cpp 's/^    \*maximised = layout.views;/    (void)maximised;/' "raycam_render_tests" "^render: ?a view's key or a double-click"
mutant maximise-key-ignored src/ui/shortcuts.cpp "s/^    if (c == '2') toggle_maximised(state, ShownView::overhead);/    (void)0;/" "raycam_render_tests" "^render: ?a view's key or a double-click"
mutant maximise-title-double-click-ignored src/ui/frame.cpp 's/^  if (ImGui::IsItemHovered() \&\& ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) toggle_maximised(display, view);/  (void)display, (void)view;/' "raycam_render_tests" "^render: ?a view's key or a double-click"
mutant k-labels-over-the-axis-names src/ui/overhead_view.cpp 's/^  for (const auto\& \[q, size\] : names) placed.push_back({q, size});/  (void)names;/' "raycam_render_tests" "^render: ?the overhead view's labels cover no"
mutant side-view-over-the-cameras src/ui/overhead_view.cpp 's/^      if (whole.at.y < clip_min.y || covers_label(whole) || meets(whole, avoid)) continue;/      if (whole.at.y < clip_min.y) continue;/' "raycam_render_tests" "^render: ?the overhead view's labels cover no"
mutant eye-height-over-the-cameras src/ui/overhead_view.cpp 's/^      label_beside(at, {1.0, -1.0}, height_size, clip_min, clip_max, taken, avoid, kLabelRings);/      label_beside(at, {1.0, -1.0}, height_size, clip_min, clip_max, taken, {}, kLabelRings);/' "raycam_render_tests" "^render: ?the overhead view's labels cover no"
mutant look-at-under-the-explanation src/ui/mistakes_section.cpp 's/^    look_at_shown |= looking;/    look_at_shown |= looking;\n    if (looking) explain(mistake_text(state, state, lesson).c_str());/' "raycam_render_tests" "^render: ?after a show-me, what to look at"
mutant status-line-drops-the-frame-time src/ui/status_line.cpp 's/^                                     trf(language, "frame %.0f · cast %.1f ms", frame_ms, cast_ms),/                                     trf(language, "cast %.2f ms", cast_ms),/' "raycam_render_tests" "^render: ?the status line shows the frame time"
mutant status-tooltip-unwrapped src/ui/status_line.cpp 's/^    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 0.6f \* ImGui::GetIO().DisplaySize.x);/    ImGui::PushTextWrapPos(-1.0f);/' "raycam_render_tests" "^render: ?the status line shows the frame time"
mutant matrix-table-shrunk-to-fit src/ui/construction_section.cpp 's/^  const int per_grid = std::min(N, int(avail \/ column_width(decimals)));/  const int per_grid = N * column_width(decimals) <= avail ? N : 0;/' "raycam_render_tests" "^render: ?M_d's table is drawn at the panel's font"
mutant pinned-marker-a-pixel-wide src/ui/frame.cpp 's/^      const float side = std::max({cw, ch, ImGui::GetFontSize()});/      const float side = std::max(cw, ch);/' "raycam_render_tests" "^render: ?the pinned pixel's marker is scaled"
mutant wheel-over-the-image-ignored src/ui/frame.cpp 's/^  orbit_with_mouse(state, view_hovered("###image", last_.image), false, false, nullptr);/  (void)0;/' "raycam_render_tests" "^render: ?the wheel over the image"
# --- #34 item 6: the overhead discs' order by a radix sort (10⁶ spheres: 225 -> 42 ms) ---
mutant disc-order-minus-zero-below-zero src/ui/overhead_view.cpp 's/^    const double key = keys\[i\] == 0.0 ? 0.0 : keys\[i\];.*/    const double key = keys[i];/' "raycam_ui_tests" "^ui: ?the overhead discs' order"
mutant disc-order-negatives-not-reversed src/ui/overhead_view.cpp 's/^    bits\[i\] = b >> 63 ? ~b : b | (std::uint64_t(1) << 63);/    bits[i] = b ^ (std::uint64_t(1) << 63);/' "raycam_ui_tests" "^ui: ?the overhead discs' order"
mutant disc-order-skips-a-shared-majority src/ui/overhead_view.cpp 's/^    if (n == 0 || \*std::max_element(start.begin(), start.end()) == n) continue;.*/    if (n == 0 || *std::max_element(start.begin(), start.end()) >= n \/ 2) continue;/' "raycam_ui_tests" "^ui: ?the overhead discs' order"
# --- #44 the handout's protocol by default ---
# One resolution variable is what the handout requires: the pair is asked only by --two-res, and merge tells
# shards graded with it from shards graded without.
mutant battery-asks-two-res-by-default src/check/battery.cpp 's/^    if (!two_res) file.camera.res_rows.reset();$/    (void)two_res;/' "$CHECK" "^check: ?(the default battery asks one|a program that reads res as one number)"
mutant two-res-flag-ignored src/check/battery.cpp 's/^    if (!two_res) file.camera.res_rows.reset();$/    file.camera.res_rows.reset();/' "$CHECK" "^check: ?(the flag --two-res|with --two-res)"
mutant merge-ignores-two-res src/check/batch_record.cpp 's/differs("two_res", two_res, other.two_res)/differs("two_res", two_res, two_res)/' "$CHECK" "$SHARDS"
# --- #47 recording: the lossless format is lossless; the window records on F9 and saves at exit ---
mutant lossless-video-through-yuv src/video/video_writer.cpp 's/AV_PIX_FMT_BGR0/AV_PIX_FMT_YUV444P/g' "raycam_video_tests" "^video: ?record: a lossless MKV"
mutant live-frame-due-one-late src/video/live_recording.cpp 's/last + 1 - written/last - written/' "raycam_video_tests" "^video: ?live recording"
mutant record-key-not-bound src/glfw_host/glfw_host_base.cpp 's/if (key == GLFW_KEY_F9)/if (false)/' "raycam raycam_window_video_tests" "^video: ?window: F9"
mutant recording-lost-at-exit src/app/glfw_host.cpp 's/^  host.save_recording();/  (void)0;/' "raycam raycam_window_video_tests" "^video: ?window: F9"
mutant page-sleeps-while-recording src/web/web_host.cpp 's/if (has_work(state, panels) || state.recording) {/if (has_work(state, panels)) {/' "raycam_web_page" "^web: the page's host"
mutant record-only-takes-the-wrong-view src/cli/record_command.cpp 's/options.only == ShownPart::image      ? layout.image/options.only == ShownPart::image      ? layout.overhead/' "raycam-cli raycam_video_tests" "^video: ?record: --only"
# --- #48 docs that stay true: figures made by one script, long work shows progress ---
# The committed figures are what scripts/docs_figures.sh makes from the scenes as they are: a scene edited
# without the figures remade fails the docs test.
mutant docs-figures-scene-edited scenes/classic2d.json 's/"theta": 70/"theta": 75/' "raycam-cli" "^docs: the figures in docs/figures/"
PROGRESS="^(check: ?progress|cli: bench (speed|accuracy)('s progress| shows| --quiet| --benchmark_filter))"
mutant progress-share-of-steps-not-work src/check/progress_line.cpp 's/std::to_string(done \* 100 \/ progress.work)/std::to_string(progress.step * 100 \/ progress.steps)/' "$CHECK" "$PROGRESS"
mutant bench-accuracy-steps-unweighed src/bench/bench_accuracy.cpp 's/check::ProgressLine progress("bench accuracy", steps, o.quiet, stderr, work);/check::ProgressLine progress("bench accuracy", steps, o.quiet);/' "raycam-cli" "$PROGRESS"
mutant progress-in-place-in-a-log src/check/progress_line.cpp 's/terminal_(isatty(fileno(out)) != 0)/terminal_(true)/' "$CHECK" "$PROGRESS"
mutant progress-a-line-a-step-on-a-terminal src/check/progress_line.cpp 's/terminal_(isatty(fileno(out)) != 0)/terminal_(false)/' "$CHECK" "$PROGRESS"
mutant progress-wider-than-the-terminal src/check/progress_line.cpp 's/if (width > 1 \&\& text.size() > width - 1) {/if (false) {/' "$CHECK" "$PROGRESS"
mutant progress-ignores-quiet src/check/progress_line.cpp 's/^  if (quiet_) return;$/  (void)quiet_;/' "$CHECK" "$PROGRESS"
mutant bench-speed-a-step-per-call src/bench/bench_speed.cpp 's/if (line_ \&\& name != current_) line_->start(current_ = name, work);/if (line_) line_->start(current_ = name, work);/' "raycam-cli" "$PROGRESS"
mutant bench-speed-total-ignores-the-filter src/bench/bench_speed.cpp 's/if (filter.empty() || filter == "all") return true;/return true;/' "raycam-cli" "$PROGRESS"
mutant bench-accuracy-references-uncounted src/bench/bench_accuracy.cpp 's/std::size_t steps = scenes.size(), work = 0;/std::size_t steps = 0, work = 0;/' "raycam-cli" "$PROGRESS"
mutant figure-export-writes-names-missing src/session/figure_export.cpp 's/  if (!figure::names_fit(e.drawn, e.frames, e.output)) {/  if (false) {/' "raycam_session_tests" "^session: ?Export figure refuses"
# --- #46 a seam for objects ---
mutant fast-caster-ignores-planes src/core/ray_caster.cpp 's/ \&\& scene.shapes.empty()) {/) {/' "$CORE" "^core: ?(a scene with planes|spheres alone keep)"
mutant plane-ids-not-after-spheres src/core/ray_caster.cpp@nearer_shape 's/if (t < hit.t) hit = Hit{first_id + int(k), t};/if (t < hit.t) hit = Hit{int(k), t};/' "$CORE" "^core: ?a scene with planes"
mutant plane-seen-behind-the-eye src/core/ray_caster.cpp@plane_hit_t 's/return t >= 0.0 || (any_sign \&\& std::isfinite(t)) ? t : kNoHit<double>;/return std::isfinite(t) ? t : kNoHit<double>;/' "$CORE" "^core: ?a plane and a sphere at the same distance"
mutant plane-ties-to-higher-id src/core/ray_caster.cpp@nearer_shape 's/if (t < hit.t) hit = Hit{first_id + int(k), t};/if (t <= hit.t) hit = Hit{first_id + int(k), t};/' "$CORE" "^core: ?a plane and a sphere at the same distance"
mutant plane-zero-normal-accepted src/core/scene.cpp 's/if (plane.normal == glm::dvec3(0.0))/if (false)/' "$CORE" "^core: ?a plane's point and normal are checked"
mutant scene-file-drops-planes src/io/scene_file.cpp@scene_to_json 's/^    require_file_kinds(scene);$/    (void)0;/' "$CORE" "^core: ?a scene file never drops a plane"
# --- #45 the page: several files as one download, the verdict in sight, wrong pixels found, the graded camera ---
ZIP="^core: ?zip:"
mutant zip-crc-wrong-polynomial src/io/zip_archive.cpp 's/0xEDB88320u/0xEDB88321u/' "$CORE" "$ZIP"
mutant page-download-said-written src/session/shown_files.cpp 's/host.files_are_downloads ? "asked the browser to save %s" : "wrote %s"/"wrote %s"/' "raycam_session_tests" "^session: ?the page says what it asked"
mutant page-steps-offered-beside-their-archive src/session/shown_files.cpp 's/for (const std::string\& file : files) std::filesystem::remove(file, ignored);/(void)ignored;/' "raycam_session_tests" "^session: ?several files become one zip"
VERDICT_IN_SIGHT="^render: ?after an answer the verdict and its next step"
mutant verdict-scrolled-without-its-next-step src/ui/check_panel.cpp 's/ImRect(low, {high.x, next_step_bottom})/ImRect(low, high)/' "raycam_render_tests" "$VERDICT_IN_SIGHT"
mutant page-answer-waits-for-the-mouse src/ui/check_panel.cpp 's/(in_view.asked || (!mouse_on_panel/(false || (!mouse_on_panel/' "raycam_render_tests" "$VERDICT_IN_SIGHT"
mutant check-case-keyed-by-tab src/session/camera_check.cpp "s/<< '|' << state.opened_version << '|'/<< '|' << state.scene_version << '|'/" "raycam_session_tests" "^session: ?the page's verdict comes back"
GRADED="^render: ?with a mistake on, the header says"
mutant graded-camera-header-red-mistake-beside-a-pass src/ui/frame.cpp 's/const bool mistake_part = !mistakes.empty() \&\& !check.names_mistake;/const bool mistake_part = !mistakes.empty();/' "raycam_render_tests" "$GRADED"
mutant graded-camera-header-silent src/session/camera_check.cpp 's/  if (!mistakes.empty() \&\& (r.status == check::CaseStatus::pass/  if (false \&\& (r.status == check::CaseStatus::pass/' "raycam_render_tests" "$GRADED"
WRONG_PIXEL="^render: ?a wrong pixel is named"
mutant wrong-pixel-framed-in-red src/ui/check_panel.cpp 's/IM_COL32(255, 255, 255, 255), 0, 0, thick/IM_COL32(255, 0, 0, 120), 0, 0, thick/' "raycam_render_tests" "$WRONG_PIXEL"
mutant wrong-pixels-named-column-first src/session/camera_check.cpp 's/{int(i \/ std::size_t(verdict.columns)), int(i % std::size_t(verdict.columns))}/{int(i % std::size_t(verdict.columns)), int(i \/ std::size_t(verdict.columns))}/' "raycam_render_tests" "$WRONG_PIXEL"
DIAGNOSIS="^render: ?the diagnosis has a heading"
mutant bad-size-answer-said-no-classic-mistake src/ui/check_panel.cpp 's/ \&\& r.status == check::CaseStatus::fail) {/) {/' "raycam_render_tests" "$DIAGNOSIS"
mutant diagnosis-without-its-heading src/ui/check_panel.cpp 's/  if (!v.diagnosis.empty()) {  \/\/ the bullets. heading: what they are/  if (false) {/' "raycam_render_tests" "$DIAGNOSIS"
mutant slider-labels-each-on-its-own src/ui/panel_widgets.cpp 's/  const float deciding_width = std::max(g_group_label_width, label_width);/  const float deciding_width = label_width;/' "raycam_render_tests" "^render: ?the camera's slider labels"
mutant page-url-first-error-only src/web/web_main.cpp 's/      errors.push_back(reason.what());/      if (errors.empty()) errors.push_back(reason.what());/' "web:raycam_web" "^web: the page in headless Chromium"
mutant fullscreen-label-never-changes src/ui/panels.h 's/return link.in_fullscreen ? "Leave full screen (F11)" : "Fullscreen (F11)";/return "Fullscreen (F11)";/' "web:raycam_web" "^web: the page's host"
mutant page-steps-as-separate-downloads src/ui/construction_section.cpp 's/if (state.host.files_are_downloads \&\& files.size() > 1) {  \/\/ the page: one download, an archive/if (false) {/' "web:raycam_web" "^web: the page's verdicts"
mutant zip-central-directory-offset-off src/io/zip_archive.cpp 's/  put32(out, central_at);/  put32(out, central_at + 1);/' "$CORE" "$ZIP"
# --- #45 item 4 / #49 items 5-6: counts, numbers, JSON reasons, notation and maths in the window's language ---
mutant french-zero-plural src/io/local_format.cpp 's/case Language::fr: return count >= 2 || count <= -2;/case Language::fr: return count != 1;/' "raycam_session_tests" "^session: ?a count picks"
mutant plural-group-ignored src/io/local_format.cpp 's/out += takes_plural(language, count) ? text.substr/out += true ? text.substr/' "raycam_session_tests" "^session: ?the window.s count texts"
mutant decimal-point-in-french src/io/local_format.cpp "s/if (c == '.') c = ',';/if (c == '.') c = '.';/" "raycam_session_tests raycam_ui_tests" "^(session: ?one number formatter|ui: ?the French window writes)"
mutant slider-number-from-imgui src/ui/local_numbers.cpp 's/own_(language != Language::en \&\&/own_(false \&\&/' "raycam_ui_tests" "^ui: ?the French window writes"
mutant bare-count-in-checker-table src/check/check_texts.cpp 's/"%zu {{rendu|rendus}}"/"%zu rendus"/' "raycam_session_tests" "^session: ?no count text"
mutant json-library-reason-shown src/io/scene_file.cpp 's/return at + "text after the end of the JSON value";/return at + reason;/' "raycam_session_tests" "^session: ?error reasons: a sample"
mutant docs-path-in-a-table src/session/text_table.cpp 's/chaque pixel comparé à celui de "/chaque pixel comparé (docs\/check.md) à celui de "/' "raycam_session_tests" "^session: ?no text of the window"
mutant figure-origin-named-o src/figure/construction_figure.cpp 's/"translation $T(\\\\vec{ΩP})$: $M_d/"translation $T(\\\\vec{OP})$: $M_d/' "raycam_session_tests" "^session: ?the window.s construction captions"
mutant shipped-name-untranslated src/io/demo_names.cpp 's/{"left twin", "jumeau gauche"}, //' "raycam_session_tests" "^session: ?in French no shipped"
mutant plain-text-maths-in-a-mistake src/core/classic_mistakes.cpp 's/seuls les impacts t ≥ 0 comptent/seuls les impacts t >= 0 comptent/' "raycam_ui_tests" "^ui: ?the mistakes. explanations"
mutant glyphs-of-the-tables-not-loaded src/ui/fonts.cpp 's/for (const char\* text : shown_table_texts()) builder.AddText(text);/(void)0;/' "raycam_ui_tests" "^ui: ?every character of the window"
mutant format-star-not-expanded src/io/local_format.cpp@one_conversion 's/  for (std::size_t star = spec.find(.\*.); star != std::string::npos;/  for (std::size_t star = std::string::npos; star != std::string::npos;/' "raycam_session_tests" "^session: ?one number formatter per language"
# --- #46 item 3: one table for every word (each call's key in its table; the reasons' plurals) ---
TEXT_CALLS="^session: ?every text call in src/"
REASON_PLURALS="^session: ?(error reasons: a count of 1|no count of an error reason)"
mutant figure-table-key-renamed src/figure/figure_texts.cpp 's/      {"up", "haut"},/      {"upward", "haut"},/' "$SESSION" "$TEXT_CALLS"
mutant figure-call-key-typo src/figure/construction_figure.cpp 's/figure_text(lang, "step ")/figure_text(lang, "step")/' "$SESSION" "$TEXT_CALLS"
mutant checker-call-key-typo src/check/check_report.cpp 's/textf(lang, "warning: %s\\n", h.limits_note/textf(lang, "warning %s\\n", h.limits_note/' "$SESSION" "$TEXT_CALLS"
mutant window-call-key-typo src/session/app_state.cpp 's/tr(state.language, " (drawn with the fast caster)")/tr(state.language, " (drawn by the fast caster)")/' "$SESSION" "$TEXT_CALLS"
mutant reason-plural-form-fixed src/io/reason_translation.cpp 's/text += takes_plural(language, count) ? (\*it)\[4\].str() : (\*it)\[3\].str();/text += (*it)[4].str();/' "$SESSION" "$REASON_PLURALS"
mutant reason-count-not-read src/io/reason_translation.cpp 's/if (k < p.names.size()) whole_number(parts\[k\], count);/(void)whole_number;/' "$SESSION" "$REASON_PLURALS"
mutant reason-plural-group-dropped src/io/reason_table.cpp 's/"ids\[{row}\] : {count} {{colonne|colonnes}} alors que/"ids[{row}] : {count} colonnes alors que/' "$SESSION" "$REASON_PLURALS"
mutant answer-english-count-bare src/check/answer.cpp 's/"ids\[%d\]: %d {{column|columns}} where row 0 has %d"/"ids[%d]: %d columns where row 0 has %d"/' "$SESSION" "$REASON_PLURALS"
MUTANTS_END=1

if [ "${1:-}" = "--list" ]; then
  printf '%s\n' "${names[@]}"
  exit 0
fi
# --check [NAME...]: does each mutant still apply to the tree as it is (its file there, its edit changing it)?
# Nothing is built: seconds for every mutant, so a refactor that moved the code a mutant edits is found at
# once (the structure test runs it) instead of at the next mutation run.
if [ "${1:-}" = "--check" ]; then
  shift
  stale=0 checked=0
  scratch_file=$(mktemp)
  trap 'rm -f "$scratch_file" "$scratch_file.before"' EXIT
  for i in "${!names[@]}"; do
    if [ $# -gt 0 ] && ! printf '%s\n' "$@" | grep -qxF "${names[$i]}"; then continue; fi
    checked=$((checked + 1))
    file=${files[$i]%@*} function=
    [ "$file" = "${files[$i]}" ] || function=${files[$i]#*@}
    if [ ! -f "$ROOT/$file" ]; then
      printf '%-40s %s\n' "${names[$i]}" "does not apply: $file is gone"
      stale=$((stale + 1))
      continue
    fi
    cp "$ROOT/$file" "$scratch_file"
    apply_edit "$scratch_file" "${edits[$i]}" "$function" 2> /dev/null
    applied=$?
    if [ $applied -eq 3 ]; then
      printf '%-40s %s\n' "${names[$i]}" "does not apply: $function() is gone from $file"
      stale=$((stale + 1))
    elif [ $applied -ne 0 ]; then
      printf '%-40s %s\n' "${names[$i]}" "does not apply: its sed script is malformed"
      stale=$((stale + 1))
    elif cmp -s "$ROOT/$file" "$scratch_file"; then
      printf '%-40s %s\n' "${names[$i]}" "does not apply: the code it edits in $file moved"
      stale=$((stale + 1))
    else
      # A script of several substitutions ("s/a/b/; s/c/d/"): each one, applied after those before it, must
      # still change the file, or the mutant is only part of the bug it was written for.
      cp "$ROOT/$file" "$scratch_file"
      while IFS= read -r part; do
        cp "$scratch_file" "$scratch_file.before"
        apply_edit "$scratch_file" "$part" "$function" 2> /dev/null
        if cmp -s "$scratch_file.before" "$scratch_file"; then
          printf '%-40s %s\n' "${names[$i]}" "does not apply: its part '$part' edits nothing in $file"
          stale=$((stale + 1))
          break
        fi
      done < <(printf '%s\n' "${edits[$i]}" | sed 's/; s\//\ns\//g' | { read -r first && [ "$first" != "${edits[$i]}" ] && { echo "$first"; cat; }; })
    fi
  done
  # Every "mutant" line of this script is one mutant (a line whose quoting swallowed the next lines into one
  # argument left 13 unlisted once), and no two share a name.
  written=$(grep -c '^mutant ' "${BASH_SOURCE[0]}")
  if [ $# -eq 0 ] && [ "$written" -ne "${#names[@]}" ]; then
    echo "mutate.sh --check: $written lines begin with 'mutant' but ${#names[@]} mutants were read: a quote is unbalanced" >&2
    stale=$((stale + 1))
  fi
  if [ $# -eq 0 ] && twice=$(printf '%s\n' "${names[@]}" | sort | uniq -d) && [ -n "$twice" ]; then
    echo "mutate.sh --check: two mutants share each of these names: $twice" >&2
    stale=$((stale + 1))
  fi
  if [ $# -gt 0 ] && [ $checked -ne $# ]; then
    echo "mutate.sh --check: $(( $# - checked )) of the names given are not mutants (see --list)" >&2
    exit 2
  fi
  echo "mutate.sh --check: $((checked - stale)) of $checked mutants apply to the tree"
  [ $stale -eq 0 ]
  exit
fi
selected=("$@")
wanted() {
  [ ${#selected[@]} -eq 0 ] && return 0
  local s
  for s in "${selected[@]}"; do [ "$s" = "$1" ] && return 0; done
  return 1
}

# A scratch copy of the working tree as it is (tracked and new files, build directories left out). The files
# arrive in a folder of their own; the tree takes those whose content changed, with a fresh time (tar keeps the
# checkout's: a file edited after an earlier run copied it, but before that run built it, looked older than
# its object, and the mutants then ran against the earlier copy), and drops those the checkout no longer has.
mkdir -p "$TREE"
incoming=$SCRATCH/incoming
rm -rf "$incoming" && mkdir -p "$incoming"
(cd "$ROOT" && git ls-files -co --exclude-standard -z | grep -zv '^build/' |
   tar --null --ignore-failed-read -T - -cf - 2>/dev/null) | tar -xf - -C "$incoming" ||
  { echo "mutate.sh: copying the tree failed" >&2; exit 2; }
(cd "$incoming" && find . -type f -print0) | while IFS= read -r -d '' f; do
  cmp -s "$incoming/$f" "$TREE/$f" || { mkdir -p "$(dirname "$TREE/$f")" && cp "$incoming/$f" "$TREE/$f"; }
done
(cd "$TREE" && find . \( -path ./build -o -path ./build-web \) -prune -o -type f -print0) |
  while IFS= read -r -d '' f; do [ -e "$incoming/$f" ] || rm -f "$TREE/$f"; done
cmake -S "$TREE" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DRAYCAM_WEB_DIR="$WEB_BUILD" "${launcher[@]}" \
  > "$SCRATCH/configure.log" 2>&1 ||
  { echo "mutate.sh: configure failed, see $SCRATCH/configure.log" >&2; exit 2; }
echo "mutate.sh: building the unmutated tree in $BUILD${launcher:+ (ccache)}"
cmake --build "$BUILD" -j"$JOBS" > "$SCRATCH/build.log" 2>&1 || { echo "mutate.sh: the unmutated tree does not build, see $SCRATCH/build.log" >&2; exit 2; }

caught=0 missed=0 broken=0 skipped=0
# Each mutant's block: the "# --- NAME ---" header above it in this file (the score is given per block).
declare -A block_of block_caught block_total
blocks=()
while IFS=$'\t' read -r mutant_name block_name; do
  block_of[$mutant_name]=$block_name
done < <(awk '/^# --- .* ---$/ { sub(/^# --- /, ""); sub(/ ---$/, ""); block = $0 } /^mutant / { print $2 "\t" block }' "$0")
known_targets=$(cmake --build "$BUILD" --target help 2>/dev/null)
# A mutant's targets: native ones in $BUILD, web:NAME ones in $WEB_BUILD (configured at the first).
build_targets() {
  local native=() web=() target
  for target in $1; do
    case $target in web:*) web+=("${target#web:}") ;; *) native+=("$target") ;; esac
  done
  if [ ${#web[@]} -gt 0 ]; then
    [ -f "$WEB_BUILD/CMakeCache.txt" ] ||
      emcmake cmake -S "$TREE" -B "$WEB_BUILD" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" || return 1
    cmake --build "$WEB_BUILD" -j"$JOBS" --target "${web[@]}" || return 1
  fi
  [ ${#native[@]} -eq 0 ] || cmake --build "$BUILD" -j"$JOBS" --target "${native[@]}"
}
report=()
for i in "${!names[@]}"; do
  name=${names[$i]} file=${files[$i]%@*} function=
  [ "$file" = "${files[$i]}" ] || function=${files[$i]#*@}
  wanted "$name" || continue
  missing=""
  for target in ${targets[$i]}; do
    if [ "${target#web:}" != "$target" ]; then command -v emcmake > /dev/null || missing="$missing $target"; continue; fi
    grep -q -E "^\.\.\. $target( |$)" <<< "$known_targets" || missing="$missing $target"
  done
  if [ -n "$missing" ]; then  # e.g. the Embree test without libembree-dev
    printf '%-32s %s\n' "$name" "skipped (not in this build:$missing)"
    skipped=$((skipped + 1))
    continue
  fi
  if [ ! -f "$ROOT/$file" ]; then
    printf '%-32s %s\n' "$name" "NOT APPLIED ($file is gone: update the mutant)"
    broken=$((broken + 1))
    continue
  fi
  cp "$ROOT/$file" "$TREE/$file"  # pristine
  apply_edit "$TREE/$file" "${edits[$i]}" "$function"
  if cmp -s "$ROOT/$file" "$TREE/$file"; then
    result="NOT APPLIED (the code it edits moved: update the mutant)"
    broken=$((broken + 1))
  elif ! build_targets "${targets[$i]}" > "$SCRATCH/$name.build.log" 2>&1; then
    result="DOES NOT BUILD (see $SCRATCH/$name.build.log)"
    broken=$((broken + 1))
  elif ctest --test-dir "$BUILD" -j"$JOBS" -R "${tests[$i]}" -LE slow --timeout 120 > "$SCRATCH/$name.test.log" 2>&1; then
    result="MISSED"
    missed=$((missed + 1))
  else
    failing=$(grep -c -E '^[[:space:]]+[0-9]+ - ' "$SCRATCH/$name.test.log")
    result="caught ($failing tests failed)"
    caught=$((caught + 1))
  fi
  cp "$ROOT/$file" "$TREE/$file"  # restored, and its targets rebuilt, before the next mutant
  build_targets "${targets[$i]}" > /dev/null 2>&1
  printf '%-32s %s\n' "$name" "$result"
  report+=("$name: $result")
  b=${block_of[$name]:-?}
  [ -n "${block_total[$b]:-}" ] || blocks+=("$b")
  block_total[$b]=$((${block_total[$b]:-0} + 1))
  block_caught[$b]=$((${block_caught[$b]:-0} + $([ "${result%% *}" = caught ] && echo 1 || echo 0)))
done
# Leave the scratch build matching the unmutated tree.
cmake --build "$BUILD" -j"$JOBS" > /dev/null 2>&1
total=$((caught + missed + broken))
for b in "${blocks[@]}"; do printf 'mutate.sh: %3d / %-3d caught  %s\n' "${block_caught[$b]}" "${block_total[$b]}" "$b"; done
echo "mutate.sh: $caught caught, $missed missed, $broken not applied or not building, of $total mutants ($skipped skipped)"
[ $missed -eq 0 ] && [ $broken -eq 0 ]
