// Fuzzes everything behind a genome the loader accepts (issue 17's one rule): load it, build
// the creature, walk it for 2 simulated seconds of random stick input on a small random level,
// and build its sprite mesh and its body (CPU side; the body skinned in the last pose, resting
// on the level's floor). Nothing may assert, produce a NaN, or hang; every accepted genome must
// also save and load back.
//
// Input: when the bytes parse as a genome file they are that genome (the seeds: shipped
// examples and the reproductions of issue 17); otherwise the bytes themselves are read as a
// genome within the loader's ranges (so mutations explore every field, biased towards the
// ends of each range), saved as JSON and loaded through the real loader. Either way the
// bytes also seed the level and the input.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string_view>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/body/body_floor.h"
#include "ossa/body/body_mesh.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/gen/genome.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/json.h"
#include "ossa/level/level.h"
#include "ossa/math/rng.h"

namespace {

// Reads bytes as values; past the end every read gives 0.
struct Bytes {
  const uint8_t* data;
  size_t size;
  size_t at = 0;
  uint32_t u8() { return at < size ? data[at++] : 0u; }
  uint32_t u16() { return u8() | (u8() << 8); }
  // A value in [lo, hi]: the two ends and the middle often, else anywhere.
  double in(double lo, double hi) {
    const uint32_t pick = u8();
    if (pick < 24) return lo;
    if (pick < 48) return hi;
    if (pick < 64) return 0.5 * (lo + hi);
    return lo + (hi - lo) * (u16() / 65535.0);
  }
};

uint64_t hash(const uint8_t* data, size_t size) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

ossa::Genome genome_from_bytes(Bytes& b) {
  using namespace ossa;
  Genome g;
  g.name = "fuzz";
  for (int d = 0; d < kPcaDims; ++d) g.pca[d] = b.in(pca_range(d).min, pca_range(d).max);
  g.neck_vertebrae = static_cast<int>(b.in(0, kMaxNeckVertebrae));
  g.back_vertebrae = static_cast<int>(b.in(2, kMaxBackVertebrae));
  g.tail_vertebrae = static_cast<int>(b.in(0, kMaxTailVertebrae));
  g.rib_interval = static_cast<float>(b.in(0.0, 1.0));
  g.contact = b.u8() & 1 ? ContactMode::kFlat : ContactMode::kTip;
  g.skull_variant = static_cast<int>(b.u8() % kSkullVariants);
  g.scale = static_cast<float>(b.in(kMinGenomeScale, kMaxGenomeScale));
  g.options.multi_limb = b.u8() & 1;
  g.options.neck_girdle = b.u8() & 1;
  // The body's genes (version 2): a look and appendages anywhere in their ranges.
  g.look.pattern = static_cast<CoatPattern>(b.u8() % kCoatPatternCount);
  g.look.pattern_scale = static_cast<float>(b.in(kMinPatternScale, kMaxPatternScale));
  g.look.fatness = static_cast<float>(b.in(kMinFatness, kMaxFatness));
  g.look.wings = b.u8() & 1 ? WingCover::kMembrane : WingCover::kFeathered;
  const uint32_t kinds = b.u16();
  for (int k = 0; k < kAppendageKindCount && k < 16; ++k) {
    if (kinds >> k & 1u) g.appendages.push_back({static_cast<AppendageKind>(k), static_cast<float>(b.in(kMinAppendageSize, kMaxAppendageSize))});
  }
  g.skull_shape = {static_cast<float>(b.in(kMinSkullLength, kMaxSkullLength)), static_cast<float>(b.in(kMinSkullHeight, kMaxSkullHeight)),
                   static_cast<float>(b.in(kMinSnout, kMaxSnout))};
  const int limbs = static_cast<int>(b.u8() % (kMaxLimbPairs + 1));
  for (int i = 0; i < limbs; ++i) {
    LimbGene l;
    l.kind = static_cast<LimbKind>(b.u8() % 4);
    l.girdle = static_cast<GirdleKind>(b.u8() % 3);
    l.slot = g.options.multi_limb ? static_cast<int>(b.u8() & 1) : 0;
    for (float& a : l.angles) a = static_cast<float>(b.in(-10.0, 10.0));
    g.limbs.push_back(l);
  }
  return g;
}

// Ground from x = -5 to 25 m with a few steps, ledges and gaps sized to the creature.
ossa::Level small_level(ossa::Rng& rng, float size) {
  using namespace ossa;
  Level level;
  level.add_box(Box::from_corner(-5.0f * size, -size, 30.0f * size, size));
  const int extra = rng.uniform_int(0, 6);
  for (int i = 0; i < extra; ++i) {
    const float x = static_cast<float>(rng.uniform(0.5, 20.0)) * size;
    const float w = static_cast<float>(rng.uniform(0.05, 4.0)) * size;
    const float h = static_cast<float>(rng.uniform(0.01, 1.5)) * size;
    const float y = rng.chance(0.7) ? 0.0f : static_cast<float>(rng.uniform(0.0, 2.0)) * size;
    level.add_box(Box::from_corner(x, y, w, h));
  }
  level.spawn_ws = {0.0f, static_cast<float>(rng.uniform(-0.5, 1.0)) * size};
  return level;
}

bool finite(const ossa::Mat2x3& m) {
  for (float v : m.m) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_creature: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ossa;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Genome genome;
  if (Result<Genome> parsed = parse_genome(text, "fuzz.creature.json"); parsed.ok()) {
    genome = *parsed;
  } else {
    Bytes bytes{data, size};
    // Through the real loader: what it accepts must run, what it refuses is not our concern.
    Result<Genome> loaded = genome_from_json(genome_to_json(genome_from_bytes(bytes)), "fuzz.creature.json");
    if (!loaded.ok()) return 0;
    genome = *loaded;
  }
  // Saved files load back.
  if (!genome_from_json(genome_to_json(genome), "saved.creature.json").ok()) fail("a saved genome does not load back");

  Result<Creature> built = build_creature(genome);
  if (!built.ok()) fail("the loader accepted a genome that does not build");
  const Creature& creature = *built;
  if (!creature.skeleton.is_valid()) fail("invalid skeleton");
  if (creature.skeleton.bone_count() > kMaxCreatureBones) fail("more bones than kMaxCreatureBones");

  const SpriteMesh mesh = build_sprite_mesh(creature, default_sprite_set());
  const Box bounds = sprite_mesh_bounds(mesh);
  if (!std::isfinite(bounds.min_ws.x) || !std::isfinite(bounds.max_ws.y)) fail("sprite mesh bounds not finite");

  Rng rng(hash(data, size));
  Animator animator(creature, SplinePrototypes::defaults());
  const float size_m = std::max(animator.hip_height(), 0.05f);
  const Level level = small_level(rng, size_m);
  animator.reset(level.spawn_ws + glm::vec2(0.0f, size_m), level, rng.chance(0.5) ? 1 : -1);
  const float top_speed = std::max(animator.run_speed(), 0.01f) * 1.2f;
  float stick = 0.0f;
  const float dt = 1.0f / 120.0f;
  for (int tick = 0; tick < 240; ++tick) {
    if (tick % 30 == 0) stick = static_cast<float>(rng.uniform(-1.0, 1.0)) * top_speed;
    animator.update(dt, stick, level);
    if (!std::isfinite(animator.x()) || !std::isfinite(animator.velocity())) fail("animator state not finite");
  }
  for (const Mat2x3& m : animator.world_matrices()) {
    if (!finite(m)) fail("pose matrix not finite");
  }

  // The body: built, its indices in range, skinned in the last pose onto the level's floor.
  Result<BodyMesh> body = try_build_body(creature);
  if (!body.ok()) fail("a creature the loader accepted has no body");
  for (const uint32_t i : body->indices) {
    if (i >= body->vertices.size()) fail("body index out of range");
  }
  const std::vector<Mat2x3>& world = animator.world_matrices();
  std::vector<Mat2x3> palette(static_cast<size_t>(body->palette_size()));
  const BodyFloor floor = body_floor(level, creature.skeleton, world, body->reach, body->feet);
  body_palette(*body, world, palette, floor);
  for (const BodyVertex& v : body->vertices) {
    for (int k = 0; k < 4; ++k) {
      if (v.weights[static_cast<size_t>(k)] > 0.0f && v.bones[static_cast<size_t>(k)] >= body->floor_entry()) fail("body vertex beyond its palette");
    }
    const glm::vec2 p = drawn_body_vertex(v, palette, floor);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("skinned body vertex not finite");
  }
  return 0;
}
