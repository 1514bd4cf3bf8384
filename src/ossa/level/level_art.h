#pragma once
// LevelArt — what a level looks like, apart from what it collides with (DESIGN.md §6: "levels
// look as designed"): the tile and image layers of a Tiled map or an LDtk level, in their
// order, each with its tilesets, flips, opacity, tint, parallax and offset, and the map's
// background. The loaders fill it (tiled.h, ldtk.h); the renderer draws it
// (ossa/render/level_view.h). Collision stays boxes: the art never changes a query.
//
// Space: world metres, +x right, +y up, like the colliders (the loaders convert pixels with
// the map's scale). A tile's rectangle is where it is drawn before parallax.
//
// Parallax (Tiled's and LDtk's model): a layer with factor p is drawn shifted by
// (1 - p) * (view centre - parallax_origin_ws), per axis: p = 1 moves with the level, p = 0 is
// fixed to the screen, 0 < p < 1 is further away.
//
// Images are named by the path to open (the map's folder joined with the path the map wrote,
// so "../tiles/a.png" works as in Tiled) and by the text the map wrote (for messages). No
// image is read here: the core needs no image decoder. Sizes the map declares are kept; 0
// means "not declared" (the renderer takes the image's own size).

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ossa {

// One image file the art samples.
struct ArtImage {
  std::string path;      // to open: the map's (or tileset's) folder joined with `source`
  std::string source;    // as the map wrote it
  int width_px = 0;      // as declared by the map, 0 = not declared
  int height_px = 0;

  friend bool operator==(const ArtImage&, const ArtImage&) = default;
};

// A set of tiles that one draw samples: a grid in one image (Tiled tilesets, LDtk tilesets),
// or a collection of whole images (Tiled "collection of images" tilesets: tile i is images[i]).
struct ArtTileset {
  std::string name;
  std::vector<int> images;   // into LevelArt::images: one for a grid, one per tile for a collection
  bool collection = false;
  // A grid's geometry, pixels: tile i sits at column i % columns, row i / columns, its
  // top-left at (margin + column * (tile_w + spacing), margin + row * (tile_h + spacing)).
  int tile_w_px = 0, tile_h_px = 0;
  int margin_px = 0, spacing_px = 0;
  int columns = 0;           // 0 = from the image's width

  friend bool operator==(const ArtTileset&, const ArtTileset&) = default;
};

// Flip flags of a drawn tile ([Tiled] order of operations: the diagonal flip first, then the
// horizontal and the vertical one).
inline constexpr uint8_t kArtFlipX = 1, kArtFlipY = 2, kArtFlipDiagonal = 4;

struct ArtTile {
  glm::vec2 min_ws{0.0f};    // bottom-left corner of the drawn rectangle, metres
  glm::vec2 size_ws{0.0f};   // metres, > 0
  uint32_t tile = 0;         // the tile in its tileset (grid index, or collection image index)
  uint8_t flags = 0;         // kArtFlip*
  uint8_t alpha = 255;       // per-tile opacity (LDtk's tile alpha), times the layer's

  friend bool operator==(const ArtTile&, const ArtTile&) = default;
};

// The tiles of one layer from one tileset: one draw.
struct ArtBatch {
  int tileset = 0;           // into LevelArt::tilesets
  std::vector<ArtTile> tiles;

  friend bool operator==(const ArtBatch&, const ArtBatch&) = default;
};

struct ArtLayer {
  enum class Kind : uint8_t { kTiles, kImage };
  Kind kind = Kind::kTiles;
  std::string name;          // for messages and the editor
  float opacity = 1.0f;      // [0, 1], the layer's times its groups'
  glm::vec4 tint{1.0f};      // RGBA multiplier (Tiled's tintcolor), groups' included
  glm::vec2 parallax{1.0f};  // factors per axis (see the top of this file)
  // Drawn in front of the creatures (Tiled: the layer's or a group's bool property
  // "foreground"; LDtk: a layer whose identifier starts with "Foreground" or "Fg").
  bool front = false;

  // kTiles: per tileset, in the order the tiles appear in the layer.
  std::vector<ArtBatch> batches;

  // kImage: one picture placed with its top-left corner at origin_ws, each image pixel
  // metres_per_px wide and high times `scale`; `crop_px` (x, y, w, h in the image; w = 0: the
  // whole image) picks a part of it. Repeated along x and/or y across the view when asked.
  int image = -1;            // into LevelArt::images
  glm::vec2 origin_ws{0.0f};
  float metres_per_px = 1.0f;
  glm::vec2 scale{1.0f};
  glm::vec4 crop_px{0.0f};
  bool repeat_x = false, repeat_y = false;

  friend bool operator==(const ArtLayer&, const ArtLayer&) = default;
};

struct LevelArt {
  std::string file;                       // the map, for messages ("world.ldtk#Level_1")
  std::vector<ArtImage> images;
  std::vector<ArtTileset> tilesets;
  std::vector<ArtLayer> layers;           // back to front
  glm::vec2 parallax_origin_ws{0.0f};
  std::optional<glm::vec4> background;    // the map's background colour (RGBA in [0, 1])

  // Tiles in every layer.
  int64_t tile_count() const;
  // Any layer to draw (tiles or images).
  bool empty() const { return layers.empty(); }
  // Adds an image (or finds the same path already added); returns its index.
  int add_image(const std::string& path, const std::string& source, int width_px, int height_px);

  friend bool operator==(const LevelArt&, const LevelArt&) = default;
};

// At most this many tiles in all the layers of one map's art (about 60 bytes each on the GPU).
// A map with more keeps its collision; the art past the limit is left out with a warning.
inline constexpr int64_t kMaxArtTiles = 1LL << 21;

// "#RRGGBB" or "#AARRGGBB" (Tiled, LDtk) as RGBA in [0, 1]; nullopt for anything else.
std::optional<glm::vec4> parse_hex_colour(const std::string& text);

// The folder-joined path of `source` next to `file` (a map or tileset; "project.ldtk#Level"
// is the project), normalised ("a/b/../c.png" -> "a/c.png"). An absolute source stays as it is.
std::string art_path_near(const std::string& file, const std::string& source);

}  // namespace ossa
