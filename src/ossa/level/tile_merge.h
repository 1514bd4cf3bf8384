#pragma once
// Merging solid grid cells into few boxes (DESIGN.md §6): tile maps (Tiled tile layers, LDtk
// IntGrid layers) mark cells solid, and a level made of one box per cell would be needlessly
// large (a 200 x 50 map would become 10 000 boxes). merge_cells() merges greedily, row then
// column:
//   1. every row's solid cells become maximal horizontal runs [x0, x1);
//   2. a run continues the rectangle of the row above when that rectangle has exactly the same
//      [x0, x1); otherwise it starts a new rectangle.
// So a filled rectangle of cells is one box, a staircase is one box per step row, and a
// checkerboard stays one box per cell. The result covers exactly the solid cells, without
// overlaps; the order is by first row, then x (deterministic).
//
// Cells are integer coordinates in the source's grid (x right, y down, as editors store
// them); duplicates are allowed and count once. Cost O(n log n) for n cells, memory O(n):
// no dense grid is built, so sparse (infinite, chunked) maps far from the origin are cheap.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/level/level.h"

namespace ossa {

struct Cell {
  int64_t x = 0;  // column
  int64_t y = 0;  // row, growing down
};

// A rectangle of cells: columns [x, x + w), rows [y, y + h), w, h >= 1.
struct CellRect {
  int64_t x = 0, y = 0, w = 0, h = 0;
  friend bool operator==(const CellRect& a, const CellRect& b) {
    return a.x == b.x && a.y == b.y && a.w == b.w && a.h == b.h;
  }
};

struct MergedCells {
  std::vector<CellRect> rects;
  int64_t cells = 0;  // distinct solid cells merged
};

// Merges `cells` (any order; sorted in place) as described above.
MergedCells merge_cells(std::vector<Cell>& cells);

// Where a map without a spawn object starts the creature: 1 m in from the left edge of its
// boxes, on the highest ground there (the origin for a map with no boxes). Shared by the
// Tiled and LDtk importers.
glm::vec2 default_map_spawn(const Level& level);

}  // namespace ossa
