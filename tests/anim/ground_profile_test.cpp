#include "ossa/anim/ground_profile.h"

#include <catch2/catch.hpp>

#include <algorithm>
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

TEST_CASE("ground profile: may_rise_above never says no where the level has higher ground", "[anim][profile]") {
  // The cheap test the body placement asks before a level query: when it answers false, the
  // level has no box top above y (up to the profile's top) over the span.
  int skipped = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Level level = scenes::random_level(seed, 200);
    const Box bounds = level.bounds();
    const float x0 = bounds.min_ws.x + 0.37f * static_cast<float>(seed), x1 = x0 + 6.0f;
    const float top = 0.5f * (bounds.min_ws.y + bounds.max_ws.y), depth = 3.0f;
    GroundProfile profile;
    profile.build(level, x0, x1, top, depth, 0.013f);
    for (int k = 0; k < 400; ++k) {
      const float a = x0 - 0.5f + 7.0f * static_cast<float>(k % 97) / 97.0f, b = a + 0.02f + 0.3f * static_cast<float>(k % 7) / 7.0f;
      const float y = top - depth + depth * static_cast<float>(k % 13) / 12.0f;
      if (profile.may_rise_above(a, b, y, top)) continue;
      ++skipped;
      const auto hit = level.ground_height_below(a, b, top, top - y);
      INFO("seed " << seed << " span " << a << ".." << b << " y " << y);
      CHECK((!hit || hit->height_ws <= y));
    }
  }
  CHECK(skipped > 100);  // the test answers no often enough to matter
}

TEST_CASE("ground profile: a run of small steps reads as a slope, a real step keeps its riser", "[anim][profile]") {
  // 18°: 5 cm columns, each 1.6 cm higher, from flat ground at x = 2 up to a 3 m plateau.
  const Level tiles = test::tile_slope_level(2.0f, 40, 0.05f, 0.016f);
  GroundProfile profile;
  profile.build(tiles, 0.0f, 8.0f, 2.0f, 3.0f, 0.01f);
  const SlopeReading reading{0.1f, 0.05f, 0.0f, 0.01f};
  const float slope = 0.016f / 0.05f, top = 40 * 0.016f;
  for (float x = 1.5f; x < 4.5f; x += 0.0123f) {
    const float line = profile.surface_line(x, reading);
    // The line through the treads' middles, running into the flat ground below and the
    // plateau above: within half a rise of the ideal ramp (a rise where it meets the flat,
    // within a tread of the ends), and never flat over a whole tread.
    const float ideal = std::clamp((x - 2.0f) * slope + 0.5f * 0.016f, 0.0f, top);
    const bool end = std::fabs(x - 2.0f) < 0.1f || std::fabs(x - 4.0f) < 0.1f;
    CHECK(line == Approx(ideal).margin((end ? 1.0f : 0.5f) * 0.016f + 1e-4f));
  }
  // No jump anywhere, the slope's ends included: a creature walks it like a ramp.
  CHECK(profile.largest_jump(1.0f, 5.0f, reading) <= 0.6f * 0.016f);
  // Treads of 30 cm are steps, not a slope: the surface is the tread's own height.
  const Level stairs = scenes::stairs_level(6, 0.15f, 0.3f);
  GroundProfile steps;
  steps.build(stairs, -2.0f, 10.0f, 3.0f, 4.0f, 0.01f);
  for (int i = 0; i < steps.size(); ++i) {
    const float x = steps.x0() + (static_cast<float>(i) + 0.5f) * steps.step();
    if (!std::isnan(steps.column(i))) CHECK(steps.surface_line(x, reading) == steps.column(i));
  }
  CHECK(steps.largest_jump(-1.0f, 9.0f, reading) == Approx(0.15f).margin(1e-4f));
  // A gap is no ground.
  const Level gap({Box::from_corner(0.0f, -1.0f, 2.0f, 1.0f), Box::from_corner(2.5f, -1.0f, 2.0f, 1.0f)}, {1.0f, 0.0f});
  GroundProfile holes;
  holes.build(gap, 0.0f, 4.5f, 1.0f, 2.0f, 0.01f);
  for (float x = 2.1f; x < 2.4f; x += 0.01f) CHECK(std::isnan(holes.column(holes.column_of(x))));
  CHECK(std::isnan(holes.surface_line(2.25f, reading)));
  CHECK(holes.column(holes.column_of(1.95f)) == 0.0f);
}

TEST_CASE("ground profile: treads narrower than the foot are a slope whatever their rise", "[anim][profile]") {
  // 30°: 3 cm columns rising 1.73 cm each, more than the 1 cm riser a small creature's legs
  // count as a slope; a 5 cm foot cannot stand on one tread, so it is a slope all the same.
  const Level tiles = test::tile_slope_level(2.0f, 20, 0.03f, 0.0173f);
  GroundProfile profile;
  profile.build(tiles, 0.0f, 6.0f, 1.0f, 2.0f, 0.005f);
  const SlopeReading legs{0.1f, 0.01f, 0.0f, 0.005f};
  SlopeReading foot = legs;
  foot.foot = 0.05f;
  CHECK(profile.largest_jump(1.5f, 3.0f, legs) == Approx(0.0173f).margin(1e-4f));
  CHECK(profile.largest_jump(1.5f, 3.0f, foot) < 0.5f * 0.0173f);
  // No steeper than GroundProfile::kMaxSlope, though: 3 cm treads rising 2.5 cm are steps.
  const Level steep = test::tile_slope_level(2.0f, 20, 0.03f, 0.025f);
  GroundProfile steep_profile;
  steep_profile.build(steep, 0.0f, 6.0f, 1.0f, 2.0f, 0.005f);
  CHECK(steep_profile.largest_jump(1.5f, 3.0f, foot) == Approx(0.025f).margin(1e-4f));
  // Nor higher than kUnderFootRiser risers: a long foot (a kangaroo's 40 cm) on a flight of
  // 35 cm treads rising 25 cm still meets steps.
  const Level flight = test::tile_slope_level(2.0f, 6, 0.35f, 0.25f);
  GroundProfile flight_profile;
  flight_profile.build(flight, 0.0f, 6.0f, 3.0f, 4.0f, 0.02f);
  const SlopeReading kangaroo{0.36f, 0.072f, 0.4f, 0.036f};
  CHECK(flight_profile.largest_jump(1.5f, 4.0f, kangaroo) == Approx(0.25f).margin(1e-4f));
}

TEST_CASE("ground profile: slope_top walks the slope to its first real riser", "[anim][profile]") {
  // A tile hill from x = 2 up to a plateau at 0.64 m (x 4 to 7), and a 40 cm wall on it at 5.
  std::vector<Box> boxes = test::tile_slope_level(2.0f, 40, 0.05f, 0.016f).colliders();
  boxes.push_back(Box::from_corner(5.0f, 0.64f, 0.3f, 0.4f));
  const Level level(boxes, {1.0f, 0.0f});
  GroundProfile profile;
  profile.build(level, -2.0f, 9.0f, 2.0f, 3.0f, 0.01f);
  const SlopeReading reading{0.1f, 0.05f, 0.0f, 0.01f};
  // From the flat ground below, the hill's top is reached either way round.
  CHECK(profile.slope_top(1.0f, 3.5f, 4.5f, reading) == Approx(0.64f).margin(1e-4f));
  CHECK(profile.slope_top(4.5f, 0.5f, 1.5f, reading) == Approx(0.0f).margin(1e-4f));
  CHECK(profile.slope_top(1.0f, 0.5f, 3.0f, reading) == Approx(0.5f * 0.64f).margin(0.02f));
  // The wall is a riser: the walk stops before it, and the part beyond it is not reached.
  CHECK(profile.slope_top(1.0f, 3.5f, 5.5f, reading) == Approx(0.64f).margin(1e-4f));
  CHECK(std::isnan(profile.slope_top(1.0f, 5.4f, 6.0f, reading)));
  // Beyond the profile it cannot vouch for anything.
  CHECK(std::isnan(profile.slope_top(1.0f, 8.0f, 10.0f, reading)));
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

TEST_CASE("ground profile: keeps treads, two bytes per column, and at most kMaxColumns columns", "[anim][profile]") {
  // Issue 31: a height and two run ends per column made the profile 16 KB of a walking
  // horse's 23 KB. Flat ground is one tread; a window too wide for kMaxColumns columns of the
  // asked width gets coarser columns that still cover it and still read the level.
  const Level flat = scenes::flat_level(400.0f);
  GroundProfile profile;
  profile.build(flat, 10.0f, 36.0f, 1.0f, 3.0f, 0.02f);  // a horse's window: 1 300 columns
  CHECK(profile.size() == 1300);
  CHECK(profile.tread_count() == 1);
  CHECK(profile.bytes() <= 2 * 1300 + 64);
  profile.build(flat, 0.0f, 390.0f, 1.0f, 3.0f, 0.001f);  // 390 000 columns asked
  CHECK(profile.size() <= GroundProfile::kMaxColumns);
  CHECK(profile.covers(flat, 1.0f, 389.0f, -1.0f, 0.5f));
  CHECK(profile.column(profile.column_of(200.0f)) == 0.0f);

  const Level level = scenes::random_level(7, 200);
  const Box bounds = level.bounds();
  const float top = 0.5f * (bounds.min_ws.y + bounds.max_ws.y);
  profile.build(level, bounds.min_ws.x, bounds.max_ws.x, top, 3.0f, 0.0001f);
  REQUIRE(profile.size() <= GroundProfile::kMaxColumns);
  REQUIRE(profile.covers(level, bounds.min_ws.x, bounds.max_ws.x, top - 3.0f, top));
  for (int i = 0; i < profile.size(); i += 97) {
    const float lo = profile.x0() + static_cast<float>(i) * profile.step(), hi = lo + profile.step();
    const auto hit = level.ground_height_below(lo, hi, top, 3.0f);
    CHECK((hit ? profile.column(i) == hit->height_ws : std::isnan(profile.column(i))));
  }
}

TEST_CASE("ground profile: largest_jump and slope_top read every column's surface line", "[anim][profile]") {
  // They pass the inside of a wide tread in one step (flat_until); a column-by-column walk of
  // surface_line is the reference, on random levels, tile slopes and stairs, for readings
  // from a mouse's to a horse's, over spans either way round.
  std::vector<Level> levels;
  for (uint64_t seed = 1; seed <= 6; ++seed) levels.push_back(scenes::random_level(seed, 120));
  levels.push_back(test::tile_slope_level(2.0f, 40, 0.05f, 0.016f));
  levels.push_back(scenes::stairs_level(6, 0.15f, 0.3f));
  const SlopeReading readings[] = {{0.1f, 0.05f, 0.0f, 0.01f}, {0.36f, 0.072f, 0.4f, 0.036f}, {0.02f, 0.01f, 0.05f, 0.005f}};
  int checked = 0;
  for (const Level& level : levels) {
    const Box bounds = level.bounds();
    const float top = bounds.max_ws.y + 0.5f;
    GroundProfile p;
    p.build(level, bounds.min_ws.x, std::min(bounds.max_ws.x, bounds.min_ws.x + 40.0f), top, bounds.max_ws.y - bounds.min_ws.y + 1.0f, 0.01f);
    auto line = [&](int i, const SlopeReading& r) { return p.surface_line(p.x0() + (static_cast<float>(i) + 0.5f) * p.step(), r); };
    for (const SlopeReading& r : readings) {
      for (int k = 0; k < 60; ++k) {
        const float a = p.x0() + 0.3f + 0.61f * static_cast<float>(k % 50), b = a + 0.05f + 0.17f * static_cast<float>(k % 23);
        float jump = 0.0f, prev = line(p.column_of(a), r);
        for (int i = p.column_of(a) + 1; i <= p.column_of(b); ++i) {
          const float y = line(i, r);
          if (!std::isnan(y) && !std::isnan(prev)) jump = std::max(jump, std::fabs(y - prev));
          prev = y;
        }
        CHECK(p.largest_jump(a, b, r) == jump);
        const float from = a - 1.0f + 0.37f * static_cast<float>(k % 9);
        if (from < p.x0() || b > p.x0() + static_cast<float>(p.size()) * p.step()) continue;
        const int lo = p.column_of(a), hi = p.column_of(b), start = p.column_of(from);
        float top_ref = start >= lo && start <= hi ? line(start, r) : NAN;
        for (int dir : {-1, 1}) {
          float last_y = line(start, r);
          for (int i = start + dir; ((dir > 0 ? hi : lo) - i) * dir >= 0; i += dir) {
            const float y = line(i, r);
            if (std::isnan(y)) continue;
            if (!std::isnan(last_y) && std::fabs(y - last_y) > r.ramp) break;
            if (i >= lo && i <= hi && !(top_ref >= y)) top_ref = y;
            last_y = y;
          }
        }
        const float got = p.slope_top(from, a, b, r);
        INFO("from " << from << " a " << a << " b " << b << " got " << got << " ref " << top_ref << " start " << start << " lo " << lo << " hi " << hi);
        CHECK(((std::isnan(got) && std::isnan(top_ref)) || got == top_ref));
        ++checked;
      }
    }
  }
  CHECK(checked > 500);
}
