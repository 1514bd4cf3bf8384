#include "ossa/anim/leg_ik.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/gen/skeleton_builder.h"
#include "ossa/math/rng.h"
#include "ossa/math/two_bone_ik.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "stage_scene.h"

using namespace ossa;

TEST_CASE("leg IK: a reachable foot keeps its rest angle, a far or a folded one rolls until the leg reaches", "[anim][ik]") {
  const test::StageScene s(scenes::quadruped(), scenes::flat_level(40.0f), 10.0f);
  const AnimRig& rig = *s.rig;
  const anim::Clearance open;  // knows nothing: the level is asked
  Rng rng(3);
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const RigLeg& leg = rig.legs[i];
    REQUIRE(leg.foot_span > 0.0f);  // the horse stands on hoof tips
    for (int k = 0; k < 200; ++k) {
      const glm::vec2 joint(0.0f, rig.girdles[leg.girdle].rest_height);
      const float angle = rng.uniform(-2.6f, -0.5f);
      const float dist = rng.uniform(0.3f, 1.0f) * leg.contact_reach;
      const glm::vec2 contact = joint + dist * glm::vec2(std::cos(angle), std::sin(angle));
      glm::vec2 dir;
      const glm::vec2 ankle = anim::leg_ankle(s.ctx, s.body, static_cast<int>(i), contact, joint, false, open, &dir, nullptr);
      // The foot bone keeps its length and ends at the contact point.
      CHECK(glm::length(contact - ankle) == Approx(leg.foot_span).epsilon(1e-4));
      CHECK(glm::length(dir) == Approx(1.0f).epsilon(1e-4));
      const float standing = glm::length(contact + (-leg.foot_span) * leg.foot_dir_ms - joint);
      if (standing <= leg.leg_reach && standing >= leg.least_reach) {
        CHECK(dir == leg.foot_dir_ms);  // in reach as it stands: no roll
      } else {  // rolled just enough: no further than the leg reaches, no closer than it folds
        CHECK(glm::length(ankle - joint) <= leg.leg_reach * 1.0001f);
        CHECK(glm::length(ankle - joint) >= leg.least_reach * 0.9999f);
      }
    }
  }
}

TEST_CASE("leg IK: a leg with a bone of length 0 rolls its foot so the toe still stands where it stands", "[anim][ik]") {
  // Random creature 22's thighs have length 0 (a draw the genome limits allow): the leg
  // reaches its shin's length and no other, so the foot's roll alone brings the toe to its
  // contact. Before, the stance ankle was planned at 0.985 of the reach, which the chain cannot
  // make: the toe went 3.7 mm into the ground at every stance.
  const Creature c = build_creature(scenes::generator().random(22)).value();
  const test::StageScene s(c, scenes::flat_level(40.0f), 10.0f);
  const AnimRig& rig = *s.rig;
  const anim::Clearance open;
  Rng rng(5);
  int vanishing = 0;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const RigLeg& leg = rig.legs[i];
    if (std::min(leg.upper, leg.lower) > 0.0f) continue;
    ++vanishing;
    REQUIRE(leg.foot_span > 0.0f);
    CHECK(leg.least_reach == Approx(leg.reach));
    CHECK(leg.leg_reach == Approx(leg.reach));  // not 0.985 of it: the chain reaches only that
    CHECK(leg.fold <= leg.leg_reach);
    for (int k = 0; k < 200; ++k) {
      const glm::vec2 joint(0.0f, rig.girdles[leg.girdle].rest_height);
      const float angle = rng.uniform(-2.6f, -0.5f);
      // Any contact the leg and foot reach: from |reach - foot| to reach + foot.
      const float lo = std::fabs(leg.reach - leg.foot_span), hi = leg.reach + leg.foot_span;
      const glm::vec2 contact = joint + static_cast<float>(rng.uniform(lo + 0.01f * hi, 0.99f * hi)) * glm::vec2(std::cos(angle), std::sin(angle));
      glm::vec2 dir;
      const glm::vec2 ankle = anim::leg_ankle(s.ctx, s.body, static_cast<int>(i), contact, joint, false, open, &dir, nullptr);
      CHECK(glm::length(contact - ankle) == Approx(leg.foot_span).epsilon(1e-4));
      CHECK(glm::length(ankle - joint) == Approx(leg.reach).epsilon(1e-3));  // where the chain ends
      const TwoBoneIkResult ik = solve_two_bone_ik_directions(joint, leg.upper, leg.lower, ankle, leg.bend);
      CHECK(glm::length(ik.end + leg.foot_span * dir - contact) < 1e-3f * leg.reach);
    }
  }
  CHECK(vanishing > 0);
}

TEST_CASE("leg IK job: every stance foot is reached, knees bend their way, both facings", "[anim][ik]") {
  for (const Creature& c : {scenes::quadruped(), scenes::biped(), scenes::three_leg_pairs()}) {
    for (int facing : {1, -1}) {
      const test::StageScene s(c, scenes::flat_level(40.0f), 10.0f, facing);
      const AnimRig& rig = *s.rig;
      std::vector<Mat2x3> model = rig.model_rest;
      Pose pose = rig.rest_pose;
      // The body where the scene stands it (root at its standing height, level).
      pose.locals[rig.root].offset_ls = {0.0f, s.body.root_y_ws};
      const std::vector<Mat2x3> placed = model_matrices(rig.skeleton, pose.locals);
      model = placed;
      anim::FootSet feet;
      feet.feet.resize(rig.legs.size());
      for (size_t i = 0; i < rig.legs.size(); ++i) {
        feet.foot_of_leg.push_back(static_cast<int>(i));
        const glm::vec2 joint = s.body.to_ws(bone_start(placed[rig.legs[i].bones[0]]));
        feet.feet[i].pos_ws = {joint.x + facing * 0.2f * rig.legs[i].reach, 0.0f};
      }
      std::vector<std::array<glm::vec2, 3>> dirs(rig.legs.size());
      anim::LegIkJob job{&s.ctx, &s.body, &feet, &pose, &model, &dirs};
      REQUIRE(job.validate());
      REQUIRE(job.run());
      for (size_t i = 0; i < rig.legs.size(); ++i) {
        const RigLeg& leg = rig.legs[i];
        const int b = leg.contact_bone;
        const glm::vec2 reached = s.body.to_ws(bone_end(model[b], rig.skeleton.length(b)));
        INFO(c.name << " facing " << facing << " leg " << i);
        CHECK(glm::length(reached - feet.feet[i].pos_ws) < 1e-3f);
        // The knee bends to the chain's side in facing space (mirrored in the world).
        const glm::vec2 hip = bone_start(model[leg.bones[0]]), knee = bone_start(model[leg.bones[1]]),
                        ankle = bone_start(model[leg.bones[2]]);
        const float side = (knee.x - hip.x) * (ankle.y - hip.y) - (knee.y - hip.y) * (ankle.x - hip.x);
        CHECK(side * leg.bend <= 1e-6f);
      }
      anim::LegIkJob incomplete = job;
      incomplete.feet = nullptr;
      CHECK_FALSE(incomplete.validate());
      CHECK_FALSE(incomplete.run());
    }
  }
}

TEST_CASE("coupled legs: the tip is reached, a standing foreleg is straight, no hock bends past straight, and no jumps", "[anim][ik]") {
  // solve_coupled_leg on the horse's legs, over random tips within reach and folds: the chain
  // ends on the tip, its bones keep their lengths, a foreleg's foot lies in line with its
  // forearm when unfolded, a hind foot never turns past straight from its shin; and a tip that
  // moves a millimetre moves no joint by more than a few (the switch to a straight hock and the
  // reach-limited fold are continuous).
  const test::StageScene s(scenes::quadruped(), scenes::flat_level(40.0f), 10.0f);
  const AnimRig& rig = *s.rig;
  Rng rng(11);
  auto cross = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
  for (const RigLeg& leg : rig.legs) {
    REQUIRE(leg.coupled);
    const glm::vec2 joint(0.0f, rig.girdles[leg.girdle].rest_height);
    const float full = leg.upper + leg.lower + leg.foot_span;
    int solved = 0;
    for (int k = 0; k < 400; ++k) {
      const float angle = rng.uniform(-2.4f, -0.7f);
      const float dist = rng.uniform(0.45f, 0.99f) * full;
      const glm::vec2 tip = joint + dist * glm::vec2(std::cos(angle), std::sin(angle));
      const float fold = k % 2 == 0 ? 0.0f : rng.uniform(0.0f, leg.swing_fold);
      TwoBoneIkResult ik;
      glm::vec2 foot;
      if (!anim::solve_coupled_leg(leg, joint, tip, fold, &ik, &foot)) continue;
      ++solved;
      INFO((leg.hind ? "hind" : "fore") << " tip at " << dist / full << " of the leg, fold " << fold);
      CHECK(glm::length(ik.end + leg.foot_span * foot - tip) <= 1e-4f * full);
      CHECK(glm::length(ik.middle - joint) == Approx(leg.upper).epsilon(1e-4));
      CHECK(glm::length(ik.end - ik.middle) == Approx(leg.lower).epsilon(1e-4));
      if (!leg.hind && fold == 0.0f) CHECK(glm::length(foot - ik.lower_dir) <= 1e-4f);
      if (leg.hind) CHECK(leg.fold_sign * cross(ik.lower_dir, foot) >= -1e-4f);
      // A millimetre further: no joint jumps.
      const glm::vec2 step = 0.001f * glm::normalize(tip - joint);
      TwoBoneIkResult next;
      glm::vec2 next_foot;
      if (anim::solve_coupled_leg(leg, joint, tip + step, fold, &next, &next_foot)) {
        CHECK(glm::length(next.middle - ik.middle) <= 0.02f * full);
        CHECK(glm::length(next.end - ik.end) <= 0.02f * full);
      }
    }
    CHECK(solved > 300);
  }
}

TEST_CASE("leg flesh: the drawn leg posed with its bones meets a box its bones clear, and a swing clears it", "[anim][ik]") {
  // The horse standing at rest beside a thin ledge that reaches in front of a shin's bone but
  // not to it: the bones clear it, the flesh drawn about the shin does not. Moved ahead of the
  // flesh, or below top_over, it is not met. Both facings.
  const Creature horse = scenes::quadruped();
  int escaped = 0;  // swings whose planned pose met the ledge with its flesh
  for (int facing : {1, -1}) {
    const auto rig = build_anim_rig(horse);
    for (size_t i = 0; i < rig->legs.size(); ++i) {
      const RigLeg& leg = rig->legs[i];
      REQUIRE(leg.flesh_outline.size() >= 8);
      CHECK(leg.flesh_margin[0] > 0.0f);
      CHECK(leg.flesh_margin[1] > 0.0f);
      auto scene_with = [&](float x0_fs, float x1_fs, float y) {
        // The box from x0 to x1 in frame space, 1 cm tall about y; no ground (the scene stands
        // the body as over ground at 0, its feet a little in it: the rest pose, not a stance).
        const float a = 10.0f + facing * x0_fs, b = 10.0f + facing * x1_fs;
        return test::StageScene(horse, Level({Box{{std::min(a, b), y - 0.005f}, {std::max(a, b), y + 0.005f}}}, {}), 10.0f, facing);
      };
      // The rest pose where the scene stands the body (frame space: the root at x 0).
      const test::StageScene flat = scene_with(50.0f, 51.0f, 0.5f);
      Pose pose = rig->rest_pose;
      pose.locals[rig->root].offset_ls = {0.0f, flat.body.root_y_ws};
      const std::vector<Mat2x3> placed = model_matrices(rig->skeleton, pose.locals);
      auto dir_of = [&](int bone) { return glm::vec2(placed[bone].m[0], placed[bone].m[1]); };
      const glm::vec2 joint = bone_start(placed[leg.bones[0]]);
      TwoBoneIkResult ik;
      ik.upper_dir = dir_of(leg.bones[0]);
      ik.lower_dir = dir_of(leg.bones[1]);
      ik.middle = bone_start(placed[leg.bones[1]]);
      ik.end = bone_start(placed[leg.bones[2]]);
      const glm::vec2 foot_dir = dir_of(leg.bones[2]);
      // The shin's front-most flesh point about its middle, and where the shin's bone lies at
      // its height.
      glm::vec2 front(-1e30f);
      Mat2x3 frames[kLimbSkinFrames] = {placed[leg.bones[0]], placed[leg.bones[1]], placed[leg.bones[2]]};
      anim::limb_skin_frames(leg.flesh_mids, frames);
      for (const LimbFleshPoint& q : leg.flesh_outline) {
        if (q.count != 1 || q.frame[0] != 1 || std::fabs(q.local[0].x - 0.5f * leg.lower) > 0.25f * leg.lower) continue;
        const glm::vec2 p = anim::posed_flesh(q, frames);
        if (p.x > front.x) front = p;
      }
      INFO("facing " << facing << " leg " << i);
      REQUIRE(front.x > -1e29f);
      const float t = (ik.middle.y - front.y) / (ik.middle.y - ik.end.y);
      const float bone_x = glm::mix(ik.middle.x, ik.end.x, t);
      REQUIRE(front.x > bone_x + 0.004f);
      const test::StageScene in = scene_with(0.5f * (bone_x + front.x), front.x + 0.02f, front.y);
      const glm::vec2 tip = ik.end + leg.foot_length * foot_dir;
      const glm::vec2 bones[4] = {in.body.to_ws(joint), in.body.to_ws(ik.middle), in.body.to_ws(ik.end), in.body.to_ws(tip)};
      std::vector<int> hits;
      CHECK_FALSE(anim::polyline_hits_level(in.level, bones, 4, hits));
      CHECK(anim::leg_flesh_hits(in.ctx, in.body, leg, joint, ik, foot_dir));
      CHECK_FALSE(anim::leg_flesh_hits(in.ctx, in.body, leg, joint, ik, foot_dir, front.y + 0.01f));
      const test::StageScene ahead = scene_with(front.x + 0.003f, front.x + 0.02f, front.y);
      CHECK_FALSE(anim::leg_flesh_hits(ahead.ctx, ahead.body, leg, joint, ik, foot_dir));
      // Swinging there, the leg IK's escape moves the leg until its flesh clears the ledge too;
      // a rig without the leg's outline keeps the planned pose, whose bones clear it.
      auto swing_clears = [&](const AnimRig& r) {
        anim::AnimContext ctx{r, in.params, in.level, in.ground, hits};
        std::vector<Mat2x3> model = placed;
        Pose posed = pose;
        anim::FootSet feet;
        feet.feet.resize(r.legs.size());
        for (size_t j = 0; j < r.legs.size(); ++j) {
          feet.foot_of_leg.push_back(static_cast<int>(j));
          const int b = r.legs[j].contact_bone;
          feet.feet[j].pos_ws = in.body.to_ws(bone_end(placed[b], r.skeleton.length(b)));
        }
        feet.feet[i].state = LegState::kSwing;
        feet.feet[i].progress = 0.5f;
        std::vector<std::array<glm::vec2, 3>> dirs(r.legs.size());
        const anim::LegIkJob job{&ctx, &in.body, &feet, &posed, &model, &dirs};
        REQUIRE(job.run());
        TwoBoneIkResult out;
        out.upper_dir = dirs[i][0];
        out.lower_dir = dirs[i][1];
        out.middle = bone_start(model[leg.bones[1]]);
        out.end = bone_start(model[leg.bones[2]]);
        const glm::vec2 chain[4] = {in.body.to_ws(joint), in.body.to_ws(out.middle), in.body.to_ws(out.end),
                                    in.body.to_ws(out.end + leg.foot_length * dirs[i][2])};
        CHECK_FALSE(anim::polyline_hits_level(in.level, chain, 4, hits));
        return !anim::leg_flesh_hits(ctx, in.body, leg, joint, out, dirs[i][2]);
      };
      CHECK(swing_clears(*rig));
      AnimRig bare = *rig;
      bare.legs[i].flesh_outline.clear();
      if (!swing_clears(bare)) ++escaped;
    }
  }
  CHECK(escaped >= 4);  // the forelegs, both facings (a hind leg's swing folds its hock clear)
}
