// Determinism across builds and commits (STYLE.md: "N fixed steps of a scripted walk hash to a
// stored value"): the horse walks, runs, stops and turns back on every shipped level, and the
// hash of every world matrix of every tick (SimProbe::pose_hash) must equal the value stored
// here, bit for bit, in the Release and in the sanitizer build alike.
//
// When motion changes ON PURPOSE (animator, prototypes, generator, levels), regenerate each
// hash with ossa-sim, which runs the same creature, script, spawn and rate:
//   build/release/bin/ossa-sim --example horse --level levels/default.json
//     --script "walk:0.5:6,run:1:4,stop:1,walk:-0.5:4" --json       (copy "pose_hash")
// (or read the actual value from this test's failure message), and say in the commit message
// why the motion changed. A hash that changes when nothing was meant to move is a bug.
// A new shipped level is one more line in kExpected.

#include <catch2/catch.hpp>

#include <cinttypes>
#include <cstdio>
#include <memory>

#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "ossa/level/level_io.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

constexpr const char* kScript = "walk:0.5:6,run:1:4,stop:1,walk:-0.5:4";  // 15 s at 120 Hz

struct ExpectedHash {
  const char* level;  // file in levels/
  uint64_t pose_hash;
};

constexpr ExpectedHash kExpected[] = {
    {"default.json", 0xc6d9021a9cf0bd6cull},
    {"rough.json", 0xd6133b81a1b4eb9full},
    {"stairs.json", 0x38eea3d9e891a8b6ull},
    {"slopes.json", 0xcf2249e6dc3f0691ull},
    {"drops.json", 0x40219ed074593ed2ull},
};

std::string hex(uint64_t v) {
  char text[24];
  std::snprintf(text, sizeof text, "%016" PRIx64, v);
  return text;
}

}  // namespace

TEST_CASE("the horse's scripted walk hashes to the stored pose hash on every shipped level", "[game][determinism]") {
  for (const ExpectedHash& e : kExpected) {
    const Level level = load_level(scenes::source_path(std::string("levels/") + e.level)).value();
    auto creature = std::make_shared<const Creature>(scenes::quadruped());
    Player player(creature, SplinePrototypes::defaults());
    player.animator().reset(level.spawn_ws + glm::vec2(0.0f, 1.0f), level);  // as ossa-sim does
    const SimResult r = run_script(player, level, parse_script(kScript).value(), 120);
    INFO(e.level << ": pose hash " << hex(r.probe.pose_hash) << ", stored " << hex(e.pose_hash));
    CHECK(r.probe.pose_hash == e.pose_hash);
    CHECK(r.probe.nan_count == 0);
  }
}
