// Creatures meet (world.h): a herd in a corridor never walks through itself, the player stops
// at an NPC in its way and the NPC gives way, and a creature under half as tall at the hip
// passes under a larger one.

#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "ossa/game/world.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

// A flat corridor from x = 0 to `length` between two walls.
Level corridor(float length) {
  Level level;
  level.add_box(Box{{-1.0f, -1.0f}, {length + 1.0f, 0.0f}});
  level.add_box(Box{{-1.0f, 0.0f}, {0.0f, 6.0f}});
  level.add_box(Box{{length, 0.0f}, {length + 1.0f, 6.0f}});
  level.spawn_ws = {1.0f, 0.0f};
  return level;
}

struct Extent {
  float lo, hi, feet, hip;
};

// The creature's drawn extent (its rest pose from tail to head, the way it faces).
Extent extent(const Entity& e) {
  const Animator& a = e.animator();
  return {a.rig().body_lo_ws(a.x(), a.facing()), a.rig().body_hi_ws(a.x(), a.facing()), a.root_y() - a.hip_height(),
          a.hip_height()};
}

// The deepest overlap (metres) of two creatures in each other's way, over every pair.
float worst_overlap(const World& world) {
  std::vector<Extent> e;
  if (world.player()) e.push_back(extent(*world.player()));
  for (int i = 0; i < world.npc_count(); ++i) e.push_back(extent(world.npc(i)));
  float worst = -1e9f;
  for (size_t i = 0; i < e.size(); ++i) {
    for (size_t j = i + 1; j < e.size(); ++j) {
      if (!creatures_in_each_others_way(e[i].hip, e[i].feet, e[j].hip, e[j].feet)) continue;
      worst = std::max(worst, std::min(e[i].hi, e[j].hi) - std::max(e[i].lo, e[j].lo));
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("a herd of NPCs in a corridor turns back at each other and never walks through", "[game]") {
  const auto horse = std::make_shared<const Creature>(scenes::quadruped());
  World world(corridor(24.0f), SplinePrototypes::defaults());
  const float xs[] = {3.0f, 9.0f, 15.0f, 21.0f};
  for (int i = 0; i < 4; ++i) world.spawn_npc(horse, {xs[i], 0.5f}, 100 + static_cast<uint64_t>(i));
  REQUIRE(worst_overlap(world) < 0.0f);
  std::vector<float> last(4), walked(4, 0.0f);
  for (int i = 0; i < 4; ++i) last[i] = world.npc(i).animator().x();
  float worst = -1e9f;
  const int ticks = 60 * world.tick_hz();
  for (int t = 0; t < ticks; ++t) {
    world.step(Controls{});
    worst = std::max(worst, worst_overlap(world));
    for (int i = 0; i < 4; ++i) {
      const float x = world.npc(i).animator().x();
      walked[static_cast<size_t>(i)] += std::abs(x - last[static_cast<size_t>(i)]);
      last[static_cast<size_t>(i)] = x;
    }
  }
  INFO("deepest overlap " << worst << " m");
  CHECK(worst < 0.05f);
  // They still wander: each walks metres in the minute.
  for (int i = 0; i < 4; ++i) CHECK(walked[static_cast<size_t>(i)] > 5.0f);
  // Order along the corridor is kept: nobody passed anybody.
  for (int i = 0; i + 1 < 4; ++i) CHECK(world.npc(i).animator().x() < world.npc(i + 1).animator().x());
}

TEST_CASE("the player stops at an NPC in its way and the NPC gives way", "[game]") {
  const auto horse = std::make_shared<const Creature>(scenes::quadruped());
  World world(corridor(30.0f), SplinePrototypes::defaults());
  world.spawn_player(horse, {3.0f, 0.5f});
  world.spawn_npc(horse, {9.0f, 0.5f}, 7);
  const float npc_x0 = world.npc(0).animator().x();
  Controls walk;
  walk.move_x = 0.5f;
  float worst = -1e9f;
  std::string when;
  for (int t = 0; t < 20 * world.tick_hz(); ++t) {
    world.step(walk);
    const float o = worst_overlap(world);
    if (o > worst) {
      worst = o;
      const Animator& p = world.player()->animator();
      const Animator& n = world.npc(0).animator();
      when = "tick " + std::to_string(t) + ": player x " + std::to_string(p.x()) + " v " + std::to_string(p.velocity()) +
             ", NPC x " + std::to_string(n.x()) + " v " + std::to_string(n.velocity()) + " facing " + std::to_string(n.facing());
    }
  }
  INFO("deepest overlap " << worst << " m at " << when);
  CHECK(worst < 0.05f);
  // Pushed along: both went right, the NPC ahead of the player all the way to the far wall.
  CHECK(world.npc(0).animator().x() > npc_x0 + 8.0f);
  CHECK(world.player()->animator().x() > 3.0f + 8.0f);
  CHECK(world.player()->animator().x() < world.npc(0).animator().x());
  // At the far wall the NPC is hemmed in: the player stands behind it.
  CHECK(std::abs(world.player()->animator().velocity()) < 0.1f);
  CHECK(world.applied_player_controls().move_x == 0.0f);
}

TEST_CASE("a creature under half as tall at the hip passes under a larger one", "[game]") {
  CHECK(creatures_in_each_others_way(1.2f, 0.0f, 1.0f, 0.0f));
  CHECK_FALSE(creatures_in_each_others_way(1.2f, 0.0f, 0.5f, 0.0f));   // passes under
  CHECK_FALSE(creatures_in_each_others_way(1.2f, 0.0f, 1.2f, 2.0f));   // on a ledge above
  CHECK(creatures_in_each_others_way(1.2f, 0.0f, 1.2f, 0.5f));         // a step up: still in the way
}
