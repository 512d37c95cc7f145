// The panel's words: the session's lookup (session/text.h: one table, the English text as the key), under
// the ui namespace's names so that the panels write tr(language, "…") as the session does.
#pragma once

#include "session/text.h"

namespace raycam::ui {
using session::tr;
using session::tr_later;
using session::tr_reason;
using session::trf;
using session::translations;
using session::with_no_break_spaces;
}  // namespace raycam::ui
