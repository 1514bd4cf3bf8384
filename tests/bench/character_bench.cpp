// Rigged characters against generated creatures (issue 15, item 7): 1 000 animated shipped
// humanoids (or dogs) per tick against 1 000 horses, measured in the same run, the same work
// per creature: Animator::update on flat ground at the same Froude number (0.25, a walk) and
// the world matrices the renderer's palette is made from.
//   characters_1000:ossa       1 000 humanoids (assets/characters/humanoid.rig.json)
//   characters_1000:reference  1 000 horses (the example horse, as in anim_bench.cpp)
//   dogs_1000:ossa             1 000 dogs (assets/characters/dog.rig.json, two leg pairs)
//   dogs_1000:reference        the horses again
// The ratio table then reads per-creature cost of a character / of a horse.
//
// Built into ossa-render-bench (it loads the characters' meshes through Assimp); ossa-bench
// links ossa::core only: there this file compiles to nothing.
#ifdef OSSA_RENDER_BENCH

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/anim/animator.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/data_dir.h"
#include "ossa/render/character_mesh.h"

namespace {

using namespace ossa;

constexpr int kCount = 1000;
constexpr float kFroude = 0.25f;
constexpr float kDt = 1.0f / 120.0f;

struct Crowd {
  Level level{{Box::from_corner(-10.0f, -1.0f, 5000.0f, 1.0f)}};
  std::shared_ptr<const Creature> creature;  // keeps the horse alive for its animators
  std::vector<std::unique_ptr<Animator>> animators;
  float speed = 0.0f;  // m/s

  void start() {
    const AnimatorParams params;
    speed = std::sqrt(kFroude * params.gravity * animators.front()->hip_height());
    for (size_t i = 0; i < animators.size(); ++i) {
      animators[i]->reset({2.0f + 0.37f * static_cast<float>(i % 100), 1.0f}, level);
      // Desynchronise: each starts some ticks into its walk.
      for (size_t t = 0; t < i % 120; ++t) animators[i]->update(kDt, speed, level);
    }
  }
  void tick() {
    for (auto& a : animators) {
      a->update(kDt, speed, level);
      benchmark::DoNotOptimize(a->world_matrices().data());
    }
  }
};

Crowd& horses() {
  static Crowd c = [] {
    Crowd h;
    // The horse of the animator benchmark (scenes::quadruped(); this binary has no test scenes).
    const Generator gen = Generator::load(data_path("assets/creatures/examples.json"), ossa::body_volume_m3).value();
    h.creature = std::make_shared<const Creature>(build_creature(gen.example("horse").value()).value());
    for (int i = 0; i < kCount; ++i) h.animators.push_back(std::make_unique<Animator>(*h.creature, SplinePrototypes::defaults()));
    h.start();
    return h;
  }();
  return c;
}

Crowd* characters(const char* name) {
  auto make = [](const char* n) -> Crowd* {
    Result<LoadedCharacter> c = load_character(data_path(std::string("assets/characters/") + n + ".rig.json"));
    if (!c.ok()) return nullptr;
    auto* crowd = new Crowd;
    for (int i = 0; i < kCount; ++i) crowd->animators.push_back(std::make_unique<Animator>(c->character->rig, SplinePrototypes::defaults()));
    crowd->start();
    return crowd;
  };
  static Crowd* humanoids = make("humanoid");
  static Crowd* dogs = make("dog");
  return std::string(name) == "humanoid" ? humanoids : dogs;
}

void run(benchmark::State& state, Crowd* crowd) {
  if (!crowd) {
    state.SkipWithError("cannot load the character (assets/characters)");
    return;
  }
  for (auto _ : state) {
    crowd->tick();
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kCount);
  // Seconds per creature: an inverted rate is printed in seconds with an SI prefix ("410us",
  // "3.2ms"); a value already in microseconds would be printed as "410s" or "1.2ks".
  state.counters["time_per_creature"] = benchmark::Counter(static_cast<double>(state.iterations()) * kCount,
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void humanoids(benchmark::State& state) { run(state, characters("humanoid")); }
void dogs(benchmark::State& state) { run(state, characters("dog")); }
void horses_for_humanoids(benchmark::State& state) {
  state.SetLabel("1 000 horses: other creatures, the same ticks");
  run(state, &horses());
}
void horses_for_dogs(benchmark::State& state) {
  state.SetLabel("1 000 horses: other creatures, the same ticks");
  run(state, &horses());
}

BENCHMARK(humanoids)->Name("characters_1000:ossa")->Unit(benchmark::kMicrosecond);
BENCHMARK(horses_for_humanoids)->Name("characters_1000:reference")->Unit(benchmark::kMicrosecond);
BENCHMARK(dogs)->Name("dogs_1000:ossa")->Unit(benchmark::kMicrosecond);
BENCHMARK(horses_for_dogs)->Name("dogs_1000:reference")->Unit(benchmark::kMicrosecond);

}  // namespace

#endif  // OSSA_RENDER_BENCH
