// The orchestrator (animator.cpp): its stages run in the order of the stage list, and what one
// tells a later one arrives on the same tick. Driven through Animator alone (no game layer).

#include "ossa/anim/animator.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

struct Driven {
  Creature creature;
  Animator animator;
  explicit Driven(Creature c) : creature(std::move(c)), animator(creature, SplinePrototypes::defaults()) {}
};

}  // namespace

TEST_CASE("animator: a wall body motion meets stops the step stage on the same tick", "[anim][animator]") {
  // Stages 7 and 8: the block body motion hands on is read by the gait clock and the step
  // stage on the same tick, so no foot lifts into the wall.
  for (const int facing : {1, -1}) {
    INFO("facing " << facing);
    const Level level({Box::from_corner(-50.0f, -1.0f, 100.0f, 1.0f),
                       facing > 0 ? Box::from_corner(4.0f, 0.0f, 1.0f, 6.0f) : Box::from_corner(-5.0f, 0.0f, 1.0f, 6.0f)},
                      {0.0f, 0.0f});
    Driven d(scenes::quadruped());
    Animator& a = d.animator;
    a.reset({0.0f, 1.0f}, level, facing);
    bool met = false;
    for (int t = 0; t < 120 * 10 && !met; ++t) {
      std::vector<LegState> before;
      for (int i = 0; i < a.leg_count(); ++i) before.push_back(a.leg_state(i));
      a.update(1.0f / 120.0f, facing * 1.0f, level);
      if (!a.last_tick().wall_ahead) continue;
      met = true;
      CHECK(a.blocked());
      for (int i = 0; i < a.leg_count(); ++i) {
        // A foot standing before this tick did not start a step on it.
        if (before[i] == LegState::kStance) CHECK((a.leg_state(i) == LegState::kStance || a.easing(i)));
      }
    }
    CHECK(met);
  }
}

TEST_CASE("animator: the turn hands the feet over before the body is placed, on one tick", "[anim][animator]") {
  // Stage 4 mirrors the body and hands the feet over; stage 10 places the body over them at
  // once (TickHandoff::turned): no foot standing before the tick moves.
  const Level flat = scenes::flat_level(200.0f);
  Driven d(scenes::quadruped());
  Animator& a = d.animator;
  a.reset({0.0f, 1.0f}, flat);
  for (int t = 0; t < 240; ++t) a.update(1.0f / 120.0f, 0.0f, flat);  // stand still
  std::vector<glm::vec2> feet;
  for (int i = 0; i < a.leg_count(); ++i) feet.push_back(a.foot_target_ws(i));
  a.update(1.0f / 120.0f, -0.5f, flat);
  CHECK(a.last_tick().turned);
  CHECK(a.facing() == -1);
  for (const glm::vec2& f : feet) {
    float nearest = 1e9f;
    for (int i = 0; i < a.leg_count(); ++i) nearest = std::min(nearest, glm::length(a.foot_target_ws(i) - f));
    CHECK(nearest < 0.05f);  // every foot is still some leg's, where it stood (or a short step from it)
  }
  a.update(1.0f / 120.0f, -0.5f, flat);
  CHECK_FALSE(a.last_tick().turned);  // the hand-off is per tick
}

TEST_CASE("animator: the crouch ends in a take-off on the same tick, after the body is placed", "[anim][animator]") {
  // Stage 9 ends the crouch, stage 10 places the body at its lowest, stage 11 takes off.
  const Level flat = scenes::flat_level(200.0f);
  Driven d(scenes::quadruped());
  Animator& a = d.animator;
  a.reset({0.0f, 1.0f}, flat);
  for (int t = 0; t < 60; ++t) a.update(1.0f / 120.0f, 0.0f, flat);
  a.update(1.0f / 120.0f, AnimatorIntent{0.0f, true}, flat);
  CHECK(a.locomotion() == Locomotion::kCrouch);
  int ticks = 0;
  while (a.locomotion() == Locomotion::kCrouch && ticks < 240) {
    a.update(1.0f / 120.0f, 0.0f, flat);
    ++ticks;
    if (a.last_tick().crouch_done) CHECK(a.locomotion() == Locomotion::kAirborne);
  }
  CHECK(a.locomotion() == Locomotion::kAirborne);
  CHECK(a.locomotion_stats().jumps == 1);
}

TEST_CASE("animator: the level changing under a standing foot is seen first on the next tick", "[anim][animator]") {
  // Stage 2: a stance foot whose ground went hangs before any later stage plans with it.
  Level level({Box::from_corner(-50.0f, -1.0f, 100.0f, 1.0f)}, {0.0f, 0.0f});
  Driven d(scenes::quadruped());
  Animator& a = d.animator;
  a.reset({0.0f, 1.0f}, level);
  for (int t = 0; t < 60; ++t) a.update(1.0f / 120.0f, 0.0f, level);
  // The floor drops by half a metre under the whole creature.
  level.set_box(0, Box::from_corner(-50.0f, -1.5f, 100.0f, 1.0f));
  a.update(1.0f / 120.0f, 0.0f, level);
  for (int i = 0; i < a.leg_count(); ++i) CHECK(a.leg_state(i) == LegState::kSwing);
}
