// The turn (turn.h): body placement mirrors the body, the step stage hands the feet to the legs
// now over them. Tested on the two stages' functions alone, with no Animator.

#include "ossa/anim/turn.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/anim/body_placement.h"
#include "ossa/anim/step.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "stage_scene.h"

using namespace ossa;

namespace {

// The creature's feet standing under their girdles on flat ground at y = 0.
anim::FootSet standing_feet(const test::StageScene& s) {
  anim::StepState step;
  step.feet.feet.resize(s.rig->legs.size());
  for (size_t i = 0; i < s.rig->legs.size(); ++i) step.feet.foot_of_leg.push_back(static_cast<int>(i));
  anim::GaitState gait = s.gait;
  anim::reset_feet(s.ctx, s.body, gait, 0.0f, 1.0f, 3.0f, false, step);
  return step.feet;
}

}  // namespace

TEST_CASE("turn: a command against the facing turns, none at rest or while landing", "[anim][turn]") {
  CHECK(anim::turn_wanted(-0.5f, 1, false));
  CHECK(anim::turn_wanted(0.5f, -1, false));
  CHECK_FALSE(anim::turn_wanted(0.5f, 1, false));
  CHECK_FALSE(anim::turn_wanted(0.0f, 1, false));
  CHECK_FALSE(anim::turn_wanted(-1e-5f, 1, false));  // a stick at rest
  CHECK_FALSE(anim::turn_wanted(-0.5f, 1, true));    // a landing's descent holds the body
}

TEST_CASE("turn: the girdles swap places over the feet, which keep their world positions", "[anim][turn]") {
  const SplinePrototypes prototypes = SplinePrototypes::defaults();
  for (const Creature& c : {scenes::quadruped(), scenes::biped(), scenes::three_leg_pairs()}) {
    for (int facing : {1, -1}) {
      INFO(c.name << " facing " << facing);
      test::StageScene s(c, scenes::flat_level(200.0f), 100.0f, facing);
      anim::FootSet feet = standing_feet(s);
      std::vector<glm::vec2> before;
      for (const anim::FootState& f : feet.feet) before.push_back(f.pos_ws);
      const float front_x = s.body.girdle_ws(*s.rig, 0).x;
      const float back_x = s.body.girdle_ws(*s.rig, static_cast<int>(s.rig->girdles.size()) - 1).x;

      anim::mirror_body(*s.rig, {}, s.body);
      CHECK(s.body.facing == -facing);
      CHECK(s.body.lean == 0.0f);
      // The front girdle now stands where the back one stood, and the other way round.
      CHECK(s.body.girdle_ws(*s.rig, 0).x == Approx(back_x).margin(1e-4));
      CHECK(s.body.girdle_ws(*s.rig, static_cast<int>(s.rig->girdles.size()) - 1).x == Approx(front_x).margin(1e-4));

      anim::turn_feet(s.ctx, prototypes, s.gait, s.body, feet);
      // Every foot is some leg's, once.
      std::vector<int> seen(feet.feet.size(), 0);
      for (int k : feet.foot_of_leg) ++seen[k];
      for (int n : seen) CHECK(n == 1);
      // A foot still standing has not moved; every leg's foot is within its reach, or stepping
      // to where it is.
      for (size_t k = 0; k < feet.feet.size(); ++k) {
        const anim::FootState& f = feet.feet[k];
        CHECK(anim::foot_consistent(f));
        if (f.state == LegState::kStance) CHECK(glm::length(f.pos_ws - before[k]) < 1e-6f);
      }
      for (size_t i = 0; i < s.rig->legs.size(); ++i) {
        const anim::FootState& f = feet.of_leg(static_cast<int>(i));
        const glm::vec2 joint = s.body.girdle_ws(*s.rig, s.rig->legs[i].girdle);
        const glm::vec2 goal = f.state == LegState::kStance ? f.pos_ws : f.to_ws;
        CHECK(glm::length(goal - joint) <= s.rig->legs[i].contact_reach + 1e-4f);
      }
    }
  }
}

TEST_CASE("turn: a foot hanging over a drop stops hanging and steps under its girdle", "[anim][turn]") {
  test::StageScene s(scenes::quadruped(), scenes::flat_level(200.0f), 100.0f, 1);
  anim::FootSet feet = standing_feet(s);
  anim::FootState& hanging = feet.of_leg(0);
  anim::hang(s.ctx, s.body, 0, 1.0f, hanging);
  hanging.hang_beyond = hanging.pos_ws.x + 0.1f;
  REQUIRE(anim::foot_consistent(hanging));
  anim::mirror_body(*s.rig, {}, s.body);
  anim::turn_feet(s.ctx, SplinePrototypes::defaults(), s.gait, s.body, feet);
  for (const anim::FootState& f : feet.feet) {
    CHECK_FALSE(f.air);
    CHECK(std::isnan(f.hang_beyond));
    CHECK(anim::foot_consistent(f));
  }
}

TEST_CASE("turn: a legless body turns within the stretch of ground it lies on", "[anim][turn]") {
  // The snake's root lies off its middle, so turning about the root would swing its tail
  // over ground ahead of its head (into the wall that stopped it). Its pose: the
  // rest pose, the root at x = 0 as in facing space.
  for (int facing : {1, -1}) {
    INFO("facing " << facing);
    test::StageScene s(scenes::example_in_frame("snake"), scenes::flat_level(200.0f), 100.0f, facing);
    const Skeleton& sk = s.rig->skeleton;
    std::vector<Mat2x3> model_fs = s.rig->model_rest;
    const float root_x = bone_start(model_fs[s.rig->root]).x;
    for (Mat2x3& m : model_fs) m.m[4] -= root_x;
    auto span = [&] {
      float lo = 1e30f, hi = -1e30f;
      for (int b = 0; b < sk.bone_count(); ++b) {
        for (glm::vec2 p : {bone_start(model_fs[b]), bone_end(model_fs[b], sk.length(b))}) {
          lo = std::min(lo, s.body.to_ws(p).x);
          hi = std::max(hi, s.body.to_ws(p).x);
        }
      }
      return glm::vec2(lo, hi);
    };
    const glm::vec2 before = span();
    REQUIRE(before.y - before.x > 1.0f);
    REQUIRE(std::fabs((before.x + before.y) * 0.5f - s.body.x_ws) > 0.05f);  // the root is off the middle
    anim::mirror_body(*s.rig, model_fs, s.body);
    CHECK(s.body.facing == -facing);
    const glm::vec2 after = span();
    CHECK(after.x == Approx(before.x).margin(1e-4));
    CHECK(after.y == Approx(before.y).margin(1e-4));
  }
}

TEST_CASE("turn: a body pitched down a ledge turns along it", "[anim][turn]") {
  // Each girdle comes to stand where the other stood, as high over that ground as it stood
  // over its own (the stegosaurus turned pitched 40° down drops.json's 2 m ledge, kept at its
  // pitch, put its new front girdle half a metre out over the lower floor, its forefeet swung
  // down there and a stance foot slid 86 cm). Turned level, it stands as before.
  for (int facing : {1, -1}) {
    for (float pitch : {-0.7f, 0.0f, 0.4f}) {
      INFO("facing " << facing << ", pitch " << pitch);
      test::StageScene s(scenes::quadruped(), scenes::flat_level(200.0f), 100.0f, facing);
      s.body.pitch = pitch;
      const AnimRig& rig = *s.rig;
      const int back = static_cast<int>(rig.girdles.size()) - 1;
      const float rise = rig.girdles.front().rest_height - rig.girdles[back].rest_height;
      const glm::vec2 front_ws = s.body.girdle_ws(rig, 0), back_ws = s.body.girdle_ws(rig, back);
      const float level_pitch = s.body.pitch;
      anim::mirror_body(rig, {}, s.body);
      CHECK(s.body.facing == -facing);
      CHECK(s.body.girdle_ws(rig, 0).x == Approx(back_ws.x).margin(1e-4));
      CHECK(s.body.girdle_ws(rig, 0).y == Approx(back_ws.y + rise).margin(1e-4));
      CHECK(s.body.girdle_ws(rig, back).y == Approx(front_ws.y - rise).margin(1e-4));
      // Near where the front girdle stood: at the heights asked for, the span between the
      // girdles lies steeper or flatter than it did (within a quarter of the span).
      const float span = glm::length(rig.girdle_joint(0, 0.0f) - rig.girdle_joint(back, 0.0f));
      CHECK(s.body.girdle_ws(rig, back).x == Approx(front_ws.x).margin(0.25f * span));
      if (pitch == 0.0f) CHECK(s.body.pitch == Approx(level_pitch).margin(0.02f));
    }
  }
}
