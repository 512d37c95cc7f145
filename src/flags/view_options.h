// The option groups every command that renders shares (`raycam-cli render`, `shot`, `check`, the app):
//   Camera:  --scene --mode (--view) --target --d --theta --phi --df --res --size
//   Caster:  --method --threads and the accuracy knobs --precision --intersect --spp --frame --placement
//   --exact
// Each function adds one CLI11 option group to `command` writing into the given struct; the help is generated
// from it. Values are checked here with the one message format (flag_values.h); make_view_setup() then
// checks what depends on the scene (a 2D scene takes no --phi, the size's shape, …).
#pragma once

#include <CLI/CLI.hpp>

#include "flags/flag_values.h"
#include "raycam/accuracy_options.h"
#include "raycam/ray_caster.h"
#include "raycam/view_setup.h"

namespace raycam::flags {

// --size's rule: N (2D) or WxH (3D), within the size limits; make_view_setup checks the shape against the
// scene's dimension, and N in 3D means N×N.
ValueRule<std::vector<int>> size_rule();
// --res's rule: R, or RC,RL (columns, rows: the handout's two resolution variables, 3D only, which
// make_view_setup checks), each in ]0, 1].
ValueRule<std::vector<double>> res_rule();

// --lang: one of the languages' codes (raycam/languages.h), its metavar "en|fr".
ValueRule<Language> language_rule();
std::string language_metavar();

// Angles are taken in degrees (make_view_setup converts them once).
CLI::Option_group* add_view_options(CLI::App& command, ViewFlags& view);

// --method and --threads into `cast`; the accuracy knobs into `accuracy` (the command then asks
// needs_reference_caster() which caster draws).
CLI::Option_group* add_caster_options(CLI::App& command, CastOptions& cast, AccuracyFlags& accuracy);

}  // namespace raycam::flags
