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
// File names are bytes but JSON is text: a level or character path that is not UTF-8 is saved
// with U+FFFD for the bad bytes (the replay is written, and playing it back names the file it
// cannot find). Loading: at most kMaxReplayTicks ticks in all, spawn within ±1000 m.

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/game/controls.h"
#include "ossa/io/json.h"
#include "ossa/io/result.h"

namespace ossa {

// `count` ticks with the same controls.
struct ReplayRun {
  long long count = 0;
  Controls controls;
};

// The ticks stay run-length encoded in memory as in the file, so a replay takes memory in
// proportion to its file (a day of ticks at 480 Hz written as one run is one run here too).
struct Replay {
  int tick_hz = 120;
  std::string level;
  Json creature;          // genome JSON (null for a character)
  std::string character;  // the character's rig file as recorded (empty for a creature)
  glm::vec2 spawn_ws{0.0f};  // within ±kMaxLevelCoordinate, as a level's spawn
  int facing = 1;
  std::vector<ReplayRun> runs;

  // Appends one tick (extending the last run when the controls are the same).
  void push(const Controls& c);
  // Ticks in all runs.
  long long tick_count() const;
};

// Plays a replay's ticks in order.
class ReplayCursor {
 public:
  explicit ReplayCursor(const Replay* replay = nullptr) : replay_(replay) {}
  bool done() const;
  // The next tick's controls (done() must be false).
  Controls next();
  long long ticks_played() const { return played_; }

 private:
  const Replay* replay_;
  size_t run_ = 0;
  long long used_ = 0;  // ticks of runs_[run_] played
  long long played_ = 0;
};

inline constexpr long long kMaxReplayTicks = 480LL * 3600 * 24;  // a day at the highest tick rate

Json replay_to_json(const Replay& replay);
Result<Replay> replay_from_json(const Json& doc, std::string_view file);
Result<Replay> load_replay(const std::string& path);
Status save_replay(const std::string& path, const Replay& replay);

}  // namespace ossa
