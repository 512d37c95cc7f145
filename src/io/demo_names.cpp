#include "raycam/demo_names.h"

#include "raycam/language.h"

namespace raycam {

const std::vector<Translation>& demo_object_name_texts() {
  // The shipped scenes' objects (the built-in demos scenes/classic2d.json, classic3d.json, and the other
  // scenes/*.json), by their English names.
  static const std::vector<Translation> texts = {
      {"red", "rouge"},         {"green", "vert"},        {"blue", "bleu"},
      {"yellow", "jaune"},      {"ground", "sol"},        {"top", "en haut"},
      {"on the axis", "sur l'axe"}, {"left twin", "jumeau gauche"}, {"right twin", "jumeau droit"},
      {"far left", "loin à gauche"}, {"far right", "loin à droite"},
  };
  return texts;
}

std::string demo_object_name(Language language, const std::string& english) {
  static const TranslationTable table(demo_object_name_texts());
  return table.lookup(language, english.c_str());
}

void name_demo_objects(ViewSetup& setup, Language language) {
  visit_view_setup(setup, [&](const auto&, auto& scene) {
    for (auto& object : objects_of(scene)) object.name = demo_object_name(language, object.name);
  });
}

}  // namespace raycam
