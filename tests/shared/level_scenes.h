#pragma once
// Shared levels for tests and benchmarks (STYLE.md "shared scenes"): the same random city
// feeds the query property tests and the ground-query benchmark.

#include <cstdint>
#include <vector>

#include "ossa/level/level.h"

namespace ossa::scenes {

// One ground box of the given width (metres) from x = 0, top at y = 0, 1 m thick; spawn at
// (1, 0).
Level flat_level(float width);

// Parameters of random_level(). Lengths in metres.
struct RandomLevelOptions {
  float metres_per_box = 2.0f;  // world width = box_count * metres_per_box (constant density)
  float world_height = 12.0f;   // box bottoms are uniform in [0, world_height]
  float min_size = 0.1f;        // box widths and heights are uniform in [min_size, max_size]
  float max_size = 3.0f;
};

// A "city" of `box_count` random boxes spread over a world whose width grows with the count,
// so every query meets a similar number of nearby boxes at any size. Deterministic per seed.
Level random_level(uint64_t seed, int box_count, const RandomLevelOptions& options = {});

// Stairs: flat run-up, `steps` steps up (rise and tread in metres), a landing, the same steps
// down, and a flat run-out. Every box is a column from y = -1 up to its step's top.
Level stairs_level(int steps = 8, float rise = 0.15f, float tread = 0.3f);

// Ground-query inputs spread over a level: span, start height and drop.
struct GroundQuery {
  float x_min, x_max, from_y, max_drop;
};
// `count` queries over `level.bounds()`: spans 0–0.5 m wide, from_y anywhere from below the
// level to above it, drops 0–4 m. Deterministic per seed.
std::vector<GroundQuery> random_ground_queries(uint64_t seed, const Level& level, int count);

}  // namespace ossa::scenes
