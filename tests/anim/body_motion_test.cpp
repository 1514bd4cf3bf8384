#include "ossa/anim/body_motion.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "ossa/anim/pose_stage.h"
#include "stage_scene.h"

using namespace ossa;

namespace {

// The creature's feet planted under its girdles at the ground height y.
anim::FootSet feet_at(const AnimRig& rig, const anim::BodyFrame& body, float y) {
  anim::FootSet feet;
  feet.feet.resize(rig.legs.size());
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    feet.foot_of_leg.push_back(static_cast<int>(i));
    feet.feet[i].state = LegState::kStance;
    feet.feet[i].pos_ws = {body.girdle_ws(rig, rig.legs[i].girdle).x, y};
  }
  return feet;
}

}  // namespace

TEST_CASE("body motion: no girdle passes over the face of a ledge its legs cannot climb, a bump it can step over is no ledge, a post taller than its hip is",
          "[anim][motion]") {
  for (const int facing : {1, -1}) {
    INFO("facing " << facing);
    // A 1 m ledge 1.5 m ahead of the girdle: the joint may come up to the face, no further than
    // a knee bending forward reaches ahead of it (the knee does not cross the face).
    const float face = 5.0f + facing * 1.5f;
    const Level ledge({Box::from_corner(-20.0f, -1.0f, 40.0f, 1.0f),
                       facing > 0 ? Box::from_corner(face, 0.0f, 10.0f, 1.0f) : Box::from_corner(face - 10.0f, 0.0f, 10.0f, 1.0f)});
    test::StageScene s(scenes::biped(), ledge, 5.0f, facing);
    const anim::FootSet feet = feet_at(*s.rig, s.body, 0.0f);
    const float joint = s.body.girdle_ws(*s.rig, 0).x;
    const float far = facing * 3.0f;
    const float dx = anim::limit_by_ledges(s.ctx, s.body, feet, s.gait.stride, far);
    float knee = 0.0f;  // how far the knees reach ahead of the joint, standing on the ground below
    for (const RigLeg& leg : s.rig->legs) knee = std::max(knee, knee_ahead(leg, s.body.girdle_ws(*s.rig, 0).y));
    CHECK(dx * facing >= 0.0f);
    CHECK(std::fabs(dx) < std::fabs(face - joint) - knee);         // the knees stop short of the face
    CHECK(std::fabs(dx) > std::fabs(face - joint) - knee - 0.1f);  // within the wall margin of it
    // A small move far from the face is not limited.
    CHECK(anim::limit_by_ledges(s.ctx, s.body, feet, s.gait.stride, facing * 0.01f) == facing * 0.01f);
    // A bump narrower than a stride, higher than the legs climb but lower than the girdle's
    // joint (stepped over), does not limit the body.
    const float bump = 5.0f + facing * 1.0f;
    const float bump_height = 0.9f * s.body.girdle_ws(*s.rig, 0).y;
    REQUIRE(bump_height > s.params.max_step_up * s.rig->climb_height);
    const Level bumpy({Box::from_corner(-20.0f, -1.0f, 40.0f, 1.0f), Box::from_corner(bump - 0.05f, 0.0f, 0.1f, bump_height)});
    test::StageScene b(scenes::biped(), bumpy, 5.0f, facing);
    CHECK(anim::limit_by_ledges(b.ctx, b.body, feet_at(*b.rig, b.body, 0.0f), b.gait.stride, far) == far);
    // A post as narrow but taller than the girdle's joint is no bump: no foot steps over it.
    const float post_height = s.body.girdle_ws(*s.rig, 0).y + 0.5f;
    const Level post({Box::from_corner(-20.0f, -1.0f, 40.0f, 1.0f), Box::from_corner(bump - 0.05f, 0.0f, 0.1f, post_height)});
    test::StageScene q(scenes::biped(), post, 5.0f, facing);
    const float to_post = anim::limit_by_ledges(q.ctx, q.body, feet_at(*q.rig, q.body, 0.0f), q.gait.stride, far);
    CHECK(to_post * facing >= 0.0f);
    CHECK(std::fabs(to_post) < std::fabs(bump - 0.05f * facing - joint) - knee);
    // The same narrow riser at the level's end (no ground behind it to step down to) is an end
    // wall: it stops the body as the ledge does (a brachiosaurus walked its shoulder into the
    // end walls of default.json, rough.json and stairs.json, lifted its chest onto their tops
    // and drew its front feet 0.3-0.5 m off the ground).
    const Level end({facing > 0 ? Box::from_corner(-20.0f, -1.0f, face + 20.0f, 1.0f) : Box::from_corner(face, -1.0f, 20.0f - face, 1.0f),
                     facing > 0 ? Box::from_corner(face, -1.0f, 0.1f, 2.0f) : Box::from_corner(face - 0.1f, -1.0f, 0.1f, 2.0f)});
    test::StageScene e(scenes::biped(), end, 5.0f, facing);
    const float to_end = anim::limit_by_ledges(e.ctx, e.body, feet_at(*e.rig, e.body, 0.0f), e.gait.stride, far);
    CHECK(to_end * facing >= 0.0f);
    CHECK(std::fabs(to_end) < std::fabs(face - joint) - knee);
    CHECK(std::fabs(to_end) > std::fabs(face - joint) - knee - 0.1f);
  }
}

TEST_CASE("body motion: the wall sweep stops the body at a wall, not at a step its legs climb", "[anim][motion]") {
  for (const Creature& c : {scenes::quadruped(), scenes::biped()}) {
    for (const int facing : {1, -1}) {
      INFO(c.name << " facing " << facing);
      const float x = 5.0f;  // (the probe stands at x + 50 on flat ground; the scene at x)
      test::StageScene probe(c, scenes::flat_level(100.0f), x + 50.0f, facing);
      anim::PoseState pose;
      anim::init_pose(*probe.rig, pose);
      anim::pose_body(probe.ctx, probe.body, 0.0f, 0.0f, 0.0f, 0.0f, pose);
      std::vector<Box> parts;
      anim::body_boxes(*probe.rig, probe.body, pose.facing, false, &parts);
      const float front = (facing > 0 ? parts[0].max_ws.x : parts[0].min_ws.x) - probe.body.x_ws + x;
      // A wall taller than the body half a metre ahead of it; a low step there instead.
      const float at = front + facing * 0.5f;
      const float step = 0.5f * probe.params.max_step_up * probe.rig->climb_height;
      for (const float height : {3.0f * probe.rig->hip_height + 2.0f, step}) {
        const Box obstacle = facing > 0 ? Box{{at, 0.0f}, {at + 1.0f, height}} : Box{{at - 1.0f, 0.0f}, {at, height}};
        test::StageScene s(c, Level({Box::from_corner(-50.0f, -1.0f, 100.0f, 1.0f), obstacle}, {0.0f, 0.0f}), x, facing);
        std::vector<Box> scratch;
        const anim::BodyMotionResult r = anim::sweep_body(s.ctx, s.body, pose.facing, facing * 2.0f, scratch);
        CHECK(r.dx * facing >= 0.0f);
        if (height > 1.0f) {
          CHECK(r.hit_wall);
          CHECK(std::fabs(r.dx) < 0.5f);                // stops at the wall's face...
          CHECK(std::fabs(r.dx) > 0.5f - 0.1f - 0.05f * s.rig->hip_height);  // ...a wall margin early
        } else {
          CHECK_FALSE(r.hit_wall);                      // a step is the legs' business
          CHECK(r.dx == facing * 2.0f);
        }
      }
    }
  }
}

TEST_CASE("body motion: a stance foot behind keeps the body within its leg's reach", "[anim][motion]") {
  for (const int facing : {1, -1}) {
    INFO("facing " << facing);
    test::StageScene s(scenes::quadruped(), scenes::flat_level(100.0f), 50.0f, facing);
    anim::FootSet feet = feet_at(*s.rig, s.body, 0.0f);
    anim::TickHandoff handoff;
    handoff.resize(s.rig->legs.size());
    const float dx = anim::limit_by_legs(s.ctx, s.body, feet, facing * 5.0f, handoff);
    CHECK(dx * facing > 0.0f);
    CHECK(std::fabs(dx) < 5.0f);
    // Moved by dx, every foot still lies within its leg's contact reach of its girdle joint.
    anim::BodyFrame moved = s.body;
    moved.x_ws += dx;
    for (size_t i = 0; i < s.rig->legs.size(); ++i) {
      const glm::vec2 joint = moved.girdle_ws(*s.rig, s.rig->legs[i].girdle);
      CHECK(glm::length(feet.of_leg(static_cast<int>(i)).pos_ws - joint) <= s.rig->legs[i].contact_reach + 1e-4f);
    }
    // A move within reach is not limited; on flat ground no foot is told to lift.
    CHECK(anim::limit_by_legs(s.ctx, s.body, feet, facing * 0.01f, handoff) == facing * 0.01f);
    for (uint8_t f : handoff.lift_now) CHECK(f == 0);
  }
}
