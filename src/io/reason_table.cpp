// Every error reason raycam shows, English pattern → French (the syntax is raycam/language.h's
// ReasonPattern). Grouped by the code that writes the English; within a group, a specific pattern comes
// before a general one that would also match (the first match wins). Field names, paths, numbers and JSON
// values stay as they are; French typography: a space before ':' and ';', « » around quoted names. A count
// that a noun follows takes a plural group "{{one|many}}" in every language (the English code writes the form
// its count asks for: "1 column", "2 columns").
// tests/session/test_error_reasons.cpp produces every message from its real code path and checks each pattern
// is used.
#include "raycam/language.h"

namespace raycam {

const std::vector<ReasonPattern>& reason_patterns() {
  static const std::vector<ReasonPattern> table = {
      // ---- io: reading a scene file ----
      {"{path}: cannot open scene file", "{path} : impossible d'ouvrir le fichier de scène"},
      {"{path}: is a folder, not a scene file", "{path} : c'est un dossier, pas un fichier de scène"},
      {"{path}: file is larger than the limit of {size} MiB",
       "{path} : fichier trop gros, au-delà de la limite de {size} Mio"},
      {"{path}: cannot read scene file", "{path} : impossible de lire le fichier de scène"},
      {"{source}: JSON syntax error at line {line}, column {column}: {reason*}",
       "{source} : erreur de syntaxe JSON à la ligne {line}, colonne {column} : {reason}"},
      {"{source}: invalid JSON: {reason*}", "{source} : JSON invalide : {reason}"},

      // ---- a JSON syntax error, in raycam's words (scene_file.cpp: syntax_error_reason), after "line L, column C:" ----
      {"a string has no closing double quote", "une chaîne n'a pas de guillemet droit fermant"},
      {"a line break or a tab inside a string (write \\n or \\t)",
       "un saut de ligne ou une tabulation dans une chaîne (écrivez \\n ou \\t)"},
      {"the text is not UTF-8", "le texte n'est pas en UTF-8"},
      {"a backslash in a string starts one of {escapes}", "une barre oblique inverse dans une chaîne commence l'un de {escapes}"},
      {"a malformed number '{word}'", "un nombre mal formé « {word} »"},
      {"text after the end of the JSON value", "du texte après la fin de la valeur JSON"},
      {"unknown word '{word}': a value is a number, a string, an object, an array, true, false or null",
       "mot inconnu « {word} » : une valeur est un nombre, une chaîne, un objet, un tableau, true, false ou null"},
      {"the text ends where {wanted*} was expected", "le texte s'arrête là où on attend {wanted}"},
      {"{found*} where {wanted*} was expected", "{found} là où on attend {wanted}"},
      {"not JSON here", "ce n'est pas du JSON ici"},
      {"a value", "une valeur"},
      {"a key in double quotes", "une clé entre guillemets droits"},
      {"the end of the text", "la fin du texte"},
      {"',' or '}'", "« , » ou « } »"},
      {"',' or ']'", "« , » ou « ] »"},
      {"'{mark}'", "« {mark} »"},
      {"number overflow parsing '{number}'", "nombre trop grand : « {number} »"},

      // ---- io: a scene file's fields (source: field: expected what, got value) ----
      {"{source}: {field}: expected no such field (known: {keys})",
       "{source} : {field} : champ inconnu (champs connus : {keys})"},
      {"{source}: {field*}: expected {what*}, got {value}",
       "{source} : {field} : on attend {what} ; reçu : {value}"},
      {"{source}: {field*}: expected {what*}", "{source} : {field} : on attend {what}"},
      {"(top level)", "(racine du document)"},
      {"a number in {range} degrees", "un nombre de degrés dans {range}"},
      {"a number in {range} or [columns, rows], each in {each}",
       "un nombre dans {range} ou [colonnes, lignes], chacun dans {each}"},
      {"a number in {range}", "un nombre dans {range}"},
      {"a finite number in {range}", "un nombre fini dans {range}"},
      {"a number", "un nombre"},
      {"an integer in {range}", "un entier dans {range}"},
      {"an array of {count} {{number|numbers}}", "un tableau de {count} {{nombre|nombres}}"},
      {"an array of {count} {{integer|integers}} in {range}", "un tableau de {count} {{entier|entiers}} dans {range}"},
      {"a string", "une chaîne de caractères"},
      {"a field \"{key}\" (it is required)", "un champ « {key} » (obligatoire)"},
      {"a JSON object with \"ids\"", "un objet JSON avec « ids »"},
      {"a JSON object {fields}", "un objet JSON {fields}"},
      {"an object {fields}", "un objet {fields}"},
      {"an object", "un objet"},
      {"an array", "un tableau"},
      {"\"{type}\" in a {dimension}D scene", "« {type} » dans une scène {dimension}D"},
      {"[columns, rows]", "[colonnes, lignes]"},
      {"columns x rows <= {count}", "colonnes × lignes <= {count}"},
      {"at most {count} {{object|objects}}", "au plus {count} {{objet|objets}}"},

      // ---- io: writing a scene file, a PNG, an id text ----
      {"{path}: cannot write (no temporary file beside it); left unchanged",
       "{path} : écriture impossible (aucun fichier temporaire possible à côté) ; laissé tel quel"},
      {"{path}: write failed; left unchanged", "{path} : échec de l'écriture ; laissé tel quel"},
      {"{path}: cannot replace file; left unchanged",
       "{path} : impossible de remplacer le fichier ; laissé tel quel"},
      {"{path}: cannot write an empty colour map",
       "{path} : impossible d'écrire une carte des couleurs vide"},
      {"{path}: cannot write PNG (does the directory exist and is it writable?)",
       "{path} : impossible d'écrire le PNG (le dossier existe-t-il, et peut-on y écrire ?)"},
      {"{path}: cannot write the zip archive", "{path} : impossible d'écrire l'archive zip"},
      {"{path}: cannot read the file", "{path} : impossible de lire le fichier"},

      // ---- the construction figure's files (src/figure), exported from the window ----
      {"{path}: cannot write the figure ({reason})", "{path} : impossible d'écrire la figure ({reason})"},
      {"{path}: cannot write the figure: no folder {folder}",
       "{path} : impossible d'écrire la figure : le dossier {folder} n'existe pas"},
      {"{path}: cannot open for writing", "{path} : impossible d'ouvrir le fichier en écriture"},
      {"{path}: cannot write the PNG", "{path} : impossible d'écrire le PNG"},

      // ---- io: the scene file against the command line's flags (shown when the app opens on the demo) ----
      {"--mode: {flag}d does not match the scene file {path}, which is {dimension}D",
       "--mode : {flag}d ne correspond pas au fichier de scène {path}, qui est en {dimension}D"},
      {"--target: expected {components} for a {dimension}D scene",
       "--target : on attend {components} pour une scène {dimension}D"},
      {"--phi: only for 3D scenes (this one is 2D)",
       "--phi : seulement pour une scène 3D (celle-ci est en 2D)"},
      {"--size: expected N for a 2D scene", "--size : on attend N pour une scène 2D"},
      {"--res: expected one number R for a 2D scene (RC,RL is for 3D)",
       "--res : on attend un seul nombre R pour une scène 2D (RC,RL est pour la 3D)"},
      {"--size: expected N in [1, {max}] for a 2D scene",
       "--size : on attend N dans [1, {max}] pour une scène 2D"},
      {"--size: expected N or WxH with sides in [1, {max}]",
       "--size : on attend N ou LxH, chaque côté dans [1, {max}]"},

      // ---- core: a camera or scene out of range ----
      {"{field}: the camera sits on its target (P = C); expected P != C",
       "{field} : la caméra est sur sa cible (P = C) ; on attend P != C"},
      {"{field} = {value} is out of range: expected {what*}",
       "{field} = {value} hors limites : on attend {what}"},
      {"a finite angle with |angle| <= {max} rad", "un angle fini avec |angle| <= {max} rad"},
      {"circles: the exact bar takes at most {max} {{circle|circles}} (its cost is quadratic), got {count}",
       "circles : la barre exacte prend au plus {max} {{cercle|cercles}} (son coût est quadratique) ; reçu : {count}"},

      // ---- the checker: how a run ended (src/check) ----
      {"exit status {code} ({signal*}?)", "code de sortie {code} ({signal} ?)"},
      {"exit status {code}", "code de sortie {code}"},
      {"killed by signal {number} (SIG{name})", "tué par le signal {number} (SIG{name})"},
      {"killed by signal {number}", "tué par le signal {number}"},
      {"no answer within the timeout", "pas de réponse dans le délai"},
      {"more than {size} MiB on stdout: stopped", "plus de {size} Mio sur la sortie : arrêté"},
      {"the checker could not run the program: {reason*}",
       "le correcteur n'a pas pu lancer le programme : {reason}"},
      {"cannot create a temporary directory: {reason}",
       "impossible de créer un dossier temporaire : {reason}"},
      {"cannot find an executable program '{program}'", "aucun programme exécutable nommé « {program} »"},
      {"cannot run '{program}': {reason}", "impossible de lancer « {program} » : {reason}"},
      {"{path}: cannot open the answer file", "{path} : impossible d'ouvrir le fichier de réponse"},

      // ---- the checker: what is wrong with an answer (src/check) ----
      {"not JSON: syntax error at byte {byte}", "pas du JSON : erreur de syntaxe à l'octet {byte}"},
      // (rows before ids: "{count} {{id|ids}}" would also take "2 rows of 2 ids")
      {"expected {rows} {{row|rows}} of {columns} {{id|ids}}, got more",
       "on attend {rows} {{ligne|lignes}} de {columns} {{identifiant|identifiants}} ; davantage reçues"},
      {"expected {rows} {{row|rows}} of {columns} {{id|ids}}, got {got_rows} of {got_columns}",
       "on attend {rows} {{ligne|lignes}} de {columns} {{identifiant|identifiants}} ; reçu : {got_rows} × {got_columns}"},
      {"expected {count} {{id|ids}}, got more", "on attend {count} {{identifiant|identifiants}} ; davantage reçus"},
      {"expected {count} {{id|ids}}, got {got}", "on attend {count} {{identifiant|identifiants}} ; reçu : {got}"},
      {"expected {what*}", "on attend {what}"},
      {"{at} = {id}: expected an id in [-1, {max}]",
       "{at} = {id} : on attend un identifiant dans [-1, {max}]"},
      {"md: expected {rows} {{row|rows}} of {columns} {{number|numbers}} (finite), got {value*}",
       "md : on attend {rows} {{ligne|lignes}} de {columns} {{nombre|nombres}} (finis) ; reçu : {value}"},
      {"md: expected {rows} {{row|rows}} of {columns} {{number|numbers}}",
       "md : on attend {rows} {{ligne|lignes}} de {columns} {{nombre|nombres}}"},
      {"{at*}: expected {what*}, got {value*}", "{at} : on attend {what} ; reçu : {value}"},
      {"the answer", "la réponse"},
      {"an integer id", "un identifiant entier"},
      {"a list of integers", "une liste d'entiers"},
      {"a list of rows", "une liste de lignes"},
      {"the number {number}", "le nombre {number}"},
      {"a number out of range", "un nombre hors limites"},
      {"a boolean", "un booléen"},
      {"a list", "une liste"},
      {"{at}: {number} is not an id", "{at} : {number} n'est pas un identifiant"},
      {"ids[{row}]: {count} {{column|columns}} (or more) where row 0 has {columns}",
       "ids[{row}] : {count} {{colonne|colonnes}} (ou plus) alors que la ligne 0 en a {columns}"},
      {"ids[{row}]: {count} {{column|columns}} where row 0 has {columns}",
       "ids[{row}] : {count} {{colonne|colonnes}} alors que la ligne 0 en a {columns}"},
      {"{at}: nested too deep", "{at} : imbrication trop profonde"},
  };
  return table;
}

}  // namespace raycam
