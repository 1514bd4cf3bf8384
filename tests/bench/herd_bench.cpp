// Herds on every core (issue 31): one fixed tick (1/60 s) of a herd of walking creatures, for
// herds of 1, 100, 1 000 and 10 000, on 1 thread and on every core.
//   herd_horses:ossa/n:N/threads:T     step_all(herd, T threads): N horses sharing one rig
//   herd_mixed:ossa/n:N/threads:T      the same for N creatures of 8 random genomes (8 rigs)
//   herd_*:reference/n:N/threads:T     the single-thread reference: the same herd stepped one
//                                      entity after the other on this thread by a plain loop of
//                                      Entity::step (no prefetch of the creatures ahead; T is
//                                      ignored; it is measured again beside each row for the
//                                      ratio)
// Wall-clock times (UseRealTime): the ratio of a T-thread row is its speed-up over one core.
// Counters: time_per_tick, time_per_creature (seconds per creature per tick) and
// bytes_per_creature (heap bytes the herd holds after its first steps, divided by N: entity,
// animator and their buffers; the shared rigs are included once, so they vanish in large
// herds; the herd's own lists of pointers and controls are not).
#include <benchmark/benchmark.h>

#include <malloc.h>

#include <memory>
#include <vector>

#include "ossa/game/herd.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

namespace {

using namespace ossa;

constexpr float kDt = 1.0f / 60.0f;

const std::vector<std::shared_ptr<const Creature>>& genomes(bool mixed) {
  static const std::vector<std::shared_ptr<const Creature>> horses{std::make_shared<const Creature>(scenes::quadruped())};
  static const std::vector<std::shared_ptr<const Creature>> random = [] {
    std::vector<std::shared_ptr<const Creature>> out;
    for (uint64_t seed = 1; out.size() < 8 && seed < 64; ++seed) {
      Result<Creature> c = build_creature(scenes::generator().random(seed * 7919));
      if (c.ok()) out.push_back(std::make_shared<const Creature>(std::move(c).value()));
    }
    return out;
  }();
  return mixed ? random : horses;
}

struct Herd {
  Level level = scenes::flat_level(5000.0f);
  RigCache rigs;
  std::vector<std::unique_ptr<Entity>> entities;
  std::vector<Entity*> list;
  std::vector<Controls> controls;
  double bytes_per_creature = 0.0;

  Herd(int n, bool mixed) {
    const auto& kinds = genomes(mixed);
    entities.reserve(n);
    list.reserve(n);
    controls.reserve(n);
    const size_t before = mallinfo2().uordblks;
    for (int i = 0; i < n; ++i) {
      const auto& c = kinds[static_cast<size_t>(i) % kinds.size()];
      entities.push_back(std::make_unique<Entity>(c, rigs.rig(c), SplinePrototypes::defaults()));
    }
    Controls walk;
    walk.move_x = 0.6f;
    for (int i = 0; i < n; ++i) {
      Animator& a = entities[i]->animator();
      a.reset({2.0f + 0.37f * static_cast<float>(i % 1000), 1.5f}, level);
      list.push_back(entities[i].get());
      controls.push_back(walk);
      // Desynchronise: each creature starts some ticks into its walk.
      for (int t = 0; t < i % 30 + 1; ++t) entities[i]->step(kDt, walk, level);
    }
    // After the first steps: buffers an animator fills lazily are counted too.
    bytes_per_creature = static_cast<double>(mallinfo2().uordblks - before) / n;
  }
};

void report(benchmark::State& state, const Herd& h, int n) {
  using benchmark::Counter;
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["time_per_tick"] = Counter(static_cast<double>(state.iterations()), Counter::kIsRate | Counter::kInvert);
  state.counters["time_per_creature"] =
      Counter(static_cast<double>(state.iterations()) * n, Counter::kIsRate | Counter::kInvert);
  state.counters["bytes_per_creature"] = Counter(h.bytes_per_creature, Counter::kDefaults, Counter::kIs1024);
}

template <bool kMixed>
void herd_ossa(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), threads = static_cast<int>(state.range(1));
  Herd h(n, kMixed);
  for (auto _ : state) {
    step_all(h.list, h.controls, kDt, h.level, threads);
    benchmark::ClobberMemory();
  }
  report(state, h, n);
}

template <bool kMixed>
void herd_reference(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Herd h(n, kMixed);
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) h.list[i]->step(kDt, h.controls[i], h.level);
    benchmark::ClobberMemory();
  }
  report(state, h, n);
}

void herd_args(benchmark::internal::Benchmark* b) {
  b->ArgNames({"n", "threads"});
  const int all = resolve_threads(0);
  for (int n : {1, 100, 1000, 10000}) {
    b->Args({n, 1});
    if (all > 1) b->Args({n, all});
  }
  b->UseRealTime()->Unit(benchmark::kMicrosecond);
}

BENCHMARK(herd_ossa<false>)->Name("herd_horses:ossa")->Apply(herd_args);
BENCHMARK(herd_reference<false>)->Name("herd_horses:reference")->Apply(herd_args);
BENCHMARK(herd_ossa<true>)->Name("herd_mixed:ossa")->Apply(herd_args);
BENCHMARK(herd_reference<true>)->Name("herd_mixed:reference")->Apply(herd_args);

}  // namespace
