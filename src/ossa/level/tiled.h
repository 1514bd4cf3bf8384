#pragma once
// Tiled (https://www.mapeditor.org) JSON map import and export (DESIGN.md §6), so designers
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
// - Only orthogonal maps. Object layers ("objectgroup") are read, also inside group layers;
//   tile layers are ignored. The first image layer gives the background image and its
//   parallaxx the parallax; the map's backgroundcolor gives the background colour.
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
// - The map property "name" (string) names the level, else the file's stem; the map property
//   "parallax" (float) overrides the image layer's parallax.
//
// Export writes one object layer "colliders" with a rectangle of type "collider" per box and
// a point object "spawn", the map properties "name" and "parallax", the backgroundcolor, and
// an image layer when the background has an image: a map Tiled 1.x opens and saves back.
// export -> import gives the same level when pixels_per_metre is a power of two; the
// background colour passes through 8 bits per channel.

#include <string_view>

#include "ossa/io/json.h"
#include "ossa/io/result.h"
#include "ossa/level/level.h"

namespace ossa {

struct TiledOptions {
  float pixels_per_metre = 32.0f;  // map pixels per world metre, > 0
  int tile_width_px = 32;          // export only: grid size of the written map, > 0
  int tile_height_px = 32;
};

// Imports a Tiled JSON map from text; `file` names the source in error messages.
Result<Level> import_tiled(std::string_view text, std::string_view file, const TiledOptions& options = {});
// The same from an already parsed document.
Result<Level> import_tiled_json(const Json& map, std::string_view file, const TiledOptions& options = {});
// A Tiled JSON map of the level.
Json export_tiled(const Level& level, const TiledOptions& options = {});

}  // namespace ossa
