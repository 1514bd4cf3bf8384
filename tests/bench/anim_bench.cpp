// Animator update for 1 000 walking quadrupeds (the horse: 102 bones, 4 legs) per tick.
//   animator_1000:ossa       Animator::update for every creature (gait, swing planning, body,
//                            IK, FK of the bones the update needs)
//   animator_1000:reference  the bare kinematics a naive animator does per creature and tick:
//                            full FK with glm::mat3 (trig per bone) before and after IK, and a
//                            naive acos/atan2 two-bone IK per leg
//   anim_ik_fk_1000:ossa     our share of the update spent in IK and FK alone (the root, the
//                            girdles and the leg chains, as the update computes them)
//   anim_ik_fk_1000:reference  the same matrices the naive way (glm::mat3 with trig, acos IK)
#include <benchmark/benchmark.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/matrix_transform_2d.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/math/angle.h"
#include "ossa/math/two_bone_ik.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

namespace {

using namespace ossa;

constexpr int kCreatures = 1000;

struct Herd {
  Level level = scenes::flat_level(5000.0f);
  std::shared_ptr<const Creature> creature = std::make_shared<const Creature>(scenes::quadruped());
  std::vector<std::unique_ptr<Animator>> animators;
  Herd() {
    for (int i = 0; i < kCreatures; ++i) {
      animators.push_back(std::make_unique<Animator>(*creature, SplinePrototypes::defaults()));
      animators.back()->reset({2.0f + 0.37f * static_cast<float>(i % 100), 1.0f}, level);
      // Desynchronise: each creature starts some ticks into its walk.
      for (int t = 0; t < i % 120; ++t) animators.back()->update(1.0f / 120.0f, 1.8f, level);
    }
  }
};

Herd& herd() {
  static Herd h;
  return h;
}

void animator_ossa(benchmark::State& state) {
  Herd& h = herd();
  for (auto _ : state) {
    for (auto& a : h.animators) a->update(1.0f / 120.0f, 1.8f, h.level);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kCreatures);
  // Seconds per tick: an inverted rate is printed in seconds with an SI prefix ("410us",
  // "3.2ms"); a value already in microseconds would be printed as "410s" or "1.2ks".
  state.counters["time_per_tick"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(animator_ossa)->Name("animator_1000:ossa")->Unit(benchmark::kMicrosecond);

// Naive kinematics of one creature: FK twice (glm::mat3, trig per bone) and one acos IK per leg.
float naive_kinematics(const Creature& c, const std::vector<BoneLocal>& locals, std::vector<glm::mat3>& model,
                       bool fk, bool ik) {
  const Skeleton& sk = c.skeleton;
  float sink = 0.0f;
  auto run_fk = [&] {
    for (int b = 0; b < sk.bone_count(); ++b) {
      glm::mat3 local = glm::rotate(glm::translate(glm::mat3(1.0f), locals[b].offset_ls), locals[b].angle_ls);
      model[b] = sk.parent(b) < 0 ? local : model[sk.parent(b)] * local;
    }
  };
  if (fk) run_fk();
  if (ik) {
    for (const Limb& limb : c.limbs) {
      if (limb.kind != LimbKind::kLeg) continue;
      const glm::vec2 root(model[limb.girdle_bone][2]);
      const glm::vec2 target = root + glm::vec2(0.1f, -0.6f);
      const float l1 = sk.length(limb.bones[0]), l2 = sk.length(limb.bones[1]);
      const glm::vec2 d = target - root;
      const float r = std::clamp(std::sqrt(d.x * d.x + d.y * d.y), std::fabs(l1 - l2), l1 + l2);
      const float a = std::acos(std::clamp((l1 * l1 + r * r - l2 * l2) / (2.0f * l1 * r), -1.0f, 1.0f));
      const float b = std::acos(std::clamp((l1 * l1 + l2 * l2 - r * r) / (2.0f * l1 * l2), -1.0f, 1.0f));
      sink += std::atan2(d.y, d.x) + a + b;
    }
  }
  if (fk) run_fk();
  return sink + model.back()[2][0];
}

void animator_reference(benchmark::State& state) {
  Herd& h = herd();
  state.SetLabel("naive FK twice and IK only: less work than an update");
  std::vector<glm::mat3> model(h.creature->skeleton.bone_count());
  for (auto _ : state) {
    for (auto& a : h.animators) benchmark::DoNotOptimize(naive_kinematics(*h.creature, a->pose().locals, model, true, true));
  }
  state.SetItemsProcessed(state.iterations() * kCreatures);
}
BENCHMARK(animator_reference)->Name("animator_1000:reference")->Unit(benchmark::kMicrosecond);

// Our IK + FK alone, as the update does them: the root's matrix, each girdle straight from it
// (its rest matrix relative to the root), one two-bone IK per leg and the leg chain's matrices
// from the solution's directions.
void ik_fk_ossa(benchmark::State& state) {
  Herd& h = herd();
  const Creature& c = *h.creature;
  const Skeleton& sk = c.skeleton;
  const std::vector<Mat2x3> rest = model_matrices(sk, c.rest_pose.locals);
  const Mat2x3 root_inv = inverse(rest[c.root]);
  std::vector<Mat2x3> model(sk.bone_count());
  std::vector<const Limb*> legs;
  std::vector<Mat2x3> girdle_rel;
  for (const Limb& limb : c.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    legs.push_back(&limb);
    girdle_rel.push_back(root_inv * rest[limb.girdle_bone]);
  }
  for (auto _ : state) {
    for (auto& a : h.animators) {
      const std::vector<BoneLocal>& locals = a->pose().locals;
      model[c.root] = local_matrix(locals[c.root]);
      for (size_t i = 0; i < legs.size(); ++i) {
        const Limb& limb = *legs[i];
        const Mat2x3 girdle = model[c.root] * girdle_rel[i];
        model[limb.girdle_bone] = girdle;
        const glm::vec2 joint = girdle.apply(locals[limb.bones[0]].offset_ls);
        const TwoBoneIkResult ik = solve_two_bone_ik_directions(joint, sk.length(limb.bones[0]), sk.length(limb.bones[1]),
                                                                joint + glm::vec2(0.1f, -0.6f), static_cast<float>(limb.bend_sign));
        const Mat2x3 upper = frame_matrix(ik.upper_dir, joint);
        const Mat2x3 lower = frame_matrix(ik.lower_dir, upper.apply(locals[limb.bones[1]].offset_ls));
        model[limb.bones[0]] = upper;
        model[limb.bones[1]] = lower;
        model[limb.bones[2]] = frame_matrix({0.0f, -1.0f}, lower.apply(locals[limb.bones[2]].offset_ls));
      }
      benchmark::DoNotOptimize(model.data());
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kCreatures);
}
BENCHMARK(ik_fk_ossa)->Name("anim_ik_fk_1000:ossa")->Unit(benchmark::kMicrosecond);

// The same IK + FK as ik_fk_ossa, the naive way: glm::mat3 with trig per matrix, each girdle
// from the root's matrix, an acos/atan2 two-bone IK per leg, its three bones' matrices from the
// angles.
void ik_fk_reference(benchmark::State& state) {
  Herd& h = herd();
  const Creature& c = *h.creature;
  const Skeleton& sk = c.skeleton;
  auto to_mat3 = [](const Mat2x3& m) {
    return glm::mat3(m.m[0], m.m[1], 0.0f, m.m[2], m.m[3], 0.0f, m.m[4], m.m[5], 1.0f);
  };
  const std::vector<Mat2x3> rest = model_matrices(sk, c.rest_pose.locals);
  const glm::mat3 root_inv = glm::inverse(to_mat3(rest[c.root]));
  std::vector<glm::mat3> model(sk.bone_count());
  std::vector<const Limb*> legs;
  std::vector<glm::mat3> girdle_rel;
  for (const Limb& limb : c.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    legs.push_back(&limb);
    girdle_rel.push_back(root_inv * to_mat3(rest[limb.girdle_bone]));
  }
  auto place = [](glm::vec2 at, float angle) { return glm::rotate(glm::translate(glm::mat3(1.0f), at), angle); };
  for (auto _ : state) {
    for (auto& a : h.animators) {
      const std::vector<BoneLocal>& locals = a->pose().locals;
      model[c.root] = place(locals[c.root].offset_ls, locals[c.root].angle_ls);
      for (size_t i = 0; i < legs.size(); ++i) {
        const Limb& limb = *legs[i];
        const glm::mat3 girdle = model[c.root] * girdle_rel[i];
        model[limb.girdle_bone] = girdle;
        const glm::vec2 joint(girdle * glm::vec3(locals[limb.bones[0]].offset_ls, 1.0f));
        const glm::vec2 d = glm::vec2(0.1f, -0.6f);
        const float l1 = sk.length(limb.bones[0]), l2 = sk.length(limb.bones[1]);
        const float r = std::clamp(std::sqrt(d.x * d.x + d.y * d.y), std::fabs(l1 - l2) + 1e-6f, l1 + l2);
        const float hip = std::acos(std::clamp((l1 * l1 + r * r - l2 * l2) / (2.0f * l1 * r), -1.0f, 1.0f));
        const float knee = std::acos(std::clamp((l1 * l1 + l2 * l2 - r * r) / (2.0f * l1 * l2), -1.0f, 1.0f));
        const float bend = static_cast<float>(limb.bend_sign);
        const float upper_angle = std::atan2(d.y, d.x) + bend * hip;
        const glm::mat3 upper = place(joint, upper_angle);
        const glm::mat3 lower = upper * place(locals[limb.bones[1]].offset_ls, -bend * (kPi - knee));
        const glm::vec2 ankle(lower * glm::vec3(locals[limb.bones[2]].offset_ls, 1.0f));
        model[limb.bones[0]] = upper;
        model[limb.bones[1]] = lower;
        model[limb.bones[2]] = place(ankle, -0.5f * kPi);
      }
      benchmark::DoNotOptimize(model.data());
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kCreatures);
}
BENCHMARK(ik_fk_reference)->Name("anim_ik_fk_1000:reference")->Unit(benchmark::kMicrosecond);

}  // namespace
