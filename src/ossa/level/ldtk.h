#pragma once
// LDtk (https://ldtk.io) project import (DESIGN.md §6), following LDtk's published JSON
// format (https://ldtk.io/json/): a project holds levels[], each with layerInstances[].
//
// Space. LDtk is y-down in pixels; ossa is y-up in metres. The chosen level keeps its place in
// the LDtk world: with p = pixels per metre and the level at (worldX, worldY) px,
//   x_ws = (worldX + x_px) / p,    y_ws = -(worldY + y_px) / p
// so the world's origin is (0, 0) and levels placed side by side in LDtk stay side by side.
// (worldX/worldY are 0 for the "LinearHorizontal"/"LinearVertical" layouts, which do not
// place levels.) Layer offsets (__pxTotalOffsetX/Y) are applied.
//
// Import rules:
// - The level: the one whose identifier is `level_name`, else the first. A level stored in
//   its own file (project option "externalLevels": layerInstances null, externalRelPath) is
//   read through LdtkOptions::read_file relative to the project.
// - IntGrid layers (__type "IntGrid"): a cell (intGridCsv, __cWid x __cHei, __gridSize px)
//   is solid when its value is not 0 and the value's identifier (defs.layers[].intGridValues
//   of the layer's definition) is not one of LdtkOptions::passable. Each layer's solid
//   cells are merged into few boxes (tile_merge.h).
// - Entity layers (__type "Entities"): the one entity whose __identifier is "Player" or
//   "Spawn" (any case) is the spawn, at its px position (its pivot, by default the
//   bottom-centre: where the feet stand). Two are an error; without one the spawn is 1 m
//   right of the colliders' left edge, on the highest top there.
// - Other layers (Tiles, AutoLayer) are skipped.
// - Scale: the level's field "pixels_per_metre" (number > 0), else one grid cell = 0.5 m
//   (2 * defaultGridSize), else LdtkOptions::pixels_per_metre.
// - The level's identifier names the level.
// Errors name the file, the level and layer, and the expectation.

#include <string>
#include <string_view>
#include <vector>

#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"
#include "ossa/level/level.h"
#include "ossa/level/level_load.h"

namespace ossa {

struct LdtkOptions {
  float pixels_per_metre = 32.0f;  // used only without the field and without defaultGridSize, > 0
  std::vector<std::string> passable = {"ladder", "water"};  // IntGrid identifiers that do not collide
  FileLoader read_file;            // reads external level files; empty: they are an error
};

// Imports level `level_name` (empty: the first) of an LDtk project; `file` names the source.
Result<Level> import_ldtk(std::string_view text, std::string_view file, const std::string& level_name = {},
                          const LdtkOptions& options = {}, LevelLoadReport* report = nullptr);
Result<Level> import_ldtk_json(const Json& project, std::string_view file, const std::string& level_name = {},
                               const LdtkOptions& options = {}, LevelLoadReport* report = nullptr);

}  // namespace ossa
