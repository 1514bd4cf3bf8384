#pragma once
// TileAtlas — a tileset's tiles re-packed for drawing (CPU only; level_view.h uploads it):
// each tile in a cell of its own with its edge pixels repeated `kTileExtrude` pixels around it,
// so linear filtering at any scale samples only the tile's own pixels (no seams from the
// neighbours in the tileset image). A grid tileset (ArtTileset, one image) is cut into its
// tiles; a collection (one image per tile) is packed with stb_rect_pack. Both give one texture:
// one draw per tileset per layer.
//
// Texture coordinates follow GL (texture.h): (0, 0) is the bottom-left of the atlas image.

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/level/level_art.h"
#include "ossa/platform/image.h"

namespace ossa {

inline constexpr int kTileExtrude = 2;  // pixels of repeated edge around every tile

struct TileAtlas {
  Image image;                  // rows top to bottom
  // Per tile: the texture coordinates of its top-left and bottom-right corners (GL space: v
  // up, so uv_tl.y > uv_br.y). A tile that lies outside its image has uv_tl == uv_br.
  std::vector<glm::vec2> uv_tl, uv_br;
  int tile_count() const { return static_cast<int>(uv_tl.size()); }
  bool has(uint32_t tile) const { return tile < uv_tl.size() && uv_tl[tile] != uv_br[tile]; }
};

// A grid tileset's atlas from its image: `set`'s tile size, margin, spacing and columns (0:
// as many as fit the image's width). At most `max_side` pixels wide and high: a tileset too
// large for that gives an atlas without extrusion (the image as it is) — still one texture.
TileAtlas build_grid_atlas(const Image& image, const ArtTileset& set, int max_side);
// A collection's atlas from its images (tile i = images[i]; an empty image is a tile not
// drawn). Empty when the images do not fit in max_side x max_side.
TileAtlas build_collection_atlas(const std::vector<const Image*>& images, int max_side);

}  // namespace ossa
