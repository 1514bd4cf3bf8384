// Issue 28, body motion per gait: the head's nod in the walk of ungulates and elephants and a
// small bird's head-bob, measured from the skull's world position tick by tick on flat ground
// (not from the animator's own head_rise / head_shift). The nod: the head rises and falls
// relative to the trunk by a few per cent of the hip height, twice per stride, and fades in the
// trot. The head-bob (Frost 1978): the head stands still in the world for part of each step and
// thrusts forward faster than the body walks, twice per stride; none in the run, and none in a
// large bird's walk.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ossa/game/player.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

constexpr float kDt = 1.0f / 120.0f;

struct HeadTrack {
  std::vector<float> head_x, head_y, root_x, root_y;
  float hip = 0.0f, frequency = 0.0f;
};

// Steps `name` with `controls` for 6 s and records the last 3 s.
HeadTrack track(const std::string& name, Controls controls) {
  const Level flat = scenes::flat_level(400.0f);
  auto creature = std::make_shared<const Creature>(build_creature(scenes::generator().example(name).value()).value());
  Player player(creature, SplinePrototypes::defaults());
  player.animator().reset({2.0f, 1.0f}, flat);
  const Animator& a = player.animator();
  const int skull = a.rig().skull;
  REQUIRE(skull >= 0);
  HeadTrack t;
  t.hip = a.hip_height();
  float frequency = 0.0f;
  int n = 0;
  for (int i = 0; i < 720; ++i) {
    player.step(kDt, controls, flat);
    if (i < 360) continue;
    const std::vector<Mat2x3>& world = a.world_matrices();
    const glm::vec2 head = bone_start(world[skull]), root = bone_start(world[a.rig().root]);
    t.head_x.push_back(head.x);
    t.head_y.push_back(head.y);
    t.root_x.push_back(root.x);
    t.root_y.push_back(root.y);
    frequency += a.cycle_frequency();
    ++n;
  }
  t.frequency = frequency / static_cast<float>(n);
  return t;
}

// How many times per stride events happen that came at ticks `at`: one over their mean
// spacing in strides.
float per_stride(const std::vector<size_t>& at, float frequency) {
  if (at.size() < 2) return 0.0f;
  const float spacing = static_cast<float>(at.back() - at.front()) * kDt / static_cast<float>(at.size() - 1);
  return 1.0f / (spacing * frequency);
}

// The head's height over the root's: its rise and fall (of the hip height) and how many times
// per stride it falls to a low (a low counts once the height has risen a third of the way back).
struct Nod {
  float range = 0.0f, lows_per_stride = 0.0f;
};

Nod nod_of(const HeadTrack& t) {
  std::vector<float> rel(t.head_y.size());
  for (size_t i = 0; i < rel.size(); ++i) rel[i] = t.head_y[i] - t.root_y[i];
  const auto [lo, hi] = std::minmax_element(rel.begin(), rel.end());
  Nod nod;
  nod.range = (*hi - *lo) / t.hip;
  const float band = (*hi - *lo) / 3.0f;
  std::vector<size_t> lows;
  bool falling = false;
  float extreme = rel[0];
  size_t extreme_at = 0;
  for (size_t i = 0; i < rel.size(); ++i) {
    const float y = rel[i];
    if (falling) {
      if (y < extreme) extreme = y, extreme_at = i;
      if (y > extreme + band) falling = false, lows.push_back(extreme_at), extreme = y;
    } else {
      extreme = std::max(extreme, y);
      if (y < extreme - band) falling = true, extreme = y, extreme_at = i;
    }
  }
  nod.lows_per_stride = per_stride(lows, t.frequency);
  return nod;
}

// The head's forward speed against the body's: the share of ticks it stands still (under a
// tenth of the body's speed), how many such holds per stride, and its fastest.
struct Bob {
  float still_share = 0.0f, holds_per_stride = 0.0f, fastest = 0.0f, slowest = 0.0f;
};

Bob bob_of(const HeadTrack& t) {
  const size_t n = t.head_x.size() - 1;
  const float body = (t.root_x.back() - t.root_x.front()) / (static_cast<float>(n) * kDt);
  Bob bob;
  bob.slowest = 1e9f;
  int still = 0;
  std::vector<size_t> holds;
  bool holding = false;
  for (size_t i = 0; i < n; ++i) {
    const float v = (t.head_x[i + 1] - t.head_x[i]) / kDt / body;
    bob.fastest = std::max(bob.fastest, v);
    bob.slowest = std::min(bob.slowest, v);
    const bool s = std::fabs(v) < 0.1f;
    still += s;
    if (s && !holding) holds.push_back(i);
    holding = s;
  }
  bob.still_share = static_cast<float>(still) / static_cast<float>(n);
  bob.holds_per_stride = per_stride(holds, t.frequency);
  return bob;
}

Controls walk(float stick) {
  Controls c;
  c.move_x = stick;
  return c;
}

Controls run(float stick) {
  Controls c = walk(stick);
  c.run = true;
  return c;
}

}  // namespace

TEST_CASE("head motion: ungulates and elephants nod twice per stride in the walk, less in the trot", "[game][gait]") {
  for (const char* name : {"horse", "red deer", "giraffe", "dromedary", "african elephant"}) {
    const Nod w = nod_of(track(name, walk(0.4f)));
    INFO(name << ": walk nod " << w.range << " of the hip height, " << w.lows_per_stride << " lows per stride");
    CHECK(w.range > 0.03f);
    CHECK(w.range < 0.10f);
    CHECK(w.lows_per_stride == Approx(2.0f).margin(0.25f));
  }
  const Nod walk_nod = nod_of(track("horse", walk(0.4f)));
  const Nod trot_nod = nod_of(track("horse", run(0.6f)));
  INFO("horse: walk nod " << walk_nod.range << ", trot " << trot_nod.range);
  CHECK(trot_nod.range < 0.5f * walk_nod.range);
}

TEST_CASE("head motion: small birds hold the head still and thrust it, twice per stride, in the walk only", "[game][gait]") {
  for (const char* name : {"pigeon", "magpie"}) {
    const Bob w = bob_of(track(name, walk(0.4f)));
    INFO(name << ": still " << w.still_share << " of the walk, " << w.holds_per_stride << " holds per stride, fastest "
              << w.fastest << " of the body's speed");
    CHECK(w.still_share > 0.15f);
    CHECK(w.holds_per_stride == Approx(2.0f).margin(0.25f));
    CHECK(w.fastest > 2.0f);
    // The head keeps its height meanwhile (it moves back and forth, not up and down).
    CHECK(nod_of(track(name, walk(0.4f))).range < 0.04f);
    const Bob r = bob_of(track(name, run(1.0f)));
    INFO(name << ": run: slowest " << r.slowest << ", fastest " << r.fastest << " of the body's speed");
    CHECK(r.still_share == 0.0f);
    CHECK(r.slowest > 0.5f);
  }
  // A large bird walks with its head carried along.
  const Bob ostrich = bob_of(track("ostrich", walk(0.4f)));
  INFO("ostrich: slowest " << ostrich.slowest << ", fastest " << ostrich.fastest);
  CHECK(ostrich.slowest > 0.8f);
  CHECK(ostrich.fastest < 1.2f);
}
