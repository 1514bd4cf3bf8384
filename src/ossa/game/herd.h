#pragma once
// Herds — many creatures stepped together, on every core.
//   RigCache   one immutable AnimRig per creature, shared by every entity of that creature
//              (a horse's rig is ~17 KB; a herd of 10 000 horses holds one).
//   step_all   one fixed step of an embedder's own list of entities, in parallel over oneTBB.
//
// Determinism: an entity's step reads only the level (const) and writes only its own
// animator, so every entity does the same arithmetic in the same order whichever thread runs
// it: the poses after any number of steps are bit-identical for 1 and N threads
// (tests/game/herd_test.cpp compares their pose hashes).

#include <memory>
#include <span>
#include <unordered_map>

#include "ossa/game/player.h"

namespace ossa {

class RigCache {
 public:
  // The rig of `creature`, built on the first call for it and shared afterwards. The cache
  // keeps the creature alive, so its address cannot be reused by another one while cached.
  // A miss first drops the rigs that only the cache still holds.
  // Not thread-safe: fill it from one thread (spawning), then step from many.
  std::shared_ptr<const AnimRig> rig(const std::shared_ptr<const Creature>& creature);
  int size() const { return static_cast<int>(rigs_.size()); }
  // Forgets every rig; entities that hold one keep it.
  void clear() { rigs_.clear(); }

 private:
  struct Entry {
    std::shared_ptr<const Creature> creature;
    std::shared_ptr<const AnimRig> rig;
  };
  std::unordered_map<const Creature*, Entry> rigs_;
};

// The number of threads a `threads` argument means: 0 → every core (oneTBB's default
// concurrency), n ≥ 1 → n.
int resolve_threads(int threads);

// One fixed step of dt seconds for every entity, entities[i] with controls[i] (the two spans
// have the same length; no entity twice), on up to `threads` threads (0: every core; 1: this
// thread only, in order). The result does not depend on `threads`.
void step_all(std::span<Entity* const> entities, std::span<const Controls> controls, float dt, const Level& level,
              int threads = 0);

}  // namespace ossa
