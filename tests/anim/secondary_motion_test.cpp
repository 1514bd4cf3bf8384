// Secondary motion (secondary_motion.h) on its own: the tail's spring, the legless wave, the
// arms' swing and the fins' beat.

#include "ossa/anim/secondary_motion.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>

#include "ossa/anim/anim_math.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

const Creature& example(const char* name) {
  static std::map<std::string, Creature> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, build_creature(scenes::generator().example(name).value()).value()).first;
  return it->second;
}

}  // namespace

TEST_CASE("secondary motion: the tail's spring settles where the body leaves it, within its swing", "[anim][secondary]") {
  const Creature& horse = example("horse");
  const auto rig = build_anim_rig(horse);
  REQUIRE_FALSE(rig->tail.empty());
  AnimatorParams params;
  anim::TailSpring tail;
  Pose pose = rig->rest_pose;
  // A body pitched up holds half its pitch back in the tail; a root rising fast lets it lag.
  for (int t = 0; t < 2400; ++t) {
    pose = rig->rest_pose;
    anim::swing_tail(*rig, params, 1.0f / 120.0f, 0.0f, 0.2f, tail, pose);
  }
  CHECK(tail.angle == Approx(-0.1f).margin(1e-3));
  CHECK(std::fabs(tail.rate) < 1e-3f);
  for (int t = 0; t < 600; ++t) anim::swing_tail(*rig, params, 1.0f / 120.0f, 50.0f, 0.0f, tail, pose);
  CHECK(std::fabs(tail.angle) <= params.tail_max_swing + 1e-6f);
}

TEST_CASE("secondary motion: arms swing counter to their own side's leg, fins beat with the motion", "[anim][secondary]") {
  const Creature& kangaroo = scenes::biped();
  const auto rig = build_anim_rig(kangaroo);
  REQUIRE_FALSE(rig->arms.empty());
  const SplinePrototypes prototypes = SplinePrototypes::defaults();
  anim::GaitState gait;
  anim::FootSet feet;
  feet.feet.resize(rig->legs.size());
  for (size_t i = 0; i < rig->legs.size(); ++i) feet.foot_of_leg.push_back(static_cast<int>(i));
  anim::reset_offsets(*rig, rig->gait_family, feet, gait);
  const RigLimb& arm = rig->arms.front();
  auto swing = [&](float phase, float motion) {
    gait.phase = phase;
    Pose pose = rig->rest_pose;
    anim::swing_arm(*rig, prototypes, gait, feet, arm, motion, pose);
    return pose.locals[arm.bones[0]].angle_ls - rig->rest_pose.locals[arm.bones[0]].angle_ls;
  };
  CHECK(swing(0.3f, 0.0f) == 0.0f);  // standing: no swing
  // Half a cycle later the arm is where the other side's arm was: the swing alternates.
  float most = 0.0f;
  for (float p = 0.0f; p < 1.0f; p += 0.05f) most = std::max(most, std::fabs(swing(p, 1.0f) - swing(p + 0.5f, 1.0f)));
  CHECK(most > 0.01f);
  // Fins: no beat without motion.
  const Creature& trout = example("trout");
  const auto fish = build_anim_rig(trout);
  if (!fish->fins.empty()) {
    Pose pose = fish->rest_pose;
    anim::beat_fin(AnimatorParams{}, fish->fins.front(), 0.0f, 0.25f, pose);
    CHECK(pose.locals[fish->fins.front().bones[0]].angle_ls == fish->rest_pose.locals[fish->fins.front().bones[0]].angle_ls);
  }
}
