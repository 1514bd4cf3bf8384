#pragma once
// AnimatorParams — everything a designer tunes about how a creature moves (tuning panel).
// Definition struct with defaults (Box2D style): every field states its unit and range.
// Names marked [T] are kept from the source thesis.

#include "ossa/gen/gait_family.h"

namespace ossa {

enum class GaitOverride : int { kAuto = -1, kWalk = 0, kTrot = 1, kGallop = 2 };

struct AnimatorParams {
  // [T] Scales the stride from Alexander's relation λ = 2.3·h·Fr^0.3. Range [0.3, 2].
  float step_distance_multiplier = 1.0f;
  // [T] Scales how fast the animator eases towards new targets (lean, height, gait blend).
  // Range [0.1, 5].
  float interpolation_speed_multiplier = 1.0f;
  // [T] Largest forward lean of the spine into the motion at full run, radians. [0, 0.6].
  float max_spine_rotation = 0.18f;

  // Duty factor (fraction of a cycle a foot is on the ground) at a walk and at a full run.
  // A running duty below 0.5 gives a flight phase. Ranges [0.5, 0.85] and [0.2, 0.6].
  float duty_walk = 0.65f;
  float duty_run = 0.36f;
  // Froude numbers Fr = v²/(g·h) where the walk→run blend starts and ends. [0.05, 3].
  float run_froude_start = 0.35f;
  float run_froude_end = 1.4f;
  // The gait family (anim/gait_family.h): kAuto moves as the creature's rig says (its genome's
  // choice or the body plan's); another family overrides it.
  GaitFamily gait_family = GaitFamily::kAuto;
  // Scales the Froude numbers where the family's gaits change (walk → trot near 0.5, trot →
  // gallop near 2.5 for a cursorial quadruped: GAITS.md). Range [0.3, 3].
  float gait_froude_scale = 1.0f;
  // Walk, the family's middle gait ("trot": its trot, pace, half-bound, run) or its fast gait
  // ("gallop": gallop, bound, aerial run) at every speed; auto chooses by Froude number.
  GaitOverride gait_override = GaitOverride::kAuto;

  // Highest step up and deepest step down a foot may take: the step up as a fraction of the
  // shortest girdle's standing height (or of 0.8 of its leg's reach where that is more:
  // crouching legs), so that every leg pair can follow; the step down as a fraction of the
  // foot's own girdle's standing height. Walls taller and drops deeper stop the creature at
  // the edge. [0.05, 1].
  float max_step_up = 0.6f;
  float max_step_down = 0.7f;
  // Standing height of the girdles as a fraction of their rest height. [0.7, 1.05].
  float stance_height = 0.97f;
  // Time for swinging feet to set down after a stop, seconds. [0.05, 0.3].
  float stop_ease_time = 0.18f;
  // Tail: spring stiffness (1/s²) and damping ratio of the tail's secondary motion.
  float tail_stiffness = 60.0f;
  float tail_damping = 0.35f;
  // Largest swing of the tail's spring, radians summed over the tail. [0, 1.5].
  float tail_max_swing = 0.8f;
  // Travelling wave of legless bodies: how high it lifts a stretch of the body off the ground,
  // of the half body length, and waves per body.
  float crawl_amplitude = 0.035f;
  float crawl_waves = 1.5f;
  // Amplitude of a fin's slow beat while moving, radians. [0, 0.5].
  float fin_beat = 0.12f;
  // Period of the idle breathing (prototype idle_y), seconds. [0.5, 10].
  float idle_period = 2.4f;
  // Jump (DESIGN.md §7): the root rises this many hip heights above where it takes off, and
  // a creature smaller than kLeastJumpRiseM at the hip this many times that (jump_rise,
  // locomotion.h). [0.1, 4].
  float jump_height = 1.0f;
  // The crouch before a jump lowers the girdles by this many hip heights; it lasts
  // jump_crouch_time √(hip height / g) seconds, so it follows the creature's size. [0, 0.5]
  // and [0.5, 4].
  float jump_crouch = 0.2f;
  float jump_crouch_time = 1.2f;
  // Landing: the legs give by this many hip heights after a fall of one hip height, growing
  // with the speed of the fall (at most twice as much). [0, 0.5].
  float landing_compression = 0.12f;
  // A fall of more than this many hip heights (from the highest point to touch-down) is a
  // hard landing: it still lands, giving twice as far, and is counted. A creature under
  // kLeastJumpRiseM at the hip counts that much instead: small animals land as they jump
  // (locomotion.h jump_rise). [1, 100].
  float hard_landing = 8.0f;

  // Gravity for the Froude number and the airborne path, m/s².
  float gravity = 9.81f;

  bool operator==(const AnimatorParams&) const = default;
};

}  // namespace ossa
