#pragma once
// RigScale — the lengths the animator's stages measure with, in the creature's own size
// (DESIGN.md §7 "Sizes": thresholds scale with the creature, never absolute metres). This is
// the one place for them: every search depth, search step, margin and tolerance the stages use
// is a fraction of the creature's body length below (the rest pose's extent along x), worked
// out once per rig (AnimRig::scale).
//
// Why the body length: it is the one length every creature and rigged character has (the
// legless have no legs and no hip), and it measures how finely a creature places its feet
// better than its hip height does: a low sprawler (a crocodile, hip 0.16 m in a 1.5 m body)
// with tolerances a hundredth of its hip let its feet slide on rough ground and stairs (the
// sweep measured slides of 7 cm), with tolerances of its length it does not. Each fraction is
// written as the metres it gives an animal kReferenceLength long: the values these had when
// they were absolute metres, for the examples' bodies of 1.4 to 1.8 m in the 2 m frame.

namespace ossa {

inline constexpr float kReferenceLength = 1.5f;  // metres

// How far below a point the stages look for ground (ground further down is no concern of a
// body standing, landing or reaching).
inline constexpr float kSearchDepthOfLength = 40.0f / kReferenceLength;
// The step of the search for the nearest place a foot fits (foothold.h nearest_fit).
inline constexpr float kSearchStepOfLength = 0.01f / kReferenceLength;
// Side clearances of a foot's box against the level, kept in this order so that a landing the
// planner found (find_landing: its foot box widened by kLandingSideOfLength, then inset by
// kLandingInsetOfLength) also fits (foot_fits, kFitSideOfLength), and the swing's own check on
// its way there (swing.h, kSwingSideOfLength, a little narrower) clears it at its end.
inline constexpr float kFitSideOfLength = 0.008f / kReferenceLength;
inline constexpr float kLandingSideOfLength = 0.01f / kReferenceLength;
inline constexpr float kLandingInsetOfLength = 0.002f / kReferenceLength;
inline constexpr float kSwingSideOfLength = 0.006f / kReferenceLength;
static_assert(kSwingSideOfLength < kLandingSideOfLength - kLandingInsetOfLength,
              "a swing's clearance check must be narrower than the landing the planner found");
static_assert(kLandingSideOfLength - kLandingInsetOfLength <= kFitSideOfLength + 1e-9f,  // (float rounding)
              "a landing the planner found must fit by foot_fits' own test");
// A foot fits with its box this far above its contact point; a swinging foot's box keeps this
// much headroom.
inline constexpr float kFitLiftOfLength = 0.0005f / kReferenceLength;
inline constexpr float kSwingTopOfLength = 0.005f / kReferenceLength;
// A flat foot's sole is widened by this much either side when it looks for ground.
inline constexpr float kSoleSideOfLength = 0.005f / kReferenceLength;
// A foot's box is at least this tall; a tread is free of ground from this high above it.
inline constexpr float kFootBoxOfLength = 0.02f / kReferenceLength;
// Walls are met this far early (body motion's wall sweep and ledge rule).
inline constexpr float kWallMarginOfLength = 0.046f / kReferenceLength;
// A swing's path keeps this far above a box it clears.
inline constexpr float kSwingClearanceOfLength = 0.01f / kReferenceLength;
// A fall, or a foot stepping off, lands only this far below the ledge it left.
inline constexpr float kLedgeGapOfLength = 0.01f / kReferenceLength;
// A hand keeps this far above the ground.
inline constexpr float kArmMarginOfLength = 0.026f / kReferenceLength;
// Ground under a point is looked for this far either side of it.
inline constexpr float kGroundSpanOfLength = 0.02f / kReferenceLength;

struct RigScale {
  float length = kReferenceLength;  // the reference length: the rest pose's extent along x, metres
  // Each of the above for this creature, metres.
  float search_depth = 0.0f, search_step = 0.0f;
  float fit_side = 0.0f, landing_side = 0.0f, landing_inset = 0.0f, swing_side = 0.0f;
  float fit_lift = 0.0f, swing_top = 0.0f, sole_side = 0.0f, foot_box = 0.0f;
  float wall_margin = 0.0f, swing_clearance = 0.0f, ledge_gap = 0.0f, arm_margin = 0.0f, ground_span = 0.0f;

  static RigScale of(float length) {
    RigScale s;
    s.length = length;
    s.search_depth = kSearchDepthOfLength * length;
    s.search_step = kSearchStepOfLength * length;
    s.fit_side = kFitSideOfLength * length;
    s.landing_side = kLandingSideOfLength * length;
    s.landing_inset = kLandingInsetOfLength * length;
    s.swing_side = kSwingSideOfLength * length;
    s.fit_lift = kFitLiftOfLength * length;
    s.swing_top = kSwingTopOfLength * length;
    s.sole_side = kSoleSideOfLength * length;
    s.foot_box = kFootBoxOfLength * length;
    s.wall_margin = kWallMarginOfLength * length;
    s.swing_clearance = kSwingClearanceOfLength * length;
    s.ledge_gap = kLedgeGapOfLength * length;
    s.arm_margin = kArmMarginOfLength * length;
    s.ground_span = kGroundSpanOfLength * length;
    return s;
  }
};

}  // namespace ossa
