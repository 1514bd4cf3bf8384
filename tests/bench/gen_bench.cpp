// Creature generation throughput: sample + build + rest pose (ossa) against the reference of
// just copying an already built creature (the floor any generator pays to hand one out). That
// is not the same work: no reference generator exists, so the table says what it measures.
#include <benchmark/benchmark.h>

#include "ossa/gen/skeleton_builder.h"
#include "shared/scenes.h"

namespace {

using namespace ossa;

void generate_ossa(benchmark::State& state) {
  const Generator& gen = scenes::generator();
  uint64_t seed = 0;
  for (auto _ : state) {
    Genome g = gen.random(seed++);
    Result<Creature> c = build_creature(g);
    benchmark::DoNotOptimize(c.ok());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(generate_ossa)->Name("generate_creature:ossa");

void generate_reference(benchmark::State& state) {
  const Generator& gen = scenes::generator();
  const Creature built = build_creature(gen.random(1)).value();
  state.SetLabel("copies a built creature: a floor, not the same work");
  for (auto _ : state) {
    Creature copy = built;
    benchmark::DoNotOptimize(copy.skeleton.bone_count());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(generate_reference)->Name("generate_creature:reference");

}  // namespace
