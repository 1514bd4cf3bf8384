#pragma once
// Foothold planner (DESIGN.md §7 "foothold planner"; part of the step stage, step.h): where a
// lifting foot lands. A landing is on ground
// the leg pairs can follow (no higher than max_step_up of the climb height, no deeper than
// max_step_down of the girdle's standing height), the whole foot fits there, and the shin
// coming down from above and behind clears the ground it steps down from (a riser, read from
// the ground profile; a tile slope of small steps is not one). find_landing is the one
// planner that lift-off, stop, turn and reset all use.
//
// Inputs: AnimContext, the body frame, the stride; positions in world space (_ws), metres.

#include <glm/vec2.hpp>

#include "ossa/anim/anim_state.h"
#include "ossa/anim/ground_profile.h"

namespace ossa::anim {

struct FootholdInputs {
  const AnimContext& ctx;
  const BodyFrame& body;
  float stride = 0.0f;  // metres per cycle (GaitState::stride)
  float duty = 0.65f;   // GaitState::duty
  // The feet, when the planner may count a step up from the feet standing on a ledge
  // (step_limits); nullptr: from the foot alone.
  const FootSet* feet = nullptr;
};

// Where a foot steps from, for find_landing's step limits: where it stands, or where a
// swinging foot lifted off (not the air it is in: a foot high over a wall would find the
// wall's top within a step of it).
inline glm::vec2 step_from(const FootState& f) { return f.state == LegState::kSwing ? f.from_ws : f.pos_ws; }

// The landing of leg `leg`, whose foot stands at foot_ws, nearest to x_wanted: the planned spot
// first, then the nearest shorter or slightly longer steps (as short as just ahead of the
// foot, at most a quarter stride longer). False: no foothold (a wall too tall, a drop too deep).
bool find_landing(const FootholdInputs& in, int leg, glm::vec2 foot_ws, float x_wanted, glm::vec2* landing);

// When find_landing finds no foothold: is it a drop — no ground within the step limits where
// the foot would land, and nothing rising more than a step between the foot and there — that
// the creature steps off (locomotion.h), rather than a wall that stops it? *hang_beyond: the
// world x the foot's contact point must pass (in the facing direction) for the whole foot to
// hang over the drop.
bool drop_ahead(const FootholdInputs& in, int leg, glm::vec2 foot_ws, float x_wanted, float* hang_beyond = nullptr);

// The foot's horizontal extent relative to its contact point, world x (the facing applied):
// back to the ankle, forward to the toe.
struct FootSpan {
  float lo = 0.0f, hi = 0.0f;
};
FootSpan foot_span_ws(const RigLeg& leg, int facing);
// The same widened by the leg's drawn flesh about the foot (RigLeg::flesh_back/flesh_front):
// what must clear the level where the foot stands or swings.
FootSpan flesh_span_ws(const RigLeg& leg, int facing);
// The height of the box a foot needs above its contact point, metres.
float foot_height(const RigScale& scale, const RigLeg& leg);
// The part of it that bears on the ground: a flat foot's sole, a tip's point (its ankle and
// foot bone stand above the ground, over whatever lies there).
FootSpan support_span_ws(const RigLeg& leg, int facing);

// Where leg `leg` would land if it lifted now at `speed` m/s (swing_phase < 0: a full swing):
// half a stance ahead of where its girdle will be at touch-down [T 4.4.1].
float landing_x(const FootholdInputs& in, int leg, float speed, float swing_phase = -1.0f);

// Does leg `leg`'s foot, standing at contact_ws as the creature now faces, clear every box?
// with_flesh: its drawn flesh too (flesh_span_ws).
bool foot_fits(const FootholdInputs& in, int leg, glm::vec2 contact_ws, bool with_flesh = false);

// Does leg `leg`'s shin, coming down from above and behind to its foot at contact_ws as the
// creature now faces, clear the ground behind the foot (no riser there that find_landing keeps
// a landing off)?
bool shin_clears_riser(const FootholdInputs& in, int leg, glm::vec2 contact_ws);

// The nearest place to near_ws (either way along the ground, up to half a leg's length) where
// leg `leg`'s foot fits, its flesh too if there is one; prefer_reach: one the leg reaches
// (within reach_use of its reach) from where its girdle is now, if there is one.
bool nearest_fit(const FootholdInputs& in, int leg, glm::vec2 near_ws, glm::vec2* spot, bool prefer_reach = false,
                 float reach_use = 1.0f);

// The step limits of a foot at foot_ws: how far it may step up and down, the lowest ground
// it may step to (from the foot, or from the ground its girdle stands over when the foot
// stands higher) and the highest (a step up from the foot, or from the highest foot standing
// on — or stepping from — a ledge above it, a riser more than a step high between them, when
// the foot came down that ledge (FootState::ledge_y): a creature that stepped down a drop with
// its leading feet and turned back steps them back up, rather than walling itself in below the
// ledge's face).
struct StepLimits {
  float up = 0.0f, down = 0.0f;     // metres
  float lowest = 0.0f, top = 0.0f;  // world y
};
StepLimits step_limits(const FootholdInputs& in, int leg, glm::vec2 foot_ws);

// A foot set down at f.pos_ws: one that came down further than a step up from where it last
// stood (or from `ledge_y`, the ledge a fall or a reach down left) remembers the ledge
// (FootState::ledge_y, for step_limits); one back up on that ledge forgets it.
void note_ledge(const AnimContext& ctx, FootState& f, float ledge_y = NAN);

// Does leg `leg` reach p_ws (within reach_use × kFootReach of its reach) from where its girdle
// is now?
bool reaches(const FootholdInputs& in, int leg, glm::vec2 p_ws, float reach_use = 1.0f);

// How the ground profile is read for a girdle of rest height h whose shortest foot is f long
// (SlopeReading): a run of treads narrower than kSlopeTreadOfRest·h with rises no higher than
// kRiserOfRest·h, or of treads narrower than f, is a slope (a tile hill); a jump in that
// reading of more than half a riser (or than the steepest ramp's per column) is a riser (a
// flight of stairs is steps).
inline constexpr float kSlopeTreadOfRest = 0.5f;
inline constexpr float kRiserOfRest = 0.1f;
SlopeReading slope_reading(const GroundProfile& ground, float rest_height, float foot_length);
// For girdle g, and for the whole body (its lowest girdle, or the hip height of the legless).
SlopeReading girdle_slope_reading(const AnimContext& ctx, int girdle);
SlopeReading body_slope_reading(const AnimContext& ctx);

// A foothold counts as in reach within this fraction of the leg's contact reach.
inline constexpr float kFootReach = 0.97f;

}  // namespace ossa::anim
