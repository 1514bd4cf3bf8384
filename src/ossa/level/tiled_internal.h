#pragma once
// Internals of the Tiled importer (tiled.h), shared by its files: tiled.cpp (the map,
// object layers, group layers, the entry points), tiled_tiles.cpp (tilesets and tile layer
// decoding: CSV, base64, zlib/gzip, solid cells), tiled_art.cpp (the art: tilesets' images,
// tile and image layers as LevelArt) and tiled_export.cpp. Not a public interface.

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ossa/io/json.h"
#include "ossa/level/level.h"
#include "ossa/level/level_io.h"
#include "ossa/level/level_load.h"
#include "ossa/level/tiled.h"

namespace ossa::tiled_detail {

constexpr int kMaxGroupDepth = 32;
constexpr uint32_t kGidFlags = 0xF0000000u;       // flip x, flip y, flip diagonal, hex rotation

std::string lower(std::string s);
// A custom property of any Tiled element (map, layer, tile), matched case-insensitively, in
// either form Tiled writes (an array of {name, type, value}, or an object name -> value).
const Json* find_property_ci(const Json& element, const char* name);
// A property value read as a flag: true, "true", or a non-zero number.
bool truthy(const Json* v);
// An element's `class` (Tiled 1.9) or else its `type`, lower case; "" when it has neither.
std::string kind_of(const Json& element);

// A tileset's solid tiles (local tile ids marked as colliders) and how its tiles are drawn.
struct Tileset {
  uint32_t firstgid = 1;
  std::vector<uint32_t> solid;  // sorted local ids
  // Art (tiled_art.cpp): the LevelArt tileset, -1 when the tileset has no image to draw.
  int art = -1;
  double tile_w_px = 0.0, tile_h_px = 0.0;     // a grid tile's drawn size
  double offset_x_px = 0.0, offset_y_px = 0.0; // tileoffset (x right, y down)
  bool grid_size = false;                      // tilerendersize "grid": drawn at the map's tile size
  // A collection of images: local id -> (index into the art tileset's images, drawn size px).
  struct CollectionTile {
    uint32_t id = 0;
    uint32_t index = 0;
    double w_px = 0.0, h_px = 0.0;
  };
  std::vector<CollectionTile> collection;      // sorted by id
};

// What groups pass down to the layers in them (tiled_art.cpp): opacity, tint and parallax
// multiply, a hidden group hides its layers' art (their colliders still count), "foreground"
// carries over.
struct LayerStyle {
  float opacity = 1.0f;
  glm::vec4 tint{1.0f};
  glm::vec2 parallax{1.0f};
  bool visible = true;
  bool front = false;
};

// One import: the reader (first error), the scale and the boxes, spawn and background found.
struct Importer {
  explicit Importer(JsonReader reader) : r(std::move(reader)) {}

  JsonReader r;
  double ppm = 1.0;
  double map_h_px = 0.0;
  std::vector<Box> boxes;
  std::optional<glm::vec2> spawn;
  std::string spawn_path;
  std::optional<Background> background;
  bool have_image = false;
  const TiledOptions* options = nullptr;
  double tile_w_px = 0.0, tile_h_px = 0.0;
  std::vector<Tileset> tilesets;  // by firstgid
  int64_t solid_cells = 0;
  int64_t boxes_from_cells = 0;
  int64_t cells_read = 0;  // tile cells of every layer and chunk so far (level_load.h kMaxMapCells)
  std::string layer_what;  // 'tile layer "Ground": ', the start of tile layer errors
  LevelArt art;            // tiled_art.cpp
  int64_t art_tiles_total = 0;
  bool art_full = false;   // kMaxArtTiles reached (warned once)
  std::vector<std::string> warnings;

  // Pixel x / y (y-down) to metres, checked against the level file's coordinate bound.
  float to_x(double px, const std::string& path) {
    const double m = px / ppm;
    if (!(std::abs(m) <= kMaxLevelCoordinate)) {
      r.fail(path, "lies more than " + std::to_string(static_cast<int>(kMaxLevelCoordinate)) + " m from the origin");
      return 0.0f;  // a float cast of an out-of-range double is undefined
    }
    return static_cast<float>(m);
  }
  float to_y(double px, const std::string& path) { return to_x(map_h_px - px, path); }

  // tiled.cpp: objects and layers.
  void object(const Json& o, const std::string& path, double offx, double offy);
  void layers(const Json& parent, const std::string& parent_path, double offx, double offy, int depth,
              const LayerStyle& style);

  // tiled_tiles.cpp: tilesets and tile layers.
  // Reads the solid tiles of one tileset document (embedded in the map or external).
  void tileset_tiles(const Json& ts, const std::string& path, Tileset& out);
  void read_tilesets(const Json& map);
  bool gid_solid(uint32_t gid) const;
  // The gids of a layer or chunk `holder` (fields data, width, height) in row order.
  bool read_gids(const Json& holder, const std::string& path, const std::string& encoding,
                 const std::string& compression, std::vector<uint32_t>& gids, long long& w, long long& h);
  void tile_layer(const Json& layer, const std::string& path, double offx, double offy, const LayerStyle& style);

  // tiled_art.cpp: the art.
  // The style of `layer` inside a group of style `parent`.
  LayerStyle layer_style(const Json& layer, const std::string& path, const LayerStyle& parent);
  // Reads how a tileset's tiles are drawn (its image or its collection of images); `file` is
  // the file the tileset is in (image paths are relative to it).
  void art_tileset(const Json& ts, const std::string& path, const std::string& file, Tileset& set);
  // The tiles of one layer (or chunk) of w x h cells at cell (x0, y0) into `layer`.
  void art_tiles(const std::vector<uint32_t>& gids, long long x0, long long y0, long long w, long long h,
                 double offx, double offy, const std::string& path, ArtLayer& layer);
  // An image layer.
  void art_image_layer(const Json& layer, const std::string& path, double offx, double offy, const LayerStyle& style);
  // An ArtLayer of kind kTiles named after `layer`, with the style's opacity, tint, parallax.
  ArtLayer art_layer(const Json& layer, const LayerStyle& style) const;
};

}  // namespace ossa::tiled_detail
