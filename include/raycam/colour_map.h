// The camera's colour map ("colmap"): colours and object ids in image order, row-major, row 0 at the top,
// column 0 at the eye's left. Id -1 is the background.
#pragma once

#include <vector>

#include "raycam/scene.h"

namespace raycam {

struct ColourMap {
  int width = 0;
  int height = 0;
  std::vector<Rgb8> colours;  // width·height
  std::vector<int> ids;       // width·height

  ColourMap() = default;
  ColourMap(int w, int h, Rgb8 fill)
      : width(w), height(h), colours(std::size_t(w) * h, fill), ids(std::size_t(w) * h, -1) {}
  // Resizes to w × h keeping the memory (no allocation when the size is unchanged); the contents are left
  // for the caster to overwrite, every pixel of them.
  void resize(int w, int h) {
    width = w;
    height = h;
    colours.resize(std::size_t(w) * h);
    ids.resize(std::size_t(w) * h);
  }
  std::size_t index(int row, int column) const { return std::size_t(row) * width + column; }
  Rgb8 colour_at(int row, int column) const { return colours[index(row, column)]; }
  int id_at(int row, int column) const { return ids[index(row, column)]; }
};

}  // namespace raycam
