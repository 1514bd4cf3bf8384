// FK of a 64-bone chain: ossa's one-pass job on 2x3 matrices against a naive reference that
// does the same pass with general glm::mat3 (translate, rotate, 3x3 products), the way FK is
// often first written.
#include <benchmark/benchmark.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/matrix_transform_2d.hpp>

#include "ossa/skeleton/pose.h"
#include "shared/scenes.h"

namespace {

using namespace ossa;

void fk_ossa(benchmark::State& state) {
  Skeleton s = scenes::chain_skeleton(64, 0.1f, 0.05f);
  Pose pose = Pose::rest(s);
  std::vector<Mat2x3> model(64);
  ForwardKinematicsJob job;
  job.skeleton = &s;
  job.locals = pose.locals;
  job.model = model;
  for (auto _ : state) {
    job.run();
    benchmark::DoNotOptimize(model.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * 64);
}
BENCHMARK(fk_ossa)->Name("fk_64_bones:ossa");

void fk_reference(benchmark::State& state) {
  Skeleton s = scenes::chain_skeleton(64, 0.1f, 0.05f);
  Pose pose = Pose::rest(s);
  std::vector<glm::mat3> model(64);
  for (auto _ : state) {
    for (int i = 0; i < 64; ++i) {
      const BoneLocal& l = pose.locals[i];
      glm::mat3 local = glm::rotate(glm::translate(glm::mat3(1.0f), l.offset_ls), l.angle_ls);
      model[i] = s.parent(i) < 0 ? local : model[s.parent(i)] * local;
    }
    benchmark::DoNotOptimize(model.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * 64);
}
BENCHMARK(fk_reference)->Name("fk_64_bones:reference");

}  // namespace
