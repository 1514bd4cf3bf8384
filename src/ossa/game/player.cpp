#include "ossa/game/player.h"

#include <algorithm>
#include <cmath>

#include "ossa/assert.h"

namespace ossa {

Entity::Entity(std::shared_ptr<const Creature> creature, const SplinePrototypes& prototypes,
               const AnimatorParams& params)
    : creature_(std::move(creature)), animator_(*creature_, prototypes, params) {}

Entity::Entity(std::shared_ptr<const Creature> creature, std::shared_ptr<const AnimRig> rig,
               const SplinePrototypes& prototypes, const AnimatorParams& params)
    : creature_(std::move(creature)), animator_(*creature_, std::move(rig), prototypes, params) {}

Entity::Entity(std::shared_ptr<const Character> character, const SplinePrototypes& prototypes,
               const AnimatorParams& params)
    : character_(std::move(character)), animator_(character_->rig, prototypes, params) {}

const Creature& Entity::creature() const {
  OSSA_ASSERT(creature_ != nullptr, "Entity::creature: this entity is a rigged character");
  return *creature_;
}

const std::string& Entity::name() const { return character_ ? character_->name : creature_->name; }

float Entity::desired_velocity(const Controls& controls) const {
  const float s = std::clamp(std::isfinite(controls.move_x) ? controls.move_x : 0.0f, -1.0f, 1.0f);
  const float a = std::fabs(s);
  const float walk = animator_.walk_speed(), run = animator_.run_speed();
  float speed;
  if (controls.run) {
    speed = a * run;
  } else if (a <= 0.5f) {
    speed = 2.0f * a * walk;
  } else {
    speed = walk + (2.0f * a - 1.0f) * (run - walk);
  }
  return std::copysign(speed, s);
}

void Entity::step(float dt, const Controls& controls, const Level& level) {
  // A jump when the button goes down (holding it does not jump again).
  const bool jump = controls.jump && !controls_.jump;
  controls_ = controls;
  animator_.update(dt, AnimatorIntent{desired_velocity(controls), jump}, level);
}

}  // namespace ossa
