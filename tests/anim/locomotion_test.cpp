// Locomotion mode (locomotion.h) on its own: the crouch, the take-off's counts and floor, the
// ballistic path and its ceiling, the reach for the ground, the landing's descent and the
// order of the mode changes. No Animator.

#include "ossa/anim/locomotion.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_motion.h"
#include "ossa/anim/pose_stage.h"
#include "ossa/anim/step.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "stage_scene.h"

using namespace ossa;

namespace {

anim::FootSet standing_feet(const test::StageScene& s) {
  anim::StepState step;
  step.feet.feet.resize(s.rig->legs.size());
  for (size_t i = 0; i < s.rig->legs.size(); ++i) step.feet.foot_of_leg.push_back(static_cast<int>(i));
  anim::reset_feet(s.ctx, s.body, s.gait, 0.0f, 1.0f, 3.0f, false, step);
  return step.feet;
}

}  // namespace

TEST_CASE("locomotion: the crouch deepens over its time and then takes off", "[anim][locomotion]") {
  const auto rig = build_anim_rig(scenes::quadruped());
  const AnimatorParams params;
  anim::LocomotionState loco;
  anim::begin_tick(*rig, params, true, 1.0f / 120.0f, loco);
  REQUIRE(loco.mode == Locomotion::kCrouch);
  float last = 0.0f;
  int ticks = 0;
  bool done = false;
  while (!done && ticks < 1000) {
    done = anim::tick_crouch(*rig, params, 1.0f / 120.0f, loco);
    CHECK(loco.crouch >= last);  // never rises on the way down
    last = loco.crouch;
    ++ticks;
  }
  CHECK(done);
  CHECK(loco.crouch == Approx(params.jump_crouch * rig->hip_height));
  CHECK(static_cast<float>(ticks) / 120.0f == Approx(loco.crouch_seconds).margin(1.0f / 120.0f));
  // Only a grounded creature with legs crouches; not one in the air.
  anim::LocomotionState air;
  air.mode = Locomotion::kAirborne;
  anim::begin_tick(*rig, params, true, 1.0f / 120.0f, air);
  CHECK(air.mode == Locomotion::kAirborne);
}

TEST_CASE("locomotion: a jump follows the ballistic path to its apex, a ceiling stops the rise", "[anim][locomotion]") {
  for (const bool ceiling : {false, true}) {
    INFO((ceiling ? "under a ceiling" : "in the open"));
    std::vector<Box> boxes{Box::from_corner(-50.0f, -1.0f, 100.0f, 1.0f)};
    test::StageScene s(scenes::quadruped(), Level(boxes, {0.0f, 0.0f}), 0.0f);
    // A ceiling a little above the standing body (added after the scene stood the creature
    // on the ground: it looks for ground from high above).
    const float ceiling_y = s.body.root_y_ws + 1.2f * s.rig->hip_height;
    if (ceiling) {
      boxes.push_back(Box::from_corner(-50.0f, ceiling_y, 100.0f, 1.0f));
      s.level = Level(boxes, {0.0f, 0.0f});
    }
    const anim::FootSet feet = standing_feet(s);
    anim::LocomotionState loco;
    const float v = anim::jump_speed(*s.rig, s.params);
    const float start = s.body.root_y_ws;
    anim::take_off(s.ctx, s.body, {0.0f, v}, true, feet, loco);
    CHECK(loco.mode == Locomotion::kAirborne);
    CHECK(loco.stats.jumps == 1);
    CHECK(loco.floor > 1e29f);  // a jump may land anywhere
    std::vector<Box> scratch;
    anim::PoseState pose;  // the body's facing-space matrices for the ceiling's sweep
    anim::init_pose(*s.rig, pose);
    float top = start;
    for (int t = 0; t < 240 && loco.vy0 * loco.time - 0.5f * s.params.gravity * loco.time * loco.time >= 0.0f; ++t) {
      anim::pose_body(s.ctx, s.body, 0.0f, 0.0f, 0.0f, 1.0f / 120.0f, pose);
      float dx;
      anim::fly_along(s.ctx, 1.0f / 120.0f, s.body, pose.facing, scratch, loco, &dx);
      const float y = anim::path_height(s.ctx, s.body, pose.facing, scratch, loco);
      s.body.root_y_ws = y;
      top = std::max(top, y);
    }
    const float apex = start + v * v / (2.0f * s.params.gravity);
    if (ceiling) {
      // The body's top stays under the ceiling.
      CHECK(top < apex);
      std::vector<Box> body;
      s.body.root_y_ws = top;
      anim::pose_body(s.ctx, s.body, 0.0f, 0.0f, 0.0f, 1.0f / 120.0f, pose);
      anim::body_boxes(*s.rig, s.body, pose.facing, false, &body);
      CHECK(body[0].max_ws.y <= ceiling_y + 1e-3f);
    } else {
      CHECK(top == Approx(apex).margin(0.01f * s.rig->hip_height));
      CHECK(loco.top_y == Approx(top));
    }
  }
}

TEST_CASE("locomotion: a fall lands only below the ledge it left", "[anim][locomotion]") {
  test::StageScene s(scenes::quadruped(), scenes::flat_level(100.0f), 50.0f);
  anim::FootSet feet = standing_feet(s);
  anim::LocomotionState loco;
  anim::take_off(s.ctx, s.body, {1.0f, 0.0f}, false, feet, loco);
  CHECK(loco.stats.falls == 1);
  CHECK(loco.floor == Approx(0.0f - s.rig->scale.ledge_gap));
  CHECK(loco.vx == 1.0f);
}

TEST_CASE("locomotion: the legs reach for the ground only when falling towards it", "[anim][locomotion]") {
  test::StageScene s(scenes::quadruped(), scenes::flat_level(100.0f), 50.0f);
  anim::LocomotionState loco;
  loco.vy = 1.0f;  // rising
  CHECK(anim::reach_extension(s.ctx, s.body, loco) == 0.0f);
  loco.vy = -1.0f;
  s.body.root_y_ws += 5.0f * s.rig->hip_height;  // far above the ground: tucked
  CHECK(anim::reach_extension(s.ctx, s.body, loco) == 0.0f);
  s.body.root_y_ws -= 5.0f * s.rig->hip_height;  // standing height: reaching fully
  CHECK(anim::reach_extension(s.ctx, s.body, loco) == Approx(1.0f));
}

TEST_CASE("locomotion: the landing's descent slows to the compressed height and ends", "[anim][locomotion]") {
  test::StageScene s(scenes::quadruped(), scenes::flat_level(100.0f), 50.0f);
  const float standing = s.body.root_y_ws;
  anim::LocomotionState loco;
  loco.mode = Locomotion::kAirborne;
  loco.vy = -3.0f;
  loco.top_y = standing + 1.0f;
  anim::begin_landing(s.ctx, s.body, standing, loco);
  REQUIRE(loco.mode == Locomotion::kLanding);
  CHECK(loco.stats.max_fall_m == Approx(1.0f));
  float last = s.body.root_y_ws;
  while (!std::isnan(anim::landing_root(loco))) {
    const float y = anim::landing_root(loco);
    CHECK(y <= last + 1e-6f);            // it only comes down
    CHECK(y >= loco.land_low - 1e-5f);   // never below the compressed height
    last = y;
    loco.time += 1.0f / 120.0f;
  }
  CHECK(loco.land_low < standing);       // the legs gave
  CHECK(loco.time <= 0.35f + 1.0f / 120.0f);
}

TEST_CASE("locomotion: a finished crouch jumps before anything else changes the mode", "[anim][locomotion]") {
  test::StageScene s(scenes::quadruped(), scenes::flat_level(100.0f), 50.0f);
  anim::FootSet feet = standing_feet(s);
  anim::LocomotionState loco;
  CHECK(anim::mode_change(s.ctx, s.body, feet, false, false, loco) == anim::ModeChange::kNone);
  CHECK(anim::mode_change(s.ctx, s.body, feet, false, true, loco) == anim::ModeChange::kJump);
  // Every foot hanging: a fall; a jump's crouch still wins.
  for (size_t i = 0; i < s.rig->legs.size(); ++i) anim::hang(s.ctx, s.body, static_cast<int>(i), 0.0f, feet.of_leg(static_cast<int>(i)));
  CHECK(anim::mode_change(s.ctx, s.body, feet, false, false, loco) == anim::ModeChange::kFall);
  CHECK(anim::mode_change(s.ctx, s.body, feet, false, true, loco) == anim::ModeChange::kJump);
  // A landing whose descent is over ends; one still descending does not.
  loco.mode = Locomotion::kLanding;
  loco.land_seconds = 0.2f;
  loco.time = 0.1f;
  CHECK(anim::mode_change(s.ctx, s.body, feet, true, false, loco) == anim::ModeChange::kNone);
  loco.time = 0.3f;
  CHECK(anim::mode_change(s.ctx, s.body, feet, true, false, loco) == anim::ModeChange::kLanded);
}
