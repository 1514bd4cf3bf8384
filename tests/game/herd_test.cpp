#include "ossa/game/herd.h"

#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "ossa/gen/skeleton_builder.h"
#include "ossa/game/world.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

// A herd of horses and random creatures (a few genomes, many creatures each).
std::vector<std::shared_ptr<const Creature>> herd_creatures() {
  std::vector<std::shared_ptr<const Creature>> creatures{std::make_shared<const Creature>(scenes::quadruped()),
                                                         std::make_shared<const Creature>(scenes::biped())};
  for (uint64_t seed : {11u, 23u, 37u}) {
    creatures.push_back(std::make_shared<const Creature>(build_creature(scenes::generator().random(seed)).value()));
  }
  return creatures;
}

// The hash of every creature's world matrices after every tick of `ticks` World steps.
uint64_t world_run_hash(int threads, int ticks) {
  World world(scenes::flat_level(400.0f), SplinePrototypes::defaults());
  world.set_threads(threads);
  const auto creatures = herd_creatures();
  world.spawn_player(creatures[0], {5.0f, 2.0f});
  for (int i = 0; i < 60; ++i) {
    world.spawn_npc(creatures[i % creatures.size()], {10.0f + 5.0f * static_cast<float>(i), 2.0f}, 1000u + i);
  }
  uint64_t hash = pose_hash({});
  Controls walk;
  walk.move_x = 0.6f;
  for (int t = 0; t < ticks; ++t) {
    world.step(walk);
    hash = pose_hash(world.player()->animator().world_matrices(), hash);
    for (int i = 0; i < world.npc_count(); ++i) hash = pose_hash(world.npc(i).animator().world_matrices(), hash);
  }
  return hash;
}

}  // namespace

TEST_CASE("RigCache builds one rig per creature and every entity of it shares that rig", "[game][herd]") {
  RigCache cache;
  const auto horse = std::make_shared<const Creature>(scenes::quadruped());
  const auto kangaroo = std::make_shared<const Creature>(scenes::biped());
  Entity a(horse, cache.rig(horse), SplinePrototypes::defaults());
  Entity b(horse, cache.rig(horse), SplinePrototypes::defaults());
  Entity c(kangaroo, cache.rig(kangaroo), SplinePrototypes::defaults());
  CHECK(a.animator().shared_rig().get() == b.animator().shared_rig().get());
  CHECK(a.animator().shared_rig().get() != c.animator().shared_rig().get());
  CHECK(cache.size() == 2);
  // The world's creatures share their rigs too.
  World world(scenes::flat_level(100.0f), SplinePrototypes::defaults());
  world.spawn_player(horse, {5.0f, 2.0f});
  world.spawn_npc(horse, {10.0f, 2.0f}, 1);
  world.spawn_npc(horse, {20.0f, 2.0f}, 2);
  CHECK(world.rigs().size() == 1);
  CHECK(world.npc(0).animator().shared_rig().get() == world.npc(1).animator().shared_rig().get());
  CHECK(world.npc(0).animator().shared_rig().get() == world.player()->animator().shared_rig().get());
}

TEST_CASE("RigCache forgets a rig no entity holds when it builds another", "[game][herd]") {
  RigCache cache;
  const auto horse = std::make_shared<const Creature>(scenes::quadruped());
  const auto kangaroo = std::make_shared<const Creature>(scenes::biped());
  { Entity a(horse, cache.rig(horse), SplinePrototypes::defaults()); }
  Entity c(kangaroo, cache.rig(kangaroo), SplinePrototypes::defaults());
  CHECK(cache.size() == 1);
}

TEST_CASE("World::step gives bit-identical poses on 1, 2 and 4 threads", "[game][herd][determinism]") {
  const uint64_t one = world_run_hash(1, 240);
  CHECK(one != world_run_hash(1, 1));  // the herd moves: the hash covers changing poses
  CHECK(world_run_hash(2, 240) == one);
  CHECK(world_run_hash(4, 240) == one);
  CHECK(world_run_hash(0, 240) == one);
}

TEST_CASE("step_all over an embedder's own list matches stepping each entity in order", "[game][herd][determinism]") {
  const Level level = scenes::flat_level(400.0f);
  const auto creatures = herd_creatures();
  RigCache cache;
  auto make_herd = [&] {
    std::vector<std::unique_ptr<Entity>> herd;
    for (int i = 0; i < 50; ++i) {
      const auto& c = creatures[i % creatures.size()];
      herd.push_back(std::make_unique<Entity>(c, cache.rig(c), SplinePrototypes::defaults()));
      herd.back()->animator().reset({5.0f + 6.0f * static_cast<float>(i), 2.0f}, level, i % 2 ? 1 : -1);
    }
    return herd;
  };
  auto serial = make_herd(), parallel = make_herd();
  std::vector<Entity*> list;
  std::vector<Controls> controls;
  for (size_t i = 0; i < parallel.size(); ++i) {
    list.push_back(parallel[i].get());
    Controls c;
    c.move_x = (i % 3 == 0 ? -0.4f : 0.8f);
    c.run = i % 5 == 0;
    controls.push_back(c);
  }
  const float dt = 1.0f / 60.0f;
  for (int t = 0; t < 180; ++t) {
    for (size_t i = 0; i < serial.size(); ++i) serial[i]->step(dt, controls[i], level);
    step_all(list, controls, dt, level, 2);
  }
  for (size_t i = 0; i < serial.size(); ++i) {
    INFO("creature " << i);
    CHECK(pose_hash(parallel[i]->animator().world_matrices()) == pose_hash(serial[i]->animator().world_matrices()));
  }
}
