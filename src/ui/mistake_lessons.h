// The classic mistakes as lessons: for each, whether it is on, what it does to the image at the current
// settings (one line that matches what the caster really computes), and a one-click "show me" that moves to
// settings where the effect is plain to see, with one line saying what to look at.
#pragma once

#include <string>
#include <vector>

#include "app_state.h"

namespace raycam::ui {

struct MistakeLesson {
  const char* id;          // the --mistake name
  const char* label;       // the checkbox
  const char* short_name;  // in the image's header while the mistake is on
  bool& (*flag)(AppState&);
  // What the mistake does, for the current formula, mode and settings.
  std::string (*what_it_does)(const AppState&);
  // Moves to settings where the effect shows (nullptr: it shows at any setting), and what to look at there.
  void (*show_me)(AppState&);
  const char* look_at;
};

const std::vector<MistakeLesson>& mistake_lessons();
// Turns the mistake on and moves to settings where it shows (the "show me" button).
void show_mistake(AppState& state, const MistakeLesson& lesson);
// The short names of the mistakes that are on, joined with ", " (empty: none).
std::string mistakes_on(const AppState& state);

}  // namespace raycam::ui
