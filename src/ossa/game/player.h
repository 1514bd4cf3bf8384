#pragma once
// Entity and Player — a creature in the world: its generated Creature or its rigged
// Character (anim/character.h), its Animator and how it is controlled. The Player maps Controls to a desired velocity so that the stick sets the
// speed precisely [T 4.1]:
//   without run: |move_x| in [0, 0.5] → 0 … walk speed, (0.5, 1] → walk … run speed,
//   with run:    |move_x| × run speed.
// Walk and run speeds come from the creature's hip height (Froude numbers 0.5 and 2.5), so a
// mouse and a horse move at speeds that look right for their size.

#include <memory>

#include "ossa/anim/animator.h"
#include "ossa/rig/character.h"
#include "ossa/game/controls.h"

namespace ossa {

class Entity {
 public:
  Entity(std::shared_ptr<const Creature> creature, const SplinePrototypes& prototypes,
         const AnimatorParams& params = {});
  // Shares `rig`, built once for every entity of this creature (build_anim_rig, RigCache).
  Entity(std::shared_ptr<const Creature> creature, std::shared_ptr<const AnimRig> rig,
         const SplinePrototypes& prototypes, const AnimatorParams& params = {});
  // A rigged character: its shared AnimRig drives the animator.
  Entity(std::shared_ptr<const Character> character, const SplinePrototypes& prototypes,
         const AnimatorParams& params = {});
  virtual ~Entity() = default;

  // Exactly one of the two is set.
  bool is_character() const { return character_ != nullptr; }
  const Creature& creature() const;  // is_character() == false only
  std::shared_ptr<const Creature> creature_ptr() const { return creature_; }
  const Character* character() const { return character_.get(); }
  std::shared_ptr<const Character> character_ptr() const { return character_; }
  // The creature's or the character's name; the bones the animator's matrices are for.
  const std::string& name() const;
  const Skeleton& skeleton() const { return animator_.rig().skeleton; }

  Animator& animator() { return animator_; }
  const Animator& animator() const { return animator_; }

  // The velocity this entity wants for the given controls (m/s, signed).
  float desired_velocity(const Controls& controls) const;
  // One fixed step with the given controls.
  void step(float dt, const Controls& controls, const Level& level);
  const Controls& last_controls() const { return controls_; }

 private:
  std::shared_ptr<const Creature> creature_;
  std::shared_ptr<const Character> character_;
  Animator animator_;
  Controls controls_;
};

// The creature the playtester drives.
class Player : public Entity {
 public:
  using Entity::Entity;
};

}  // namespace ossa
