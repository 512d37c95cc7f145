#include "figure/figure_texts.h"

#include <string_view>
#include <unordered_map>

namespace raycam::figure {

namespace {
// The captions are cut where a number is written in ("d_f = " … "$: the eye moves back"): each piece is a
// key. French in the handout's words; a space before ':' and ';' as the handout prints it.
const std::vector<LocalText>& table() {
  static const std::vector<LocalText> entries = {
      // A frame's title: "frame (a)", "step 2".
      {"frame (", "cadre ("},
      {"step ", "étape "},
      // The 2D frames (a) … (d).
      {"$M_d = I$: the canonical camera, screen $[−1, 1]$ on the $x$ axis centred at $Ω$, eye $E_0 = (0, "
       "1)$, "
       "$\\vec{u}_0 = (0, −1)$",
       "$M_d = I$ : la caméra canonique, écran $[−1, 1]$ sur l'axe $x$ centré en $Ω$, œil $E_0 = (0, 1)$, "
       "$\\vec{u}_0 = (0, −1)$"},
      {"scaling $H(1, d_f)$, $d_f = ", "homothétie $H(1, d_f)$, $d_f = "},
      {"$: the eye moves back to $E = (0, d_f)$", "$ : l'œil recule en $E = (0, d_f)$"},
      // (reads the same in French)
      {"rotation $R(α) = R(φ_v)·R(ψ_0)$, $ψ_0 = +π/2$, $φ_v = ",
       "rotation $R(α) = R(φ_v)·R(ψ_0)$, $ψ_0 = +π/2$, $φ_v = "},
      {"$: $\\vec{u}$ is aligned with $\\vec{v} = \\vec{PC}/‖\\vec{PC}‖$",
       "$ : $\\vec{u}$ est aligné sur $\\vec{v} = \\vec{PC}/‖\\vec{PC}‖$"},
      {"translation $T(\\vec{ΩP})$: $M_d = T·R·H$, $P = C + d (cos θ, sin θ)$, $d = ",
       "translation $T(\\vec{ΩP})$ : $M_d = T·R·H$, $P = C + d (cos θ, sin θ)$, $d = "},
      // The 3D steps 0 … 5 (steps 3 and 4, "rotation $R_y(φ)$", read the same in both and are written in
      // place).
      {"$M_d = I$: the canonical camera, screen $[−1, 1]^2$ centred at $Ω$, eye $E_0 = (0, 0, 1)$, "
       "$\\vec{u}_0 = (0, 0, −1)$",
       "$M_d = I$ : la caméra canonique, écran $[−1, 1]^2$ centré en $Ω$, œil $E_0 = (0, 0, 1)$, "
       "$\\vec{u}_0 = (0, 0, −1)$"},
      {"scaling $H(1, 1, d_f)$, $d_f = ", "homothétie $H(1, 1, d_f)$, $d_f = "},
      {"$: the eye moves back to $E = (0, 0, d_f)$", "$ : l'œil recule en $E = (0, 0, d_f)$"},
      {"rotation $R_z(ψ_0)$, $ψ_0 = +π/2$: the image's up turns within the screen",
       "rotation $R_z(ψ_0)$, $ψ_0 = +π/2$ : le haut de l'image tourne dans l'écran"},
      {"translation $T(\\vec{ΩP})$: $M_d = T·R_z(θ)·R_y(φ)·R_z(ψ_0)·H$, $d = ",
       "translation $T(\\vec{ΩP})$ : $M_d = T·R_z(θ)·R_y(φ)·R_z(ψ_0)·H$, $d = "},
      {"up", "haut"},  // the camera's up vector, drawn in the 3D steps
      // A caption's last words when the camera drawn has classic mistakes on (their names follow).
      {"; classic mistake on: ", " ; erreur classique activée : "},
  };
  return entries;
}
}  // namespace

const std::vector<LocalText>& figure_translations() { return table(); }

const char* figure_text(Language language, const char* english) {
  static const std::unordered_map<std::string_view, const LocalText*> by_key = [] {
    std::unordered_map<std::string_view, const LocalText*> out;
    for (const LocalText& entry : table()) out.emplace(entry.english(), &entry);
    return out;
  }();
  const auto found = by_key.find(english);
  return found == by_key.end() ? english : (*found->second)[language];
}

}  // namespace raycam::figure
