// Greedy row-then-column merging of solid cells (tile_merge.h): exact figures for filled,
// checkerboard and stepped grids, and a property test against the cells themselves.

#include "ossa/level/tile_merge.h"
#include "ossa/math/rng.h"

#include <catch2/catch.hpp>

#include <set>
#include <utility>

using namespace ossa;

namespace {

std::vector<Cell> filled(int64_t w, int64_t h, int64_t x0 = 0, int64_t y0 = 0) {
  std::vector<Cell> cells;
  for (int64_t y = 0; y < h; ++y)
    for (int64_t x = 0; x < w; ++x) cells.push_back({x0 + x, y0 + y});
  return cells;
}

std::set<std::pair<int64_t, int64_t>> covered(const MergedCells& m) {
  std::set<std::pair<int64_t, int64_t>> out;
  for (const CellRect& r : m.rects) {
    REQUIRE(r.w >= 1);
    REQUIRE(r.h >= 1);
    for (int64_t y = r.y; y < r.y + r.h; ++y)
      for (int64_t x = r.x; x < r.x + r.w; ++x) REQUIRE(out.insert({x, y}).second);  // no overlaps
  }
  return out;
}

}  // namespace

TEST_CASE("a filled 200 x 50 map is one box, a checkerboard one box per cell", "[level][tiles]") {
  std::vector<Cell> full = filled(200, 50);
  const MergedCells a = merge_cells(full);
  CHECK(a.cells == 10000);
  REQUIRE(a.rects.size() == 1);
  CHECK(a.rects[0] == CellRect{0, 0, 200, 50});

  std::vector<Cell> board;
  for (int64_t y = 0; y < 50; ++y)
    for (int64_t x = 0; x < 200; ++x)
      if ((x + y) % 2 == 0) board.push_back({x, y});
  const MergedCells b = merge_cells(board);
  CHECK(b.cells == 5000);
  CHECK(b.rects.size() == 5000);
}

TEST_CASE("merge: runs continue only with the same span, duplicates count once, far cells are cheap", "[level][tiles]") {
  // A staircase: each row one cell wider than the one above -> one box per row.
  std::vector<Cell> stairs;
  for (int64_t y = 0; y < 4; ++y)
    for (int64_t x = 0; x <= y; ++x) stairs.push_back({x, y});
  const MergedCells s = merge_cells(stairs);
  CHECK(s.cells == 10);
  CHECK(s.rects == std::vector<CellRect>{{0, 0, 1, 1}, {0, 1, 2, 1}, {0, 2, 3, 1}, {0, 3, 4, 1}});
  // Two equal spans separated by an empty row stay two boxes; duplicates count once.
  std::vector<Cell> gap = {{2, 0}, {3, 0}, {2, 2}, {3, 2}, {3, 2}, {2, 0}};
  const MergedCells g = merge_cells(gap);
  CHECK(g.cells == 4);
  CHECK(g.rects == std::vector<CellRect>{{2, 0, 2, 1}, {2, 2, 2, 1}});
  // Sparse cells a billion apart cost nothing (no dense grid).
  std::vector<Cell> far = filled(3, 2, -1000000000, 7);
  for (const Cell& c : filled(3, 2, 1000000000, 7)) far.push_back(c);
  const MergedCells f = merge_cells(far);
  CHECK(f.rects == std::vector<CellRect>{{-1000000000, 7, 3, 2}, {1000000000, 7, 3, 2}});
  std::vector<Cell> none;
  CHECK(merge_cells(none).rects.empty());
}

TEST_CASE("merge covers exactly the solid cells of random grids", "[level][tiles]") {
  Rng rng(18);
  for (int trial = 0; trial < 200; ++trial) {
    const int w = rng.uniform_int(1, 30);
    const int h = rng.uniform_int(1, 30);
    const double density = rng.uniform();
    std::vector<Cell> cells;
    std::set<std::pair<int64_t, int64_t>> want;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (rng.uniform() < density) {
          cells.push_back({x, y});
          want.insert({x, y});
        }
    const MergedCells m = merge_cells(cells);
    INFO("trial " << trial);
    REQUIRE(covered(m) == want);
    REQUIRE(m.cells == static_cast<int64_t>(want.size()));
    REQUIRE(m.rects.size() <= want.size());
  }
}
