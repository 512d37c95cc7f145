// A slider's or a drag's number in the window's language. ImGui writes a widget's value with the C
// library's printf (a point, whatever the language); in French the widget is drawn without its number and
// the number, written by format_text() (a comma), is drawn where ImGui puts it, centred in the frame.
// While the value is typed (ctrl+click), ImGui's own text is shown: it is what ImGui parses.
#pragma once

#include <imgui.h>

#include "raycam/language.h"

namespace raycam::ui {

class LocalNumber {
 public:
  // `label`: the widget's, "###id" included; `format`: its printf format ("%.1f°").
  LocalNumber(Language language, const char* label, const char* format);
  // The format to give ImGui: `format`, or "" when this draws the number itself.
  const char* format() const { return own_ ? "" : format_; }
  // After the widget: its value rounded as `format` shows it (ImGui rounds only with a format), and the
  // number drawn over the widget's frame.
  double shown(double value) const;

 private:
  Language language_;
  const char* label_;
  const char* format_;
  bool own_;
};

}  // namespace raycam::ui
