#pragma once
// Tiled (https://www.mapeditor.org) map import (JSON .tmj and XML .tmx) and JSON export (DESIGN.md §6), so designers
// can draw levels in Tiled.
//
// Space. Tiled is y-down in pixels with the origin at the map's top-left corner; ossa is y-up
// in metres. With p = pixels_per_metre and H = height * tileheight (the map's pixel height):
//   x_ws = x_px / p,    y_ws = (H - y_px) / p
// so the bottom edge of the map grid is y = 0 and a rectangle at (x, y, w, h) px becomes the
// box [x/p, (x+w)/p] x [(H-y-h)/p, (H-y)/p]. Objects may lie outside the grid (y < 0 m is
// below the map's bottom edge); layer offsets (offsetx, offsety) are applied, also through
// group layers.
//
// Import rules:
// - Only orthogonal maps, finite or infinite (chunked). Object layers ("objectgroup") and tile
//   layers ("tilelayer") are read, also inside group layers. The first image layer gives the
//   background image and its parallaxx the parallax; the map's backgroundcolor gives the
//   background colour.
// - An object's kind is its `class` (Tiled 1.9) or else its `type` (Tiled < 1.9 and >= 1.10),
//   compared case-insensitively.
// - Spawn: the one object whose kind or name is "spawn": a point gives its position; any
//   other shape gives the bottom-centre of its bounds. Two spawn objects are an error. Without
//   one, the spawn is 1 m right of the colliders' left edge, on the highest top there.
// - Colliders: objects of kind "collider" or of no kind. They must be plain axis-aligned
//   rectangles with width and height > 0: rotated rectangles, ellipses, points, polygons,
//   polylines, text and tile objects of these kinds are an error naming the object (give
//   such an object another class, e.g. "decoration", to have it skipped).
// - Objects of any other kind are skipped.
// - Tiles: a cell of a tile layer is solid when its tile (the gid with the flip and rotation
//   flags 0xF0000000 cleared) is marked in its tileset — a custom property `collider` = true,
//   a class/type "collider", or any object in the tile's collision editor (objectgroup) — or
//   when the layer's class or name is "collision" or "colliders" (every non-empty cell). A
//   solid cell collides as its whole grid cell (tilewidth x tileheight at the layer's
//   offset). Layer data: a JSON array (CSV), or base64 uncompressed, zlib or gzip; zstd is
//   refused with a message. Infinite maps store chunks, each read the same way. The solid
//   cells of each layer are merged into few boxes (tile_merge.h) and counted in the report.
// - Tilesets: embedded, or external (`source`, .tsj/.json or .tsx) read through
//   TiledOptions::read_file relative to the map's folder.
// - Scale: the map property "pixels_per_metre" (number > 0), else with tile_is_half_metre
//   2 * tilewidth (one tile = 0.5 m), else TiledOptions::pixels_per_metre.
// - The map property "name" (string) names the level, else the file's stem; the map property
//   "parallax" (float) overrides the image layer's parallax.
//
// Export writes one object layer "colliders" with a rectangle of type "collider" per box and
// a point object "spawn", the map properties "name" and "parallax", the backgroundcolor, and
// an image layer when the background has an image: a map Tiled 1.x opens and saves back.
// export -> import gives the same level when pixels_per_metre is a power of two; the
// background colour passes through 8 bits per channel.

#include <string_view>

#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"
#include "ossa/level/level.h"
#include "ossa/level/level_load.h"

namespace ossa {

struct TiledOptions {
  float pixels_per_metre = 32.0f;  // map pixels per world metre, > 0 (import: see Scale above)
  bool tile_is_half_metre = false; // import: one tile = 0.5 m unless the map says otherwise
  FileLoader read_file;            // import: reads external tilesets; empty: they are an error
  int tile_width_px = 32;          // export only: grid size of the written map, > 0
  int tile_height_px = 32;
};

// Imports a Tiled JSON map from text; `file` names the source in error messages.
// `report` (optional) receives the scale used and the merge figures.
Result<Level> import_tiled(std::string_view text, std::string_view file, const TiledOptions& options = {},
                           LevelLoadReport* report = nullptr);
// The same from an already parsed document.
Result<Level> import_tiled_json(const Json& map, std::string_view file, const TiledOptions& options = {},
                                LevelLoadReport* report = nullptr);
// Imports a Tiled XML map (.tmx) by converting it to the JSON document Tiled itself would
// write (tmx_to_json) and importing that: the rules above hold for both.
Result<Level> import_tmx(std::string_view text, std::string_view file, const TiledOptions& options = {},
                         LevelLoadReport* report = nullptr);
// A TMX map, or a TSX tileset, as Tiled's JSON document (tile data stays encoded as in the
// file, CSV becoming an array). Errors name the file and the XML element.
Result<Json> tmx_to_json(std::string_view text, std::string_view file);
Result<Json> tsx_to_json(std::string_view text, std::string_view file);
// A Tiled JSON map of the level.
Json export_tiled(const Level& level, const TiledOptions& options = {});

}  // namespace ossa
