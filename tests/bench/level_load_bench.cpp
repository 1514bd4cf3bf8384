// Loading a level file of N boxes (issue 33: 1 000 000 boxes, the documented maximum, in under
// 5 s; 100 000 in under 0.5 s) and the per-tick kill height, each against a reference doing
// the same work the plain way in the same run:
// - level_load: load_level's parse (duplicate keys refused, nesting and memory bounded, every
//   field checked) against nlohmann::json::parse with no checks at all and a loop reading the
//   four numbers of each box into a Level. The ratio is the price of the checks; before
//   issue 33 the duplicate-key check alone made the load quadratic (100 000 boxes 2.4 s,
//   1 000 000 over 5 minutes).
// - kill_y: Level::kill_y (the index's root bound) against a scan for the lowest box, what
//   every creature paid every tick before.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "ossa/io/json.h"
#include "ossa/level/level.h"
#include "ossa/level/level_io.h"
#include "shared/level_scenes.h"

namespace {

using namespace ossa;

// The file text of a random level of `boxes` boxes (as save_level writes it), made once.
const std::string& level_text(int boxes) {
  static std::map<int, std::string> cache;
  auto it = cache.find(boxes);
  if (it == cache.end()) {
    // Within the ±1000 m a level file allows: 1 800 m wide whatever the count.
    scenes::RandomLevelOptions o;
    o.metres_per_box = 1800.0f / static_cast<float>(boxes);
    o.min_size = 0.01f;
    o.max_size = 1.0f;
    Level level = scenes::random_level(33, boxes, o);
    std::vector<Box> moved = level.colliders();
    for (Box& b : moved) b = b.translated({-900.0f, 0.0f});
    level.set_colliders(std::move(moved));
    it = cache.emplace(boxes, level_to_text(level)).first;
  }
  return it->second;
}

void level_load_ossa(benchmark::State& state) {
  const std::string& text = level_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Result<Level> level = parse_level(text, "bench.json");
    if (!level) state.SkipWithError(level.message().c_str());
    benchmark::DoNotOptimize(level);
  }
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
}

void level_load_reference(benchmark::State& state) {
  const std::string& text = level_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const nlohmann::json doc = nlohmann::json::parse(text);
    std::vector<Box> boxes;
    boxes.reserve(doc["colliders"].size());
    for (const auto& c : doc["colliders"]) {
      const float x = c["x"].get<float>(), y = c["y"].get<float>();
      boxes.push_back(Box{{x, y}, {x + c["w"].get<float>(), y + c["h"].get<float>()}});
    }
    Level level(std::move(boxes), {doc["spawn"]["x"].get<float>(), doc["spawn"]["y"].get<float>()});
    benchmark::DoNotOptimize(level);
  }
}

const Level& kill_level(int boxes) {
  static std::map<int, Level> cache;
  auto it = cache.find(boxes);
  if (it == cache.end()) it = cache.emplace(boxes, scenes::random_level(34, boxes)).first;
  return it->second;
}

void kill_y_ossa(benchmark::State& state) {
  const Level& level = kill_level(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(level.kill_y(1.0f));
}

void kill_y_reference(benchmark::State& state) {
  const Level& level = kill_level(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    float lowest = level.colliders().front().min_ws.y;
    for (const Box& b : level.colliders()) lowest = std::min(lowest, b.min_ws.y);
    benchmark::DoNotOptimize(lowest - Level::kKillMargin);
  }
}

}  // namespace

BENCHMARK(level_load_ossa)->Name("level_load:ossa")->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(level_load_reference)->Name("level_load:reference")->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(kill_y_ossa)->Name("kill_y:ossa")->Arg(100000)->Arg(1000000);
BENCHMARK(kill_y_reference)->Name("kill_y:reference")->Arg(100000)->Arg(1000000);
