#include "ossa/game/world.h"

#include <algorithm>
#include <cstring>

namespace ossa {

World::World(Level level, SplinePrototypes prototypes, AnimatorParams params, int tick_hz)
    : level_(std::move(level)), prototypes_(std::move(prototypes)), params_(params),
      tick_hz_(std::clamp(tick_hz, 30, 480)) {}

Player& World::place_player(std::unique_ptr<Player> player, glm::vec2 at_ws, int facing) {
  player_ = std::move(player);
  player_->animator().reset(at_ws, level_, facing);
  return *player_;
}

Player& World::spawn_player(std::shared_ptr<const Creature> creature, glm::vec2 at_ws, int facing) {
  std::shared_ptr<const AnimRig> rig = rigs_.rig(creature);
  return place_player(std::make_unique<Player>(std::move(creature), std::move(rig), prototypes_, params_), at_ws, facing);
}

Player& World::spawn_player(std::shared_ptr<const Character> character, glm::vec2 at_ws, int facing) {
  return place_player(std::make_unique<Player>(std::move(character), prototypes_, params_), at_ws, facing);
}

Entity& World::place_npc(std::unique_ptr<Entity> entity, glm::vec2 at_ws, uint64_t seed) {
  Npc npc{std::move(entity), Rng(seed), {}, 0.0f};
  npc.entity->animator().reset(at_ws, level_, npc.rng.chance(0.5) ? 1 : -1);
  npcs_.push_back(std::move(npc));
  return *npcs_.back().entity;
}

Entity& World::spawn_npc(std::shared_ptr<const Creature> creature, glm::vec2 at_ws, uint64_t seed) {
  std::shared_ptr<const AnimRig> rig = rigs_.rig(creature);
  return place_npc(std::make_unique<Entity>(std::move(creature), std::move(rig), prototypes_, params_), at_ws, seed);
}

Entity& World::spawn_npc(std::shared_ptr<const Character> character, glm::vec2 at_ws, uint64_t seed) {
  return place_npc(std::make_unique<Entity>(std::move(character), prototypes_, params_), at_ws, seed);
}

void World::remove_npcs() { npcs_.clear(); }

glm::vec2 World::player_stand() const {
  const float x = player_->animator().x();
  const Animator& a = player_->animator();
  const float y = a.leg_count() > 0 ? a.foot_target_ws(0).y : bone_start(a.world_matrices()[a.rig().root]).y;
  return {x, y + 1.0f};
}

void World::set_player_creature(std::shared_ptr<const Creature> creature) {
  if (!player_) return;
  spawn_player(std::move(creature), player_stand(), player_->animator().facing());
}

void World::set_player_character(std::shared_ptr<const Character> character) {
  if (!player_) return;
  spawn_player(std::move(character), player_stand(), player_->animator().facing());
}

void World::set_prototypes(const SplinePrototypes& prototypes) {
  prototypes_ = prototypes;
  if (player_) player_->animator().set_spline_prototypes(prototypes);
  for (Npc& n : npcs_) n.entity->animator().set_spline_prototypes(prototypes);
}

void World::set_params(const AnimatorParams& params) {
  params_ = params;
  if (player_) player_->animator().params() = params;
  for (Npc& n : npcs_) n.entity->animator().params() = params;
}

void World::step(const Controls& player_controls) {
  const float h = dt();
  step_entities_.clear();
  step_controls_.clear();
  if (player_) {
    step_entities_.push_back(player_.get());
    step_controls_.push_back(player_controls);
  }
  for (Npc& n : npcs_) {
    // Wander: hold a heading and a pace for a while; pause sometimes; turn when blocked.
    n.timer -= h;
    if (n.timer <= 0.0f) {
      n.timer = static_cast<float>(n.rng.uniform(1.5, 5.0));
      if (n.rng.chance(0.25)) {
        n.controls = {};
      } else {
        const float dir = n.rng.chance(0.5) ? 1.0f : -1.0f;
        n.controls.move_x = dir * static_cast<float>(n.rng.uniform(0.25, 0.9));
        n.controls.run = n.rng.chance(0.15);
      }
    }
    if (n.entity->animator().blocked() && n.controls.move_x != 0.0f) {
      n.controls.move_x = -n.controls.move_x;
      n.timer = std::max(n.timer, 1.5f);
    }
    step_entities_.push_back(n.entity.get());
    step_controls_.push_back(n.controls);
  }
  step_all(step_entities_, step_controls_, h, level_, threads_);
  ++tick_;
}

uint64_t pose_hash(const std::vector<Mat2x3>& matrices, uint64_t hash) {
  for (const Mat2x3& m : matrices) {
    for (float v : m.m) {
      uint32_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      for (int k = 0; k < 4; ++k) {
        hash ^= (bits >> (8 * k)) & 0xffu;
        hash *= 1099511628211ull;
      }
    }
  }
  return hash;
}

}  // namespace ossa
