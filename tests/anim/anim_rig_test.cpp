// AnimRig (anim_rig.h): what build_anim_rig makes of creatures of every body plan.

#include "ossa/anim/anim_rig.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "ossa/gen/skeleton_builder.h"
#include "shared/scenes.h"

using namespace ossa;

TEST_CASE("anim rig: legs, girdles front to back, reaches and heights of every example", "[anim][rig]") {
  const Generator& gen = scenes::generator();
  int legged = 0;
  for (const Animal& animal : gen.dataset().animals) {
    INFO(animal.name);
    const Creature c = build_creature(gen.example(animal.name).value()).value();
    const auto rig = build_anim_rig(c);
    int legs = 0;
    for (const Limb& l : c.limbs) legs += l.kind == LimbKind::kLeg ? 1 : 0;
    REQUIRE(static_cast<int>(rig->legs.size()) == legs);
    if (rig->legs.empty()) {
      CHECK(rig->girdles.empty());
      CHECK_FALSE(rig->drape_bones.empty());
      continue;
    }
    ++legged;
    float mean = 0.0f;
    for (size_t g = 0; g < rig->girdles.size(); ++g) {
      const RigGirdle& girdle = rig->girdles[g];
      if (g > 0) CHECK(girdle.joint_ms.x < rig->girdles[g - 1].joint_ms.x);  // front first
      CHECK(girdle.rest_height > 0.0f);
      CHECK(girdle.rest_height == Approx(girdle.joint_ms.y));
      for (int leg : girdle.legs) CHECK(rig->legs[leg].girdle == static_cast<int>(g));
      mean += girdle.rest_height;
    }
    CHECK(rig->hip_height == Approx(mean / static_cast<float>(rig->girdles.size())));
    for (const RigLeg& leg : rig->legs) {
      CHECK(leg.reach == Approx(leg.upper + leg.lower));
      CHECK(leg.leg_reach == Approx(kReachLimit * leg.reach));
      CHECK(leg.contact_reach >= leg.leg_reach - 1e-5f);  // a rolled foot adds to the reach
      CHECK((leg.bend == 1.0f || leg.bend == -1.0f));
      // The knee's side: ahead of the joint for a knee bending forward, behind for one bending back.
      const float h = 0.7f * leg.reach;
      const float ahead = knee_ahead(leg, h);
      CHECK(std::isfinite(ahead));
      CHECK(std::fabs(ahead) <= leg.upper + 1e-5f);
    }
    // Every bone the stages read each tick is kept current.
    for (int b : rig->needed_bones) CHECK(rig->tick_bone[b]);
    for (const RigLeg& leg : rig->legs) {
      for (int b : leg.bones) CHECK(rig->tick_bone[b]);
    }
  }
  CHECK(legged > 30);
}

TEST_CASE("anim rig: a girdle knows how far its knees reach ahead of it", "[anim][rig]") {
  // RigGirdle::knee_reach (the ledge rule's look-ahead): the thigh's length for a girdle with a
  // knee that bends forward, 0 for knees that bend back; knee_ahead agrees.
  const Generator& gen = scenes::generator();
  for (const char* name : {"horse", "kangaroo", "ostrich", "african elephant", "frog", "crocodile"}) {
    INFO(name);
    const auto rig = build_anim_rig(build_creature(gen.example(name).value()).value());
    for (const RigGirdle& g : rig->girdles) {
      float most = 0.0f;
      for (int leg : g.legs) {
        for (float h : {0.5f, 0.7f, 0.9f}) most = std::max(most, knee_ahead(rig->legs[leg], h * rig->legs[leg].reach));
      }
      if (most > 1e-4f) CHECK(g.knee_reach > 0.0f);
      CHECK(most <= g.knee_reach + 1e-4f);
    }
  }
}

TEST_CASE("anim rig: three leg pairs make three girdles, the legless none", "[anim][rig]") {
  const auto six = build_anim_rig(scenes::three_leg_pairs());
  CHECK(six->girdles.size() == 3);
  CHECK(six->legs.size() == 6);
  CHECK(six->climb_height <= six->girdles.front().step_height);
}
