#pragma once
// Level files (DESIGN.md §6): versioned JSON, loaded at start from levels/default.json.
//
// Format, version 1 (units metres, +x right, +y up):
//
//   {
//     "format": "ossa.level",            required, exactly this string
//     "version": 1,                      required, integer; this build reads version 1
//     "name": "default",                 optional string, default ""
//     "spawn": {"x": 2.0, "y": 0.0},     required: where the player's creature starts
//     "background": {                    optional object; every field optional
//       "image": "backgrounds/hills.png",   image path relative to the level's folder (see
//                                           resolve_level_resource), default ""
//       "parallax": 0.5,                    scroll factor in [0, 1], default 0.5
//       "colour": [0.55, 0.70, 0.85]        linear RGB, three numbers in [0, 1]
//     },
//     "look": {                          optional object: the boxes drawn with tiles (level.h
//                                        LevelLook); without it, plain earth-coloured boxes
//       "tileset": "tiles/meadow.png",      required: image path relative to the level's folder,
//                                           else assets/ (resolve_level_resource)
//       "tile_px": 32,                      a tile's side in the image, pixels, 1-4096 (default 32)
//       "tile_m": 0.5,                      a tile's side in the world, metres, 0.01-100 (0.5)
//       "top": 0, "top_left": 1, "top_right": 2, "left": 3, "right": 4, "fill": 5
//                                           tile numbers in row order from the image's top-left;
//                                           top and fill >= 0 (default 0), the others -1 (none)
//     },
//     "kill_height": -12.0,              optional number below the spawn's y: a creature whose
//                                        root falls below this y has left the level and starts
//                                        again at the spawn; default 2 m (or the creature's hip
//                                        height, if more) below the lowest box
//     "colliders": [                     required array (may be empty), at most 1 000 000
//       {"x": 0.0, "y": -1.0, "w": 70.0, "h": 1.0},   x, y = bottom-left corner;
//       ...                                            w, h = width and height > 0
//     ]
//   }
//
// Coordinates must be finite with |x|, |y| <= kMaxLevelCoordinate (1000 m), far edges included
// (x + w, rounded to the float the level holds); sizes > 0. Unknown fields are ignored, so
// newer writers may add fields without breaking older readers.
// Numbers are written in their shortest form that reads back to the same float ("0.1", not
// "0.10000000149011612"), and loading a saved level gives an equal Level.
//
// Errors name the file and the field, e.g.
//   levels/x.json: colliders[3].w: expected a number > 0, got -2
// No input, however malformed, crashes the loader.

#include <string>
#include <string_view>

#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"
#include "ossa/level/level.h"
#include "ossa/level/level_load.h"

namespace ossa {

inline constexpr const char* kLevelFormat = "ossa.level";
inline constexpr int kLevelVersion = 1;
inline constexpr int kMaxLevelColliders = 1000000;
// Metres, the bound on |x| and |y| of every box corner and the spawn. Within it a float keeps
// steps of at most 2^-14 m = 0.061 mm, so feet planted far from the origin do not slip from
// rounding (at 999 000 m the step is 6 cm).
inline constexpr double kMaxLevelCoordinate = 1000.0;

// Reads and parses a level file of any format: load_level(path, LevelLoadOptions{}) of
// level_load.h (ossa levels, Tiled .tmj/.tmx maps, LDtk "project.ldtk#Level").
Result<Level> load_level(const std::string& path);
// Parses level JSON text; `file` names the source in error messages.
Result<Level> parse_level(std::string_view text, std::string_view file);
// Reads a level from an already parsed document.
Result<Level> level_from_json(const Json& doc, std::string_view file);
// The JSON document of a level (format above).
Json level_to_json(const Level& level);
// The file text: the same document in the documented key order, one collider per line.
std::string level_to_text(const Level& level);
// Saves level_to_text atomically (write_file_atomic: temporary file, fsync, rename), so a
// failed save leaves the old file intact. A level check_level refuses is not written (the
// error names the field), so every saved level loads back.
Status save_level(const std::string& path, const Level& level);

// What the loader requires of a whole level beyond each field's own range: the spawn, every
// box and the kill height within kMaxLevelCoordinate, the kill height below the spawn, at most
// kMaxLevelColliders boxes. Errors name `file` and the field.
Status check_level(const Level& level, std::string_view file);

// The double closest to the shortest decimal that reads back as `f` (0.1f -> 0.1), so files
// stay readable. Shared with the Tiled export.
double shortest_decimal(float f);

}  // namespace ossa
