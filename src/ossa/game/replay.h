#pragma once
// Replay — the Controls of every tick, so a session plays back bit-for-bit (DESIGN.md §8).
// File (`.replay.json`, versioned; saved atomically):
//
//   { "format": "ossa.replay", "version": 2, "tick_hz": 120,
//     "level": "levels/default.json",           // informational: where it was recorded
//     "creature": { ...a .creature.json genome... },   // or, for a rigged character:
//     "character": "assets/characters/humanoid.rig.json",  // its rig file (exactly one of the two)
//     "spawn": [x, y], "facing": 1,
//     "ticks": [[count, move_x, run, jump], ...] }   // run-length encoded controls
//                                        // (version 1, still read: [count, move_x, run])
//
// Playback: build the genome's creature (or load the character), spawn it at `spawn` on the
// level, and step the world with the recorded controls; poses come out identical (same build).

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/game/controls.h"
#include "ossa/io/json.h"
#include "ossa/io/result.h"

namespace ossa {

struct Replay {
  int tick_hz = 120;
  std::string level;
  Json creature;          // genome JSON (null for a character)
  std::string character;  // the character's rig file as recorded (empty for a creature)
  glm::vec2 spawn_ws{0.0f};
  int facing = 1;
  std::vector<Controls> ticks;
};

Json replay_to_json(const Replay& replay);
Result<Replay> replay_from_json(const Json& doc, std::string_view file);
Result<Replay> load_replay(const std::string& path);
Status save_replay(const std::string& path, const Replay& replay);

}  // namespace ossa
