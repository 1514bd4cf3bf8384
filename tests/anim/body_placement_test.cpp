#include "ossa/anim/body_placement.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/anim/leg_ik.h"
#include "ossa/anim/swing.h"
#include "ossa/math/rng.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "stage_scene.h"

using namespace ossa;

TEST_CASE("body placement keeps every stance leg within reach and the girdles above the ground", "[anim][placement]") {
  // Feet scattered within a quarter leg of their girdles, on flat ground and on stairs, the
  // body placed from them at once: on flat ground no stance leg over-extends (its anchor lies
  // within its reach of the girdle joint); on stairs, where a girdle over a higher step may
  // have to rise past what a foot on a lower one reaches, such a foot is told to lift
  // (TickHandoff::release_next) and there are few of them. Every girdle stays above the ground.
  Rng rng(7);
  for (const bool on_stairs : {false, true}) {
    const Level level = on_stairs ? scenes::stairs_level(8, 0.12f, 0.35f) : scenes::flat_level(40.0f);
    int legs = 0, released = 0;
    for (const Creature& c : {scenes::quadruped(), scenes::biped(), scenes::three_leg_pairs()}) {
      for (int trial = 0; trial < 60; ++trial) {
        const int facing = trial % 2 == 0 ? 1 : -1;
        const float x = static_cast<float>(rng.uniform(2.5, 8.0)) + (on_stairs ? 0.0f : 10.0f);
        test::StageScene s(c, level, x, facing);
        const AnimRig& rig = *s.rig;
        anim::FootSet feet;
        feet.feet.resize(rig.legs.size());
        for (size_t i = 0; i < rig.legs.size(); ++i) {
          feet.foot_of_leg.push_back(static_cast<int>(i));
          const glm::vec2 joint = s.body.girdle_ws(rig, rig.legs[i].girdle);
          const float fx = joint.x + static_cast<float>(rng.uniform(-0.25, 0.25)) * rig.legs[i].reach;
          const auto ground = level.ground_height_below(fx - 0.005f, fx + 0.005f, joint.y, 3.0f * rig.legs[i].reach);
          REQUIRE(ground);
          feet.feet[i].pos_ws = {fx, ground->height_ws};
          anim::update_stance_clearance(s.ctx, feet.feet[i]);
        }
        anim::BodyState state;
        anim::TickHandoff handoff;
        handoff.resize(rig.legs.size());
        anim::PlacementInputs in;
        in.dt = 0.0f;  // placed at once
        anim::place_body(s.ctx, in, feet, handoff, s.body, state);
        for (size_t i = 0; i < rig.legs.size(); ++i) {
          const glm::vec2 joint = s.body.to_fs(s.body.girdle_ws(rig, rig.legs[i].girdle));
          float r;
          const glm::vec2 anchor = anim::leg_anchor(s.ctx, s.body, static_cast<int>(i), s.body.to_fs(feet.feet[i].pos_ws), joint,
                                                    feet.feet[i].stance_clear, &r);
          INFO(c.name << (on_stairs ? " on stairs" : " on flat") << " trial " << trial << " leg " << i << " over by "
                      << glm::length(anchor - joint) - r);
          const bool in_reach = glm::length(anchor - joint) <= r * 1.0001f;
          if (!on_stairs) CHECK(in_reach);
          if (!in_reach) CHECK(handoff.release_next[i]);
          ++legs;
          released += handoff.release_next[i] ? 1 : 0;
        }
        for (size_t g = 0; g < rig.girdles.size(); ++g) {
          const glm::vec2 joint = s.body.girdle_ws(rig, static_cast<int>(g));
          const auto below = level.ground_height_below(joint.x - 1e-3f, joint.x + 1e-3f, joint.y + 1.0f, 5.0f);
          REQUIRE(below);
          CHECK(joint.y > below->height_ws);
        }
      }
    }
    INFO((on_stairs ? "stairs" : "flat") << ": " << released << " of " << legs << " feet told to lift");
    CHECK(released <= legs / 10);
  }
}

TEST_CASE("body placement pitches the body up a slope and keeps it level on flat ground", "[anim][placement]") {
  const Creature horse = scenes::quadruped();
  for (float rise : {0.0f, 0.016f}) {
    const Level level = test::tile_slope_level(-5.0f, 400, 0.05f, rise);
    test::StageScene s(horse, level, 0.0f, 1);
    const AnimRig& rig = *s.rig;
    anim::FootSet feet;
    feet.feet.resize(rig.legs.size());
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      feet.foot_of_leg.push_back(static_cast<int>(i));
      const float fx = s.body.girdle_ws(rig, rig.legs[i].girdle).x;
      feet.feet[i].pos_ws = {fx, level.ground_height_below(fx - 0.001f, fx + 0.001f, 10.0f, 20.0f)->height_ws};
      anim::update_stance_clearance(s.ctx, feet.feet[i]);
    }
    anim::BodyState state;
    anim::TickHandoff handoff;
    handoff.resize(rig.legs.size());
    anim::PlacementInputs in;
    anim::place_body(s.ctx, in, feet, handoff, s.body, state);
    const float ground_pitch = std::atan(rise / 0.05f);
    CHECK(s.body.pitch == Approx(ground_pitch).margin(0.05));
  }
}
