#pragma once
// World — the level, the player and NPC walkers, stepped together at one fixed rate
// (default 120 Hz, up to 480 Hz; DESIGN.md §2). NPCs wander: they pick a direction and a
// speed for a few seconds, pause now and then, and turn around when blocked. Stepping is
// deterministic: the same level, creatures, seeds and player controls give the same poses,
// on any number of threads (set_threads; the creatures are stepped with step_all, herd.h).
// Every creature spawned from the same Creature shares one rig (RigCache).
//
// Creatures meet (they never walk through each other): two creatures are in each other's way
// when their feet are at about the same height (closer than the smaller hip height) and
// neither is less than kPassUnderRatio as tall at the hip as the other — a creature that small
// passes under the larger one's belly. A creature moving towards one in its way whose body
// (its rest pose's longer reach from the root, head or tail, taken both ways, so turning
// around does not change it) is closer than kMeetGap plus kMeetLookAhead seconds of its speed
// (at least its walk's):
//   * an NPC turns back and holds its new heading at least 1.5 s (hemmed in on both sides it
//     waits);
//   * the player stops (moving away is free), and an NPC it walks up to gives way: it walks
//     off ahead of the player, at least as fast as the player's stick asks (and at least at
//     0.6, a brisk walk), running when the player runs.

#include <cstdint>
#include <memory>
#include <vector>

#include "ossa/game/herd.h"
#include "ossa/game/player.h"
#include "ossa/math/rng.h"

namespace ossa {

inline constexpr float kPassUnderRatio = 0.5f;  // hip heights: under this ratio, the small one passes under
inline constexpr float kMeetGap = 0.15f;        // metres between bodies
inline constexpr float kMeetLookAhead = 0.5f;   // seconds of speed added to the gap

// The rule above: creatures with these hip heights and feet heights (metres) block each other.
bool creatures_in_each_others_way(float hip_a, float feet_a, float hip_b, float feet_b);

class World {
 public:
  // tick_hz in [30, 480].
  World(Level level, SplinePrototypes prototypes, AnimatorParams params = {}, int tick_hz = 120);

  Player& spawn_player(std::shared_ptr<const Creature> creature, glm::vec2 at_ws, int facing = 1);
  Player& spawn_player(std::shared_ptr<const Character> character, glm::vec2 at_ws, int facing = 1);
  Entity& spawn_npc(std::shared_ptr<const Creature> creature, glm::vec2 at_ws, uint64_t seed);
  Entity& spawn_npc(std::shared_ptr<const Character> character, glm::vec2 at_ws, uint64_t seed);
  void remove_npcs();
  // Replaces the player's creature (or character), standing where the old one stood.
  void set_player_creature(std::shared_ptr<const Creature> creature);
  void set_player_character(std::shared_ptr<const Character> character);

  // One fixed tick of 1 / tick_hz seconds: the NPCs choose their controls (in order, one
  // random stream each), then every creature steps, in parallel on up to threads() threads.
  void step(const Controls& player_controls);
  // The player's controls the last step applied: the given ones, with the move towards a
  // creature in its way dropped (what a replay records, so it plays back without the NPCs).
  const Controls& applied_player_controls() const { return applied_; }
  // Off: the player is not stopped by creatures (a replay's controls already were) and NPCs
  // do not give way to it; NPCs still turn back from it.
  bool player_meets_creatures = true;
  // Threads for step: 0 = every core (the default), 1 = this thread only. Poses do not depend on it.
  void set_threads(int threads) { threads_ = threads; }
  int threads() const { return threads_; }
  // The shared rigs of the creatures spawned so far.
  const RigCache& rigs() const { return rigs_; }

  const Level& level() const { return level_; }
  Level& level() { return level_; }
  Player* player() { return player_.get(); }
  const Player* player() const { return player_.get(); }
  int npc_count() const { return static_cast<int>(npcs_.size()); }
  Entity& npc(int i) { return *npcs_[i].entity; }
  const Entity& npc(int i) const { return *npcs_[i].entity; }
  int tick_hz() const { return tick_hz_; }
  float dt() const { return 1.0f / static_cast<float>(tick_hz_); }
  uint64_t tick() const { return tick_; }
  const SplinePrototypes& prototypes() const { return prototypes_; }
  // New prototypes / params for every creature (live editing).
  void set_prototypes(const SplinePrototypes& prototypes);
  void set_params(const AnimatorParams& params);
  const AnimatorParams& params() const { return params_; }

 private:
  struct Npc {
    std::unique_ptr<Entity> entity;
    Rng rng;
    Controls controls;
    float timer = 0.0f;
  };
  Level level_;
  SplinePrototypes prototypes_;
  AnimatorParams params_;
  int tick_hz_;
  uint64_t tick_ = 0;
  std::unique_ptr<Player> player_;
  std::vector<Npc> npcs_;
  Controls applied_;
  RigCache rigs_;
  int threads_ = 0;
  std::vector<Entity*> step_entities_;  // step's scratch lists, kept to spare the allocations
  std::vector<Controls> step_controls_;

  Player& place_player(std::unique_ptr<Player> player, glm::vec2 at_ws, int facing);
  Entity& place_npc(std::unique_ptr<Entity> entity, glm::vec2 at_ws, uint64_t seed);
  glm::vec2 player_stand() const;  // where a replacement player is spawned
  // The creature in `self`'s way moving in direction `dir` (sign): -1 the player, i >= 0 NPC i,
  // -2 none.
  int blocker_ahead(const Entity& self, float dir) const;
};

// FNV-1a over the bits of every matrix: equal poses hash equal, bit for bit.
uint64_t pose_hash(const std::vector<Mat2x3>& matrices, uint64_t hash = 1469598103934665603ull);

}  // namespace ossa
