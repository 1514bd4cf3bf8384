#pragma once
// Locomotion mode (DESIGN.md §7, stage 3): grounded → airborne → landing → grounded, and the
// jump's crouch and take-off.
//   kGrounded  the gait clock, foothold planner, swing and body placement run (stages 2, 4–6);
//   kCrouch    the same, the girdles lowered by the crouch before a jump;
//   kAirborne  the root follows a ballistic path under gravity from where it left the ground,
//              with the speed it had (a wall stops it horizontally, a ceiling vertically); the
//              feet hang tucked and reach for the ground before contact; the first foot (or
//              the body itself) to meet the ground starts the landing;
//   kLanding   the root comes down, slowing evenly, over the legs' compression, which grows
//              with the speed of the fall; feet are planted where they touch; then grounded,
//              and body placement's smoothing brings the body back up.
// A creature steps off a drop deeper than its legs reach: the foothold planner finds no ground
// (foothold.h drop_ahead), the lifting foot hangs over the edge reaching down (FootState::air),
// and once no foot is left on the ground the creature is airborne.
//
// Inputs: AnimContext, the body frame, the feet; world space (_ws), metres, seconds.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

enum class Locomotion : uint8_t { kGrounded, kCrouch, kAirborne, kLanding };
const char* locomotion_name(Locomotion mode);  // "grounded", "crouch", "airborne", "landing"

namespace anim {

// A foot stepping off a ledge, or a fall, lands only on ground this far below the ledge left
// (FootState::floor, LocomotionState::floor), metres.
inline constexpr float kFloorBelowLedge = 0.01f;

// Counted since the animator's reset (a respawn keeps them).
struct LocomotionStats {
  int falls = 0;                   // airborne phases not begun by a jump
  int jumps = 0;
  int hard_landings = 0;           // landings after a fall of more than params.hard_landing
  int respawns = 0;                // falls below the level's kill height
  float max_fall_m = 0.0f;         // the largest drop of the root, highest point to touch-down
  float max_jump_height_m = 0.0f;  // the highest rise of the root above its take-off
  float airborne_s = 0.0f;         // seconds in the air
};

struct LocomotionState {
  Locomotion mode = Locomotion::kGrounded;
  float time = 0.0f;               // seconds since the mode (or the airborne path) began
  float crouch_seconds = 0.0f;     // kCrouch: its length
  // kAirborne: the root's path y(t) = origin_y + vy0 t - g t²/2, and its horizontal speed
  // (signed, world x); jumped: a jump (not a fall); where it took off; its highest point.
  float origin_y = 0.0f, vy0 = 0.0f, vx = 0.0f;
  bool jumped = false;
  float start_y = 0.0f, top_y = 0.0f;
  float floor = 1e30f;             // a fall lands only on ground below this (the ledge it left)
  // kLanding: the root from land_y, moving at land_v (< 0), to land_low over land_seconds.
  float land_y = 0.0f, land_v = 0.0f, land_low = 0.0f, land_seconds = 0.0f;
  float crouch = 0.0f;             // metres body placement lowers the girdles by (kCrouch)
  float vy = 0.0f;                 // the root's vertical speed in the air and landing, m/s
  LocomotionStats stats;
};

// The vertical take-off speed that lifts the root params.jump_height hip heights, m/s.
float jump_speed(const AnimRig& rig, const AnimatorParams& params);

// The jump button, grounded: the crouch begins; its depth and length follow the creature's
// size. advance_crouch moves it on by dt (loco.crouch follows); true when it is over and
// the creature takes off.
void begin_crouch(const AnimRig& rig, const AnimatorParams& params, LocomotionState& loco);
bool advance_crouch(const AnimRig& rig, const AnimatorParams& params, float dt, LocomotionState& loco);

// The root leaves the ground with `velocity` (world, m/s): a jump (feet on the ground push off
// until their legs are stretched, a quadruped's front feet first, so the hind legs push last)
// or a fall (every foot hangs).
void take_off(const AnimContext& ctx, const BodyFrame& body, glm::vec2 velocity, bool jump, FootSet& feet,
              LocomotionState& loco);

// Is no foot on the ground and none about to land (every foot hangs in the air)?
bool unsupported(const FootSet& feet);
// Has a legless body crawled off a drop it falls (no ground within a quarter of its length
// below it, under the whole body)?
bool legless_over_drop(const AnimContext& ctx, const BodyFrame& body);

// Where leg `leg`'s foot hangs in the air: under its girdle, tucked (extension 0) or reaching
// for the ground (1), a front leg ahead and a hind leg behind.
glm::vec2 air_target(const AnimContext& ctx, const BodyFrame& body, int leg, float extension);

// A foot starts hanging in the air from where it is (no jump: its offset eases away).
void hang(const AnimContext& ctx, const BodyFrame& body, int leg, float extension, FootState& foot);

// Feet hanging in the air follow their targets and are planted where they meet the top of a
// box on the way down; reach_ground (on the ground: stepping off, landing): a foot reaches
// down to ground its leg reaches below it; may_land false (the body still rising): a foot
// meeting ground is carried along it, not planted. Returns how many were planted.
int update_air_feet(const AnimContext& ctx, const BodyFrame& body, float extension, float dt, bool reach_ground,
                    FootSet& feet, bool may_land = true);

// One tick in the air: the body along its path (`model_fs`, the last pose's facing-space
// matrices, give the wall sweep its outline; `boxes` is scratch), pitch and lean easing level
// (keep_level: exp(-rate·dt)), the feet pushing off, hanging and reaching. True at touch-down
// (a foot planted, or the body meeting the ground first): call begin_landing.
bool airborne_tick(const AnimContext& ctx, float dt, float keep_level, const std::vector<Mat2x3>& model_fs,
                   std::vector<Box>& boxes, BodyFrame& body, FootSet& feet, LocomotionState& loco);

// Touch-down: the landing's descent from the root's height now to `standing_root` (body
// placement's, for the feet where they are) less the compression. Counts the fall.
void begin_landing(const AnimContext& ctx, const BodyFrame& body, float standing_root, LocomotionState& loco);
// The root's height during the landing's descent at loco.time; NaN once it is over.
float landing_root(const LocomotionState& loco);

}  // namespace anim
}  // namespace ossa
