// The panel's "Caster and accuracy" section: the cast method, and the reference caster's knobs (precision,
// intersection formula, samples per pixel, camera-relative rays, the exact bar).
#include "ui/panels.h"

#include <imgui.h>

#include <array>
#include <iterator>
#include <utility>

#include "ui/panel_widgets.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

void caster_section(AppState& state, const PanelState& panels) {
  if (!section(tr(state.language, "Caster and accuracy###caster"), tr(state.language, "Caster###caster"),
                               uses_reference_caster(state) ? ImGuiTreeNodeFlags_DefaultOpen : 0))
    return;
  static constexpr std::pair<Scalar, const char*> kScalars[] = {{Scalar::float32, tr_later("float")},
                                                                {Scalar::float64, tr_later("double")},
                                                                {Scalar::extended, tr_later("long double")}};
  static constexpr std::pair<IntersectFormula, const char*> kFormulas[] = {
      {IntersectFormula::stable, tr_later("stable (Ray Tracing Gems)")},
      {IntersectFormula::naive, tr_later("naive (b² − c)")}};
  static constexpr std::pair<int, const char*> kSamples[] = {{1, "1"}, {4, "4"}, {16, "16"}, {64, "64"}};
  ReferenceOptions& knobs = state.accuracy.options;
  static const auto kMethods = [] {  // the core's list and names
    std::array<std::pair<CastMethod, const char*>, std::size(kCastMethods)> methods;
    for (std::size_t i = 0; i < methods.size(); ++i) methods[i] = {kCastMethods[i], cast_method_name(kCastMethods[i])};
    return methods;
  }();
  bool changed = choice(state.language, panels, tr(state.language, "method###method"), state.cast_options.method, kMethods);
  explain(
      tr(state.language, "Every method gives the plain loop's image; the faster ones skip objects behind the screen or out "
         "of view and test each object only on the pixels its projection can cover. The status line's "
         "tooltip shows the work done and skipped."));
  changed |= choice(state.language, panels, tr(state.language, "precision###precision"), knobs.scalar, kScalars);
  changed |= choice(state.language, panels, tr(state.language, "intersection###intersection"), knobs.formula, kFormulas);
  changed |= choice(state.language, panels, tr(state.language, "samples per pixel###spp"), knobs.samples_per_pixel, kSamples);
  changed |= checkbox(tr(state.language, "camera-relative rays"), &knobs.camera_relative);
  if (exact_bar_applies(state.view))
    changed |= checkbox(tr(state.language, "exact bar (area-weighted)"), &state.accuracy.exact);
  explain(uses_reference_caster(state)
              ? tr(state.language, "These knobs use the reference caster: slower, and the method above is not used. For "
                   "the handout's image keep double, stable, 1 sample; float needs the stable formula and "
                   "camera-relative rays.")
              : tr(state.language, "double, 1 sample, world coordinates: the fast caster."));
  show_message(state, panels, MessageSource::caster);
  if (changed) state.cameras_dirty = true;
}

}  // namespace raycam::ui
