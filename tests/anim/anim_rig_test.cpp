// AnimRig (anim_rig.h): what build_anim_rig makes of creatures of every body plan.

#include "ossa/anim/anim_rig.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "ossa/anim/animator.h"
#include "ossa/anim/leg_geometry.h"
#include "ossa/body/body_floor.h"
#include "ossa/body/body_mesh.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
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

TEST_CASE("anim rig: a limb's flesh outline, posed by the animator, lies on the drawn body's outline", "[anim][rig]") {
  // The leg and arm outlines every clearance keeps off the level (RigLeg::flesh_outline,
  // RigLimb::flesh_outline) are skinned as the body draws them: the knee's and ankle's mid
  // joints, a hoof's or toes' level frame. Posed with the animator's bones, each point lies on
  // a vertex of the drawn outline (body_mesh.h skin_body_vertex) — but for the weight a point
  // near the girdle puts on the girdle's frames, which the limb's outline leaves out. Every
  // example and eight random creatures, walking and running both ways over a random level.
  const Generator& gen = scenes::generator();
  std::vector<Creature> creatures;
  for (const Animal& animal : gen.dataset().animals) creatures.push_back(build_creature(gen.example(animal.name).value()).value());
  for (uint64_t seed = 1; seed <= 8; ++seed) creatures.push_back(build_creature(gen.random(seed * 31)).value());
  const Level level = scenes::random_level(5, 40, {2.0f, 3.0f, 0.2f, 2.0f});
  size_t points = 0, on_outline = 0;
  for (const Creature& c : creatures) {
    const auto rig = build_anim_rig(c);
    Result<BodyMesh> body = try_build_body(c);
    if (!body) continue;
    std::vector<Mat2x3> palette(static_cast<size_t>(body->palette_size()));
    Animator a(c, rig, SplinePrototypes::defaults());
    a.reset({0.0f, 6.0f}, level, 1);
    for (int t = 0; t < 360; ++t) {
      a.update(1.0f / 120.0f, t < 240 ? 2.0f * a.walk_speed() : -a.walk_speed(), level);
      if (t % 30 != 29) continue;
      const std::vector<Mat2x3>& world = a.world_matrices();
      body_palette(*body, world, palette, flat_floor(-1e9f));
      std::vector<glm::vec2> drawn;
      for (const BodyPart& part : body->parts) {
        for (uint32_t i : part.outline) drawn.push_back(skin_body_vertex(body->vertices[i], palette));
      }
      auto check = [&](const std::array<int, 3>& bones, const std::vector<LimbFleshPoint>& outline, const std::vector<MidJoint>& mids) {
        Mat2x3 frames[kLimbSkinFrames] = {world[bones[0]], world[bones[1]], world[bones[2]]};
        anim::limb_skin_frames(mids, frames);
        for (const LimbFleshPoint& q : outline) {
          const glm::vec2 p = anim::posed_flesh(q, frames);
          float nearest = 1e30f;
          for (glm::vec2 d : drawn) nearest = std::min(nearest, glm::length(d - p));
          ++points;
          on_outline += nearest < 1e-4f * (1.0f + rig->hip_height) ? 1 : 0;
          // Off the outline only by the girdle's share: within the limb's reach of it.
          INFO(c.name << " t " << t);
          REQUIRE(nearest < 0.25f * rig->hip_height);
        }
      };
      for (const RigLeg& leg : rig->legs) check(leg.bones, leg.flesh_outline, leg.flesh_mids);
      for (const RigLimb& arm : rig->arms) check(arm.bones, arm.flesh_outline, arm.flesh_mids);
    }
  }
  INFO(on_outline << " of " << points << " points on the drawn outline");
  CHECK(points > 10000);
  CHECK(on_outline >= points * 95 / 100);
}
