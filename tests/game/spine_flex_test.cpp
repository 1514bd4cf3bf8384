// Issue 28, body motion per gait: the back flexes and extends once per stride in the gallop
// and the bound, and stays still in the walk and the trot. Measured from the bones' world
// matrices tick by tick on flat ground (not from the animator's own spine_flex): the spine's
// bend is the angle between its last bone towards the shoulders and its last bone towards the
// pelvis (turned round), less that angle at rest. The back should arch as the feet gather under
// the body and hollow as they reach apart (fore feet's mean x less the hind feet's).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ossa/anim/gait_family.h"
#include "ossa/game/player.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

constexpr float kDt = 1.0f / 120.0f;
constexpr float kPi = 3.14159265f;

// The last bone of the back chain named prefix (back_f: towards the shoulders, back_r: the
// pelvis).
int chain_end(const Skeleton& sk, const std::string& prefix) {
  int best = -1, best_n = -1;
  for (int b = 0; b < sk.bone_count(); ++b) {
    const std::string& name = sk.name(b);
    if (name.rfind(prefix, 0) != 0) continue;
    const int n = std::stoi(name.substr(prefix.size()));
    if (n > best_n) best = b, best_n = n;
  }
  return best;
}

float angle_of(const Mat2x3& m) { return std::atan2(m.m[1], m.m[0]); }

float wrap(float a) {
  while (a > kPi) a -= 2.0f * kPi;
  while (a < -kPi) a += 2.0f * kPi;
  return a;
}

struct BendTrack {
  std::vector<float> bend;  // radians, > 0 arched (flexed), from the rest bend
  std::vector<float> spread;  // the fore feet's mean x less the hind feet's (facing +x), metres
  float frequency = 0.0f;   // strides per second
  float slip = 0.0f;        // the largest stance slip, metres
  Gait gait = Gait::kIdle;  // at the end
};

// Steps `name` with `controls` for 6 s and records the spine's bend over the last 3 s.
BendTrack track(const std::string& name, Controls controls) {
  const Level flat = scenes::flat_level(400.0f);
  auto creature = std::make_shared<const Creature>(build_creature(scenes::generator().example(name).value()).value());
  Player player(creature, SplinePrototypes::defaults());
  player.animator().reset({2.0f, 1.0f}, flat);
  const Animator& a = player.animator();
  const Skeleton& sk = a.rig().skeleton;
  const int front = chain_end(sk, "back_f"), back = chain_end(sk, "back_r");
  REQUIRE(front >= 0);
  REQUIRE(back >= 0);
  auto bend_of = [&](const std::vector<Mat2x3>& m) {
    // Facing +x, an arched back turns clockwise towards the shoulders and counter-clockwise
    // (turned round) towards the pelvis.
    return wrap(angle_of(m[back]) + kPi - angle_of(m[front])) * static_cast<float>(a.facing());
  };
  const float rest = bend_of(a.rig().model_rest);
  BendTrack t;
  const size_t legs = a.rig().legs.size();
  std::vector<glm::vec2> planted(legs);
  std::vector<bool> down(legs, false);
  int n = 0;
  for (int i = 0; i < 720; ++i) {
    player.step(kDt, controls, flat);
    if (i < 360) continue;
    t.bend.push_back(wrap(bend_of(a.world_matrices()) - rest));
    {
      const std::vector<Mat2x3>& w = a.world_matrices();
      float fore = 0.0f, hind = 0.0f;
      int n_fore = 0, n_hind = 0;
      for (const RigLeg& leg : a.rig().legs) {
        const int foot = leg.bones[2];
        const float x = bone_end(w[foot], a.rig().skeleton.length(foot)).x;
        (leg.girdle == 0 ? fore : hind) += x;
        ++(leg.girdle == 0 ? n_fore : n_hind);
      }
      t.spread.push_back(static_cast<float>(a.facing()) * (fore / std::max(n_fore, 1) - hind / std::max(n_hind, 1)));
    }
    t.frequency += a.cycle_frequency();
    ++n;
    for (size_t k = 0; k < legs; ++k) {
      const int leg = static_cast<int>(k);
      const bool stance = a.leg_state(leg) == LegState::kStance;
      if (stance && down[k]) t.slip = std::max(t.slip, glm::length(a.foot_target_ws(leg) - planted[k]));
      if (stance && !down[k]) planted[k] = a.foot_target_ws(leg);
      down[k] = stance;
    }
  }
  t.frequency /= static_cast<float>(n);
  t.gait = a.gait();
  return t;
}

Controls moving(float stick, bool run) {
  Controls c;
  c.move_x = stick;
  c.run = run;
  return c;
}

float peak_to_peak(const std::vector<float>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

// Pearson's correlation of a and b.
float correlation(const std::vector<float>& a, const std::vector<float>& b) {
  double ma = 0.0, mb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= static_cast<double>(a.size());
  mb /= static_cast<double>(b.size());
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return aa > 0.0 && bb > 0.0 ? static_cast<float>(ab / std::sqrt(aa * bb)) : 0.0f;
}

// Arches per second: upward crossings of the mean.
float arches_per_second(const std::vector<float>& v) {
  float mean = 0.0f;
  for (float x : v) mean += x;
  mean /= static_cast<float>(v.size());
  int crossings = 0;
  for (size_t i = 1; i < v.size(); ++i) crossings += v[i - 1] < mean && v[i] >= mean;
  return static_cast<float>(crossings) / (static_cast<float>(v.size()) * kDt);
}

}  // namespace

TEST_CASE("the back flexes and extends once per stride in the gallop and the bound", "[game][anim][gait]") {
  struct Case {
    const char* name;
    float most;  // the family's spine_flex: flexed to extended is at most twice it
  };
  // Two hoofed gallopers (a stiff back) and two bounders (a supple one).
  for (const Case c : {Case{"horse", 0.09f}, Case{"red deer", 0.09f}, Case{"rabbit", 0.25f}, Case{"rock hyrax", 0.25f}}) {
    const BendTrack t = track(c.name, moving(1.0f, true));
    const float range = peak_to_peak(t.bend);
    const float rate = arches_per_second(t.bend);
    // Arched when the feet are gathered under the body, hollow when they reach apart.
    const float with_spread = correlation(t.bend, t.spread);
    INFO(c.name << ": bend " << range << " rad flexed to extended, " << rate << " arches/s, " << t.frequency
                 << " strides/s, slip " << t.slip << " m, correlation with the feet's spread " << with_spread);
    CHECK(with_spread < -0.5f);
    CHECK(range >= 0.5f * c.most);
    CHECK(range <= 2.0f * c.most + 0.01f);
    CHECK(std::fabs(rate - t.frequency) <= 0.2f * t.frequency);
    CHECK(t.slip <= 0.001f);
  }
}

TEST_CASE("the back stays still in the walk and the trot", "[game][anim][gait]") {
  for (const char* name : {"horse", "rabbit"}) {
    for (const float stick : {0.4f, 0.6f}) {
      const BendTrack t = track(name, moving(stick, false));  // a walk, and a trot or half-bound
      INFO(name << ", stick " << stick << ": " << gait_name(t.gait) << ", bend " << peak_to_peak(t.bend) << " rad");
      CHECK((t.gait == Gait::kWalk || t.gait == Gait::kTrot || t.gait == Gait::kHalfBound));
      CHECK(peak_to_peak(t.bend) < 1e-3f);
    }
  }
}
