// The option groups every command that renders shares (`raycam-cli render`, `shot`, `check`, the app):
//   Camera:  --scene --mode (--view) --target --d --theta --phi --df --res --size
//   Caster:  --method --threads and the accuracy knobs --precision --intersect --spp --frame --placement
//   --exact
// Each function adds one CLI11 option group to `command` writing into the given struct; the help is generated
// from it. Values are checked here with the one message format (flag_values.h); make_view_setup() then
// checks what depends on the scene (a 2D scene takes no --phi, the size's shape, …).
#pragma once

#include <CLI/CLI.hpp>

#include "raycam/accuracy_options.h"
#include "raycam/ray_caster.h"
#include "raycam/view_setup.h"

namespace raycam::flags {

// Angles are taken in degrees (make_view_setup converts them once).
CLI::Option_group* add_view_options(CLI::App& command, ViewFlags& view);

// --method and --threads into `cast`; the accuracy knobs into `accuracy` (the command then asks
// needs_reference_caster() which caster draws).
CLI::Option_group* add_caster_options(CLI::App& command, CastOptions& cast, AccuracyFlags& accuracy);

}  // namespace raycam::flags
