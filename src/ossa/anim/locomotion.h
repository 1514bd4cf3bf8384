#pragma once
// Locomotion mode (DESIGN.md §7; stages 3, 9 and 11 of Animator::update, and A1, A4 and A5 in
// the air):
// grounded → airborne → landing → grounded, and the jump's crouch and take-off.
//   kGrounded  the gait clock, the step stage and body placement run (stages 6–10);
//   kCrouch    the same, the girdles lowered by the crouch before a jump;
//   kAirborne  the root follows a ballistic path under gravity from where it left the ground,
//              with the speed it had (a wall stops it horizontally, a ceiling vertically); the
//              feet hang tucked and reach for the ground before contact; the first foot (or
//              the body itself) to meet the ground starts the landing;
//   kLanding   the root comes down, slowing evenly, over the legs' compression, which grows
//              with the speed of the fall; feet are planted where they touch; then grounded,
//              and body placement's smoothing brings the body back up.
// A creature steps off a drop deeper than its legs reach: the foothold planner finds no ground
// (foothold.h drop_ahead), the lifting foot hangs over the edge reaching down (step.h), and
// once no foot is left on the ground the creature is airborne.
// Owned here: LocomotionState (the mode, the crouch, the path in the air, the landing's
// descent, the counts). The body moves through body placement's transitions, the feet through
// the step stage's.
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


// Counted since the animator's reset (a respawn keeps them).
struct LocomotionStats {
  int falls = 0;                   // airborne phases not begun by a jump
  int jumps = 0;
  int hard_landings = 0;           // landings after a fall of more than params.hard_landing
                                   // hip heights (at least that many kLeastJumpRiseM)
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

// How high a jump lifts the root, metres: params.jump_height hip heights, and a small
// creature's at least params.jump_height × kLeastJumpRiseM (Borelli's law: animals of any size
// jump about as high, a flea, a locust or a rabbit some tenths of a metre, as their muscle's
// work grows with their mass; large ones jump about their hip height).
inline constexpr float kLeastJumpRiseM = 0.5f;
float jump_rise(const AnimRig& rig, const AnimatorParams& params);
// The vertical take-off speed that lifts the root jump_rise, m/s.
float jump_speed(const AnimRig& rig, const AnimatorParams& params);
// A jump's take-off velocity (x along the facing, y up), m/s, for a creature moving at `speed`
// with the stick asking `asked` (both >= 0): forwards at the faster of the two, jump_speed up.
// A creature whose legs throw it faster than it runs (a small one: jump_speed is Borelli's, its
// run Froude's) leans its jump forwards with the stick, up to kLeapLeanMost from the vertical
// at the full run's stick: a frog leaps a metre at a quarter metre high rather than hopping
// half a metre straight up. The forward speed the leap adds comes from the same take-off
// speed (sqrt(jump_speed^2 - leap^2 + forwards^2) up). Blocked at a step it jumps up.
inline constexpr float kLeapLeanMost = 0.785398f;  // 45°: the farthest throw for a take-off speed
glm::vec2 jump_velocity(const AnimRig& rig, const AnimatorParams& params, float speed, float asked, bool blocked);

// The jump button, grounded: the crouch begins; its depth and length follow the creature's
// size. advance_crouch moves it on by dt (loco.crouch follows); true when it is over and
// the creature takes off.
void begin_crouch(const AnimRig& rig, const AnimatorParams& params, LocomotionState& loco);
bool advance_crouch(const AnimRig& rig, const AnimatorParams& params, float dt, LocomotionState& loco);

// Stage 3: the landing's descent runs on; the jump button, grounded, begins the crouch.
void begin_tick(const AnimRig& rig, const AnimatorParams& params, bool jump, float dt, LocomotionState& loco);
// Stage 9: the crouch deepens; true when it is over (TickHandoff::crouch_done).
bool tick_crouch(const AnimRig& rig, const AnimatorParams& params, float dt, LocomotionState& loco);

// Stage 11: what changes the mode at the end of a grounded tick: the crouch over (a jump), the
// last foot or the legless body gone over a drop (a fall), the landing's descent over.
enum class ModeChange : uint8_t { kNone, kJump, kFall, kLanded };
// `body_lift`: how far body placement holds a legless body above its resting height
// (BodyState::body_lift, where the drape could not keep it out of the ground).
ModeChange mode_change(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, bool was_landing, bool crouch_done,
                       const LocomotionState& loco, float body_lift = 0.0f);
// A creature standing on a floor at the kill height is below it once its legs give on landing:
// where the feet would stand under the root is below the level's kill height.
bool below_kill_height(const AnimRig& rig, const BodyFrame& body, const Level& level);

// The root leaves the ground with `velocity` (world, m/s): a jump or a fall. Counts it and sets
// loco.floor, the height a fall lands only below (the highest ledge a foot stepped off); the
// step stage then lifts the feet (step.h leave_ground).
void take_off(const AnimContext& ctx, const BodyFrame& body, glm::vec2 velocity, bool jump, const FootSet& feet,
              LocomotionState& loco);

// Is no foot on the ground and none about to land (every foot hangs in the air)?
bool unsupported(const FootSet& feet);
// Has a legless body crawled off a drop it falls (no ground within a quarter of its length
// below it, under the whole body)?
bool legless_over_drop(const AnimContext& ctx, const BodyFrame& body, float body_lift = 0.0f);

// ---- In the air (stages A1, A4) ----------------------------------------------------------------
// The path's time advances by dt; its horizontal step is swept against walls (`model_fs`, the
// last pose's facing-space matrices, give the sweep its outline; `boxes` is scratch): a wall
// stops the path horizontally. True with *dx (world metres) when the body moves along x.
bool fly_along(const AnimContext& ctx, float dt, const BodyFrame& body, const std::vector<Mat2x3>& model_fs,
               std::vector<Box>& boxes, LocomotionState& loco, float* dx);
// The root's height on the path now (in closed form from its origin: the apex is the
// ballistic one); a ceiling stops the rise. Sets loco.vy.
float path_height(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, std::vector<Box>& boxes,
                  LocomotionState& loco);
// A part of the body (its hull's slabs, the skull, the trunk's bones as segments; `model_fs`
// the pose just made) that came into a box ahead of it — falling, a head held over the far
// side of a gap the body falls into; standing, a chest leant into the corner of a ledge —
// takes the body back, away from that box's face, so far as it came in (world metres, >= 0; 0
// when clear, or where the body there would meet another box). flesh: the trunk's and the
// head's drawn flesh (AnimRig::flesh) as segments too (falling: a deer's muzzle came down
// 2.7 cm into drops.json's far pit wall, its skull clear). Not on the ground, where a chest
// over a tread ahead lies on it (body_floor.h), not in a face. 0 too where the body would go
// back further than `most`. stance: standing on these feet, the stance legs' drawn outline too,
// the legs following the body, no further than legs_most (leg_geometry.h stance_flesh_push).
float push_back_from_face(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, std::vector<Box>& boxes,
                          bool flesh, float most, const FootSet* stance = nullptr, float legs_most = 0.0f);
// How far the legs reach for the ground, in [0, 1]: tucked while rising or high above it.
float reach_extension(const AnimContext& ctx, const BodyFrame& body, const LocomotionState& loco);
// Stage A4. No foot planted yet: may the body itself meet the ground (no foot stands, and it
// falls)?
// `floor` is the height below which it lands (the ledge a fall left).
bool body_may_land(const LocomotionState& loco, const FootSet& feet, float* floor);

// Stage A5, touch-down: the landing's descent from the root's height now to `standing_root` (body
// placement's, for the feet where they are) less the compression. Counts the fall.
void begin_landing(const AnimContext& ctx, const BodyFrame& body, float standing_root, LocomotionState& loco);
// The root's height during the landing's descent at loco.time; NaN once it is over.
float landing_root(const LocomotionState& loco);
// The landing's descent is over: grounded again (step.h set_down_after_landing sets the feet
// that found no ground down).
void finish_landing(LocomotionState& loco);

}  // namespace anim
}  // namespace ossa
