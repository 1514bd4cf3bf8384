#include "ossa/anim/body_motion.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "shared/scenes.h"
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

TEST_CASE("body motion: no girdle passes over the face of a ledge its legs cannot climb, a bump it can step over is no ledge",
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
    // A 1 m bump narrower than a stride (stepped over) does not limit the body.
    const float bump = 5.0f + facing * 1.0f;
    const Level bumpy({Box::from_corner(-20.0f, -1.0f, 40.0f, 1.0f), Box::from_corner(bump - 0.05f, 0.0f, 0.1f, 1.0f)});
    test::StageScene b(scenes::biped(), bumpy, 5.0f, facing);
    CHECK(anim::limit_by_ledges(b.ctx, b.body, feet_at(*b.rig, b.body, 0.0f), b.gait.stride, far) == far);
  }
}
