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
  for (int k = 0; k < 3; ++k) anim::update_gait(rig, params, speed, false, 0.0f, 0.0f, gait);
  anim::update_target_offsets(rig, anim::gait_family(rig, params), gait);
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

// When the leg on `girdle` and `side` lands, cycles after the near hind foot (a larger phase
// offset lands earlier).
float lands(const AnimRig& rig, const anim::GaitState& gait, int girdle, Side side) {
  return anim::frac(offset_of(rig, gait, 1, Side::kNear) - offset_of(rig, gait, girdle, side));
}

TEST_CASE("gait clock: a cursorial quadruped walks in lateral sequence, trots and gallops by Froude number", "[anim][gait]") {
  const auto rig = build_anim_rig(scenes::quadruped());
  AnimatorParams params;
  params.gait_family = GaitFamily::kCursorial;
  // Lateral-sequence walk (Hildebrand): near hind, near fore ¼ later, far hind ½, far fore ¾.
  anim::GaitState walk = settled(*rig, params, speed_at_froude(*rig, params, 0.15f));
  CHECK(walk.gait == Gait::kWalk);
  CHECK(lands(*rig, walk, 0, Side::kNear) == Approx(0.25f).margin(1e-4));
  CHECK(lands(*rig, walk, 1, Side::kFar) == Approx(0.5f).margin(1e-4));
  CHECK(lands(*rig, walk, 0, Side::kFar) == Approx(0.75f).margin(1e-4));
  // Trot: diagonal pairs in phase.
  anim::GaitState trot = settled(*rig, params, speed_at_froude(*rig, params, 1.2f));
  CHECK(trot.gait == Gait::kTrot);
  CHECK(lands(*rig, trot, 0, Side::kFar) == Approx(0.0f).margin(1e-4));
  CHECK(lands(*rig, trot, 0, Side::kNear) == Approx(0.5f).margin(1e-4));
  // Gallop above Fr 2: hind pair, then fore pair, each slightly apart.
  anim::GaitState gallop = settled(*rig, params, speed_at_froude(*rig, params, 3.5f));
  CHECK(gallop.gait == Gait::kGallop);
  CHECK(lands(*rig, gallop, 1, Side::kFar) == Approx(0.1f).margin(1e-4));
  CHECK(lands(*rig, gallop, 0, Side::kNear) == Approx(0.45f).margin(1e-4));
  // The full stick reaches the family's top speed, well inside the gallop.
  CHECK(anim::run_speed(*rig, params) == Approx(speed_at_froude(*rig, params, 3.0f)));
}

TEST_CASE("gait clock: every family's gaits, top speed and duty floor", "[anim][gait]") {
  const auto quad = build_anim_rig(scenes::quadruped());
  const auto biped = build_anim_rig(scenes::biped());
  auto at = [](const AnimRig& rig, GaitFamily family, float froude) {
    AnimatorParams params;
    params.gait_family = family;
    return settled(rig, params, speed_at_froude(rig, params, froude));
  };
  SECTION("graviportal: lateral sequence at every speed, never all feet in the air") {
    for (float fr : {0.1f, 0.8f, 1.9f}) {
      const anim::GaitState g = at(*quad, GaitFamily::kGraviportal, fr);
      CHECK(lands(*quad, g, 0, Side::kNear) == Approx(0.25f).margin(1e-4));
      CHECK(g.duty >= 0.5f);
      CHECK((g.gait == Gait::kWalk || g.gait == Gait::kAmble));
    }
  }
  SECTION("pacer: lateral pairs in phase") {
    const anim::GaitState g = at(*quad, GaitFamily::kPacer, 1.2f);
    CHECK(g.gait == Gait::kPace);
    CHECK(lands(*quad, g, 0, Side::kNear) == Approx(0.0f).margin(1e-4));
    CHECK(lands(*quad, g, 0, Side::kFar) == Approx(0.5f).margin(1e-4));
  }
  SECTION("bounder: hind feet together in the half-bound and the bound") {
    for (float fr : {1.2f, 3.0f}) {
      const anim::GaitState g = at(*quad, GaitFamily::kBounder, fr);
      CHECK(lands(*quad, g, 1, Side::kFar) == Approx(0.0f).margin(1e-4));
      CHECK((g.gait == (fr < 1.5f ? Gait::kHalfBound : Gait::kBound)));
    }
  }
  SECTION("hopper: a biped's feet land together at every speed") {
    // With arms and a tail it walks on five supports below the hop (pentapedal.h).
    const bool five = !biped->arms.empty() && !biped->tail.empty();
    CHECK(anim::gait_family_traits(GaitFamily::kHopper, *biped).pentapedal == five);
    for (float fr : {0.1f, 1.0f, 2.5f}) {
      const anim::GaitState g = at(*biped, GaitFamily::kHopper, fr);
      CHECK(std::fabs(anim::phase_diff(offset_of(*biped, g, 0, Side::kNear), offset_of(*biped, g, 0, Side::kFar))) < 1e-4f);
      CHECK(g.gait == (five && fr < 0.5f ? Gait::kPentapedal : Gait::kHop));
    }
  }
  SECTION("bird: a grounded run before the aerial run") {
    const anim::GaitState grounded = at(*biped, GaitFamily::kBird, 1.2f);
    CHECK(grounded.gait == Gait::kGroundedRun);
    CHECK(grounded.duty >= 0.5f);
    const anim::GaitState aerial = at(*biped, GaitFamily::kBird, 2.5f);
    CHECK(aerial.gait == Gait::kRun);
    CHECK(aerial.duty < 0.5f);
  }
  SECTION("sprawler: a diagonal-couplet walk and a trot, a tail-driven top speed") {
    const anim::GaitState g = at(*quad, GaitFamily::kSprawler, 0.1f);
    CHECK(lands(*quad, g, 0, Side::kNear) == Approx(0.4f).margin(1e-4));
    AnimatorParams params;
    params.gait_family = GaitFamily::kSprawler;
    CHECK(anim::run_speed(*quad, params) > anim::walk_speed(*quad, params));
    CHECK(anim::gait_family_traits(GaitFamily::kSprawler, *quad).top_froude <= 1.5f);
  }
}

TEST_CASE("gait clock: duty factor falls from walk to run, stride follows Alexander's relation", "[anim][gait]") {
  for (const Creature& c : {scenes::biped(), scenes::quadruped(), scenes::three_leg_pairs()}) {
    const auto rig = build_anim_rig(c);
    const AnimatorParams params;
    const anim::GaitState slow = settled(*rig, params, speed_at_froude(*rig, params, 0.1f));
    const anim::GaitState fast = settled(*rig, params, speed_at_froude(*rig, params, 2.0f));
    CHECK(slow.duty == Approx(params.duty_walk));
    if (anim::gait_family_traits(rig->gait_family, *rig).duty_floor > 0.0f) continue;
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
  anim::reset_offsets(*rig, GaitFamily::kBiped, feet, gait);
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
