#include "ossa/level/tile_merge.h"

#include <algorithm>
#include <map>
#include <utility>

namespace ossa {

MergedCells merge_cells(std::vector<Cell>& cells) {
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) {
    return a.y != b.y ? a.y < b.y : a.x < b.x;
  });
  MergedCells out;
  // Rectangles still open at the previous row, by their column span [x0, x1).
  std::map<std::pair<int64_t, int64_t>, size_t> open, next;
  int64_t row = 0;
  size_t i = 0;
  while (i < cells.size()) {
    row = cells[i].y;
    next.clear();
    // Step 1: the maximal runs of this row (duplicates skipped).
    while (i < cells.size() && cells[i].y == row) {
      const int64_t x0 = cells[i].x;
      int64_t x1 = x0 + 1;
      ++i;
      while (i < cells.size() && cells[i].y == row && cells[i].x <= x1) {
        if (cells[i].x == x1) ++x1;
        ++i;
      }
      out.cells += x1 - x0;
      // Step 2: continue the rectangle above with the same span, if it ended on row - 1.
      const auto span = std::make_pair(x0, x1);
      auto above = open.find(span);
      if (above != open.end()) {
        CellRect& r = out.rects[above->second];
        if (r.y + r.h == row) {
          ++r.h;
          next.emplace(span, above->second);
          continue;
        }
      }
      out.rects.push_back({x0, row, x1 - x0, 1});
      next.emplace(span, out.rects.size() - 1);
    }
    open.swap(next);
  }
  return out;
}

glm::vec2 default_map_spawn(const Level& level) {
  if (level.empty()) return glm::vec2(0.0f);
  Box b = level.box(0);  // the colliders' bounds (Level::bounds() would add the spawn)
  for (const Box& c : level.colliders()) b = b.united(c);
  const float x = b.min_ws.x + 1.0f;
  const auto g = level.ground_height_below(x, x, b.max_ws.y, b.height());
  return {x, g ? g->height_ws : b.max_ws.y};
}

}  // namespace ossa
