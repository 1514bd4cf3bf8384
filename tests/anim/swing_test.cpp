#include "ossa/anim/swing.h"

#include <catch2/catch.hpp>

#include <algorithm>

#include "ossa/anim/spline_prototypes.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/scenes.h"
#include "stage_scene.h"

using namespace ossa;

namespace {

SplinePrototypes shipped_prototypes() {
  auto loaded = load_prototypes(scenes::source_path("assets/animation/prototypes.json"));
  REQUIRE(loaded);
  return *loaded;
}

// Does the foot (ankle to toe, as the leg holds it) at swing progress s cut a box?
bool foot_hits(const test::StageScene& s, int leg, const anim::FootState& f, float t) {
  const RigLeg& info = s.rig->legs[leg];
  const glm::vec2 p = anim::swing_point(f, t);
  const glm::vec2 ankle = p + glm::vec2(s.body.facing * info.ankle_rel_ms.x, info.ankle_rel_ms.y);
  const glm::vec2 tip = p + glm::vec2(s.body.facing * info.tip_rel_ms.x, info.tip_rel_ms.y);
  const glm::vec2 lo = glm::min(glm::min(p, ankle), tip) + glm::vec2(1e-3f), hi = glm::max(glm::max(p, ankle), tip) - glm::vec2(0.0f, 1e-3f);
  return s.level.overlaps(Box{{lo.x, lo.y}, {std::max(hi.x, lo.x + 1e-4f), std::max(hi.y, lo.y + 1e-4f)}});
}

}  // namespace

TEST_CASE("swing: a step onto and off a step clears its riser all the way", "[anim][swing]") {
  const SplinePrototypes prototypes = shipped_prototypes();
  for (const Creature& c : {scenes::quadruped(), scenes::biped(), scenes::three_leg_pairs()}) {
    for (int facing : {1, -1}) {
      for (float rise : {0.05f, 0.15f, -0.15f}) {
        const float edge = facing > 0 ? 5.0f : -5.0f;
        std::vector<Box> boxes{Box::from_corner(-40.0f, -1.0f, 80.0f, 1.0f)};
        // The step rises (or falls) ahead of the creature.
        if (facing > 0) boxes.push_back(Box{{edge, -1.0f}, {40.0f, std::max(rise, -0.5f)}});
        else boxes.push_back(Box{{-40.0f, -1.0f}, {edge, std::max(rise, -0.5f)}});
        if (rise < 0.0f) boxes = {Box{{-40.0f, -1.0f}, {40.0f, rise}},
                                  facing > 0 ? Box{{-40.0f, -1.0f}, {edge, 0.0f}} : Box{{edge, -1.0f}, {40.0f, 0.0f}}};
        const Level level(boxes, {});
        test::StageScene s(c, level, edge - facing * 0.5f, facing);
        const anim::AnimContext& ctx = s.ctx;
        for (size_t i = 0; i < s.rig->legs.size(); ++i) {
          const int leg = static_cast<int>(i);
          // From where the whole foot stands before the edge to where it stands beyond it.
          const RigLeg& info = s.rig->legs[i];
          const float ahead = std::max({0.0f, info.tip_rel_ms.x, info.ankle_rel_ms.x}) + 0.05f;
          const float behind = -std::min({0.0f, info.tip_rel_ms.x, info.ankle_rel_ms.x}) + 0.05f;
          anim::FootState f;
          f.pos_ws = {edge - facing * ahead, 0.0f};
          const glm::vec2 to{edge + facing * behind, rise};
          REQUIRE(anim::foot_fits(s.inputs(), leg, f.pos_ws));
          REQUIRE(anim::foot_fits(s.inputs(), leg, to));
          const anim::SwingShape shape = anim::step_shape(prototypes, 0.0f, s.rig->legs[i].reach, 2.0f, false);
          INFO(c.name << " facing " << facing << " rise " << rise << " leg " << leg);
          REQUIRE(anim::begin_swing(ctx, s.body, leg, f, to, shape));
          CHECK(f.state == LegState::kSwing);
          CHECK(anim::swing_point(f, 0.0f) == f.from_ws);
          CHECK(anim::swing_point(f, 1.0f).x == Approx(to.x).margin(1e-4));
          CHECK(anim::swing_point(f, 1.0f).y == Approx(to.y).margin(1e-4));
          for (int k = 1; k < 200; ++k) {
            const float t = static_cast<float>(k) / 200.0f;
            INFO("s = " << t);
            CHECK_FALSE(foot_hits(s, leg, f, t));
          }
        }
      }
    }
  }
}

TEST_CASE("swing: a path through a wall is refused, an eased step stays on the ground", "[anim][swing]") {
  // The horse in the 2 m frame, its body at x 4.3 behind the wall at x 5 (at its true size its
  // head would be in the wall).
  const test::StageScene s(scenes::example_in_frame("horse"),
                           Level({Box::from_corner(-40.0f, -1.0f, 80.0f, 1.0f), Box::from_corner(5.0f, -1.0f, 0.2f, 20.0f)}, {}), 4.3f);
  anim::FootState f;
  f.pos_ws = {4.8f, 0.0f};
  const SplinePrototypes prototypes = shipped_prototypes();
  CHECK_FALSE(anim::begin_swing(s.ctx, s.body, 0, f, {5.5f, 0.0f}, anim::step_shape(prototypes, 0.0f, s.rig->legs[0].reach, 2.0f, false)));
  anim::FootState e;
  e.pos_ws = {4.0f, 0.0f};
  REQUIRE(anim::begin_swing(s.ctx, s.body, 0, e, {4.2f, 0.0f}, anim::ease_shape(0.18f)));
  CHECK(e.easing);
  CHECK(e.rate == Approx(1.0f / 0.18f));
  for (int k = 0; k <= 10; ++k) CHECK(anim::swing_point(e, k / 10.0f).y == Approx(0.0f).margin(1e-6));
}

TEST_CASE("swing: a landing beyond the leg's reach across gives way to a place the leg reaches", "[anim][swing]") {
  // The horse in the 2 m frame standing on flat ground; a foreleg at the end of its swing, its
  // landing 1.2 reaches ahead of its joint (the body was held back meanwhile). Touching down
  // there, out of reach, body placement's reach clamp would pull the girdle down to it within
  // the tick (a parasaurolophus dropped 13 cm, a rib 3 cm into the ground). It eases instead to
  // a place below the joint that the leg reaches.
  for (int facing : {1, -1}) {
    const Level flat({Box::from_corner(-40.0f, -1.0f, 80.0f, 1.0f)}, {});
    const test::StageScene s(scenes::example_in_frame("horse"), flat, 0.0f, facing);
    const int leg = s.rig->girdles[0].legs[0];
    const RigLeg& info = s.rig->legs[leg];
    const glm::vec2 joint = s.body.girdle_ws(*s.rig, info.girdle);
    anim::FootState f;
    f.state = LegState::kSwing;
    f.from_ws = {joint.x, 0.0f};
    f.to_ws = f.pos_ws = {joint.x + facing * 1.2f * info.contact_reach, 0.0f};
    f.progress = 1.0f;
    f.rate = 1.0f;
    anim::update_swing_clearance(s.ctx, leg, f);
    INFO("facing " << facing);
    CHECK_FALSE(anim::advance_swing(s.inputs(), anim::SwingTick{1.0f / 120.0f, 1.0f, true}, leg, f));
    CHECK(f.state == LegState::kSwing);
    CHECK(f.easing);
    CHECK(anim::reaches(s.inputs(), leg, f.to_ws));
  }
}

TEST_CASE("swing: a foot's drawn flesh clears a riser on the way up and down", "[anim][swing]") {
  // The horse at its true size steps onto and off a step from a place where its hoof's flesh
  // (anim_rig.h RigLeg::flesh_front, flesh_back) clears the level to one where it does: the
  // swing is raised until the flesh, not only the bones, passes over the step's corner.
  const SplinePrototypes prototypes = shipped_prototypes();
  const Creature horse = build_creature(scenes::generator().example("horse").value()).value();
  for (int facing : {1, -1}) {
    for (float rise : {0.15f, -0.15f}) {
      const float edge = facing > 0 ? 5.0f : -5.0f;
      std::vector<Box> boxes{Box::from_corner(-40.0f, -1.0f, 80.0f, 1.0f)};
      if (facing > 0) boxes.push_back(Box{{edge, -1.0f}, {40.0f, std::max(rise, -0.5f)}});
      else boxes.push_back(Box{{-40.0f, -1.0f}, {edge, std::max(rise, -0.5f)}});
      if (rise < 0.0f) boxes = {Box{{-40.0f, -1.0f}, {40.0f, rise}},
                                facing > 0 ? Box{{-40.0f, -1.0f}, {edge, 0.0f}} : Box{{edge, -1.0f}, {40.0f, 0.0f}}};
      const Level level(boxes, {});
      test::StageScene s(horse, level, edge - facing * 1.0f, facing);
      for (size_t i = 0; i < s.rig->legs.size(); ++i) {
        const int leg = static_cast<int>(i);
        const RigLeg& info = s.rig->legs[i];
        const anim::FootSpan bones = anim::foot_span_ws(info, facing), flesh = anim::flesh_span_ws(info, facing);
        REQUIRE(flesh.hi - flesh.lo > bones.hi - bones.lo);
        // Where the whole foot and its flesh stand before the edge, to where they stand beyond it.
        const float ahead = (facing > 0 ? flesh.hi : -flesh.lo) + 0.02f, behind = (facing > 0 ? -flesh.lo : flesh.hi) + 0.02f;
        anim::FootState f;
        f.pos_ws = {edge - facing * ahead, 0.0f};
        const glm::vec2 to{edge + facing * behind, rise};
        REQUIRE(anim::foot_fits(s.inputs(), leg, f.pos_ws, true));
        REQUIRE(anim::foot_fits(s.inputs(), leg, to, true));
        INFO("facing " << facing << " rise " << rise << " leg " << leg);
        REQUIRE(anim::begin_swing(s.ctx, s.body, leg, f, to, anim::step_shape(prototypes, 0.0f, info.reach, 2.0f, false)));
        for (int k = 1; k < 200; ++k) {
          const float t = static_cast<float>(k) / 200.0f;
          const glm::vec2 p = anim::swing_point(f, t);
          const glm::vec2 ankle = p + glm::vec2(facing * info.ankle_rel_ms.x, info.ankle_rel_ms.y);
          const glm::vec2 tip = p + glm::vec2(facing * info.tip_rel_ms.x, info.tip_rel_ms.y);
          const float lo_y = std::min({p.y, ankle.y, tip.y}), hi_y = std::max({p.y, ankle.y, tip.y, lo_y + 1e-3f});
          INFO("s = " << t);
          CHECK_FALSE(s.level.overlaps(Box{{p.x + flesh.lo + 1e-3f, lo_y + 1e-3f}, {p.x + flesh.hi - 1e-3f, hi_y}}));
        }
      }
    }
  }
}
