#pragma once
// Box look — an ossa level's boxes drawn with the tiles of its LevelLook (level.h), as
// geometry on the CPU (no GL; level_view.h draws it): per part of the look a list of quads
// whose texture coordinates count tiles (beyond [0, 1] the part's texture repeats), so a box
// of any size is a few quads whatever its size.
//
// Rules (world metres, tile side t = look.tile_m):
//   fill       the whole box, on the world grid of t (neighbouring boxes line up);
//   left/right a column min(t, box width) wide down each stretch of the box's side that no
//              other box covers, the tile's outer edge on the box's edge, on the world grid
//              vertically;
//   top        a row min(t, box height) high along each stretch of the top no other box
//              covers, the tile's top on the box's top, on the world grid horizontally;
//   corners    where an uncovered top meets an uncovered side: the corner tile, t wide.
// Parts are drawn in that order (fill first). A part whose tile is -1 is left out (corners
// then show the top row; sides the fill).

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/level/box.h"

namespace ossa {

class Level;
struct LevelLook;

enum class LookPart : int { kFill, kLeft, kRight, kTop, kTopLeft, kTopRight, kCount };
inline constexpr int kLookPartCount = static_cast<int>(LookPart::kCount);

// The tile a part uses (-1: none).
int look_tile(const LevelLook& look, LookPart part);

struct LookQuad {
  Box rect_ws;
  glm::vec2 uv_min{0.0f}, uv_max{1.0f};  // of rect's bottom-left and top-right; tiles, v up
};

struct BoxLookGeometry {
  std::array<std::vector<LookQuad>, kLookPartCount> parts;
  size_t quad_count() const;
};

// The intervals of [lo, hi] left when the intervals `covers` (any order, may overlap) are
// taken away, in order; pieces shorter than `min_length` are dropped.
std::vector<glm::vec2> uncovered(float lo, float hi, std::vector<glm::vec2> covers, float min_length = 1e-5f);

BoxLookGeometry build_box_look(const Level& level, const LevelLook& look);

}  // namespace ossa
