// The construction figures as TikZ, for LaTeX course notes and Beamer slides: LaTeX sets the labels ($…$),
// the caption and the matrix (pmatrix) in the document's fonts, at the places the page layout chose.
#pragma once

#include <string>
#include <vector>

#include "figure/construction_figure.h"
#include "figure/figure_layout.h"

namespace raycam::figure {

// The LaTeX of the frames listed: one tikzpicture per frame; with output.pages one tikzpicture whose
// frames are Beamer overlays \only<1> … \only<n>; with output.standalone a whole `standalone` document.
// Coordinates are in cm (the page's, origin at its lower left); the picture's `scale` key scales them.
std::string tikz_document(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output);

// The names the TikZ output gives the marked points: \coordinate (eye) at (…); and so on.
const char* coordinate_name(Point point);

}  // namespace raycam::figure
