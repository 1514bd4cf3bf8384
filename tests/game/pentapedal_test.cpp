// Issue 28, the hopper family: slowly, the kangaroo walks on five supports (Dawson & Taylor
// 1973). Its hind feet move together; while they swing, the hands and the tail's tip stand on
// the ground and hold still there; faster, it hops upright with its hands off the ground.
// Measured from the bones' world matrices tick by tick on flat ground (not from the
// animator's own hand places).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "ossa/anim/gait_family.h"
#include "ossa/game/player.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

constexpr float kDt = 1.0f / 120.0f;
constexpr float kDown = 0.005f;  // a hand or tail tip this close to the ground stands on it

struct Walk {
  Gait gait = Gait::kIdle;
  int ticks = 0, hands_down = 0, hind_swing = 0, supported = 0, hind_apart = 0;
  float hand_slide = 0.0f;     // the most a standing wrist moved since it came down, metres
  float lowest = 1e30f;        // the lowest bone end over the ground, metres
  float highest_hand = -1e30f; // the lowest wrist's most over the ground, metres
};

Walk walk(float stick, bool run) {
  const Level flat = scenes::flat_level(400.0f);
  auto creature = std::make_shared<const Creature>(build_creature(scenes::generator().example("kangaroo").value()).value());
  Player player(creature, SplinePrototypes::defaults());
  player.animator().reset({2.0f, 1.0f}, flat);
  const Animator& a = player.animator();
  const AnimRig& rig = a.rig();
  REQUIRE(rig.arms.size() == 2);
  REQUIRE(rig.legs.size() == 2);
  const int tip = rig.tail.back();
  Controls controls;
  controls.move_x = stick;
  controls.run = run;
  Walk w;
  std::vector<float> planted(rig.arms.size(), NAN);
  for (int i = 0; i < 720; ++i) {
    player.step(kDt, controls, flat);
    if (i < 360) continue;  // (the body goes down onto its hands over the first second)
    ++w.ticks;
    const std::vector<Mat2x3>& world = a.world_matrices();
    for (int b = 0; b < rig.skeleton.bone_count(); ++b) {
      w.lowest = std::min({w.lowest, bone_start(world[b]).y, bone_end(world[b], rig.skeleton.length(b)).y});
    }
    bool hands = true;
    float low_hand = 1e30f;
    for (size_t k = 0; k < rig.arms.size(); ++k) {
      const glm::vec2 wrist = bone_start(world[rig.arms[k].bones[2]]);
      low_hand = std::min(low_hand, wrist.y);
      if (wrist.y > kDown) {
        hands = false;
        planted[k] = NAN;
        continue;
      }
      if (std::isnan(planted[k])) planted[k] = wrist.x;
      w.hand_slide = std::max(w.hand_slide, std::fabs(wrist.x - planted[k]));
    }
    w.highest_hand = std::max(w.highest_hand, low_hand);
    w.hands_down += hands;
    const bool near_swings = a.leg_state(0) == LegState::kSwing, far_swings = a.leg_state(1) == LegState::kSwing;
    w.hind_apart += near_swings != far_swings;
    if (near_swings && far_swings) {
      ++w.hind_swing;
      const float tail = bone_end(world[tip], rig.skeleton.length(tip)).y;
      w.supported += hands && tail <= kDown;
    }
  }
  w.gait = a.gait();
  return w;
}

}  // namespace

TEST_CASE("the kangaroo walks slowly on its hands, tail and hind feet, and hops upright", "[game][anim][gait]") {
  SECTION("slow: five supports") {
    const Walk w = walk(0.3f, false);
    INFO(gait_name(w.gait) << ": hands down " << w.hands_down << " of " << w.ticks << " ticks, hind feet swinging " << w.hind_swing
                           << " (held by hands and tail " << w.supported << "), hind feet apart " << w.hind_apart
                           << ", hand slide " << w.hand_slide << " m, lowest bone " << w.lowest << " m");
    CHECK(w.gait == Gait::kPentapedal);
    CHECK(w.hind_swing > w.ticks / 5);            // the hind feet swing forward together
    CHECK(w.hind_apart == 0);                     // in phase
    CHECK(w.supported == w.hind_swing);           // while they do, hands and tail hold the body
    CHECK(w.hands_down > w.hind_swing);           // the hands stand longer (all five down a moment)
    CHECK(w.hands_down < w.ticks);                // and swing forward while the hind feet stand
    CHECK(w.hand_slide <= 0.001f);                // a standing hand stays where it came down
    CHECK(w.lowest >= -0.001f);                   // no bone in the ground
  }
  SECTION("fast: the hop, upright") {
    const Walk w = walk(1.0f, true);
    INFO(gait_name(w.gait) << ": the lowest wrist at most " << w.highest_hand << " m over the ground, hands down " << w.hands_down);
    CHECK(w.gait == Gait::kHop);
    CHECK(w.hands_down == 0);
    CHECK(w.hind_apart == 0);
  }
}
