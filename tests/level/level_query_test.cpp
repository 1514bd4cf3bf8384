// Property tests: every Level query equals a brute-force linear scan over all boxes, over
// thousands of seeded random queries, on random levels from 0 to 100 000 boxes, including
// grid-snapped levels full of ties and touching edges, and after random edits.

#include "ossa/level/level.h"
#include "ossa/math/rng.h"
#include "shared/level_scenes.h"

#include <catch2/catch.hpp>

#include <climits>

using namespace ossa;

namespace {

std::optional<GroundHit> brute_ground(const std::vector<Box>& boxes, float x0, float x1, float from_y,
                                      float drop) {
  std::optional<GroundHit> best;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    if (!is_ground_candidate(boxes[i], x0, x1, from_y - drop, from_y + kGroundEpsilon)) continue;
    if (!best || boxes[i].max_ws.y > best->height_ws) best = GroundHit{boxes[i].max_ws.y, i};
  }
  return best;
}

std::vector<int> brute_overlapping(const std::vector<Box>& boxes, const Box& q) {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    if (boxes[i].overlaps(q)) out.push_back(i);
  }
  return out;
}

std::optional<SweepHit> brute_sweep(const std::vector<Box>& boxes, const Box& m, glm::vec2 d) {
  std::optional<SweepHit> best;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    auto h = sweep_against(m, d, boxes[i]);
    if (h && (!best || h->t < best->t)) {
      best = h;
      best->index = i;
    }
  }
  return best;
}

// Snapping to a coarse grid makes equal tops, shared edges and exact touching common.
float snap(float v, float grid) { return grid > 0.0f ? std::round(v / grid) * grid : v; }

Level grid_level(uint64_t seed, int count, float grid) {
  Rng rng(seed);
  std::vector<Box> boxes;
  const float width = std::max(4.0f, 0.5f * static_cast<float>(count));
  for (int i = 0; i < count; ++i) {
    const float x = snap(static_cast<float>(rng.uniform(0.0, width)), grid);
    const float y = snap(static_cast<float>(rng.uniform(0.0, 4.0)), grid);
    const float w = std::max(grid, snap(static_cast<float>(rng.uniform(0.1, 2.0)), grid));
    const float h = std::max(grid, snap(static_cast<float>(rng.uniform(0.1, 2.0)), grid));
    boxes.push_back(Box::from_corner(x, y, w, h));
  }
  return Level(std::move(boxes));
}

// Compares every query kind on `queries` random inputs, snapped to `grid` (0 = unsnapped).
void check_against_brute_force(const Level& level, uint64_t seed, int queries, float grid) {
  const std::vector<Box>& boxes = level.colliders();
  const Box b = level.empty() ? Box{{0, 0}, {10, 10}} : level.bounds();
  Rng rng(seed);
  auto x = [&] { return snap(static_cast<float>(rng.uniform(b.min_ws.x - 1.0, b.max_ws.x + 1.0)), grid); };
  auto y = [&] { return snap(static_cast<float>(rng.uniform(b.min_ws.y - 1.0, b.max_ws.y + 1.0)), grid); };
  auto len = [&](double hi) { return snap(static_cast<float>(rng.uniform(0.0, hi)), grid); };
  std::vector<int> got;
  for (int q = 0; q < queries; ++q) {
    INFO("query " << q);
    // Ground.
    const float x0 = x(), x1 = x0 + len(rng.chance(0.2) ? 0.0 : 1.0), fy = y(), drop = len(4.0);
    const auto g = level.ground_height_below(x0, x1, fy, drop);
    const auto gb = brute_ground(boxes, x0, x1, fy, drop);
    REQUIRE(g.has_value() == gb.has_value());
    if (g) {
      REQUIRE(g->height_ws == gb->height_ws);
      REQUIRE(g->index == gb->index);
    }
    // Overlap.
    const glm::vec2 p{x(), y()};
    const Box qb = Box::from_corner(p, {len(3.0), len(3.0)});
    const std::vector<int> ob = brute_overlapping(boxes, qb);
    got.clear();
    level.overlapping(qb, got);
    REQUIRE(got == ob);
    REQUIRE(level.overlaps(qb) == !ob.empty());
    const auto first = level.first_overlap(qb);
    REQUIRE(first.has_value() == !ob.empty());
    if (first) REQUIRE(*first == ob.front());
    REQUIRE(level.point_inside(p) == !brute_overlapping(boxes, Box{p, p}).empty());
    // Sweep: short steps and long ones, sometimes axis-aligned.
    glm::vec2 d{snap(static_cast<float>(rng.uniform(-3.0, 3.0)), grid),
                snap(static_cast<float>(rng.uniform(-3.0, 3.0)), grid)};
    if (rng.chance(0.2)) d.x = 0.0f;
    if (rng.chance(0.2)) d.y = 0.0f;
    const Box mover = Box::from_corner(p, {len(1.0), len(1.5)});
    const auto s = level.sweep_box(mover, d);
    const auto sb = brute_sweep(boxes, mover, d);
    REQUIRE(s.has_value() == sb.has_value());
    if (s) {
      REQUIRE(s->t == sb->t);
      REQUIRE(s->index == sb->index);
      REQUIRE(s->normal == sb->normal);
      REQUIRE(s->started_inside == sb->started_inside);
      REQUIRE(s->t >= 0.0f);
      REQUIRE(s->t <= 1.0f);
    }
    const auto r = level.raycast(p, p + d);
    const auto rb = brute_sweep(boxes, Box{p, p}, (p + d) - p);  // as raycast computes it
    REQUIRE(r.has_value() == rb.has_value());
    if (r) {
      REQUIRE(r->t == rb->t);
      REQUIRE(r->index == rb->index);
    }
  }
}

}  // namespace

TEST_CASE("queries equal a linear scan on random levels of every size", "[level]") {
  for (int n : {0, 1, 2, 16, 32, 33, 100, 256, 5000}) {
    INFO("boxes " << n);
    check_against_brute_force(scenes::random_level(1000 + n, n), 7 + n, 2000, 0.0f);
  }
}

TEST_CASE("queries equal a linear scan at 100 000 boxes", "[level]") {
  const Level level = scenes::random_level(42, 100000);
  check_against_brute_force(level, 43, 1500, 0.0f);
}

TEST_CASE("queries equal a linear scan on grid-snapped levels (ties, shared edges)", "[level]") {
  for (int n : {5, 31, 200, 3000}) {
    INFO("boxes " << n);
    check_against_brute_force(grid_level(500 + n, n, 0.25f), 11 + n, 2000, 0.25f);
  }
}

TEST_CASE("queries stay exact through random edits", "[level]") {
  Level level = grid_level(77, 300, 0.25f);
  Rng rng(78);
  for (int step = 0; step < 600; ++step) {
    const int op = rng.uniform_int(0, 9);
    const Box nb = Box::from_corner(static_cast<float>(rng.uniform(0.0, 150.0)),
                                    static_cast<float>(rng.uniform(0.0, 4.0)),
                                    static_cast<float>(rng.uniform(0.1, 3.0)),
                                    static_cast<float>(rng.uniform(0.1, 3.0)));
    if (op == 0 || level.empty()) {
      const int added = level.add_box(nb);
      REQUIRE(added == level.size() - 1);
      REQUIRE(level.colliders().back() == nb);
    } else if (op == 1) {
      const int i = rng.uniform_int(0, level.size() - 1);
      const Box next = i + 1 < level.size() ? level.box(i + 1) : Box{};
      const int before = level.size();
      level.remove_box(i);
      REQUIRE(level.size() == before - 1);
      if (i < level.size()) REQUIRE(level.box(i) == next);
    } else {
      // Mostly moves: the editor's drag path (refit, rebuild after many).
      const int i = rng.uniform_int(0, level.size() - 1);
      level.set_box(i, nb);
      REQUIRE(level.box(i) == nb);
    }
    if (step % 50 == 0) check_against_brute_force(level, 1000 + step, 200, 0.0f);
  }
  check_against_brute_force(level, 5, 2000, 0.0f);
}
