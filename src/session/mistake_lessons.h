// The classic mistakes as lessons, on top of the core's table (raycam/classic_mistakes.h: ids, labels and
// the handout's step, in English and French) plus the app's arccos route: for each, what it does to the
// image at the current settings (words that match what the caster really computes), and a one-click
// "show me" that moves to settings where the effect is plain to see, with one line saying what to look at.
#pragma once

#include <string>
#include <vector>

#include "session/app_state.h"
#include "raycam/classic_mistakes.h"

namespace raycam::session {

struct MistakeLesson {
  const char* id;            // the core's id, or "arccos"
  const MistakeInfo* info;   // the core's entry; nullptr for the arccos route (an app setting, not a flag)
  // What the mistake does at the current settings, after the core's one line (nullptr: nothing to add).
  std::string (*what_it_does)(const Lesson&, const CastCache&);
  // Moves to settings where the effect shows; nullptr: it shows at any setting.
  void (*show_me)(AppState&);
  const char* look_at;  // what to look at after "show me" (one line)
};

// Every lesson, in the core's order, then the arccos route.
const std::vector<MistakeLesson>& mistake_lessons();
const MistakeLesson* find_lesson(const std::string& id);
bool& mistake_flag(Lesson& state, const MistakeLesson& lesson);
bool mistake_is_on(const Lesson& state, const MistakeLesson& lesson);
bool mistake_applies(const Lesson& state, const MistakeLesson& lesson);  // exists in the current mode
const char* mistake_label(const Lesson& state, const MistakeLesson& lesson);
// The core's line and what it does at the current settings.
std::string mistake_text(const Lesson& state, const CastCache& cast, const MistakeLesson& lesson);
// Turns the mistake on and moves to settings where it shows (the "show me" button).
void show_mistake(AppState& state, const MistakeLesson& lesson);
// The labels of the mistakes that are on, joined with ", " (empty: none), for the image's header.
std::string mistakes_on(const Lesson& state);

}  // namespace raycam::session
