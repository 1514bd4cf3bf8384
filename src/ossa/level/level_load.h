#pragma once
// load_level(path, options): one entry point for every level format ossa reads (DESIGN.md §6)
// — ossa levels (level_io.h), Tiled maps in JSON (.tmj/.json) and XML (.tmx, tiled.h) and
// LDtk projects (.ldtk, ldtk.h). The format is recognised by content first (a JSON object
// with "format" is an ossa level, one with "jsonVersion"/"__header__" and "levels" an LDtk
// project, one with "orientation", "tilewidth" or "type": "map" a Tiled map; text starting
// with '<' a Tiled XML map) and by the extension second (.tmx, .tmj, .ldtk) when the content
// says nothing. An LDtk level is picked with "project.ldtk#LevelName" (default: the first
// level).
//
// Scale of the editors' pixel maps, in this order (the first that applies wins):
//   1. the map's custom property `pixels_per_metre` (Tiled: a map property; LDtk: a level
//      field of the chosen level), a number > 0;
//   2. the format's default, one tile = 0.5 m: 2 * the tile width (Tiled `tilewidth`, LDtk
//      `defaultGridSize`);
//   3. LevelLoadOptions::pixels_per_metre (the tools' --pixels-per-metre), when the map has
//      no tile size.
// LevelLoadReport::scale_from says which one applied.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ossa/io/result.h"
#include "ossa/level/level.h"

namespace ossa {

enum class LevelFormat { kOssa, kTiledJson, kTiledXml, kLdtk };
// "ossa", "tiled-json", "tiled-xml", "ldtk".
const char* level_format_name(LevelFormat format);

struct LevelLoadOptions {
  // Pixels per metre of a map that has neither a `pixels_per_metre` property nor a tile size
  // (rule 3 above), > 0. The tools' --pixels-per-metre.
  float pixels_per_metre = 32.0f;
  // LDtk IntGrid values whose identifier is one of these (compared case-insensitively) are
  // not solid; every other non-zero value is.
  std::vector<std::string> ldtk_passable = {"ladder", "water"};
};

// What the loader found, for tools and tests (ossa-level info).
struct LevelLoadReport {
  LevelFormat format = LevelFormat::kOssa;
  std::string level_name;          // LDtk: the chosen level's identifier
  float pixels_per_metre = 0.0f;   // the scale used (0 for ossa levels)
  std::string scale_from;          // "map property", "tile size" or "option"
  int64_t solid_cells = 0;         // solid tiles / IntGrid cells merged into boxes
  int64_t boxes_from_cells = 0;    // the boxes they became (tile_merge.h)
  std::vector<std::string> warnings;
  // Every file read (the map first, then external tilesets and LDtk level files), as opened:
  // a tool refuses to write over any of them (io/file.h check_output_path).
  std::vector<std::string> files;
};

// Tile maps (Tiled tile layers and chunks, LDtk IntGrid layers): at most this many cells in
// all the layers of one map together, so the work of decoding and merging a map (O(n log n) in
// its cells) is bounded per map, whatever its layers' count.
inline constexpr int64_t kMaxMapCells = 1LL << 24;

// What a designer should know about a level that loads (every tool prints these as
// "warning: FILE: ..." lines): a level without boxes, a spawn inside a box, a spawn with no
// ground below it above the kill height (the creature falls and starts again, forever), a
// spawn well above the ground (the creature drops).
std::vector<std::string> level_warnings(const Level& level);

// Reads a file named relative to nothing (the caller resolves paths); Result names the file.
using FileLoader = std::function<Result<std::string>(const std::string& path)>;

// The format of `text` by content, else by the extension of `path`, else kOssa.
LevelFormat detect_level_format(std::string_view text, std::string_view path);

// A file a level names (its background image) as a path to open: relative to the level's own
// folder (`level_file` may end in "#LevelName"); a path that leaves that folder ("..", or an
// absolute path) is refused with a message naming the level and the field. When no such file
// exists in the level's folder, `fallback_folder` (the game's assets/, where images were looked
// up before) is tried, with the same rule.
Result<std::string> resolve_level_resource(const std::string& level_file, std::string_view field,
                                           const std::string& resource, const std::string& fallback_folder = {});

// Loads a level file of any format above; `path` may end in "#LevelName" for LDtk. External
// Tiled tilesets and LDtk level files are read relative to the map.
Result<Level> load_level(const std::string& path, const LevelLoadOptions& options,
                         LevelLoadReport* report = nullptr);

// The same from text already read; `file` names the source (and the folder of external
// files, read with `loader`; without a loader they are an error).
Result<Level> parse_level_any(std::string_view text, const std::string& file, const LevelLoadOptions& options,
                              LevelLoadReport* report = nullptr, const FileLoader& loader = {},
                              const std::string& level_name = {});

}  // namespace ossa
