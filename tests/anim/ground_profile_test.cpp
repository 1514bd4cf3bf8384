#include "ossa/anim/ground_profile.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "shared/level_scenes.h"
#include "stage_scene.h"

using namespace ossa;

TEST_CASE("ground profile: every column is the level's ground below its span", "[anim][profile]") {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Level level = scenes::random_level(seed, 200);
    const Box bounds = level.bounds();
    for (float step : {0.005f, 0.013f, 0.02f}) {
      const float x0 = bounds.min_ws.x + 0.37f * static_cast<float>(seed), x1 = x0 + 6.0f;
      const float top = 0.5f * (bounds.min_ws.y + bounds.max_ws.y), depth = 3.0f;
      GroundProfile profile;
      profile.build(level, x0, x1, top, depth, step);
      REQUIRE(profile.size() >= static_cast<int>((x1 - x0) / step));
      for (int i = 0; i < profile.size(); ++i) {
        const float lo = x0 + static_cast<float>(i) * step, hi = x0 + static_cast<float>(i + 1) * step;
        const auto hit = level.ground_height_below(lo, hi, top, depth);
        if (!hit) {
          CHECK(std::isnan(profile.column(i)));
        } else {
          CHECK(profile.column(i) == hit->height_ws);
        }
      }
    }
  }
}

TEST_CASE("ground profile: a run of small steps reads as a slope, a real step keeps its riser", "[anim][profile]") {
  // 18°: 5 cm columns, each 1.6 cm higher.
  const Level tiles = test::tile_slope_level(2.0f, 40, 0.05f, 0.016f);
  GroundProfile profile;
  profile.build(tiles, 0.0f, 8.0f, 2.0f, 3.0f, 0.01f);
  const float slope = 0.016f / 0.05f;
  for (float x = 2.2f; x < 3.8f; x += 0.0123f) {
    const float line = profile.surface_line(x, 0.1f, 0.05f);
    // The line through the treads' middles: within half a rise of the ideal ramp, and never
    // flat over a whole tread.
    const float ideal = (x - 2.0f) * slope + 0.5f * 0.016f;
    CHECK(line == Approx(ideal).margin(0.5f * 0.016f + 1e-4f));
  }
  // Treads of 30 cm are steps, not a slope: the surface is the tread's own height.
  const Level stairs = scenes::stairs_level(6, 0.15f, 0.3f);
  GroundProfile steps;
  steps.build(stairs, -2.0f, 10.0f, 3.0f, 4.0f, 0.01f);
  for (int i = 0; i < steps.size(); ++i) {
    const float x = steps.x0() + (static_cast<float>(i) + 0.5f) * steps.step();
    if (!std::isnan(steps.column(i))) CHECK(steps.surface_line(x, 0.1f, 0.05f) == steps.column(i));
  }
  // A gap is no ground.
  const Level gap({Box::from_corner(0.0f, -1.0f, 2.0f, 1.0f), Box::from_corner(2.5f, -1.0f, 2.0f, 1.0f)}, {1.0f, 0.0f});
  GroundProfile holes;
  holes.build(gap, 0.0f, 4.5f, 1.0f, 2.0f, 0.01f);
  for (float x = 2.1f; x < 2.4f; x += 0.01f) CHECK(std::isnan(holes.column(holes.column_of(x))));
  CHECK(std::isnan(holes.surface_line(2.25f, 0.1f, 0.05f)));
  CHECK(holes.column(holes.column_of(1.95f)) == 0.0f);
}

TEST_CASE("ground profile: knows when it must be sampled again", "[anim][profile]") {
  Level level = scenes::flat_level(20.0f);
  GroundProfile profile;
  profile.build(level, 1.0f, 9.0f, 1.0f, 2.0f, 0.01f);
  CHECK(profile.covers(level, 2.0f, 8.0f, -0.5f, 0.5f));
  CHECK_FALSE(profile.covers(level, 0.0f, 8.0f, -0.5f, 0.5f));  // beyond its window
  CHECK_FALSE(profile.covers(level, 2.0f, 8.0f, -0.5f, 1.5f));  // above its band
  level.add_box(Box::from_corner(5.0f, 0.0f, 0.5f, 0.2f));
  CHECK_FALSE(profile.covers(level, 2.0f, 8.0f, -0.5f, 0.5f));  // the level changed
  const Level other = scenes::flat_level(20.0f);
  CHECK_FALSE(profile.covers(other, 2.0f, 8.0f, -0.5f, 0.5f));
}
