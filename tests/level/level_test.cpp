// Level basics and the exact contact rules of each query on hand-made cases.

#include "ossa/level/level.h"
#include "shared/level_scenes.h"

#include <catch2/catch.hpp>

using namespace ossa;

TEST_CASE("Box helpers", "[level]") {
  const Box b = Box::from_corner(1.0f, 2.0f, 3.0f, 4.0f);
  CHECK(b.max_ws == glm::vec2(4.0f, 6.0f));
  CHECK(b.width() == 3.0f);
  CHECK(b.height() == 4.0f);
  CHECK(b.center() == glm::vec2(2.5f, 4.0f));
  CHECK(b.is_valid());
  CHECK_FALSE(Box::from_corner(0, 0, 0, 1).is_valid());
  CHECK_FALSE(Box::from_corner(0, 0, 1, -1).is_valid());
  CHECK_FALSE(Box::from_corner(0, 0, std::numeric_limits<float>::infinity(), 1).is_valid());
  // Touching is not overlapping.
  CHECK_FALSE(b.overlaps(Box::from_corner(4.0f, 2.0f, 1.0f, 1.0f)));
  CHECK(b.overlaps(Box::from_corner(3.9f, 2.0f, 1.0f, 1.0f)));
  CHECK(Box::from_center({0, 0}, {1, 2}) == Box{{-1, -2}, {1, 2}});
}

TEST_CASE("ground_height_below finds the highest top in reach", "[level]") {
  // Ground top at 0, a step top at 0.2 from x = 2, a ceiling at 3 over everything.
  Level level({Box::from_corner(0, -1, 10, 1), Box::from_corner(2, -1, 1, 1.2f),
               Box::from_corner(0, 3, 10, 1)});
  auto g = level.ground_height_below(0.5f, 0.7f, 1.0f, 2.0f);
  REQUIRE(g);
  CHECK(g->height_ws == 0.0f);
  CHECK(g->index == 0);
  // The span touches the step: the step wins.
  g = level.ground_height_below(1.9f, 2.0f, 1.0f, 2.0f);
  REQUIRE(g);
  CHECK(g->index == 1);
  CHECK(g->height_ws == Approx(0.2f));
  // Too far to drop.
  CHECK_FALSE(level.ground_height_below(0.5f, 0.5f, 1.0f, 0.5f));
  // Standing exactly on the top (and a hair below) still finds it; the ceiling is above.
  g = level.ground_height_below(0.5f, 0.5f, -0.0005f, 0.1f);
  REQUIRE(g);
  CHECK(g->index == 0);
  // From above the ceiling, the ceiling's top is the ground.
  g = level.ground_height_below(5.0f, 5.0f, 5.0f, 10.0f);
  REQUIRE(g);
  CHECK(g->index == 2);
  // Off the level.
  CHECK_FALSE(level.ground_height_below(11.0f, 12.0f, 1.0f, 100.0f));
  CHECK_FALSE(Level().ground_height_below(0.0f, 1.0f, 0.0f, 1.0f));
}

TEST_CASE("sweep_box: time of impact, normals, sliding and starting inside", "[level]") {
  Level level({Box::from_corner(0, -1, 10, 1), Box::from_corner(5, 0, 1, 2)});
  const Box foot = Box::from_corner(1, 0.5f, 0.2f, 0.1f);
  // Falling onto the ground from 0.5 m with a 1 m move: contact half way.
  auto h = level.sweep_box(foot, {0.0f, -1.0f});
  REQUIRE(h);
  CHECK(h->t == Approx(0.5f));
  CHECK(h->normal == glm::vec2(0, 1));
  CHECK(h->index == 0);
  CHECK_FALSE(h->started_inside);
  // Walking right into the wall at x = 5.
  h = level.sweep_box(foot, {8.0f, 0.0f});
  REQUIRE(h);
  CHECK(h->index == 1);
  CHECK(h->normal == glm::vec2(-1, 0));
  CHECK(h->t == Approx((5.0f - 1.2f) / 8.0f));
  // Sliding along the ground's top face is not a hit; pressing into it is, at t = 0.
  const Box resting = Box::from_corner(1, 0, 0.2f, 0.1f);
  CHECK_FALSE(level.sweep_box(resting, {2.0f, 0.0f}));
  h = level.sweep_box(resting, {0.0f, -0.1f});
  REQUIRE(h);
  CHECK(h->t == 0.0f);
  CHECK(h->normal == glm::vec2(0, 1));
  // Moving away from a touching face is free.
  CHECK_FALSE(level.sweep_box(resting, {0.0f, 0.3f}));
  // Stopping exactly on contact is not a hit.
  CHECK_FALSE(level.sweep_box(foot, {0.0f, -0.5f}));
  // Starting inside.
  h = level.sweep_box(Box::from_corner(5.2f, 0.5f, 0.1f, 0.1f), {1.0f, 0.0f});
  REQUIRE(h);
  CHECK(h->started_inside);
  CHECK(h->t == 0.0f);
  CHECK(h->index == 1);
  // Raycast down onto the ground.
  h = level.raycast({2.0f, 3.0f}, {2.0f, -3.0f});
  REQUIRE(h);
  CHECK(h->t == Approx(0.5f));
  CHECK(h->index == 0);
}

TEST_CASE("overlap queries ignore touching boxes", "[level]") {
  Level level = scenes::stairs_level(4, 0.2f, 0.5f);
  // A box standing on the first step touches it only.
  const Box& step = level.box(1);
  const Box on_top = Box::from_corner(step.min_ws.x + 0.1f, step.max_ws.y, 0.2f, 1.0f);
  CHECK_FALSE(level.overlaps(on_top));
  CHECK_FALSE(level.first_overlap(on_top));
  const Box sunk = on_top.translated({0.0f, -0.01f});
  CHECK(level.overlaps(sunk));
  REQUIRE(level.first_overlap(sunk));
  CHECK(*level.first_overlap(sunk) == 1);
  std::vector<int> out{99};
  level.overlapping(Box::from_corner(step.min_ws.x - 0.1f, -0.5f, 0.7f, 0.1f), out);
  CHECK(out == std::vector<int>{99, 0, 1, 2});  // appended, increasing
}

TEST_CASE("Level editing keeps indices and bounds", "[level]") {
  Level level = scenes::flat_level(20.0f);
  CHECK(level.size() == 1);
  const int i = level.add_box(Box::from_corner(3, 0, 1, 1));
  CHECK(i == 1);
  CHECK(level.ground_height_below(3.5f, 3.5f, 2.0f, 3.0f)->index == 1);
  level.set_box(1, Box::from_corner(6, 0, 1, 2));
  CHECK(level.ground_height_below(3.5f, 3.5f, 2.0f, 3.0f)->index == 0);
  CHECK(level.ground_height_below(6.5f, 6.5f, 2.0f, 3.0f)->height_ws == 2.0f);
  level.remove_box(0);
  CHECK(level.size() == 1);
  CHECK(level.ground_height_below(6.5f, 6.5f, 2.0f, 3.0f)->index == 0);
  CHECK_FALSE(level.ground_height_below(3.5f, 3.5f, 2.0f, 3.0f));
  CHECK(level.bounds().max_ws == glm::vec2(7.0f, 2.0f));
  CHECK(level.bounds().min_ws == glm::vec2(1.0f, 0.0f));  // includes the spawn point
}

TEST_CASE("a spawn inside a box stands on the first free ground above it", "[level]") {
  Level level(std::vector<Box>{Box::from_corner(-5.0f, -2.0f, 40.0f, 2.0f),   // ground, top 0
                               Box::from_corner(3.0f, 0.0f, 1.0f, 0.3f),      // a step on it
                               Box::from_corner(3.2f, 0.3f, 0.2f, 0.5f)},     // a post on the step
              glm::vec2(1.0f, -0.5f));
  CHECK(level.spawn_inside_box());
  CHECK(level.free_point_above({1.0f, -0.5f}) == glm::vec2(1.0f, 0.0f));
  CHECK(level.free_point_above({3.5f, -1.0f}) == glm::vec2(3.5f, 0.3f));
  CHECK(level.free_point_above({3.3f, -1.0f}) == glm::vec2(3.3f, 0.8f));  // through stacked boxes
  CHECK(level.free_point_above({1.0f, 2.0f}) == glm::vec2(1.0f, 2.0f));   // free: unchanged
  CHECK(level.free_point_above({1.0f, 0.0f}) == glm::vec2(1.0f, 0.0f));   // on a top: free
  level.spawn_ws = {1.0f, 0.0f};
  CHECK_FALSE(level.spawn_inside_box());
}
