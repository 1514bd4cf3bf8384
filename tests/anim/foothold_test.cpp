#include "ossa/anim/foothold.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "stage_scene.h"

using namespace ossa;

namespace {

// The landing of the leg whose foot stands at foot_x (on the ground) for a step to x_wanted.
bool landing_for(const test::StageScene& s, int leg, float foot_x, float x_wanted, glm::vec2* landing) {
  const auto ground = s.level.ground_height_below(foot_x - 0.01f, foot_x + 0.01f, 50.0f, 100.0f);
  return anim::find_landing(s.inputs(), leg, {foot_x, ground ? ground->height_ws : 0.0f}, x_wanted, landing);
}

}  // namespace

TEST_CASE("foothold planner: onto a riser the legs can climb, not across its edge", "[anim][foothold]") {
  for (int facing : {1, -1}) {
    const float rise = 0.1f;
    const Level level({Box::from_corner(-20.0f, -1.0f, 25.0f, 1.0f), Box::from_corner(5.0f, -1.0f, 20.0f, 1.0f + rise)},
                      {0.0f, 0.0f});
    // Mirror the scene for the creature facing -x: the step is behind x = 5, it comes from the right.
    const Level& lv = level;
    const float x = facing > 0 ? 4.4f : 5.6f;
    test::StageScene s(scenes::quadruped(), lv, x, facing);
    const AnimRig& rig = *s.rig;
    REQUIRE(rise < s.params.max_step_up * rig.climb_height);
    for (size_t leg = 0; leg < rig.legs.size(); ++leg) {
      // Aim right at the step's edge: the foot lands wholly on one side of it.
      glm::vec2 landing;
      const float foot_x = s.body.girdle_ws(rig, rig.legs[leg].girdle).x;
      REQUIRE(landing_for(s, static_cast<int>(leg), foot_x, 5.0f, &landing));
      CHECK(anim::foot_fits(s.inputs(), static_cast<int>(leg), landing));
      const auto ground = lv.ground_height_below(landing.x - 1e-3f, landing.x + 1e-3f, 50.0f, 100.0f);
      CHECK(landing.y == ground->height_ws);
    }
  }
}

TEST_CASE("foothold planner: a wall too tall or a drop too deep has no foothold", "[anim][foothold]") {
  const Creature horse = scenes::quadruped();
  const auto rig = build_anim_rig(horse);
  const AnimatorParams params;
  const float wall = 2.0f * params.max_step_up * rig->climb_height;
  test::StageScene up(horse, Level({Box::from_corner(-20.0f, -1.0f, 25.0f, 1.0f), Box::from_corner(5.0f, -1.0f, 5.0f, 1.0f + wall)}, {}),
                      4.0f);
  glm::vec2 landing;
  const int front = up.rig->girdles[0].legs[0];
  CHECK_FALSE(landing_for(up, front, 4.98f, 5.3f, &landing));
  const float drop = 2.0f * params.max_step_down * rig->girdles[0].rest_height;
  test::StageScene down(horse, Level({Box::from_corner(-20.0f, -1.0f, 25.0f, 1.0f), Box::from_corner(5.0f, -1.0f - drop, 20.0f, 1.0f)}, {}),
                        4.0f);
  CHECK_FALSE(landing_for(down, front, 4.98f, 5.3f, &landing));
}

TEST_CASE("foothold planner: a gap narrower than a stride is stepped over, a wider one is not", "[anim][foothold]") {
  const Creature horse = scenes::quadruped();
  for (int facing : {1, -1}) {
    auto gap_level = [&](float width) {
      const float a = facing > 0 ? 5.0f : -5.0f - width;
      const float b = facing > 0 ? 5.0f + width : -5.0f;
      return Level({Box::from_corner(-40.0f, -3.0f, a + 40.0f, 3.0f), Box::from_corner(b, -3.0f, 40.0f, 3.0f)}, {});
    };
    const float x = facing > 0 ? 4.0f : -4.0f;
    test::StageScene probe(horse, gap_level(0.1f), x, facing);
    const float stride = probe.gait.stride;
    const int front = probe.rig->girdles[0].legs[0];
    const float foot_x = x + facing * 0.6f;
    // Narrow: aimed into the gap, it lands just beyond (or just before) it, on the ground.
    {
      test::StageScene s(horse, gap_level(0.25f * stride), x, facing);
      glm::vec2 landing;
      const float edge = facing > 0 ? 5.0f : -5.0f;
      REQUIRE(landing_for(s, front, foot_x, edge + facing * 0.1f * stride, &landing));
      CHECK(landing.y == 0.0f);
      CHECK(anim::foot_fits(s.inputs(), front, landing));
    }
    // Wider than the search (a quarter stride past the wanted spot, and no ground short of it):
    // no landing.
    {
      test::StageScene s(horse, gap_level(3.0f * stride), x, facing);
      glm::vec2 landing;
      const float edge = facing > 0 ? 5.0f : -5.0f;
      CHECK_FALSE(landing_for(s, front, edge + facing * 0.01f, edge + facing * 1.5f * stride, &landing));
    }
  }
}

TEST_CASE("foothold planner: tile slopes up and down are walked like ramps", "[anim][foothold]") {
  // 18° (5 cm columns, 1.6 cm apart) and 30° (3.5 cm, 2 cm), up and down, both facings: every
  // leg finds a landing near where it aims, all along the slope.
  struct Slope {
    float width, rise;
  };
  for (const Creature& c : {scenes::quadruped(), scenes::biped(), scenes::three_leg_pairs()}) {
    for (Slope slope : {Slope{0.05f, 0.016f}, Slope{0.035f, 0.02f}, Slope{0.05f, -0.016f}, Slope{0.035f, -0.02f}}) {
      const Level level = test::tile_slope_level(2.0f, 60, slope.width, slope.rise, 3.0f);
      for (int facing : {1, -1}) {
        for (float x = 2.3f; x < 2.0f + 60.0f * slope.width - 0.3f; x += 0.29f) {
          test::StageScene s(c, level, x, facing);
          for (size_t leg = 0; leg < s.rig->legs.size(); ++leg) {
            glm::vec2 landing;
            const float wanted = x + facing * 0.3f * s.gait.stride;
            INFO(c.name << " rise " << slope.rise << " facing " << facing << " x " << x << " leg " << leg);
            REQUIRE(landing_for(s, static_cast<int>(leg), x, wanted, &landing));
            CHECK(std::fabs(landing.x - wanted) <= 0.26f * s.gait.stride);
          }
        }
      }
    }
  }
}

TEST_CASE("foothold planner: a foot's drawn flesh keeps off a wall ahead, not only its bones", "[anim][foothold]") {
  // The horse at its true size before a wall too tall to climb (x = 5, mirrored for -x), every
  // foot aimed where its bones' box would just touch the face: the hoof's flesh reaches
  // beyond the bones (anim_rig.h RigLeg::flesh_front), and the landing keeps it off the face.
  const Creature horse = build_creature(scenes::generator().example("horse").value()).value();
  for (int facing : {1, -1}) {
    const Box wall = facing > 0 ? Box::from_corner(5.0f, -1.0f, 20.0f, 21.0f) : Box::from_corner(-15.0f, -1.0f, 20.0f, 21.0f);
    const Level level({Box::from_corner(-20.0f, -1.0f, 45.0f, 1.0f), wall}, {});
    test::StageScene s(horse, level, 5.0f - facing * 2.0f, facing);
    const AnimRig& rig = *s.rig;
    for (size_t i = 0; i < rig.legs.size(); ++i) {
      const int leg = static_cast<int>(i);
      const RigLeg& info = rig.legs[i];
      INFO("facing " << facing << " leg " << leg);
      REQUIRE(info.flesh_front > 0.0f);
      const anim::FootSpan bones = anim::foot_span_ws(info, facing), flesh = anim::flesh_span_ws(info, facing);
      const float toe = facing > 0 ? bones.hi : -bones.lo;
      const float wanted = 5.0f - facing * (toe + rig.scale.landing_side);
      glm::vec2 landing;
      REQUIRE(landing_for(s, leg, s.body.girdle_ws(rig, info.girdle).x, wanted, &landing));
      CHECK(landing.y == 0.0f);
      // The flesh's front stays off the face (by the landing's side margin, less its inset).
      const float front = facing > 0 ? landing.x + flesh.hi : landing.x + flesh.lo;
      CHECK(facing * (5.0f - front) >= rig.scale.landing_side - rig.scale.landing_inset - 1e-5f);
      CHECK(anim::foot_fits(s.inputs(), leg, landing, true));
      // Where the bones alone were asked, the foot would have stood with its flesh in the face.
      CHECK_FALSE(anim::foot_fits(s.inputs(), leg, {wanted, 0.0f}, true));
      CHECK(anim::foot_fits(s.inputs(), leg, {wanted, 0.0f}));
    }
  }
}

TEST_CASE("foothold planner: on treads narrower than a foot and its flesh the bones' landing is taken", "[anim][foothold]") {
  // The rabbit at its true size reads slopes.json's tiles (5 cm wide, 8.8 mm apart) as steps,
  // and no landing keeps its flesh off their risers: it still finds one for its bones, up and
  // down, both facings (rather than stop at the crest).
  const Creature rabbit = build_creature(scenes::generator().example("rabbit").value()).value();
  for (float rise : {0.0088f, -0.0088f}) {
    const Level level = test::tile_slope_level(2.0f, 40, 0.05f, rise, 3.0f);
    for (int facing : {1, -1}) {
      for (float x = 2.3f; x < 3.7f; x += 0.13f) {
        test::StageScene s(rabbit, level, x, facing);
        for (size_t leg = 0; leg < s.rig->legs.size(); ++leg) {
          glm::vec2 landing;
          const float foot_x = s.body.girdle_ws(*s.rig, s.rig->legs[leg].girdle).x;
          const float wanted = foot_x + facing * 0.5f * s.gait.stride;
          INFO("rise " << rise << " facing " << facing << " x " << x << " leg " << leg);
          REQUIRE(landing_for(s, static_cast<int>(leg), foot_x, wanted, &landing));
          CHECK(anim::foot_fits(s.inputs(), static_cast<int>(leg), landing));
        }
      }
    }
  }
}
