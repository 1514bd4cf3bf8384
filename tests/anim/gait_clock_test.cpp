#include "ossa/anim/gait_clock.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/anim/anim_math.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

// The gait settled at `speed` (smoothing factors 0 jump to the targets).
anim::GaitState settled(const AnimRig& rig, const AnimatorParams& params, float speed) {
  anim::GaitState gait;
  for (int k = 0; k < 3; ++k) anim::update_gait(rig, params, speed, 0.0f, 0.0f, gait);
  anim::update_target_offsets(rig, gait);
  return gait;
}
float speed_at_froude(const AnimRig& rig, const AnimatorParams& params, float froude) {
  return std::sqrt(froude * params.gravity * rig.hip_height);
}
// The offset of the leg on `girdle` (0 front) and `side`.
float offset_of(const AnimRig& rig, const anim::GaitState& gait, int girdle, Side side) {
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    if (rig.legs[i].girdle == girdle && rig.legs[i].side == side) return gait.target_offset[i];
  }
  FAIL("no such leg");
  return 0.0f;
}

}  // namespace

TEST_CASE("gait clock: a biped's legs alternate at every speed", "[anim][gait]") {
  const auto rig = build_anim_rig(scenes::biped());
  const AnimatorParams params;
  for (float froude : {0.1f, 0.5f, 1.5f, 3.0f}) {
    const anim::GaitState gait = settled(*rig, params, speed_at_froude(*rig, params, froude));
    CHECK(std::fabs(anim::phase_diff(offset_of(*rig, gait, 0, Side::kNear), offset_of(*rig, gait, 0, Side::kFar))) ==
          Approx(0.5f));
    CHECK((gait.gait == Gait::kWalk || gait.gait == Gait::kRun));
  }
}

TEST_CASE("gait clock: a quadruped walks, trots and gallops by Froude number", "[anim][gait]") {
  const auto rig = build_anim_rig(scenes::quadruped());
  const AnimatorParams params;
  // Lateral-sequence walk: hind near 0, fore near ¼, hind far ½, fore far ¾.
  anim::GaitState walk = settled(*rig, params, speed_at_froude(*rig, params, 0.15f));
  CHECK(walk.gait == Gait::kWalk);
  const float hn = offset_of(*rig, walk, 1, Side::kNear);
  CHECK(anim::frac(offset_of(*rig, walk, 0, Side::kNear) - hn) == Approx(0.25f).margin(1e-4));
  CHECK(anim::frac(offset_of(*rig, walk, 1, Side::kFar) - hn) == Approx(0.5f).margin(1e-4));
  CHECK(anim::frac(offset_of(*rig, walk, 0, Side::kFar) - hn) == Approx(0.75f).margin(1e-4));
  // Trot: diagonal pairs in phase.
  anim::GaitState trot = settled(*rig, params, speed_at_froude(*rig, params, 1.2f));
  CHECK(trot.gait == Gait::kTrot);
  CHECK(std::fabs(anim::phase_diff(offset_of(*rig, trot, 0, Side::kNear), offset_of(*rig, trot, 1, Side::kFar))) < 1e-4f);
  CHECK(std::fabs(anim::phase_diff(offset_of(*rig, trot, 0, Side::kFar), offset_of(*rig, trot, 1, Side::kNear))) < 1e-4f);
  // Gallop above gallop_froude: hind pair, then fore pair, each slightly apart.
  anim::GaitState gallop = settled(*rig, params, speed_at_froude(*rig, params, 1.3f * params.gallop_froude));
  CHECK(gallop.gait == Gait::kGallop);
  CHECK(std::fabs(anim::phase_diff(offset_of(*rig, gallop, 1, Side::kNear), offset_of(*rig, gallop, 1, Side::kFar))) ==
        Approx(0.12f).margin(1e-4));
}

TEST_CASE("gait clock: duty factor falls from walk to run, stride follows Alexander's relation", "[anim][gait]") {
  for (const Creature& c : {scenes::biped(), scenes::quadruped(), scenes::three_leg_pairs()}) {
    const auto rig = build_anim_rig(c);
    const AnimatorParams params;
    const anim::GaitState slow = settled(*rig, params, speed_at_froude(*rig, params, 0.1f));
    const anim::GaitState fast = settled(*rig, params, speed_at_froude(*rig, params, 2.0f));
    CHECK(slow.duty == Approx(params.duty_walk));
    CHECK(fast.duty == Approx(params.duty_run));
    CHECK(fast.duty < 0.5f);  // a flight phase
    // λ = 2.3·h·Fr^0.3 where the legs' reach does not limit it, never longer where it does.
    const float alexander = 2.3f * rig->hip_height * std::pow(0.1f, 0.3f);
    CHECK(slow.stride <= alexander * 1.0001f);
    CHECK(slow.stride >= 0.25f * rig->hip_height);
    CHECK(slow.frequency == Approx(speed_at_froude(*rig, params, 0.1f) / slow.stride));
    CHECK(fast.stride > slow.stride);
  }
  // A standing creature has no frequency.
  const auto rig = build_anim_rig(scenes::quadruped());
  CHECK(settled(*rig, AnimatorParams{}, 0.0f).frequency == 0.0f);
  CHECK(settled(*rig, AnimatorParams{}, 0.0f).gait == Gait::kIdle);
}

TEST_CASE("gait clock: more leg pairs step in a wave alternating down the body", "[anim][gait]") {
  const auto rig = build_anim_rig(scenes::three_leg_pairs());
  REQUIRE(rig->girdles.size() >= 3);
  const anim::GaitState gait = settled(*rig, AnimatorParams{}, 1.0f);
  for (size_t g = 0; g + 1 < rig->girdles.size(); ++g) {
    const int a = static_cast<int>(g), b = static_cast<int>(g + 1);
    CHECK(std::fabs(anim::phase_diff(offset_of(*rig, gait, a, Side::kNear), offset_of(*rig, gait, b, Side::kNear))) ==
          Approx(0.5f));
  }
}

TEST_CASE("gait clock: a foot lifts when its phase crosses the duty factor", "[anim][gait]") {
  const auto rig = build_anim_rig(scenes::biped());
  anim::GaitState gait = settled(*rig, AnimatorParams{}, 1.0f);
  anim::FootSet feet;
  feet.feet.resize(rig->legs.size());
  feet.foot_of_leg = {0, 1};
  anim::reset_offsets(*rig, feet, gait);
  for (size_t i = 0; i < rig->legs.size(); ++i) gait.foot_offset[i] = gait.target_offset[i];
  anim::start_clock(gait, feet, 0);
  // The lead leg lifts on the first tick; the other one half a cycle later.
  CHECK(anim::advance_leg_phase(gait, 0, true, gait.target_offset[0], true, 1.0f, 1.0f / 120.0f).lift_due);
  CHECK_FALSE(anim::advance_leg_phase(gait, 1, true, gait.target_offset[1], true, 1.0f, 1.0f / 120.0f).lift_due);
  int ticks = 0;
  bool lifted = false;
  while (!lifted && ticks < 1000) {
    gait.phase = anim::frac(gait.phase + gait.frequency / 120.0f);
    const anim::LegPhase p = anim::advance_leg_phase(gait, 1, true, gait.target_offset[1], false, 1.0f, 1.0f / 120.0f);
    lifted = p.lift_due;
    anim::end_leg_phase(gait, 1, p);
    ++ticks;
  }
  CHECK(lifted);
  CHECK(static_cast<float>(ticks) / 120.0f == Approx(0.5f / gait.frequency).epsilon(0.05));
}
