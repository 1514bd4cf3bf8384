#include "ossa/skeleton/pose.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/math/rng.h"
#include "shared/scenes.h"

using namespace ossa;
using Catch::Matchers::WithinAbs;

TEST_CASE("skeleton keeps parents before children and finds bones by name", "[skeleton]") {
  Skeleton s = scenes::chain_skeleton(5, 0.5f);
  CHECK(s.bone_count() == 5);
  CHECK(s.is_valid());
  CHECK(s.find("bone3") == 3);
  CHECK(s.find("nope") == -1);
  CHECK(s.parent(0) == kNoParent);
  CHECK(s.parent(4) == 3);
  CHECK(s.count(BoneKind::kRoot) == 1);
  s.set_rest(2, BoneLocal{{std::nanf(""), 0.0f}, 0.0f});
  CHECK_FALSE(s.is_valid());
}

TEST_CASE("forward kinematics of a bent chain matches the closed form", "[skeleton][fk]") {
  const float bend = 0.3f;
  Skeleton s = scenes::chain_skeleton(8, 0.25f, bend);
  Pose pose = Pose::rest(s);
  std::vector<Mat2x3> model = model_matrices(s, pose.locals);
  // Bone k points at angle k*bend (the root at 0); bone i starts where bone i-1 ends.
  glm::vec2 expected(0.0f);
  for (int i = 1; i < s.bone_count(); ++i) {
    const float prev = (i - 1) * bend;
    expected += 0.25f * glm::vec2(std::cos(prev), std::sin(prev));
    CHECK_THAT(bone_start(model[i]).x, WithinAbs(expected.x, 1e-5));
    CHECK_THAT(bone_start(model[i]).y, WithinAbs(expected.y, 1e-5));
  }
  const int last = s.bone_count() - 1;
  const glm::vec2 tip = bone_end(model[last], s.length(last));
  const float a = last * bend;
  CHECK_THAT(tip.x, WithinAbs(expected.x + 0.25f * std::cos(a), 1e-5));
  CHECK_THAT(tip.y, WithinAbs(expected.y + 0.25f * std::sin(a), 1e-5));
}

TEST_CASE("world matrices place and mirror the creature", "[skeleton][fk]") {
  Skeleton s = scenes::chain_skeleton(6, 0.4f, 0.2f);
  Pose pose = Pose::rest(s);
  std::vector<Mat2x3> model(s.bone_count()), world(s.bone_count());
  Transform2D placement;
  placement.translation = {10.0f, 2.0f};
  placement.mirror_x = true;
  ForwardKinematicsJob job;
  job.skeleton = &s;
  job.locals = pose.locals;
  job.model_to_world = placement.to_mat2x3();
  job.model = model;
  job.world = world;
  REQUIRE(job.run());
  for (int i = 0; i < s.bone_count(); ++i) {
    const glm::vec2 m = bone_end(model[i], s.length(i));
    const glm::vec2 w = bone_end(world[i], s.length(i));
    CHECK_THAT(w.x, WithinAbs(10.0f - m.x, 1e-5));
    CHECK_THAT(w.y, WithinAbs(2.0f + m.y, 1e-5));
  }
  // Wrong sizes are rejected, not written out of bounds.
  job.model = std::span<Mat2x3>(model.data(), 3);
  CHECK_FALSE(job.validate());
  CHECK_FALSE(job.run());
}

TEST_CASE("palette of the bind pose is the identity, inverse undoes a matrix", "[skeleton][palette]") {
  Rng rng(7);
  Skeleton s = scenes::chain_skeleton(12, 0.3f, 0.1f);
  Pose pose = Pose::rest(s);
  for (auto& l : pose.locals) l.angle_ls = static_cast<float>(rng.uniform(-1.0, 1.0));
  std::vector<Mat2x3> model = model_matrices(s, pose.locals);
  std::vector<Mat2x3> inverse_bind(model.size()), palette(model.size());
  for (size_t i = 0; i < model.size(); ++i) inverse_bind[i] = inverse(model[i]);
  PaletteJob job{model, inverse_bind, palette};
  REQUIRE(job.run());
  for (const Mat2x3& p : palette) {
    const float expected[6] = {1, 0, 0, 1, 0, 0};
    for (int k = 0; k < 6; ++k) CHECK_THAT(p.m[k], WithinAbs(expected[k], 1e-4));
  }
  // A vertex authored in the bind pose follows its bone when the pose changes.
  const glm::vec2 v_bind = bone_end(model[5], 0.1f);
  pose.locals[3].angle_ls += 0.5f;
  std::vector<Mat2x3> moved = model_matrices(s, pose.locals);
  PaletteJob job2{moved, inverse_bind, palette};
  REQUIRE(job2.run());
  const glm::vec2 v_now = palette[5].apply(v_bind);
  const glm::vec2 expected = bone_end(moved[5], 0.1f);
  CHECK_THAT(v_now.x, WithinAbs(expected.x, 1e-4));
  CHECK_THAT(v_now.y, WithinAbs(expected.y, 1e-4));
}
