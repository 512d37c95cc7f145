// Every visible string of the window, in English (the key) and French. French follows the handout's words
// and notation: distance focale d_f, cible C, œil E, écran, point de visée, résolution res, carte des
// couleurs, barre de couleurs, rayons primaires, homothétie, M_d = T·R·H. Keep printf conversions and any
// "###id" identical in both columns (tests/session/test_text.cpp checks). Group entries by the file that shows
// them, so that branches adding strings rarely touch the same lines.
#include "session/text.h"

namespace raycam::session {

const std::vector<Translation>& translation_table() {
  static const std::vector<Translation> table = {
      // ---- language names (shown in their own language) ----
      {"English", "English"},
      {"Français", "Français"},
      {"Language / Langue###language", "Langue / Language###language"},

      // ---- frame.cpp: window titles ----
      {"Colour bar: n = %d {{pixel|pixels}}, column 0 = the eye's left###image",
       "Barre de couleurs : n = %d {{pixel|pixels}}, colonne 0 = gauche de l'œil###image"},
      {"Image: %d × %d###image", "Image : %d × %d###image"},
      {"Colour bar: n = %d###image", "Barre de couleurs : n = %d###image"},
      {"%d × %d###image", "%d × %d###image"},
      {"Overhead view###overhead", "Vue de dessus###overhead"},
      {"Overhead###overhead", "Dessus###overhead"},
      {"Observer: the camera among the spheres###observer",
       "Observateur : la caméra parmi les sphères###observer"},
      {"Observer###observer", "Observateur###observer"},
      {"Overhead view: the plane, the camera and its rays###overhead",
       "Vue de dessus : le plan, la caméra et ses rayons###overhead"},
      {"Overhead view: looking down the z axis###overhead",
       "Vue de dessus : selon l'axe z vers le bas###overhead"},
      {"Observer: the camera among the spheres (left drag: orbit the camera, right drag: turn the observer, "
       "ctrl+wheel: zoom)###observer",
       "Observateur : la caméra parmi les sphères (glisser : tourner la caméra, clic droit : tourner "
       "l'observateur, ctrl+molette : zoom)###observer"},

      // ---- camera_section.cpp: camera ----
      {"Camera###camera", "Caméra###camera"},
      {"Ray###inspector", "Rayon###inspector"},
      {"Mistakes###mistakes", "Erreurs###mistakes"},
      {"Caster###caster", "Lanceur###caster"},
      {"Files###files", "Fichiers###files"},
      {"Lecture###lecture", "Cours###lecture"},
      {"2D camera", "Caméra 2D"},
      {"3D camera", "Caméra 3D"},
      {"d_f focal distance###df", "d_f distance focale###df"},
      {"d distance to C###d", "d distance à la cible###d"},
      {"θ azimuth###theta", "θ azimut###theta"},
      {"φ polar angle###phi", "φ angle polaire###phi"},
      {"res resolution###res", "res résolution###res"},
      {"res_c columns###res", "res_c colonnes###res"},
      {"res_l rows###res_rows", "res_l lignes###res_rows"},
      {"non-square: res per side", "non carrée : une res par côté"},
      {"target C###target", "cible C###target"},
      {"N max pixels###N", "N pixels max###N"},
      {"max size W, H###size", "taille max L, H###size"},
      {"n = %d × %d, field of view %.1f°", "n = %d × %d, angle d'ouverture %.1f°"},
      {"Reset camera", "Réinitialiser la caméra"},
      {"drag in a view: orbit; wheel: d; shift+wheel: d_f; double-click an object: target",
       "glisser dans une vue : tourner ; molette : d ; maj+molette : d_f ; double-clic sur un objet : cible"},
      {"switched to the built-in %dD demo scene", "passage à la scène de démonstration %dD intégrée"},

      // ---- construction_section.cpp: construction of M_d ----
      {"Construction of M_d###construction", "Construction de M_d###construction"},
      {"step###step", "étape###step"},
      // ---- construction_view.cpp: each step's caption, in the figures' notation (docs/conventions.md) ----
      {"a: the canonical camera (identity): screen centred at Ω, eye E₀",
       "a : la caméra canonique (identité) : écran centré en Ω, œil E₀"},
      {"b: H(1, d_f) sets the focal distance: the eye moves back to E",
       "b : l'homothétie H(1, d_f) règle la distance focale : l'œil recule en E"},
      {"c: R(α) = R(φᵥ)·R(ψ₀) turns u₀ onto v = PC/‖PC‖", "c : R(α) = R(φᵥ)·R(ψ₀) aligne u₀ sur v = PC/‖PC‖"},
      {"d: T(ΩP) moves the screen from Ω to P = C + d(cos θ, sin θ)",
       "d : T(ΩP) place l'écran de Ω en P = C + d(cos θ, sin θ)"},
      {"the canonical camera (identity): screen centred at Ω, eye E₀",
       "la caméra canonique (identité) : écran centré en Ω, œil E₀"},
      {"1: H(1, 1, d_f) sets the focal distance: the eye moves back to E",
       "1 : l'homothétie H(1, 1, d_f) règle la distance focale : l'œil recule en E"},
      {"2: Rz(ψ₀), ψ₀ = +90°, rolls the image upright", "2 : Rz(ψ₀), ψ₀ = +90°, redresse l'image"},
      {"3: Ry(φ) tilts u₀ into the plane y = 0", "3 : Ry(φ) place u₀ dans le plan y = 0"},
      {"4: Rz(θ) turns u₀ onto v", "4 : Rz(θ) rend u₀ colinéaire à v"},
      {"5: T(ΩP) moves the screen from Ω to P: M_d = T·Rz(θ)·Ry(φ)·Rz(ψ₀)·H",
       "5 : T(ΩP) place l'écran de Ω en P : M_d = T·Rz(θ)·Ry(φ)·Rz(ψ₀)·H"},
      {"M_d = T(ΩP)·R(α)·H(1, d_f), α = φᵥ + ψ₀ = %.1f°", "M_d = T(ΩP)·R(α)·H(1, d_f), α = φᵥ + ψ₀ = %.1f°"},
      {"product of the first %d {{factor|factors}}", "produit des %d {{premier facteur|premiers facteurs}}"},

      // ---- inspector_section.cpp: ray inspector ----
      {"Ray inspector###inspector", "Inspecteur de rayon###inspector"},
      {"Hover a pixel of the colour bar or image to see its ray; click to pin it.",
       "Survolez un pixel de la barre de couleurs ou de l'image pour voir son rayon ; cliquez pour le "
       "fixer."},
      {"column %d = pixel k = %d (k = n−1−column)", "colonne %d = pixel k = %d (k = n−1−colonne)"},
      {"row %d, column %d", "ligne %d, colonne %d"},
      {"hit: nothing (background)", "touché : rien (fond)"},
      {"hit: object %d %s at t = %.4f", "touché : objet %d %s en t = %.4f"},

      // ---- mistakes_section.cpp: classic mistakes ----
      {"Classic mistakes###mistakes", "Erreurs classiques###mistakes"},
      {"arccos route near a pole", "calcul par arccos près d'un pôle"},
      {"show me", "montre-moi"},
      {"Look: %s", "Regarder : %s"},

      // ---- frame.cpp / the panel's sections: views that hold still and follow (i11views) ----
      {"Fit view (F)", "Cadrer (F)"},
      {"Fit (F)###fit", "Cadrer (F)###fit"},
      {"holds still while the camera moves; drag: the camera around C",
       "reste fixe quand la caméra bouge ; glisser : la caméra autour de C"},
      {"F", "F"},
      {"fit the overhead view to the scene and the camera",
       "cadrer la vue de dessus sur la scène et la caméra"},

      // ---- overhead_view.cpp: the construction's intermediate camera ----
      {"eye E: z = %.2f", "œil E : z = %.2f"},
      {"side view: x →, z ↑", "vue de côté : x →, z ↑"},
      // ---- overhead_view.cpp: the screen's ends (the demo's object names: raycam/demo_names.h) ----
      {"k = 0", "k = 0"},
      {"k = 0 (eye's right)", "k = 0 (droite de l'œil)"},
      {"column 0", "colonne 0"},
      {"column 0 (eye's left)", "colonne 0 (gauche de l'œil)"},

      // ---- construction_section.cpp: the 3D construction, step by step (i11views) ----
      {"Drawn in orange in both views: the screen (its top edge green), the eye, and the axes image right "
       "(red), "
       "image up (green), view (blue).",
       "Dessinés en orange dans les deux vues : l'écran (son bord haut en vert), l'œil, et les axes droite "
       "de "
       "l'image (rouge), haut de l'image (vert), visée (bleu)."},
      {"Why ψ₀ = +π/2: after Ry(φ)·Rz(ψ₀) the image's up R·(0, 1, 0) must have z > 0. With +π/2 it is "
       "(−cos θ "
       "cos φ, −sin θ cos φ, sin φ), and sin φ > 0. The handout prints −π/2, the opposite vector: world up "
       "points "
       "down and the image is upside down.",
       "Pourquoi ψ₀ = +π/2 : après Ry(φ)·Rz(ψ₀), le haut de l'image R·(0, 1, 0) doit avoir z > 0. Avec "
       "+π/2 "
       "c'est (−cos θ cos φ, −sin θ cos φ, sin φ), et sin φ > 0. Le TD imprime −π/2, le vecteur opposé : le "
       "haut "
       "du monde pointe vers le bas et l'image est à l'envers."},
      {"show the handout's ψ₀ = −π/2", "montrer le ψ₀ = −π/2 du TD"},

      // ---- mistake_lessons.cpp: what each mistake does now, and where to look after "show me" ----
      {"MISTAKE ON: %s", "ERREUR ACTIVE : %s"},
      {"MISTAKE ON", "ERREUR ACTIVE"},
      {"Every ray leaves half a pixel (1/n = %.3g) off its centre: a symmetric scene no longer gives a "
       "symmetric "
       "image.",
       "Chaque rayon part à un demi-pixel (1/n = %.3g) de son centre : une scène symétrique ne donne plus "
       "une "
       "image symétrique."},
      {"At n = %d, half a pixel is too small to see: show me.",
       "Avec n = %d, un demi-pixel est trop petit pour se voir : montre-moi."},
      {"Here |u| = %.2f on the axis to %.2f at the edges.", "Ici |u| = %.2f sur l'axe à %.2f aux bords."},
      {"The stable test takes |f − (f·u)u| as the ray's distance to the centre; that is a distance only if "
       "|u| = "
       "1, and otherwise grows with how far the object is: rays miss everything not touching the screen, so "
       "the "
       "image is background (the ground too). With the naive formula objects swell instead.",
       "Le test stable prend |f − (f·u)u| pour la distance du rayon au centre ; ce n'est une distance que si "
       "|u| = 1, sinon elle grandit avec l'éloignement de l'objet : les rayons manquent tout ce qui ne "
       "touche pas "
       "l'écran, l'image n'est que fond (le sol aussi). Avec la formule naïve, les objets gonflent au "
       "contraire."},
      {"The naive test Δ = b² − c uses b = f·u, too big by |u|: a ray hits when it passes within √(r² + "
       "(|u|² − "
       "1)·b²) of the centre, so every object swells, the far ones most, and covers its neighbours; t is "
       "wrong "
       "too. With the stable formula objects vanish instead.",
       "Le test naïf Δ = b² − c utilise b = f·u, trop grand d'un facteur |u| : un rayon touche s'il passe à "
       "moins "
       "de √(r² + (|u|² − 1)·b²) du centre, donc chaque objet gonfle, les lointains le plus, et recouvre ses "
       "voisins ; t est faux aussi. Avec la formule stable, les objets disparaissent au contraire."},
      {"Placing the camera from P and C with the handout's arccos: an input rounding ε becomes an angle "
       "error "
       "√(2ε), at most ~10⁻⁸ rad in 2D: no pixel moves at any setting (the numbers below show it). Show me "
       "goes "
       "to 3D, where the pole makes it visible.",
       "Placer la caméra à partir de P et C avec l'arccos du TD : un arrondi ε de l'entrée devient une "
       "erreur "
       "d'angle √(2ε), au plus ~10⁻⁸ rad en 2D : aucun pixel ne bouge, quels que soient les réglages (les "
       "nombres ci-dessous le montrent). « Montre-moi » passe en 3D, où le pôle la rend visible."},
      {"Placing the camera from P and C with the handout's arccos: near a pole an input rounding ε becomes "
       "an "
       "angle error √(2ε); below φ ≈ 10⁻⁸ rad cos φ rounds to 1, φ becomes 0 and θ is lost.",
       "Placer la caméra à partir de P et C avec l'arccos du TD : près d'un pôle, un arrondi ε de l'entrée "
       "devient "
       "une erreur d'angle √(2ε) ; sous φ ≈ 10⁻⁸ rad, cos φ s'arrondit à 1, φ devient 0 et θ est perdu."},
      {"res 0.05: each ray leaves from a pixel's left edge, not its centre; toggle to see the image jump half a "
       "pixel",
       "res 0.05 : chaque rayon part du bord gauche d'un pixel, pas de son centre ; cocher et décocher pour voir "
       "l'image sauter d'un demi-pixel"},
      {"d_f = 1: the axis ray has |u| = 1 and is right; the error grows towards the edges of the image",
       "d_f = 1 : le rayon de l'axe a |u| = 1 et il est juste ; l'erreur grandit vers les bords de l'image"},
      {"res·N = 12.75: floor gives 12 pixels, round 13; count them",
       "res·N = 12.75 : la partie entière donne 12 pixels, l'arrondi 13 ; comptez-les"},
      {"the image is now twice as wide as tall: the square screen gives it pixels twice as tall as wide, the "
       "stretched screen sees twice the field across",
       "l'image est maintenant deux fois plus large que haute : l'écran carré lui donne des pixels deux fois "
       "plus hauts que larges, l'écran étiré voit un champ deux fois plus large"},
      {"d_f = 3: without H the field of view stays 90°, as at d_f = 1",
       "d_f = 3 : sans H l'angle d'ouverture reste 90°, comme avec d_f = 1"},
      {"the object nearest the target is now between the eye and the screen, to the right: the correct camera "
       "sees past it, the mistaken one shows it on the right half of the image",
       "l'objet le plus proche de la cible est maintenant entre l'œil et l'écran, à droite : la caméra correcte "
       "voit au-delà, la caméra erronée le montre sur la moitié droite de l'image"},
      {"Rays start at the eye instead of the pixel on the screen: what lies between the eye and the screen is "
       "now seen, and t is measured from the eye. At most settings nothing is there: show me.",
       "Les rayons partent de l'œil au lieu du pixel sur l'écran : ce qui est entre l'œil et l'écran devient "
       "visible, et t se mesure depuis l'œil. Le plus souvent il n'y a rien là : « Montre-moi »."},
      {"The smaller root is taken whatever its sign: a hit behind the ray's start on the screen counts, and "
       "beats any in front. At most settings nothing is behind the screen: show me.",
       "La plus petite racine est prise quel que soit son signe : un impact derrière le départ du rayon sur "
       "l'écran compte, et l'emporte sur ceux de devant. Le plus souvent il n'y a rien derrière l'écran : "
       "« Montre-moi »."},
      {"φ = 10⁻⁷°: arccos returns φ = 0 and θ = 0, so the image turns by θ; toggle to compare",
       "φ = 10⁻⁷° : arccos rend φ = 0 et θ = 0, donc l'image tourne de θ ; cocher et décocher pour comparer"},
      {"θ error now: arccos %.1e rad, atan2 %.1e rad", "erreur sur θ : arccos %.1e rad, atan2 %.1e rad"},
      {"φ error now: arccos %.1e rad, atan2 %.1e rad", "erreur sur φ : arccos %.1e rad, atan2 %.1e rad"},

      // ---- caster_section.cpp: caster and accuracy ----
      {"Caster and accuracy###caster", "Lancer de rayons et précision###caster"},
      {"method###method", "méthode###method"},
      {"automatic", "automatique"},
      {"plain", "simple"},
      {"culled", "élagué"},
      {"footprint", "empreinte"},
      {"binned", "par bandes"},
      {"reference caster", "lanceur de référence"},
      {"Every method gives the plain loop's image; the faster ones skip objects behind the screen or out of "
       "view "
       "and test each object only on the pixels its projection can cover. The status line's tooltip shows "
       "the "
       "work done and skipped.",
       "Toutes les méthodes donnent l'image de la boucle simple ; les plus rapides écartent les objets "
       "derrière "
       "l'écran ou hors champ et ne testent chaque objet que sur les pixels que sa projection peut couvrir. "
       "L'infobulle de la ligne d'état montre le travail fait et évité."},
      {"precision###precision", "précision###precision"},
      {"float", "float"},
      {"double", "double"},
      {"long double", "long double"},
      {"intersection###intersection", "intersection###intersection"},
      {"stable (Ray Tracing Gems)", "stable (Ray Tracing Gems)"},
      {"naive (b² − c)", "naïve (b² − c)"},
      {"samples per pixel###spp", "échantillons par pixel###spp"},
      {"camera-relative rays", "rayons relatifs à la caméra"},
      {"exact bar (area-weighted)", "barre exacte (pondérée par l'aire)"},
      {"These knobs use the reference caster: slower, and the method above is not used. For the handout's "
       "image keep double, stable, 1 sample; float needs the stable formula and camera-relative rays.",
       "Ces réglages utilisent le lanceur de référence : plus lent, et la méthode ci-dessus n'est pas "
       "utilisée. Pour l'image du TD, gardez double, stable, 1 échantillon ; float demande la formule stable "
       "et les rayons relatifs à la caméra."},
      {"double, 1 sample, world coordinates: the fast caster.",
       "double, 1 échantillon, coordonnées du monde : le lanceur rapide."},

      // ---- files_section.cpp: files ----
      {"Scene file###files", "Fichier de scène###files"},
      {"open###open_path", "ouvrir###open_path"},
      {"Open", "Ouvrir"},
      {"save as###save_path", "enregistrer sous###save_path"},
      {"Save camera preset as…", "Enregistrer la caméra sous…"},
      {"%s already exists. Replace it?", "%s existe déjà. Le remplacer ?"},
      {"Replace", "Remplacer"},
      {"Cancel", "Annuler"},
      {"Save as: type the path of the file to write",
       "Enregistrer sous : tapez le chemin du fichier à écrire"},
      {"cannot open %s: %s", "impossible d'ouvrir %s : %s"},
      {"cannot open: %s", "impossible d'ouvrir : %s"},
      {"cannot save: %s", "impossible d'enregistrer : %s"},
      {"demo scene", "scène de démonstration"},
      {"or drop a scene file on the window", "ou déposez un fichier de scène sur la fenêtre"},
      {"Open a scene file…###files_open", "Ouvrir un fichier de scène…###files_open"},
      {"or drop a scene file on the page", "ou déposez un fichier de scène sur la page"},
      {"Download the camera preset (%s)###save_download", "Télécharger la caméra (%s)###save_download"},
      {"TikZ (.tex, for LaTeX) only: SVG, PDF and PNG need the desktop app (drawn by cairo).",
       "TikZ (.tex, pour LaTeX) seulement : SVG, PDF et PNG demandent l'application de bureau (dessinés par cairo)."},
      {"export###export", "exporter###export"},
      {"Export colour map PNG", "Exporter la carte des couleurs (PNG)"},
      // ---- construction_section.cpp: the construction's figures ----
      {"figure###figure_path", "figure###figure_path"},
      {"-colour-map.png", "-carte-des-couleurs.png"},
      {"raycam-screenshot", "raycam-capture"},
      {"Export figure…", "Exporter la figure…"},
      {"Export every step", "Exporter toutes les étapes"},
      {"not every object's name fits on the figure's %d × %d mm page: raycam-cli figure --size %dx%dmm names them all",
       "les noms des objets ne tiennent pas tous sur la page de la figure (%d × %d mm) : raycam-cli figure --size %dx%dmm les place tous"},
      {"The step shown or every step: the camera and its screen after each factor of M_d, one figure a step, "
       "for a handout or slides.",
       "L'étape affichée ou toutes les étapes : la caméra et son écran après chaque facteur de M_d, une figure "
       "par étape, pour un polycopié ou des diapositives."},
      {"%s: expected a name ending in .svg, .pdf, .png or .tex", "%s : nom attendu en .svg, .pdf, .png ou .tex"},
      {"format###figure_format", "format###figure_format"},
      {"rays###figure_rays", "rayons###figure_rays"},
      {"matrix###figure_matrix", "matrice###figure_matrix"},
      {"wrote %d {{file|files}}: %s", "%d {{fichier écrit|fichiers écrits}} : %s"},
      {"%d {{file already exists|files already exist}}: %s. Replace {{it|them}}?",
       "%d {{fichier existe déjà|fichiers existent déjà}} : %s. {{Le|Les}} remplacer ?"},
      {"Replace###figure_replace", "Remplacer###figure_replace"},
      {"Cancel###figure_cancel", "Annuler###figure_cancel"},
      {"Screenshot (F12)", "Capture d'écran (F12)"},
      {"Stop recording (F9)###record", "Arrêter l'enregistrement (F9)###record"},
      {"Record a video (F9)###record", "Enregistrer une vidéo (F9)###record"},
      {"-recording", "-enregistrement"},
      {"recording the window to %s (F9 stops)", "enregistrement de la fenêtre dans %s (F9 l'arrête)"},
      {"wrote %s (%d:%02d, %d {{frame|frames}})", "écrit : %s (%d:%02d, %d {{image|images}})"},
      {"cannot record: %s", "impossible d'enregistrer la vidéo : %s"},
      {"the window has no pixels to record", "la fenêtre n'a aucun pixel à enregistrer"},
      {"asked the browser to save %s (%d:%02d)", "téléchargement de %s demandé au navigateur (%d:%02d)"},
      {"this browser cannot record the page (no MediaRecorder)",
       "ce navigateur ne peut pas enregistrer la page (pas de MediaRecorder)"},
      {"wrote %s", "écrit : %s"},
      {"opened %s", "ouvert : %s"},
      {"saved the camera preset to %s", "caméra enregistrée dans %s"},

      // ---- issue 45 (the page): downloads as asked, the verdict's pixels, the graded camera ----
      {"asked the browser to save %s", "téléchargement de %s demandé au navigateur"},
      {"asked the browser to save %s (%d {{figure|figures}})", "téléchargement de %s demandé au navigateur (%d {{figure|figures}})"},
      {"asked the browser to save the camera preset as %s", "téléchargement de la caméra sous %s demandé au navigateur"},
      {"CHECK: passed for the downloaded case — the image shown shows the mistake « %s »",
       "VÉRIFICATION : réussie pour le cas téléchargé — l'image affichée montre l'erreur « %s »"},
      {"CHECK: passed for your camera — the image shown shows the mistake « %s »",
       "VÉRIFICATION : réussie pour votre caméra — l'image affichée montre l'erreur « %s »"},
      {"✓ case passed — the image shows « %s »", "✓ cas réussi — l'image montre « %s »"},
      {"✓ case passed", "✓ cas réussi"},
      {"CHECK: %lld {{pixel|pixels}} wrong for the downloaded case — the image shown shows the mistake « %s »",
       "VÉRIFICATION : %lld {{pixel faux|pixels faux}} pour le cas téléchargé — l'image affichée montre l'erreur « %s »"},
      {"CHECK: %lld {{pixel|pixels}} wrong for your camera — the image shown shows the mistake « %s »",
       "VÉRIFICATION : %lld {{pixel faux|pixels faux}} pour votre caméra — l'image affichée montre l'erreur « %s »"},
      {"✗ case: %lld wrong — the image shows « %s »", "✗ cas : %lld faux — l'image montre « %s »"},
      {"✗ case: %lld wrong", "✗ cas : %lld faux"},
      {"wrong pixels (row, column), framed on the image: %s", "pixels faux (ligne, colonne), encadrés sur l'image : %s"},
      {"Classic mistakes that make this same image:", "Erreurs classiques qui donnent cette même image :"},
      {"Leave full screen (F11)", "Quitter le plein écran (F11)"},
      {"graded for the downloaded case: the image shown shows the mistake « %s »",
       "noté pour le cas téléchargé : l'image affichée montre l'erreur « %s »"},

      // ---- lecture_section.cpp: lecture mode ----
      {"Lecture mode###lecture", "Mode cours###lecture"},
      {"font scale###font_scale", "taille du texte###font_scale"},
      {"high contrast", "contraste élevé"},
      {"Fullscreen (F11)", "Plein écran (F11)"},
      {"Help (F1)", "Aide (F1)"},

      // ---- status_line.cpp: status line ----
      {"frame %.1f ms · cast %.2f ms (%s)", "affichage %.1f ms · lancer de rayons %.2f ms (%s)"},
      {"frame %.1f ms · cast %.2f ms", "affichage %.1f ms · lancer de rayons %.2f ms"},
      {"cast %.2f ms", "rayons %.2f ms"},
      {"caster: %s", "lanceur : %s"},
      {"%lld {{cast|casts}} in %lld {{frame|frames}}", "%lld {{lancer|lancers}} en %lld {{image|images}}"},
      {"rays %lld, %lld {{pixel|pixels}} skipped", "rayons %lld, %lld {{pixel évité|pixels évités}}"},
      {"intersection tests %lld (%.1f%% of the plain loop)",
       "tests d'intersection %lld (%.1f%% de la boucle simple)"},
      {"objects culled %lld", "objets élagués %lld"},
      {" (drawn with the fast caster)", " (dessiné avec le lanceur rapide)"},
      {"Dismiss###dismiss_message", "Fermer###dismiss_message"},
      {"REC %d:%02d (F9 stops)###recording_sign", "ENR %d:%02d (F9 l'arrête)###recording_sign"},
      {"REC %d:%02d###recording_sign", "ENR %d:%02d###recording_sign"},
      {"Panel (P)###show_panel", "Panneau (P)###show_panel"},
      {"Hide the panel (P)###hide_panel", "Cacher le panneau (P)###hide_panel"},
      {"P", "P"},
      {"hide / show the panel: the views take its room", "cacher / montrer le panneau : les vues prennent sa place"},
      {"coarse preview while dragging", "aperçu grossier pendant le glissement"},

      // ---- help_overlay.cpp: help ----
      {"Keyboard and mouse (F1 closes)###help", "Clavier et souris (F1 ferme)###help"},
      {"F1", "F1"},
      {"this help", "cette aide"},
      {"F11", "F11"},
      {"fullscreen", "plein écran"},
      {"The browser refused full screen for this page.", "Le navigateur a refusé le plein écran pour cette page."},
      {"F12", "F12"},
      {"numbered screenshot (raycam-screenshot-NNN.png)",
       "capture d'écran numérotée (raycam-capture-NNN.png)"},
      {"F9", "F9"},
      {"record the window as a video, F9 again stops (SCENE-recording-NNN.mp4; the page: a WebM download)",
       "enregistrer la fenêtre en vidéo, F9 à nouveau l'arrête (SCÈNE-enregistrement-NNN.mp4 ; la page : un téléchargement WebM)"},
      {"← / →", "← / →"},
      {"θ −/+ 5°", "θ −/+ 5°"},
      {"↑ / ↓", "↑ / ↓"},
      {"φ −/+ 5° (3D)", "φ −/+ 5° (3D)"},
      {"+ / −", "+ / −"},
      {"d closer / further", "d plus près / plus loin"},
      {"PgUp / PgDn", "Pg préc. / Pg suiv."},
      {"d_f larger / smaller", "d_f plus grande / plus petite"},
      {"[ / ]", "[ / ]"},
      {"construction step back / forward", "étape de construction précédente / suivante"},
      {"Tab", "Tab"},
      {"2D / 3D", "2D / 3D"},
      {"Esc", "Échap"},
      {"leave a text field; else unpin the inspected pixel",
       "quitter un champ de texte ; sinon libérer le pixel inspecté"},
      {"mouse drag", "glisser"},
      {"orbit the camera (overhead: around the target)",
       "tourner la caméra (vue de dessus : autour de la cible)"},
      {"wheel", "molette"},
      {"d;  shift+wheel: d_f;  ctrl+wheel (observer): zoom",
       "d ;  maj+molette : d_f ;  ctrl+molette (observateur) : zoom"},
      {"right drag", "glisser (clic droit)"},
      {"turn the observer (3D)", "tourner l'observateur (3D)"},
      {"double-click", "double-clic"},
      {"make an object the target", "prendre un objet comme cible"},
      {"click a pixel", "clic sur un pixel"},
      {"pin the ray inspector", "fixer l'inspecteur de rayon"},

      // ---- check_panel.cpp: Check my camera ----
      {"CHECK: %lld {{pixel|pixels}} wrong", "VÉRIFICATION : %lld {{pixel faux|pixels faux}}"},
      {"CHECK: %s", "VÉRIFICATION : %s"},
      {"✗ %lld {{pixel|pixels}} wrong", "✗ %lld {{pixel faux|pixels faux}}"},
      {"✗ %lld wrong", "✗ %lld faux"},
      {"CHECK: passed", "VÉRIFICATION : réussie"},
      {"✓ passed", "✓ réussie"},
      {"Running your program needs the desktop app: a page cannot start a program on your computer.",
       "Lancer votre programme demande l'application de bureau : une page ne peut pas lancer un programme sur "
       "votre ordinateur."},
      {"Check my camera###check", "Vérifier ma caméra###check"},
      {"Check###check", "Vérifier###check"},
      {"Your program reads this camera and scene as JSON on stdin and prints {\"ids\": …}; it is checked "
       "whenever they change: every pixel must equal raycam's, except those where a ray grazes an object.",
       "Votre programme lit cette caméra et cette scène en JSON sur stdin et écrit {\"ids\": …} ; il est "
       "vérifié à chaque changement : chaque pixel doit être celui de raycam, sauf là où un rayon frôle un "
       "objet."},
      {"program###check_command", "programme###check_command"},
      {"Your program reads a case (a camera and its scene) as JSON on stdin and prints {\"ids\": …}; a page "
       "cannot run it, so:",
       "Votre programme lit un cas (une caméra et sa scène) en JSON sur stdin et écrit {\"ids\": …} ; une page "
       "ne peut pas le lancer, donc :"},
      {"1. download this camera's case;", "1. téléchargez le cas de cette caméra ;"},
      {"2. run your program on it: python3 my_camera.py < raycam-case.json > answer.json;",
       "2. lancez votre programme dessus : python3 ma_camera.py < raycam-case.json > answer.json ;"},
      {"3. give the answer file: it is graded for the camera of that case, every pixel against raycam's.",
       "3. donnez le fichier de réponse : il est noté pour la caméra de ce cas, chaque pixel comparé à celui de "
       "raycam."},
      {"no answer yet", "pas encore de réponse"},
      {"graded for the camera shown", "noté pour la caméra affichée"},
      {"answer for an earlier camera: download the new case",
       "réponse pour une caméra précédente : téléchargez le nouveau cas"},
      {"Clear the verdict###check_clear", "Effacer le verdict###check_clear"},
      {"Download this camera's case###check_case", "Télécharger le cas de cette caméra###check_case"},
      {"Give the answer file…###check_answer", "Donner le fichier de réponse…###check_answer"},
      {"Open a scene file…###open_scene_file", "Ouvrir un fichier de scène…###open_scene_file"},
      {"Open…###open_scene_file", "Ouvrir…###open_scene_file"},
      {"type a scene file's path in the box, then Open",
       "tapez le chemin d'un fichier de scène dans la case, puis Ouvrir"},
      {"answer file: %s", "fichier de réponse : %s"},
      {"an answer file, not a program###check_is_file",
       "un fichier de réponse, pas un programme###check_is_file"},
      {"check when the camera changes###check_auto", "vérifier quand la caméra change###check_auto"},
      {"Check now###check_now", "Vérifier###check_now"},
      {"running… (%.1f s)", "en cours… (%.1f s)"},
      {"pass: every pixel agrees", "réussi : chaque pixel est juste"},
      {"fail: %lld of %lld {{pixel|pixels}} wrong (in red on the image)",
       "échec : %lld {{pixel faux|pixels faux}} sur %lld (en rouge sur l'image)"},
      {"%s: %s", "%s : %s"},
      {"opening %s: read %.1f of %.1f MB", "ouverture de %s : %.1f Mo lus sur %.1f"},
      {"opening %s: reading the objects of %.1f MB, then packing them…",
       "ouverture de %s : lecture des objets de %.1f Mo, puis leur rangement…"},
      {"opening %s: finding the objects (%.1f of %.1f MB)", "ouverture de %s : recherche des objets (%.1f Mo sur %.1f)"},
      {"opening %s: objects read %zu of %zu", "ouverture de %s : %zu {{objet lu|objets lus}} sur %zu"},
      {"opening %s: packing %zu {{object|objects}}…", "ouverture de %s : rangement de %zu {{objet|objets}}…"},
      {"opened %s (%zu {{object|objects}}) in %.1f s", "%s ouvert (%zu {{objet|objets}}) en %.1f s"},
      {"(for the camera before your last change)", "(pour la caméra d'avant votre dernier changement)"},
      {"no sandbox: bubblewrap is not available here",
       "pas de bac à sable : bubblewrap n'est pas disponible ici"},
      {"no classic mistake reproduces this image", "aucune erreur classique ne reproduit cette image"},
      // The views in a lecture hall: a view fills their room, where to look after a show-me, the status line.
      {"1 / 2 / 3", "1 / 2 / 3"},
      {"frame %.0f · cast %.1f ms", "affichage %.0f · rayons %.1f ms"},
      {"%.0f ms · %.1f ms", "%.0f ms · %.1f ms"},
      {"column %d:", "colonne %d :"},
      {"columns %d to %d:", "colonnes %d à %d :"},
      {"the image / overhead / observer view fills the views' room; again: back (or double-click its title)",
       "la vue image / de dessus / de l'observateur prend toute la place des vues ; à nouveau : retour (ou double-clic sur son titre)"},
      // The verdicts' names (pass, fail, crash...) are the check command's words: check_texts.cpp.
  };
  return table;
}

}  // namespace raycam::session
