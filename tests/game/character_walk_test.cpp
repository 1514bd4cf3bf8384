// A character built from an imported skeleton and a rig mapping (rig/character.h) walks
// through the game layer's Player like a generated creature (the build itself is tested in
// tests/rig/character_test.cpp).

#include <catch2/catch.hpp>

#include <memory>

#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "shared/imported_biped.h"
#include "shared/level_scenes.h"

using namespace ossa;

TEST_CASE("a built character walks, runs, stops and turns on flat ground like a creature", "[game][rig]") {
  const scenes::ImportedBiped b = scenes::imported_biped();
  auto c = std::make_shared<const Character>(build_character(b.skeleton, b.mapping, "biped.rig.json").value());
  const Level flat = scenes::flat_level(400.0f);
  Player player(c, SplinePrototypes::defaults());
  CHECK(player.is_character());
  CHECK(player.name() == "biped");
  CHECK_FALSE(player.animator().has_creature());
  player.animator().reset(flat.spawn_ws + glm::vec2(0.0f, 1.0f), flat);
  const SimResult r = run_script(player, flat, parse_script("walk:0.5:6,run:1:6,stop:1,walk:-0.5:6").value(), 120);
  CHECK(r.probe.max_stance_slip_m <= 0.001f);
  CHECK(r.probe.max_limb_penetration_m <= 0.001f);
  CHECK(r.probe.nan_count == 0);
  for (const SegmentMetrics& s : r.segments) {
    INFO(s.command);
    CHECK(s.speed_error <= 0.02f);
  }
  CHECK(r.steps > 20);
}

