#pragma once
// Internals of the LDtk importer (ldtk.h): the art of one level (level_art.h). Not a public
// interface.
//
// Read from LDtk's JSON (https://ldtk.io/json/):
// - tilesets: defs.tilesets[] (uid, relPath relative to the project, tileGridSize, spacing,
//   padding, __cWid, pxWid, pxHei); a tileset without relPath (LDtk's internal icons) is not drawn;
// - layers: layerInstances[] are front to back, so they are drawn last to first. Tiles layers
//   draw gridTiles, AutoLayer layers and IntGrid layers with rules draw autoLayerTiles, each
//   tile at px (+ the layer's __pxTotalOffsetX/Y) from tile t of the layer's tileset
//   (__tilesetDefUid), flipped by f (bit 0: x, bit 1: y), with alpha a (LDtk 1.4); the
//   layer's __opacity and visible; its definition's parallaxFactorX/Y f (-1 to 1, LDtk's
//   default 0) as the parallax p = 1 - f (f = 1: fixed to the screen). A layer whose identifier
//   starts with "Foreground" or is "Fg"/starts with "Fg_" (any case) is drawn in front of the
//   creatures. Entities' tiles are not drawn.
// - the level's background: __bgColor, and bgRelPath placed by __bgPos (topLeftPx, scale,
//   cropRect).
// Pixels become metres as the colliders do: x = (worldX + px) / p, y = -(worldY + py) / p.

#include <string>
#include <vector>

#include "ossa/io/json_fwd.h"
#include "ossa/level/level_art.h"

namespace ossa::ldtk_detail {

struct ArtFrame {
  double ppm = 32.0;                    // pixels per metre
  double world_x = 0.0, world_y = 0.0;  // the level's place in the world, pixels
};

// The art of the level `level` (the JSON holding its layerInstances: the project's level or
// its external file; `level_path` is its path in `r`'s file) into `art`. Tileset and
// background paths are relative to `project_file`. Errors go to `r`; a map past kMaxArtTiles
// adds a warning and stops adding tiles.
void read_art(const Json& project, const Json& level, const std::string& level_path, const std::string& project_file,
              const ArtFrame& frame, JsonReader& r, LevelArt& art, std::vector<std::string>& warnings);

}  // namespace ossa::ldtk_detail
