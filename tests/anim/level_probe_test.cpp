// Level probes (level_probe.h) against brute force over random levels.

#include "ossa/anim/level_probe.h"

#include <catch2/catch.hpp>

#include <cmath>

#include "ossa/math/rng.h"
#include "shared/level_scenes.h"

using namespace ossa;

namespace {

// Does segment a-b pass through the interior (shrunk by a millimetre) of `box`? Sampled finely.
bool segment_hits(const Box& box, glm::vec2 a, glm::vec2 b) {
  for (int k = 0; k <= 2000; ++k) {
    const glm::vec2 p = a + (b - a) * (static_cast<float>(k) / 2000.0f);
    if (p.x > box.min_ws.x + 1.001e-3f && p.x < box.max_ws.x - 1.001e-3f && p.y > box.min_ws.y + 1.001e-3f &&
        p.y < box.max_ws.y - 1.001e-3f) {
      return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE("level probe: ground_below takes a span in either order and no drop below zero", "[anim][probe]") {
  const Level level({Box::from_corner(0.0f, -1.0f, 10.0f, 1.0f), Box::from_corner(4.0f, 0.0f, 1.0f, 0.5f)}, {1.0f, 0.0f});
  const auto a = anim::ground_below(level, 3.0f, 4.5f, 2.0f, 5.0f);
  const auto b = anim::ground_below(level, 4.5f, 3.0f, 2.0f, 5.0f);
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->height_ws == b->height_ws);
  CHECK(a->height_ws == Approx(0.5f));
  CHECK_FALSE(anim::ground_below(level, 1.0f, 2.0f, 2.0f, -3.0f));  // a negative drop is no drop
  CHECK(anim::ground_below(level, 1.0f, 2.0f, 0.0f, -3.0f));       // ...but ground right at from_y counts
}

TEST_CASE("level probe: polyline_hits_level equals a fine sampling, raise_to_clear clears", "[anim][probe]") {
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    INFO("seed " << seed);
    const Level level = scenes::random_level(seed, 30);
    Rng rng(seed * 7919);
    auto u = [&](float lo, float hi) { return static_cast<float>(rng.uniform(lo, hi)); };
    std::vector<int> hits;
    for (int k = 0; k < 60; ++k) {
      const glm::vec2 a{u(0.0f, 60.0f), u(0.0f, 12.0f)};
      const glm::vec2 b = a + glm::vec2(u(-2.0f, 2.0f), u(-2.0f, 2.0f));
      bool brute = false;
      for (int i = 0; i < level.size() && !brute; ++i) brute = segment_hits(level.box(i), a, b);
      const glm::vec2 p[2] = {a, b};
      CHECK(anim::polyline_hits_level(level, p, 2, hits) == brute);
      // Raised by raise_to_clear, the segment leaves every box it cut.
      const float up = anim::raise_to_clear(a, b, level, hits);
      CHECK(up >= 0.0f);
      const glm::vec2 q[2] = {a + glm::vec2(0.0f, up + 2e-3f), b + glm::vec2(0.0f, up + 2e-3f)};
      for (int i = 0; i < level.size(); ++i) {
        if (segment_hits(level.box(i), a, b)) CHECK_FALSE(segment_hits(level.box(i), q[0], q[1]));
      }
    }
  }
}

TEST_CASE("level probe: keep_out_height changes smoothly past the edge of a step", "[anim][probe]") {
  // A 0.3 m step from x = 5: the needed height fades from its top to the ground's as a point
  // moves away from its edge, no jump larger than the motion's share of the fade (the fade
  // reaches below the ground's own keep-out: a step no higher than fade - keep).
  const Level level({Box::from_corner(-10.0f, -1.0f, 30.0f, 1.0f), Box::from_corner(5.0f, 0.0f, 10.0f, 0.3f)}, {0.0f, 0.0f});
  std::vector<int> hits;
  const float half = 0.1f, keep = 0.05f, fade = 0.3f;
  float last = anim::keep_out_height(level, 4.5f, half, keep, fade, 1.0f, 5.0f, hits);
  CHECK(last == Approx(keep));  // far from the step: the ground's keep-out
  for (float x = 4.5f; x <= 5.2f; x += 0.001f) {
    const float h = anim::keep_out_height(level, x, half, keep, fade, 1.0f, 5.0f, hits);
    CHECK(std::fabs(h - last) < 0.02f);
    last = h;
  }
  CHECK(last == Approx(0.3f + keep));  // over the step: its keep-out
  CHECK(anim::keep_out_height(level, 40.0f, half, keep, fade, 1.0f, 5.0f, hits) < -1e29f);  // no ground
}

TEST_CASE("level probe: a clearance knows the highest top above its base near a foot", "[anim][probe]") {
  const Level level({Box::from_corner(-10.0f, -1.0f, 30.0f, 1.0f), Box::from_corner(1.0f, 0.0f, 0.5f, 0.4f)}, {0.0f, 0.0f});
  std::vector<int> hits;
  const anim::Clearance near = anim::clearance_in(Box{{0.0f, -0.5f}, {2.0f, 1.0f}}, 0.0f, level, hits);
  CHECK(near.top == Approx(0.4f));
  CHECK_FALSE(near.clear_above(0.2f));  // a limb at 0.2 m may meet the box
  CHECK(near.clear_above(0.45f));       // above its top it meets nothing
  const anim::Clearance far = anim::clearance_in(Box{{3.0f, -0.5f}, {4.0f, 1.0f}}, 0.0f, level, hits);
  CHECK(far.clear_above(0.01f));        // flat ground only
  CHECK_FALSE(anim::Clearance{}.clear_above(100.0f));  // the default knows nothing
}

TEST_CASE("level probe: a body that would stand in a wall is placed clear of it, on ground", "[anim][probe]") {
  // Floor from x = 0 to 20 with a 4 m wall at [-1, 0] (default.json's left end) and a 2 m
  // post at [8, 8.5]. A body reaching 5 m behind its root and 1 m ahead, 1.5 m tall.
  const Level level({Box::from_corner(0.0f, -1.0f, 20.0f, 1.0f), Box::from_corner(-1.0f, -1.0f, 1.0f, 5.0f),
                     Box::from_corner(8.0f, 0.0f, 0.5f, 2.0f)},
                    {2.0f, 0.0f});
  std::vector<int> hits;
  const float back = -5.0f, front = 1.0f, top = 1.5f, from = 1.0f, drop = 3.0f, reach = 20.0f;
  // Fits: unchanged.
  CHECK(anim::clear_standing_x(level, 6.0f, back, front, top, from, drop, INFINITY, reach, hits) == 6.0f);
  // Its tail in the end wall: pushed forwards until the tail clears it (left of x 0 there is
  // no floor, so not backwards however short that is).
  const float x = anim::clear_standing_x(level, 2.0f, back, front, top, from, drop, INFINITY, reach, hits);
  CHECK(x + back >= 0.0f);
  CHECK(x + back < 0.01f);
  // Its front in the post: the shorter way, backwards (x 7.5 → 6.999).
  const float y = anim::clear_standing_x(level, 7.5f, back, front, top, from, drop, INFINITY, reach, hits);
  CHECK(y + front <= 8.0f);
  CHECK(y + front > 7.99f);
  // Nowhere within reach: unchanged.
  CHECK(anim::clear_standing_x(level, 2.0f, back, front, top, from, drop, INFINITY, 0.5f, hits) == 2.0f);
}

TEST_CASE("level probe: a body that climbs little does not lie on an end wall beside it", "[anim][probe]") {
  // default.json's left end: a 4 m wall at [-1, 0] over a floor at 0. A legless body reaching
  // 5 m behind its root, 1 m ahead and 1.5 m tall, searched from 5 m up (above the wall).
  const Level level({Box::from_corner(0.0f, -1.0f, 20.0f, 1.0f), Box::from_corner(-1.0f, -1.0f, 1.0f, 5.0f)}, {2.0f, 0.0f});
  std::vector<int> hits;
  const float back = -5.0f, front = 1.0f, top = 1.5f, from = 5.0f, drop = 6.0f, reach = 20.0f;
  // Climbing anything, it would lie on the wall's top with its root over the floor.
  CHECK(anim::standing_ground(level, 2.0f, 2.0f + back, 2.0f + front, from, drop, INFINITY) == Approx(4.0f));
  CHECK(anim::clear_standing_x(level, 2.0f, back, front, top, from, drop, INFINITY, reach, hits) == 2.0f);
  // Climbing 1 m, the wall is a wall: it lies on the floor, its tail clear of the wall.
  CHECK(anim::standing_ground(level, 2.0f, 2.0f + back, 2.0f + front, from, drop, 1.0f) == Approx(0.0f));
  const float x = anim::clear_standing_x(level, 2.0f, back, front, top, from, drop, 1.0f, reach, hits);
  CHECK(x + back >= 0.0f);
  CHECK(x + back < 0.01f);
  CHECK(anim::standing_ground(level, x, x + back, x + front, from, drop, 1.0f) == Approx(0.0f));
  // No ground under the root (a gap): the span's highest, as before.
  const Level gap({Box::from_corner(0.0f, -1.0f, 1.0f, 1.0f), Box::from_corner(3.0f, -1.0f, 1.0f, 1.5f)}, {2.0f, 0.0f});
  CHECK(anim::standing_ground(gap, 2.0f, 0.5f, 3.5f, from, drop, 0.1f) == Approx(0.5f));
  // A flight of 0.3 m steps up to 3 m ahead of the root is ground to lie on, climbing 0.5 m;
  // the 4 m wall behind is not.
  std::vector<Box> flight{Box::from_corner(-1.0f, -1.0f, 1.0f, 5.0f), Box::from_corner(0.0f, -1.0f, 30.0f, 1.0f)};
  for (int i = 1; i <= 10; ++i) flight.push_back(Box::from_corner(4.0f + 0.5f * static_cast<float>(i), 0.0f, 30.0f, 0.3f * static_cast<float>(i)));
  const Level stairs(flight, {2.0f, 0.0f});
  CHECK(anim::standing_ground(stairs, 2.0f, -3.0f, 12.0f, 5.0f, 6.0f, 0.5f) == Approx(3.0f));
  CHECK(anim::standing_ground(stairs, 2.0f, -3.0f, 12.0f, 5.0f, 6.0f, 0.2f) == Approx(0.0f));
}
