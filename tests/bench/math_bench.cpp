// Benchmarks for src/ossa/math (see bench_main.cpp for the ratio table).
//  ik:ossa              TwoBoneIkJob::run with compute_angles = false: joint positions and
//                       bone directions (the two bone matrices, what skinning needs) and `reached`
//  ik_with_angles:ossa  the same job with compute_angles = true: also both joint angles (the
//                       form forward kinematics and Pose use)
//  ik:reference, ik_with_angles:reference
//                       a naive law-of-cosines solver: atan2 for the target direction, acos for
//                       both triangle angles, then cos/sin of both absolute bone angles to build
//                       the joint positions — all the outputs, angles included. It is the
//                       reference of both rows: a naive solver needs all that trig for the
//                       positions alone.
//  hermite:ossa/…       HermiteSpline::position (inline, hermite.h), 8 keys
//  hermite:reference/…  a linear scan from the first key per evaluation and the textbook Hermite
//                       basis
// Every benchmark runs over the same pre-generated batch of 1024 inputs per iteration.

#include "ossa/math/hermite.h"
#include "ossa/math/rng.h"
#include "ossa/math/two_bone_ik.h"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace ossa;

constexpr int kBatch = 1024;

// ---------------------------------------------------------------------------------------------
// Two-bone IK

struct IkCase {
  glm::vec2 root;
  float l1, l2;
  glm::vec2 target;
  float bend;
};

const std::vector<IkCase>& ik_cases() {
  static const std::vector<IkCase> cases = [] {
    Rng rng(2024);
    std::vector<IkCase> v;
    for (int i = 0; i < kBatch; ++i) {
      IkCase c;
      c.root = {static_cast<float>(rng.uniform(-1, 1)), static_cast<float>(rng.uniform(-1, 1))};
      c.l1 = static_cast<float>(rng.uniform(0.2, 1.0));
      c.l2 = static_cast<float>(rng.uniform(0.2, 1.0));
      // Mostly reachable targets, as for feet on the ground; ~15 % beyond reach.
      const double dist = (c.l1 + c.l2) * rng.uniform(0.0, 1.15);
      const double angle = rng.uniform(-3.14159, 3.14159);
      c.target = c.root + static_cast<float>(dist) *
                              glm::vec2(static_cast<float>(std::cos(angle)),
                                        static_cast<float>(std::sin(angle)));
      c.bend = rng.chance(0.5) ? 1.0f : -1.0f;
      v.push_back(c);
    }
    return v;
  }();
  return cases;
}

// The naive reference: what a typical engine snippet does.
TwoBoneIkResult naive_two_bone_ik(glm::vec2 root, float l1, float l2, glm::vec2 target, float bend) {
  TwoBoneIkResult out;
  const glm::vec2 d = target - root;
  const float dist = std::sqrt(d.x * d.x + d.y * d.y);
  const float r = std::clamp(dist, std::fabs(l1 - l2), l1 + l2);
  const float base = std::atan2(d.y, d.x);
  const float cos_a = std::clamp((l1 * l1 + r * r - l2 * l2) / std::max(2.0f * l1 * r, 1e-20f), -1.0f, 1.0f);
  const float cos_b = std::clamp((l1 * l1 + l2 * l2 - r * r) / std::max(2.0f * l1 * l2, 1e-20f), -1.0f, 1.0f);
  const float a = std::acos(cos_a);   // angle at the root
  const float b = std::acos(cos_b);   // interior angle at the middle joint
  out.upper_angle = base + bend * a;
  out.lower_angle = -bend * (3.14159265f - b);
  const float abs_lower = out.upper_angle + out.lower_angle;
  out.upper_dir = {std::cos(out.upper_angle), std::sin(out.upper_angle)};
  out.lower_dir = {std::cos(abs_lower), std::sin(abs_lower)};
  out.middle = root + l1 * out.upper_dir;
  out.end = out.middle + l2 * out.lower_dir;
  out.reached = glm::length(out.end - target) <= 1e-5f * (l1 + l2);
  return out;
}

void ik_ossa(benchmark::State& state, bool angles) {
  const std::vector<IkCase>& cases = ik_cases();
  TwoBoneIkJob job;
  job.compute_angles = angles;
  for (auto _ : state) {
    for (const IkCase& c : cases) {
      job.root = c.root;
      job.upper_length = c.l1;
      job.lower_length = c.l2;
      job.target = c.target;
      job.bend_sign = c.bend;
      job.run();
      benchmark::DoNotOptimize(job.result);
    }
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

void ik_reference(benchmark::State& state) {
  const std::vector<IkCase>& cases = ik_cases();
  for (auto _ : state) {
    for (const IkCase& c : cases) {
      TwoBoneIkResult r = naive_two_bone_ik(c.root, c.l1, c.l2, c.target, c.bend);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

// "ik": the solve to what skinning needs — joint positions and bone directions, i.e. the two
// bone matrices — against the naive acos/atan2 + sin/cos solve that builds the same matrices.
// "ik_with_angles": ours also returning the two joint angles (what Pose stores).
BENCHMARK_CAPTURE(ik_ossa, positions, false)->Name("ik:ossa");
BENCHMARK(ik_reference)->Name("ik:reference");
BENCHMARK_CAPTURE(ik_ossa, angles, true)->Name("ik_with_angles:ossa");
BENCHMARK(ik_reference)->Name("ik_with_angles:reference");

// ---------------------------------------------------------------------------------------------
// Hermite spline evaluation

HermiteSpline bench_spline() {
  Rng rng(7);
  HermiteSpline s;
  for (int i = 0; i < 8; ++i) {
    s.keys.push_back({i / 7.0f, static_cast<float>(rng.uniform(-1, 1)),
                      static_cast<float>(rng.uniform(-3, 3))});
  }
  return s;
}

std::vector<float> bench_times(bool sorted) {
  Rng rng(8);
  std::vector<float> t(kBatch);
  for (float& v : t) v = static_cast<float>(rng.uniform());
  if (sorted) std::sort(t.begin(), t.end());
  return t;
}

// Reference: linear scan from the first key on every evaluation.
float reference_position(const std::vector<HermiteKey>& k, float t) {
  t = std::clamp(t, k.front().t, k.back().t);
  std::size_t i = 0;
  while (i + 2 < k.size() && k[i + 1].t <= t) ++i;
  const float dt = k[i + 1].t - k[i].t;
  const float u = (t - k[i].t) / dt;
  const float u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * k[i].p + (u3 - 2 * u2 + u) * dt * k[i].m +
         (-2 * u3 + 3 * u2) * k[i + 1].p + (u3 - u2) * dt * k[i + 1].m;
}

void hermite_ossa(benchmark::State& state, bool sorted) {
  const HermiteSpline s = bench_spline();
  const std::vector<float> ts = bench_times(sorted);
  for (auto _ : state) {
    for (float t : ts) benchmark::DoNotOptimize(s.position(t));
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

void hermite_reference(benchmark::State& state, bool sorted) {
  const HermiteSpline s = bench_spline();
  const std::vector<float> ts = bench_times(sorted);
  for (auto _ : state) {
    for (float t : ts) benchmark::DoNotOptimize(reference_position(s.keys, t));
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

BENCHMARK_CAPTURE(hermite_ossa, sorted, true)->Name("hermite:ossa/sorted");
BENCHMARK_CAPTURE(hermite_reference, sorted, true)->Name("hermite:reference/sorted");
BENCHMARK_CAPTURE(hermite_ossa, random, false)->Name("hermite:ossa/random");
BENCHMARK_CAPTURE(hermite_reference, random, false)->Name("hermite:reference/random");

}  // namespace
