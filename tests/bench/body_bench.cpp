// Body building (issue 30: a body in at most 2 ms per creature): build_body for the 44
// examples in turn (ossa) against generating those creatures from their genomes — skeleton,
// limbs and rest pose (the reference: the work a body dresses). The ratio says what a body
// adds to a creature's creation; items/s gives the bodies per second (1 / time per body).
#include <benchmark/benchmark.h>

#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/scenes.h"

namespace {

using namespace ossa;

const std::vector<Genome>& example_genomes() {
  static const std::vector<Genome> genomes = [] {
    std::vector<Genome> out;
    for (const Animal& a : scenes::generator().dataset().animals) out.push_back(scenes::generator().example(a.name).value());
    return out;
  }();
  return genomes;
}

const std::vector<Creature>& example_creatures() {
  static const std::vector<Creature> creatures = [] {
    std::vector<Creature> out;
    for (const Genome& g : example_genomes()) out.push_back(build_creature(g).value());
    return out;
  }();
  return creatures;
}

void body_build_ossa(benchmark::State& state) {
  const std::vector<Creature>& creatures = example_creatures();
  size_t i = 0;
  for (auto _ : state) {
    const BodyMesh body = build_body(creatures[i++ % creatures.size()]);
    benchmark::DoNotOptimize(body.vertices.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(body_build_ossa)->Name("body_build:ossa")->Unit(benchmark::kMillisecond);

void body_build_reference(benchmark::State& state) {
  const std::vector<Genome>& genomes = example_genomes();
  size_t i = 0;
  state.SetLabel("generates the creatures the bodies dress: other work");
  for (auto _ : state) {
    Result<Creature> c = build_creature(genomes[i++ % genomes.size()]);
    benchmark::DoNotOptimize(c.ok());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(body_build_reference)->Name("body_build:reference")->Unit(benchmark::kMillisecond);

}  // namespace
