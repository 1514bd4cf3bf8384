// Limb clearance (limb_clearance.h) on its own: arms, tails and fins that reach into a step
// leave it; a legless body its wave bent into the ground is told how far to rise. The body is
// placed and posed by the pose stage's body pass (pose_stage.h), no Animator.

#include "ossa/anim/limb_clearance.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "ossa/anim/pose_stage.h"
#include "ossa/anim/level_probe.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "stage_scene.h"

using namespace ossa;

namespace {

const Creature& example(const char* name) {
  static std::map<std::string, Creature> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, build_creature(scenes::generator().example(name).value()).value()).first;
  return it->second;
}

// World points of a chain of bones (their joints and the last one's end) as posed.
std::vector<glm::vec2> chain_ws(const test::StageScene& s, const std::vector<Mat2x3>& girdle, int girdle_bone,
                                const std::vector<int>& bones, const Pose& pose) {
  std::vector<glm::vec2> p;
  Mat2x3 m = girdle[girdle_bone];
  for (size_t k = 0; k < bones.size(); ++k) {
    m = m * local_matrix(pose.locals[bones[k]]);
    p.push_back(s.body.to_ws(bone_start(m)));
    if (k + 1 == bones.size()) p.push_back(s.body.to_ws(bone_end(m, s.rig->skeleton.length(bones[k]))));
  }
  return p;
}

// A tail at rest, posed on flat ground at x 50: its root's and tip's world points, the root
// bone's height there and the tail's length.
struct RestTail {
  glm::vec2 root, tip;
  float body_y = 0.0f, len = 0.0f;
};
RestTail rest_tail(const Creature& c, int facing) {
  test::StageScene flat(c, scenes::flat_level(100.0f), 50.0f, facing);
  REQUIRE(flat.rig->tail_length > 0.0f);
  anim::PoseState ps;
  anim::init_pose(*flat.rig, ps);
  anim::pose_body(flat.ctx, flat.body, 0.0f, 0.0f, 0.0f, 0.0f, ps);
  const std::vector<Mat2x3> fs = anim::facing_matrices(*flat.rig, ps);
  const int last = flat.rig->tail.back();
  return {flat.body.to_ws(bone_start(fs[flat.rig->tail.front()])),
          flat.body.to_ws(bone_end(fs[last], flat.rig->skeleton.length(last))), flat.body.root_y_ws, flat.rig->tail_length};
}

// The tail's joints and tip (world) as posed.
std::vector<glm::vec2> tail_ws(const test::StageScene& s, const Pose& pose) {
  const std::vector<Mat2x3> m = model_matrices(s.rig->skeleton, pose.locals);
  std::vector<glm::vec2> tail;
  for (int b : s.rig->tail) tail.push_back(s.body.to_ws(bone_start(m[b])));
  tail.push_back(s.body.to_ws(bone_end(m[s.rig->tail.back()], s.rig->skeleton.length(s.rig->tail.back()))));
  return tail;
}

}  // namespace

TEST_CASE("limb clearance: an arm lifted off the ground keeps its elbow on the side it bends to", "[anim][limbs]") {
  // The wrist is lifted by two-bone IK until the arm clears the ground under it; the elbow
  // stays on its side of the line from the shoulder to the wrist. (The side was read the other
  // way round, so every lift bent the elbow the other way: the eared seal's elbow, its fore
  // flipper laid on the ground, went 0.3 m behind its shoulder one tick and 0.3 m in front of
  // it the next.) A low block under the whole arm, 2 cm above its lowest point at rest.
  for (const char* name : {"eared seal", "harbour seal"}) {
    for (int facing : {1, -1}) {
      INFO(name << " facing " << facing);
      const Creature& c = example(name);
      test::StageScene probe(c, scenes::flat_level(100.0f), 50.0f, facing);
      REQUIRE_FALSE(probe.rig->arms.empty());
      const RigLimb& arm = probe.rig->arms.front();
      const std::vector<int> bones = {arm.bones[0], arm.bones[1], arm.bones[2]};
      anim::PoseState ps;
      anim::init_pose(*probe.rig, ps);
      anim::pose_body(probe.ctx, probe.body, 0.0f, 0.0f, 0.0f, 0.0f, ps);
      const std::vector<glm::vec2> rest = chain_ws(probe, ps.facing, arm.girdle_bone, bones, ps.pose);
      float x0 = 1e30f, x1 = -1e30f, low = 1e30f;
      for (glm::vec2 q : rest) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), low = std::min(low, q.y);
      const Level block({Box::from_corner(0.0f, -1.0f, 100.0f, 1.0f), Box{{x0 - 0.5f, 0.0f}, {x1 + 0.5f, low + 0.02f}}}, {0.0f, 0.0f});
      test::StageScene s(c, block, 50.0f, facing);
      anim::PoseState pose;
      anim::init_pose(*s.rig, pose);
      anim::pose_body(s.ctx, s.body, 0.0f, 0.0f, 0.0f, 0.0f, pose);
      const std::vector<glm::vec2> before = chain_ws(s, pose.facing, arm.girdle_bone, bones, pose.pose);
      anim::keep_arm_above_ground(s.ctx, s.body, arm, pose.facing, s.rig->scale.arm_margin, pose.pose, false);
      const std::vector<glm::vec2> after = chain_ws(s, pose.facing, arm.girdle_bone, bones, pose.pose);
      auto side = [](const std::vector<glm::vec2>& p) {
        const glm::vec2 a = p[1] - p[0], b = p[2] - p[0];
        return b.x * a.y - b.y * a.x;
      };
      INFO("elbow side before " << side(before) << ", after " << side(after) << "; wrist y " << before[2].y << " -> " << after[2].y);
      CHECK(after[2].y > before[2].y);  // lifted
      CHECK(side(before) * side(after) > 0.0f);
    }
  }
}

TEST_CASE("limb clearance: an arm reaching into a step in front of the chest folds out of it", "[anim][limbs]") {
  const Creature& c = scenes::biped();  // the kangaroo's arms hang forward of its chest
  for (int facing : {1, -1}) {
    INFO("facing " << facing);
    test::StageScene probe(c, scenes::flat_level(100.0f), 50.0f, facing);
    REQUIRE_FALSE(probe.rig->arms.empty());
    const RigLimb& arm = probe.rig->arms.front();
    anim::PoseState ps;
    anim::init_pose(*probe.rig, ps);
    anim::pose_body(probe.ctx, probe.body, 0.0f, 0.0f, 0.0f, 0.0f, ps);
    // A step rising right where the hand hangs.
    const std::vector<glm::vec2> rest = chain_ws(probe, ps.facing, arm.girdle_bone,
                                                 {arm.bones[0], arm.bones[1], arm.bones[2]}, ps.pose);
    const float hand_x = rest.back().x, hand_y = rest.back().y;
    const Level step({Box::from_corner(0.0f, -1.0f, 100.0f, 1.0f),
                      Box{{hand_x - 0.05f, 0.0f}, {hand_x + 0.05f, hand_y + 0.03f}}}, {0.0f, 0.0f});
    test::StageScene s(c, step, 50.0f, facing);
    anim::PoseState pose;
    anim::init_pose(*s.rig, pose);
    anim::pose_body(s.ctx, s.body, 0.0f, 0.0f, 0.0f, 0.0f, pose);
    std::vector<glm::vec2> before = chain_ws(s, pose.facing, arm.girdle_bone, {arm.bones[0], arm.bones[1], arm.bones[2]}, pose.pose);
    REQUIRE(anim::polyline_hits_level(s.level, before.data(), static_cast<int>(before.size()), s.hits));
    anim::keep_arm_above_ground(s.ctx, s.body, arm, pose.facing, s.rig->scale.arm_margin, pose.pose);
    const std::vector<glm::vec2> after = chain_ws(s, pose.facing, arm.girdle_bone, {arm.bones[0], arm.bones[1], arm.bones[2]}, pose.pose);
    CHECK_FALSE(anim::polyline_hits_level(s.level, after.data(), static_cast<int>(after.size()), s.hits));
    CHECK(glm::length(after.front() - before.front()) < 1e-5f);  // the shoulder stays
  }
}

TEST_CASE("limb clearance: a tail in a step curls or lifts out of it, a fin turns up", "[anim][limbs]") {
  for (const char* name : {"crocodile", "kangaroo", "dimetrodon"}) {
    for (int facing : {1, -1}) {
      INFO(name << " facing " << facing);
      const Creature& c = example(name);
      // A step behind the body, as high as the tail's root hangs.
      const RestTail t = rest_tail(c, facing);
      const glm::vec2 root = t.root, tip = t.tip;
      const float x0 = std::min(root.x, tip.x), x1 = std::max(root.x, tip.x);
      const Level step({Box::from_corner(0.0f, -1.0f, 100.0f, 1.0f),
                        Box{{x0 + 0.3f * (x1 - x0), 0.0f}, {x1 + 1.0f, std::max(root.y, tip.y) * 0.8f}}}, {0.0f, 0.0f});
      test::StageScene s(c, step, 50.0f, facing);
      anim::PoseState pose;
      anim::init_pose(*s.rig, pose);
      anim::pose_body(s.ctx, s.body, 0.0f, 0.0f, 0.0f, 0.0f, pose);
      anim::keep_tail_clear(s.ctx, s.body, pose.facing, 0.0f, pose.tail, pose.pose);
      const std::vector<glm::vec2> tail = tail_ws(s, pose.pose);
      CHECK_FALSE(anim::polyline_hits_level(s.level, tail.data(), static_cast<int>(tail.size()), s.hits));
    }
  }
}

TEST_CASE("limb clearance: a tail reaching into a wall that rises far above it curls out of it", "[anim][limbs]") {
  // A wall behind a body in the air, whose face the tail's far fifth reaches past and whose top
  // lies three tails above its root (the tarsier falling down drops.json's 1 m ledge trailed its
  // tail into the face: only ground within a tail's length above its root was looked for).
  for (const char* name : {"crocodile", "tarsier", "dimetrodon"}) {
    for (int facing : {1, -1}) {
      INFO(name << " facing " << facing);
      const Creature& c = example(name);
      const RestTail t = rest_tail(c, facing);
      const glm::vec2 root = t.root, tip = t.tip;
      // (The body in the air, the ground two tails below the tail's root: falling down the face.)
      const float len = t.len, floor = root.y - 2.0f * len;
      const float face = tip.x + 0.2f * (root.x - tip.x), top = root.y + 3.0f * len;
      const Box wall = tip.x < root.x ? Box{{face - 2.0f, floor}, {face, top}} : Box{{face, floor}, {face + 2.0f, top}};
      const Level level({Box::from_corner(-50.0f, floor - 1.0f, 200.0f, 1.0f), wall}, {0.0f, 0.0f});
      test::StageScene s(c, level, 50.0f, facing);
      s.body.root_y_ws = t.body_y;
      anim::PoseState pose;
      anim::init_pose(*s.rig, pose);
      anim::pose_body(s.ctx, s.body, 0.0f, 0.0f, 0.0f, 0.0f, pose);
      std::vector<glm::vec2> tail = tail_ws(s, pose.pose);
      REQUIRE(anim::polyline_hits_level(s.level, tail.data(), static_cast<int>(tail.size()), s.hits));
      anim::keep_tail_clear(s.ctx, s.body, pose.facing, 0.0f, pose.tail, pose.pose);
      tail = tail_ws(s, pose.pose);
      CHECK_FALSE(anim::polyline_hits_level(s.level, tail.data(), static_cast<int>(tail.size()), s.hits));
    }
  }
}

TEST_CASE("limb clearance: a legless body bent into the ground rises by the deepest point", "[anim][limbs]") {
  const Creature& c = example("snake");
  test::StageScene s(c, scenes::flat_level(100.0f), 50.0f);
  anim::PoseState pose;
  anim::init_pose(*s.rig, pose);
  // The root half its rest height into the ground.
  s.body.root_y_ws -= 1.5f * s.rig->root_rest_y;
  anim::pose_body(s.ctx, s.body, 0.0f, 0.0f, 0.0f, 0.0f, pose);
  const float raise = anim::body_out_of_ground(s.ctx, s.body, pose.facing, pose.pose);
  CHECK(raise > 0.0f);
  // After rising by it (as the animator does: the pose moves up whole) no bone's end is below
  // the ground.
  s.body.root_y_ws += raise;
  anim::lift_pose(*s.rig, raise, pose);
  const std::vector<Mat2x3> all = model_matrices(s.rig->skeleton, pose.pose.locals);  // every bone, as drawn
  for (int b = 0; b < s.rig->skeleton.bone_count(); ++b) {
    CHECK(bone_start(all[b]).y >= -1e-4f);
    CHECK(bone_end(all[b], s.rig->skeleton.length(b)).y >= -1e-4f);
  }
  CHECK(anim::body_out_of_ground(s.ctx, s.body, pose.facing, pose.pose) == Approx(0.0f).margin(1e-4));
}
