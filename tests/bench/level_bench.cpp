// Ground query through Level's spatial index vs a linear scan over every box doing the same
// test (DESIGN.md §6: a level may hold 100 000 boxes). Both sides use the same shared random
// level and the same pre-generated query spans.

#include <benchmark/benchmark.h>

#include <map>
#include <optional>

#include "ossa/level/level.h"
#include "shared/level_scenes.h"

namespace {

using namespace ossa;

struct Scene {
  Level level;
  std::vector<scenes::GroundQuery> queries;
};

const Scene& scene(int boxes) {
  static std::map<int, Scene> cache;
  auto it = cache.find(boxes);
  if (it == cache.end()) {
    Scene s;
    s.level = scenes::random_level(2024, boxes);
    s.queries = scenes::random_ground_queries(2025, s.level, 4096);
    it = cache.emplace(boxes, std::move(s)).first;
  }
  return it->second;
}

// The reference: the obvious loop over all boxes.
std::optional<GroundHit> linear_ground(const std::vector<Box>& boxes, float x_min, float x_max,
                                       float from_y, float max_drop) {
  std::optional<GroundHit> best;
  const float lo = from_y - max_drop, hi = from_y + kGroundEpsilon;
  for (int i = 0, n = static_cast<int>(boxes.size()); i < n; ++i) {
    const Box& b = boxes[i];
    if (b.min_ws.x <= x_max && b.max_ws.x >= x_min && b.max_ws.y >= lo && b.max_ws.y <= hi &&
        (!best || b.max_ws.y > best->height_ws)) {
      best = GroundHit{b.max_ws.y, i};
    }
  }
  return best;
}

void ground_query_ossa(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)));
  size_t q = 0;
  for (auto _ : state) {
    const scenes::GroundQuery& g = s.queries[q++ & 4095];
    benchmark::DoNotOptimize(s.level.ground_height_below(g.x_min, g.x_max, g.from_y, g.max_drop));
  }
}

void ground_query_reference(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)));
  size_t q = 0;
  for (auto _ : state) {
    const scenes::GroundQuery& g = s.queries[q++ & 4095];
    benchmark::DoNotOptimize(linear_ground(s.level.colliders(), g.x_min, g.x_max, g.from_y, g.max_drop));
  }
}

}  // namespace

BENCHMARK(ground_query_ossa)->Name("ground_query:ossa")->Arg(16)->Arg(256)->Arg(100000);
BENCHMARK(ground_query_reference)->Name("ground_query:reference")->Arg(16)->Arg(256)->Arg(100000);
