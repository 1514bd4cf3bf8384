#pragma once
// Internals of the Tiled importer (tiled.h), shared by its three files: tiled.cpp (the map,
// object layers, group layers, the entry points), tiled_tiles.cpp (tilesets and tile layer
// decoding: CSV, base64, zlib/gzip, solid cells) and tiled_export.cpp. Not a public interface.

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

// A tileset's solid tiles: local tile ids marked as colliders.
struct Tileset {
  uint32_t firstgid = 1;
  std::vector<uint32_t> solid;  // sorted local ids
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
  void layers(const Json& parent, const std::string& parent_path, double offx, double offy, int depth);

  // tiled_tiles.cpp: tilesets and tile layers.
  // Reads the solid tiles of one tileset document (embedded in the map or external).
  void tileset_tiles(const Json& ts, const std::string& path, Tileset& out);
  void read_tilesets(const Json& map);
  bool gid_solid(uint32_t gid) const;
  // The gids of a layer or chunk `holder` (fields data, width, height) in row order.
  bool read_gids(const Json& holder, const std::string& path, const std::string& encoding,
                 const std::string& compression, std::vector<uint32_t>& gids, long long& w, long long& h);
  void tile_layer(const Json& layer, const std::string& path, double offx, double offy);
};

}  // namespace ossa::tiled_detail
