#include "ossa/game/world.h"

#include <algorithm>
#include <cmath>
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

namespace {

// A creature's body for the meeting rule: its x-extent, feet height and hip height.
struct Body {
  float lo = 0.0f, hi = 0.0f, feet = 0.0f, hip = 1.0f, velocity = 0.0f;
};

// The x-extent is symmetric about the root (its larger reach, head or tail, both ways), so it
// does not jump when a creature turns around.
Body body_of(const Entity& e) {
  const Animator& a = e.animator();
  const AnimRig& rig = a.rig();
  const float reach = std::max(rig.body_front, -rig.body_back);
  return {a.x() - reach, a.x() + reach, a.root_y() - a.hip_height(), a.hip_height(), a.velocity()};
}

}  // namespace

bool creatures_in_each_others_way(float hip_a, float feet_a, float hip_b, float feet_b) {
  const float small = std::min(hip_a, hip_b), large = std::max(hip_a, hip_b);
  if (small < kPassUnderRatio * large) return false;  // the small one passes under
  return std::abs(feet_a - feet_b) < small;
}

int World::blocker_ahead(const Entity& self, float dir) const {
  const Body me = body_of(self);
  // At least the walk's speed: a creature at rest that starts walking must not start into
  // one it would have to stop for at once.
  const float speed = std::max(std::abs(me.velocity), self.animator().walk_speed());
  const float reach = kMeetGap + kMeetLookAhead * speed;
  int found = -2;  // -2: none; -1: the player; i: NPC i
  const auto check = [&](const Entity& other, int id) {
    if (&other == &self || found != -2) return;
    const Body b = body_of(other);
    if (!creatures_in_each_others_way(me.hip, me.feet, b.hip, b.feet)) return;
    // The gap between the bodies in the direction of motion (negative: they overlap).
    const float gap = dir > 0.0f ? b.lo - me.hi : me.lo - b.hi;
    const float centre_ahead = dir > 0.0f ? (b.lo + b.hi) - (me.lo + me.hi) : (me.lo + me.hi) - (b.lo + b.hi);
    if (gap < reach && centre_ahead > 0.0f) found = id;
  };
  if (player_) check(*player_, -1);
  for (size_t i = 0; i < npcs_.size(); ++i) check(*npcs_[i].entity, static_cast<int>(i));
  return found;
}

void World::step(const Controls& player_controls) {
  const float h = dt();
  step_entities_.clear();
  step_controls_.clear();
  if (player_) {
    // The player stops at a creature in its way; an NPC it walks up to gives way (below).
    Controls c = player_controls;
    if (c.move_x != 0.0f && player_meets_creatures) {
      const int blocker = blocker_ahead(*player_, c.move_x);
      if (blocker >= 0) {
        Npc& n = npcs_[static_cast<size_t>(blocker)];
        // At least as fast as the player asks to go (and at least 0.6: a brisk walk).
        n.controls.move_x =
            (c.move_x > 0.0f ? 1.0f : -1.0f) * std::max({0.6f, std::abs(n.controls.move_x), std::abs(c.move_x)});
        n.controls.run = c.run;
        n.timer = std::max(n.timer, 1.5f);
      }
      if (blocker != -2) c.move_x = 0.0f;
    }
    applied_ = c;
    step_entities_.push_back(player_.get());
    step_controls_.push_back(c);
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
    // Blocked by the level or meeting a creature in its way: turn back — or wait, when the
    // way back is taken by a creature too (hemmed in) or the creature ahead is the player
    // walking on the same way.
    if (n.controls.move_x != 0.0f) {
      const float dir = n.controls.move_x;
      const bool wall = n.entity->animator().blocked();
      const int blocker = blocker_ahead(*n.entity, dir);
      if (wall || blocker != -2) {
        const bool follow_player = !wall && blocker == -1 && applied_.move_x * dir > 0.0f;
        const bool back_free = blocker_ahead(*n.entity, -dir) == -2;
        if (!follow_player && back_free) {
          n.controls.move_x = -dir;
          n.timer = std::max(n.timer, 1.5f);
        } else {
          n.controls.move_x = 0.0f;
          n.timer = std::max(n.timer, 0.5f);
        }
      }
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
