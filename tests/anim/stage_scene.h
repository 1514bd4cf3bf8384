#pragma once
// A creature's rig standing on a level, with the per-tick inputs the animator's stages take,
// built directly (no Animator, no game layer): the stage tests' common scene.

#include <memory>
#include <vector>

#include "ossa/anim/anim_rig.h"
#include "ossa/anim/anim_state.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/ground_profile.h"
#include "ossa/level/level.h"

namespace ossa::test {

struct StageScene {
  std::shared_ptr<const AnimRig> rig;
  AnimatorParams params;
  Level level;
  GroundProfile ground;
  std::vector<int> hits;
  anim::AnimContext ctx;
  anim::BodyFrame body;
  anim::GaitState gait;

  // The creature at x facing `facing`, its root at its standing height above the ground
  // under x, its gait settled at `speed` m/s.
  StageScene(const Creature& creature, Level lv, float x, int facing = 1, float speed = 1.0f)
      : rig(build_anim_rig(creature)), level(std::move(lv)), ctx{*rig, params, level, ground, hits} {
    body.x_ws = x;
    body.facing = facing;
    const auto hit = level.ground_height_below(x - 0.01f, x + 0.01f, 50.0f, 100.0f);
    body.root_y_ws = (hit ? hit->height_ws : 0.0f) + rig->root_rest_y * params.stance_height;
    for (int k = 0; k < 40; ++k) anim::update_gait(*rig, params, speed, false, 0.0f, 0.0f, gait);
    ground.build(level, x - 20.0f, x + 20.0f, body.root_y_ws + rig->hip_height, 5.0f * rig->hip_height, 0.01f);
  }
  anim::FootholdInputs inputs() const { return {ctx, body, gait.stride, gait.duty}; }
};

// Columns of `width` metres, each `rise` metres higher than the last (negative: lower), from
// x0 for `count` columns, over flat ground at y = 0 either side; a wall at each end.
inline Level tile_slope_level(float x0, int count, float width, float rise, float plateau = 3.0f) {
  std::vector<Box> boxes{Box::from_corner(-50.0f, -2.0f, 50.0f + x0, 2.0f)};
  float x = x0, y = 0.0f;
  for (int i = 0; i < count; ++i) {
    y += rise;
    boxes.push_back(Box{{x, -2.0f}, {x + width, std::max(y, -1.5f)}});
    x += width;
  }
  boxes.push_back(Box{{x, -2.0f}, {x + plateau, std::max(y, -1.5f)}});
  boxes.push_back(Box::from_corner(x + plateau, -2.0f, 50.0f, 2.0f));
  return Level(boxes, {1.0f, 0.0f});
}

}  // namespace ossa::test
