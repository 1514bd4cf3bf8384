// Renderer benchmarks (issue "Renderer"): the batched GPU-skinning path of CreatureBatch
// against the per-bone reference, the palette upload against a memcpy of the same bytes, and
// (issue 30) a frame of 1 000 bodies against the same frame of bone sprites.
// Built into ossa-render-bench (tools/ossa-render/CMakeLists.txt) with bench_main.cpp, so the
// ratio table is printed at the end. Runs offscreen (SDL's offscreen driver, Mesa llvmpipe):
// GPU time here is CPU time of the software rasteriser, so the frame figures include it.
//
// tests/bench/CMakeLists.txt globs every *_bench.cpp into ossa-bench, which links ossa::core
// only: this file compiles to nothing there; ossa-render-bench defines OSSA_RENDER_BENCH.
#ifdef OSSA_RENDER_BENCH

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "ossa/body/body_floor.h"
#include "ossa/body/body_mesh.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/data_dir.h"
#include "ossa/platform/window.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/gl.h"
#include "ossa/render/renderer.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/render/texture.h"
#include "ossa/skeleton/pose.h"

namespace {

using namespace ossa;

constexpr int kCreatures = 1000;
constexpr int kWidth = 640, kHeight = 360;

// One GL context, renderer, atlas and a batch of 1000 creatures (20 examples and random
// creatures mixed) with their world matrices, built once per process.
struct Scene {
  Window window;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Atlas> atlas;
  std::unique_ptr<CreatureBatch> batch;
  std::unique_ptr<CreatureBatch> rigid_batch;  // the same creatures without smooth skinning
  std::unique_ptr<CreatureBatch> body_batch;   // the same creatures with bodies (issue 30)
  std::vector<BodyMesh> bodies;                // per kind
  Level ground;                                // a floor under the grid's rows
  std::vector<Creature> kinds;
  std::vector<int> kind_of;                  // per instance
  std::vector<std::vector<Mat2x3>> world;    // per instance, per bone
  bool ok = false;

  Scene() {
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    WindowDesc desc;
    desc.width = kWidth;
    desc.height = kHeight;
    desc.offscreen = true;
    auto w = Window::create(desc);
    if (!w.ok()) return;
    window = std::move(w.value());
    auto r = Renderer::create(default_shader_dir());
    if (!r.ok()) return;
    renderer = std::make_unique<Renderer>(std::move(r.value()));
    const std::string dir = data_path("assets/sprites/bones");
    auto set = load_sprite_set(dir + "/sprites.json");
    atlas = std::make_unique<Atlas>(Atlas::build(set.ok() ? set.value() : default_sprite_set(), dir));
    auto gen = Generator::load(data_path("assets/creatures/examples.json"), ossa::body_volume_m3);
    if (!gen.ok()) return;
    for (const char* name : {"horse", "kangaroo", "giraffe", "pig", "red deer"}) {
      if (auto g = gen->example(name, 1); g.ok()) {
        if (auto c = build_creature(g.value()); c.ok()) kinds.push_back(std::move(c.value()));
      }
    }
    for (uint64_t seed = 1; kinds.size() < 20; ++seed) {
      if (auto c = build_creature(gen->random(seed)); c.ok()) kinds.push_back(std::move(c.value()));
    }
    batch = std::make_unique<CreatureBatch>();
    rigid_batch = std::make_unique<CreatureBatch>();
    body_batch = std::make_unique<CreatureBatch>();
    for (const Creature& c : kinds) bodies.push_back(build_body(c));
    for (int row = 0; row < kCreatures / 40; ++row) ground.add_box(Box::from_corner(-2.0f, 2.5f * static_cast<float>(row) - 0.5f, 124.0f, 0.5f));
    std::vector<SpriteMesh> meshes, rigid_meshes;
    SpriteMeshOptions rigid;
    rigid.smooth_weights = false;
    for (const Creature& c : kinds) {
      meshes.push_back(build_sprite_mesh(c, atlas->sprites));
      rigid_meshes.push_back(build_sprite_mesh(c, atlas->sprites, rigid));
    }
    for (int i = 0; i < kCreatures; ++i) {
      const int k = i % static_cast<int>(kinds.size());
      kind_of.push_back(k);
      batch->add(meshes[k], kinds[k].skeleton);
      rigid_batch->add(rigid_meshes[k], kinds[k].skeleton);
      body_batch->add_body(bodies[k], kinds[k].skeleton);
      // A 40 x 25 grid of creatures, 3 m apart.
      Transform2D place;
      place.translation = {3.0f * static_cast<float>(i % 40), 2.5f * static_cast<float>(i / 40)};
      const auto model = model_matrices(kinds[k].skeleton, kinds[k].rest_pose.locals);
      std::vector<Mat2x3> wm(model.size());
      for (size_t b = 0; b < model.size(); ++b) wm[b] = place.to_mat2x3() * model[b];
      world.push_back(std::move(wm));
    }
    renderer->camera.fit({{-1.0f, -1.0f}, {120.0f, 63.0f}}, float(kWidth) / kHeight, 0.02f);
    ok = true;
  }

  void build_palettes() {
    for (int i = 0; i < kCreatures; ++i) batch->set_world(i, world[i]);
  }
  void build_rigid_palettes() {
    for (int i = 0; i < kCreatures; ++i) rigid_batch->set_world(i, world[i]);
  }
  // As the game does every frame: each body's palette and the floor under it.
  void build_body_palettes() {
    for (int i = 0; i < kCreatures; ++i) {
      const int k = kind_of[static_cast<size_t>(i)];
      body_batch->set_world(i, world[i]);
      body_batch->set_floor(i, body_floor(ground, kinds[k].skeleton, world[i], bodies[k].reach, bodies[k].feet));
    }
  }
};

Scene& scene() {
  static Scene s;
  return s;
}

void frame_1000_creatures_ossa(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  for (auto _ : state) {
    s.build_palettes();
    s.batch->upload_palettes();
    s.renderer->begin_frame(kWidth, kHeight, {0.5f, 0.6f, 0.7f});
    s.renderer->draw_batch(*s.batch, s.atlas->texture);
    glFinish();
  }
  state.counters["draw_calls"] = s.renderer->stats.draw_calls;
  state.counters["bones"] = s.batch->bone_count();
  state.counters["vertices"] = s.batch->vertex_count();
}

void frame_1000_creatures_reference(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  for (auto _ : state) {
    s.build_palettes();
    s.renderer->begin_frame(kWidth, kHeight, {0.5f, 0.6f, 0.7f});
    s.renderer->draw_batch_naive(*s.batch, s.atlas->texture);
    glFinish();
  }
  state.counters["draw_calls"] = s.renderer->stats.draw_calls;
  state.counters["bones"] = s.batch->bone_count();
  state.counters["vertices"] = s.batch->vertex_count();
}

// Smooth skinning's cost: the same frame with smooth weights (ossa's default: more vertices —
// blend columns and four rows of quads on limb sprites — and three mid-joint palette entries
// per limb joint) against rigid sprites (the reference).
void smooth_skinning_frame_ossa(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  for (auto _ : state) {
    s.build_palettes();
    s.batch->upload_palettes();
    s.renderer->begin_frame(kWidth, kHeight, {0.5f, 0.6f, 0.7f});
    s.renderer->draw_batch(*s.batch, s.atlas->texture);
    glFinish();
  }
  state.counters["vertices"] = s.batch->vertex_count();
  state.counters["palette"] = s.batch->palette_size();
}

void smooth_skinning_frame_reference(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  state.SetLabel("rigid sprites: the frame without smooth skinning");
  for (auto _ : state) {
    s.build_rigid_palettes();
    s.rigid_batch->upload_palettes();
    s.renderer->begin_frame(kWidth, kHeight, {0.5f, 0.6f, 0.7f});
    s.renderer->draw_batch(*s.rigid_batch, s.atlas->texture);
    glFinish();
  }
  state.counters["vertices"] = s.rigid_batch->vertex_count();
  state.counters["palette"] = s.rigid_batch->palette_size();
}

// Bodies (issue 30: a frame of 1 000 creatures with bodies at most 1.5 times the same frame
// with bone sprites): palettes and floors, the one upload, the body look's draws, against the
// bone sprites' frame of the same creatures (the reference).
void bodies_frame_ossa(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  const int uploads = s.body_batch->palette_uploads();
  for (auto _ : state) {
    s.build_body_palettes();
    s.body_batch->upload_palettes();
    s.renderer->begin_frame(kWidth, kHeight, {0.5f, 0.6f, 0.7f});
    s.renderer->draw_creatures(*s.body_batch, {}, CreatureLook::kBody);
    glFinish();
  }
  state.counters["draw_calls"] = s.renderer->stats.draw_calls;
  state.counters["vertices"] = s.body_batch->body_vertex_count();
  state.counters["uploads_per_frame"] = static_cast<double>(s.body_batch->palette_uploads() - uploads) / static_cast<double>(state.iterations());
}

void bodies_frame_reference(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  state.SetLabel("the same creatures' bone-sprite frame");
  const Texture* textures[] = {&s.atlas->texture};
  for (auto _ : state) {
    s.build_palettes();
    s.batch->upload_palettes();
    s.renderer->begin_frame(kWidth, kHeight, {0.5f, 0.6f, 0.7f});
    s.renderer->draw_creatures(*s.batch, textures, CreatureLook::kBones);
    glFinish();
  }
  state.counters["draw_calls"] = s.renderer->stats.draw_calls;
  state.counters["vertices"] = s.batch->vertex_count();
}

void palette_upload_ossa(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  s.build_palettes();
  for (auto _ : state) {
    s.batch->upload_palettes();
    glFinish();  // the driver copies at once or at the next sync; count it either way
  }
  state.SetBytesProcessed(state.iterations() * int64_t(s.batch->palette().size_bytes()));
}

void palette_upload_reference(benchmark::State& state) {
  Scene& s = scene();
  if (!s.ok) return state.SkipWithError("no GL context / data");
  s.build_palettes();
  const auto src = s.batch->palette();
  std::vector<Mat2x3> dst(src.size());
  for (auto _ : state) {
    std::memcpy(dst.data(), src.data(), src.size_bytes());
    benchmark::DoNotOptimize(dst.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(state.iterations() * int64_t(src.size_bytes()));
}

BENCHMARK(frame_1000_creatures_ossa)->Name("frame_1000_creatures:ossa")->Unit(benchmark::kMillisecond);
BENCHMARK(frame_1000_creatures_reference)->Name("frame_1000_creatures:reference")->Unit(benchmark::kMillisecond);
BENCHMARK(smooth_skinning_frame_ossa)->Name("smooth_skinning_frame:ossa")->Unit(benchmark::kMillisecond);
BENCHMARK(smooth_skinning_frame_reference)->Name("smooth_skinning_frame:reference")->Unit(benchmark::kMillisecond);
BENCHMARK(bodies_frame_ossa)->Name("bodies_frame_1000:ossa")->Unit(benchmark::kMillisecond);
BENCHMARK(bodies_frame_reference)->Name("bodies_frame_1000:reference")->Unit(benchmark::kMillisecond);
BENCHMARK(palette_upload_ossa)->Name("palette_upload:ossa")->Unit(benchmark::kMicrosecond);
BENCHMARK(palette_upload_reference)->Name("palette_upload:reference")->Unit(benchmark::kMicrosecond);

}  // namespace
#endif  // OSSA_RENDER_BENCH
