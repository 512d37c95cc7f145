#include "check/check_texts.h"

#include <cstdarg>
#include <vector>

#include "raycam/language.h"

namespace raycam::check {

namespace {
// French in the handout's words. Keep the printf conversions identical in both columns.
const std::vector<Translation>& table() {
  static const std::vector<Translation> entries = {
      {"raycam-cli check: %zu {{case|cases}} (mode %s, seed %llu), sandbox: %s\n",
       "raycam-cli check : %zu cas (mode %s, graine %llu), bac à sable : %s\n"},
      {"none", "aucun"},
      {"warning: %s\n", "attention : %s\n"},
      {"case", "cas"},
      {"dim", "dim"},
      {"status", "statut"},
      {"wrong pixels", "pixels faux"},
      {"worst pixel or reason", "pire pixel ou raison"},
      {"case %d (%dD)", "cas %d (%dD)"},  // a Gradescope test's name
      {": %lld / %lld wrong {{pixel|pixels}}", " : %lld / %lld {{pixel faux|pixels faux}}"},
      {"pass", "réussi"},
      {"fail", "échec"},
      {"crash", "plantage"},
      {"checker-error", "erreur du correcteur"},
      {"timeout", "trop long"},
      {"bad-output", "sortie invalide"},
      {" (md differs)", " (md diffère)"},
      {"pixel k = %d: expected %d, got %d", "pixel k = %d : attendu %d, obtenu %d"},
      {"row %d, column %d: expected %d, got %d", "ligne %d, colonne %d : attendu %d, obtenu %d"},
      {"score: %d / %d {{case|cases}} passed (%.0f %%)\n", "score : %d / %d cas {{réussi|réussis}} (%.0f %%)\n"},
      {"diagnosis: no classic mistake, alone or in pairs, reproduces your output.\n",
       "diagnostic : aucune erreur classique, seule ou par deux, ne reproduit votre sortie.\n"},
      {"diagnosis (mistakes that reproduce your output exactly):\n",
       "diagnostic (erreurs qui reproduisent exactement votre sortie) :\n"},
      {"  %zu. %s: explains %zu of %d failing {{case|cases}} (%s)\n",
       "  %zu. %s : explique %zu des %d cas en échec (%s)\n"},
      {"stderr of case %d:\n", "stderr du cas %d :\n"},
      {"wrote %zu case {{file|files}} to %s (answers go in answer_NN.json beside them)\n",
       "%zu {{fichier de cas écrit|fichiers de cas écrits}} dans %s (les réponses vont dans answer_NN.json à côté)\n"},
      {"wrote %zu difference {{image|images}} to %s\n",
       "%zu {{image de différences écrite|images de différences écrites}} dans %s\n"},
      {"the sandbox cannot start (%s): student programs run only in it, or without one when --no-sandbox is given",
       "le bac à sable ne démarre pas (%s) : les programmes des étudiants ne tournent que dedans, ou sans lui "
       "si --no-sandbox est donné"},
      {"running student programs WITHOUT a sandbox (%s): they can read and write what you can",
       "programmes des étudiants lancés SANS bac à sable (%s) : ils peuvent lire et écrire ce que vous pouvez"},
      {"%s x %s on %s\n", "%s × %s, %s\n"},  // submissions x cases on threads, each counted()
      {"%zu {{submission|submissions}}", "%zu {{rendu|rendus}}"},
      {"%zu {{case|cases}}", "%zu cas"},
      {"%zu {{thread|threads}}", "%zu {{exécution|exécutions}} à la fois"},
      {"wrote %s (%zu {{student|students}})\n", "%s écrit (%zu {{étudiant|étudiants}})\n"},
      {"memory-limit: the run reached its memory bound (--memory), all its processes together",
       "memory-limit : l'exécution a atteint sa borne de mémoire (--memory), tous ses processus ensemble"},
      {"process-limit: the run reached its bound on processes and threads (--processes)",
       "process-limit : l'exécution a atteint sa borne de processus et de fils (--processes)"},
      {"runs: %.2f s, %.2f s of CPU in all; peak memory %.1f MiB (case %d)\n",
       "exécutions : %.2f s, dont %.2f s de calcul en tout ; mémoire au plus haut %.1f Mio (cas %d)\n"},
      {"CPU time over the timeout (all its processes together)",
       "temps de calcul au-delà du délai (tous ses processus ensemble)"},
      {"fails only the two-resolution case (case %d, res = [res_c, res_l]): your program most likely reads "
       "res as one number. One resolution variable is what the handout requires and all the default "
       "battery asks; this case is asked only by --two-res.\n",
       "seul le cas à deux résolutions échoue (cas %d, res = [res_c, res_l]) : votre programme lit sans doute "
       "res comme un seul nombre. Une seule variable de résolution, c'est ce que le sujet exige et tout ce que "
       "demande la batterie par défaut ; ce cas n'est demandé qu'avec --two-res.\n"},
      {"disk-limit: the run filled its writable folder (--disk)",
       "disk-limit : l'exécution a rempli son dossier inscriptible (--disk)"},
      // A batch's progress: runs and students done, and the time left at the pace so far.
      {"%zu/%zu {{run|runs}}, %zu/%zu {{student|students}}", "%zu/%zu {{exécution|exécutions}}, %zu/%zu {{étudiant|étudiants}}"},
      {"about %d s left", "encore %d s environ"},
      {"about %d min %02d s left", "encore %d min %02d s environ"},
      {"about %d h %02d min left", "encore %d h %02d min environ"},
  };
  return entries;
}
}  // namespace

const std::vector<Translation>& check_translations() { return table(); }

Language check_language(std::optional<Language> flag) { return flag.value_or(language_from_environment()); }

const char* text(Language language, const char* english) {
  static const TranslationTable texts(table());
  return texts.lookup(language, english);
}

std::string textf(Language language, const char* english_format, ...) {
  va_list args;
  va_start(args, english_format);
  std::string out = format_text(language, text(language, english_format), args);
  va_end(args);
  return out;
}

std::string time_left(Language language, std::size_t done, std::size_t total, double elapsed_seconds) {
  if (done == 0 || done >= total || !(elapsed_seconds > 0)) return {};
  // The pace so far, rounded up to whole seconds: "0 s left" would read as done.
  const long long left = (long long)(elapsed_seconds * double(total - done) / double(done)) + 1;
  if (left < 60) return textf(language, "about %d s left", int(left));
  if (left < 3600) return textf(language, "about %d min %02d s left", int(left / 60), int(left % 60));
  return textf(language, "about %d h %02d min left", int(left / 3600), int(left / 60 % 60));
}

}  // namespace raycam::check
