#include "raycam/classic_mistakes.h"

namespace raycam {

// Step numbers are the handout's: exercise 1 (2D camera), 2 (primary rays), 3 (3D camera).
const MistakeInfo kClassicMistakes[kClassicMistakeCount] = {
    {"printed_rotation_sign", &ClassicMistakes::printed_rotation_sign, true, true,
     MistakeHook::placement, true, "a scene not symmetric about the view axis",
     {"printed rotation sign", "signe de rotation imprimé"},
     {"Ex. 1 step 2 / ex. 3 step 3: the rotation must take the angles of CP, not of v = PC; with PC the "
      "camera turns its back to the target.",
      "Ex. 1 étape 2 / ex. 3 étape 3 : la rotation prend les angles de CP, pas de v = PC ; avec PC la "
      "caméra tourne le dos à la cible."}},
    {"pixel_edges", &ClassicMistakes::pixel_edges, true, true,
     MistakeHook::pixel, false, "a small image, so that half a pixel moves an edge",
     {"pixel edges instead of centres", "bords des pixels au lieu des centres"},
     {"Ex. 2: −1 + 2k/n is the left edge of pixel k; its centre is −1 + (2k+1)/n (the image slides half a "
      "pixel).",
      "Ex. 2 : −1 + 2k/n est le bord gauche du pixel k ; son centre est −1 + (2k+1)/n (l'image glisse d'un "
      "demi-pixel)."}},
    {"skip_renormalise", &ClassicMistakes::skip_renormalise, true, true,
     MistakeHook::pixel, false, "d_f away from 1, so that |u| ≠ 1 (both intersection formulas)",
     {"forgot to renormalise uₖ", "uₖ non renormé"},
     {"Ex. 2: M_d contains the scaling H, so uₖ = M_d·u⁰ₖ must be renormalised before an intersection "
      "that assumes |u| = 1.",
      "Ex. 2 : M_d contient l'homothétie H, il faut renormer uₖ = M_d·u⁰ₖ avant une intersection qui "
      "suppose |u| = 1."}},
    {"mirrored", &ClassicMistakes::mirrored, true, true,
     MistakeHook::pixel, false, "a scene not symmetric left to right",
     {"mirrored image", "image en miroir"},
     {"Ex. 2 (last step): pixel k goes at index k, from x = −1 (2D); in 3D column 0 is canonical x near −1.",
      "Ex. 2 (dernière étape) : le pixel k va à l'indice k, depuis x = −1 (2D) ; en 3D la colonne 0 est x "
      "canonique proche de −1."}},
    {"upside_down", &ClassicMistakes::upside_down, false, true,
     MistakeHook::placement, true, "a 3D scene not symmetric top to bottom",
     {"roll −π/2 as printed", "roulis −π/2 imprimé"},
     {"Ex. 3 step 2: the roll ψ₀ = −π/2 as printed turns the image upside down; +π/2 keeps world up "
      "(+z) at the top.",
      "Ex. 3 étape 2 : le roulis ψ₀ = −π/2 imprimé retourne l'image ; +π/2 garde le haut du monde (+z) en "
      "haut."}},
    {"rows_flipped", &ClassicMistakes::rows_flipped, false, true,
     MistakeHook::pixel, false, "a 3D scene not symmetric top to bottom",
     {"rows from the bottom", "lignes depuis le bas"},
     {"Ex. 3 (colmap): row 0 is the top of the image, canonical y near +1; storing from y = −1 flips it.",
      "Ex. 3 (carte des couleurs) : la ligne 0 est le haut de l'image, y canonique proche de +1 ; partir "
      "de y = −1 la retourne."}},
    {"degrees_as_radians", &ClassicMistakes::degrees_as_radians, true, true,
     MistakeHook::placement, true, "angles whose degrees and radians place the camera apart",
     {"degrees used as radians", "degrés pris pour des radians"},
     {"Ex. 1 step 2 / ex. 3 step 3: the angles are given in degrees; cos and sin take radians (multiply by "
      "π/180).",
      "Ex. 1 étape 2 / ex. 3 étape 3 : les angles sont donnés en degrés ; cos et sin prennent des radians "
      "(multiplier par π/180)."}},
    {"no_focal_scale", &ClassicMistakes::no_focal_scale, true, true,
     MistakeHook::placement, true, "d_f away from 1",
     {"scaling H forgotten", "homothétie H oubliée"},
     {"Ex. 1 step 2 / ex. 3 step 1: M_d starts with the scaling H(1, d_f); without it the camera behaves "
      "as if d_f = 1.",
      "Ex. 1 étape 2 / ex. 3 étape 1 : M_d commence par l'homothétie H(1, d_f) ; sans elle la caméra fait "
      "comme si d_f = 1."}},
    {"direction_translated", &ClassicMistakes::direction_translated, true, true,
     MistakeHook::pixel, false, "a screen centre P far from the origin",
     {"direction moved as a point", "direction translatée comme un point"},
     {"Ex. 2: uₖ = M_d·u⁰ₖ is a vector (w = 0): the translation T(ΩP) must not move it.",
      "Ex. 2 : uₖ = M_d·u⁰ₖ est un vecteur (w = 0) : la translation T(ΩP) ne doit pas le déplacer."}},
    {"eye_origin", &ClassicMistakes::eye_origin, true, true,
     MistakeHook::pixel, false, "an object between the eye and the screen",
     {"rays start at the eye", "rayons partant de l'œil"},
     {"Ex. 2: the ray is [Pₖ, uₖ), starting on the screen at Pₖ = M_d·P⁰ₖ; from the eye, objects "
      "between the eye and the screen appear.",
      "Ex. 2 : le rayon est [Pₖ, uₖ), il part de l'écran en Pₖ = M_d·P⁰ₖ ; depuis l'œil, les objets "
      "entre l'œil et l'écran apparaissent."}},
    {"no_t_min", &ClassicMistakes::no_t_min, true, true,
     MistakeHook::hit_rule, false, "an object behind the screen: between it and the eye, or behind the eye",
     {"hits behind the ray accepted", "impacts derrière le rayon acceptés"},
     {"Ex. 2: a ray is a half-line, only hits with t ≥ 0 count; otherwise objects behind the screen come "
      "through.",
      "Ex. 2 : un rayon est une demi-droite, seuls les impacts t ≥ 0 comptent ; sinon les objets derrière "
      "l'écran passent devant."}},
    {"theta_phi_swapped", &ClassicMistakes::theta_phi_swapped, false, true,
     MistakeHook::placement, true, "θ and φ far apart",
     {"θ and φ swapped", "θ et φ inversés"},
     {"Ex. 3 step 3: θ is the azimuth (rotation about z), φ the angle from +z (rotation about y); "
      "they were swapped.",
      "Ex. 3 étape 3 : θ est l'azimut (rotation autour de z), φ l'angle depuis +z (rotation autour de y) ; "
      "ils sont inversés."}},
    {"res_truncated", &ClassicMistakes::res_truncated, true, true,
     MistakeHook::pixel, true, "res < 1 with res·N near an integer plus 0.7 (round and floor then differ)",
     {"n = ⌊res·N⌋", "n = ⌊res·N⌋, partie entière"},
     {"Ex. 1 step 3: the useful size is n = res·N rounded to the nearest integer, not truncated.",
      "Ex. 1 étape 3 : la taille utile est n = res·N arrondi à l'entier le plus proche, pas tronqué."}},
    {"square_pixels", &ClassicMistakes::square_pixels, false, true,
     MistakeHook::pixel, false, "a non-square 3D image",
     {"screen stretched to the image's aspect", "écran étiré au format de l'image"},
     {"Ex. 3: the canonical screen is the square [−1, 1]² whatever nbl and nbc; stretched to the image's "
      "aspect (the square pixels of a look-at camera), a non-square image sees a wider field.",
      "Ex. 3 : l'écran canonique est le carré [−1, 1]², quels que soient nbl et nbc ; étiré au format de "
      "l'image (les pixels carrés d'une caméra « look-at »), une image non carrée voit un champ plus "
      "large."}},
};

const MistakeInfo* find_mistake(std::string_view id) {
  for (const MistakeInfo& info : kClassicMistakes)
    if (id == info.id) return &info;
  return nullptr;
}

bool any_mistake(const ClassicMistakes& mistakes) {
  for (const MistakeInfo& info : kClassicMistakes)
    if (mistakes.*info.flag) return true;
  return false;
}

bool mistakes_change_only_placement(const ClassicMistakes& mistakes) {
  // Those that only move the camera build another M_d (still a rotation times H and T) or another n: the
  // footprint bounds, computed from the camera's own M_d and pixel count, hold for them.
  for (const MistakeInfo& info : kClassicMistakes)
    if (mistakes.*info.flag && !info.only_moves_camera) return false;
  return true;
}

}  // namespace raycam
