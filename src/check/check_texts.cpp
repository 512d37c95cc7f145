#include "check_texts.h"

#include <cstdarg>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace raycam::check {

namespace {
struct Translation {
  const char* en;
  const char* fr;
};

// French in the handout's words. Keep the printf conversions identical in both columns.
const std::vector<Translation>& table() {
  static const std::vector<Translation> entries = {
      {"raycam-cli check: %zu cases (mode %s, seed %llu), sandbox: %s\n",
       "raycam-cli check : %zu cas (mode %s, graine %llu), bac à sable : %s\n"},
      {"none", "aucun"},
      {"warning: %s\n", "attention : %s\n"},
      {"case", "cas"},
      {"dim", "dim"},
      {"status", "statut"},
      {"wrong pixels", "pixels faux"},
      {"worst pixel or reason", "pire pixel ou raison"},
      {"pass", "réussi"},
      {"fail", "échec"},
      {"crash", "plantage"},
      {"timeout", "trop long"},
      {"bad-output", "sortie invalide"},
      {" (md differs)", " (md diffère)"},
      {"pixel k = %d: expected %d, got %d", "pixel k = %d : attendu %d, obtenu %d"},
      {"row %d, column %d: expected %d, got %d", "ligne %d, colonne %d : attendu %d, obtenu %d"},
      {"score: %d / %d cases passed (%.0f %%)\n", "score : %d / %d cas réussis (%.0f %%)\n"},
      {"diagnosis: no classic mistake, alone or in pairs, reproduces your output.\n",
       "diagnostic : aucune erreur classique, seule ou par deux, ne reproduit votre sortie.\n"},
      {"diagnosis (mistakes that reproduce your output exactly):\n",
       "diagnostic (erreurs qui reproduisent exactement votre sortie) :\n"},
      {"  %zu. %s: explains %zu of %d failing cases (%s)\n", "  %zu. %s : explique %zu des %d cas en échec (%s)\n"},
      {"stderr of case %d:\n", "stderr du cas %d :\n"},
      {"wrote %zu case files to %s (answers go in answer_NN.json beside them)\n",
       "%zu fichiers de cas écrits dans %s (les réponses vont dans answer_NN.json à côté)\n"},
      {"wrote %zu difference images to %s\n", "%zu images de différences écrites dans %s\n"},
      {"the sandbox cannot start and --require-sandbox was given: %s",
       "le bac à sable ne démarre pas et --require-sandbox est donné : %s"},
      {"running student programs WITHOUT a sandbox (%s): they can read and write what you can",
       "programmes des étudiants lancés SANS bac à sable (%s) : ils peuvent lire et écrire ce que vous pouvez"},
      {"%zu submissions x %zu cases on %d threads\n", "%zu rendus x %zu cas sur %d fils\n"},
      {"wrote %s (%zu students)\n", "%s écrit (%zu étudiants)\n"},
  };
  return entries;
}
}  // namespace

const char* text(const std::string& lang, const char* english) {
  if (lang != "fr") return english;
  for (const Translation& t : table())
    if (std::strcmp(t.en, english) == 0) return t.fr;
  return english;
}

std::string textf(const std::string& lang, const char* english_format, ...) {
  const char* format = text(lang, english_format);
  va_list args;
  va_start(args, english_format);
  va_list copy;
  va_copy(copy, args);
  const int size = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string out(std::size_t(std::max(size, 0)), '\0');
  if (size > 0) std::vsnprintf(out.data(), out.size() + 1, format, args);
  va_end(args);
  return out;
}

std::string check_language(const std::string& flag_value) {
  if (flag_value == "fr" || flag_value == "en") return flag_value;
  if (!flag_value.empty()) throw std::invalid_argument("--lang: expected fr or en, got '" + flag_value + "'");
  for (const char* name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) {
    const char* value = std::getenv(name);
    if (value && *value) return std::strncmp(value, "fr", 2) == 0 ? "fr" : "en";
  }
  return "en";
}

}  // namespace raycam::check
