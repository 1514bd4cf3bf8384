#include "ossa/game/sim.h"

#include <catch2/catch.hpp>

#include <memory>
#include <optional>

#include "ossa/game/outline_probe.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/level/level_io.h"
#include "ossa/game/player.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

SimResult run_horse(const Level& level, const char* text) {
  auto creature = std::make_shared<const Creature>(scenes::quadruped());
  Player player(creature, SplinePrototypes::defaults());
  player.animator().reset({2.0f, 1.0f}, level);
  return run_script(player, level, parse_script(text).value(), 120);
}

}  // namespace

TEST_CASE("parse_script reads walk, run and stop segments and names the bad one", "[game][sim]") {
  const auto ok = parse_script("walk:0.5:10,run:-1:6,stop:2");
  REQUIRE(ok.ok());
  REQUIRE(ok->size() == 3);
  CHECK((*ok)[1].mode == "run");
  CHECK((*ok)[1].stick == -1.0f);
  CHECK((*ok)[2].controls().move_x == 0.0f);
  const auto bad = parse_script("walk:0.5:1,fly:1:2");
  REQUIRE_FALSE(bad.ok());
  CHECK_THAT(bad.message(), Catch::Contains("segment 1"));
}

TEST_CASE("parse_script reads jump (one tick) and jump:SECONDS (held), keeping the stick", "[game][sim]") {
  const auto ok = parse_script("run:1:2,jump,jump:0.5,walk:0.5:1");
  REQUIRE(ok.ok());
  REQUIRE(ok->size() == 4);
  CHECK((*ok)[1].mode == "jump");
  CHECK((*ok)[1].ticks(120) == 1);
  CHECK((*ok)[2].ticks(120) == 60);
  const Controls held = (*ok)[1].controls((*ok)[0].controls());
  CHECK(held.jump);
  CHECK(held.move_x == 1.0f);  // the stick of the segment before
  CHECK(held.run);
  CHECK_FALSE((*ok)[3].controls(held).jump);
  for (const char* bad : {"jump:x", "jump:-1", "jump:1:2"}) {
    const auto r = parse_script(std::string("walk:0.5:1,") + bad);
    INFO(bad);
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains("segment 1"));
  }
}

TEST_CASE("x_reached is the final x, x_max_m the furthest right, blocked_s the time at a wall", "[game][sim]") {
  SECTION("there and back on flat ground: never blocked, ends short of its furthest point") {
    const Level flat = scenes::flat_level(100.0f);
    const SimResult r = run_horse(flat, "walk:0.5:4,stop:1,walk:-0.5:3");
    CHECK(r.blocked_s == 0.0f);
    CHECK(r.x_max_m > 5.0f);
    CHECK(r.x_reached < r.x_max_m - 2.0f);
  }
  SECTION("into a wall: blocked most of the time, the furthest x in front of the wall") {
    Level wall = scenes::flat_level(40.0f);
    wall.add_box(Box::from_corner(8.0f, 0.0f, 0.5f, 3.0f));
    const SimResult r = run_horse(wall, "walk:0.6:10");
    CHECK(r.x_max_m < 8.0f);
    CHECK(r.x_max_m > 5.0f);
    CHECK(r.x_reached == r.x_max_m);  // it stopped where it got furthest
    CHECK(r.blocked_s > 4.0f);
    CHECK(r.blocked_s <= 10.0f);
  }
}

TEST_CASE("joint_angles: each leg's hip, knee and ankle in stance and swing, 180 degrees in line", "[game][sim]") {
  const Level flat = scenes::flat_level(100.0f);
  SECTION("walking: every leg stands and swings, and folds its knee further in the swing") {
    const SimResult r = run_horse(flat, "walk:0.5:6");
    REQUIRE(r.probe.joint_angles.size() == 4);
    for (const SimProbe::LegJointAngles& leg : r.probe.joint_angles) {
      for (const auto* phase : {&leg.stance, &leg.swing}) {
        for (const SimProbe::AngleStats& s : *phase) {
          REQUIRE(s.count > 0);
          CHECK(s.min > 0.0f);
          CHECK(s.min <= s.mean() + 1e-3f);
          CHECK(s.mean() < 360.0f);
        }
      }
      CHECK(leg.swing[1].min < leg.stance[1].min);
    }
  }
  SECTION("standing: every tick counts as stance, none as swing") {
    const SimResult r = run_horse(flat, "stop:3");
    REQUIRE(r.probe.joint_angles.size() == 4);
    for (const SimProbe::LegJointAngles& leg : r.probe.joint_angles) {
      for (size_t k = 0; k < 3; ++k) {
        CHECK(leg.swing[k].count == 0);
        CHECK(leg.stance[k].count == 360);
      }
    }
  }
}

TEST_CASE("OutlineProbe measures the drawn body where the bones' figure does not look", "[game][sim]") {
  // The drawn body (flesh, fins, horns beyond the bones, rested on the floor as the game draws
  // it) against the level. Walking on flat ground it stays out. The chamois climbing
  // default.json's stairs keeps its bones out of the steps, but the drawn flesh of its chest
  // lies 3.6 cm in the riser ahead (README Known limits), which only the outline figure sees.
  auto run = [&](const char* name, const Level& level, const char* script, std::optional<OutlineProbe>& outline) {
    const auto c = std::make_shared<const Creature>(build_creature(scenes::generator().example(name).value()).value());
    outline.emplace(*c);
    Player player(c, SplinePrototypes::defaults());
    player.animator().reset(level.spawn_ws + glm::vec2(0.0f, 1.0f), level);
    return run_script(player, level, parse_script(script).value(), 120, [&](long long tick) {
      outline->observe(player.animator(), level, static_cast<float>(tick + 1) / 120.0f);
    });
  };
  std::optional<OutlineProbe> outline;
  // The run's bones and its legs' drawn outline within 1 mm of every box.
  auto legs_clear = [&](const char* animal, const char* level, const char* script) {
    const SimResult r = run(animal, load_level(scenes::source_path(level)).value(), script, outline);
    INFO(animal << " on " << level << ", " << script << ": leg " << outline->max_by_kind[static_cast<size_t>(BodyPartKind::kLeg)]
                << " m, deepest " << outline->deepest_outline_part << " at " << outline->deepest_outline_at_s << " s");
    CHECK(r.probe.max_penetration_m <= 0.001f);
    CHECK(outline->max_by_kind[static_cast<size_t>(BodyPartKind::kLeg)] <= 0.001f);
    return r;
  };
  SECTION("on flat ground: out of it") {
    const SimResult r = run("horse", scenes::flat_level(100.0f), "walk:0.6:4,run:1:3", outline);
    INFO("deepest " << outline->deepest_outline_part << " " << outline->max_outline_penetration_m << " m at " << outline->deepest_outline_at_s << " s");
    CHECK(outline->max_outline_penetration_m <= 0.001f);
    CHECK(r.probe.max_penetration_m <= 0.001f);
  }
  SECTION("under a ceiling just above its bones: the bones out of it, the drawn head in it") {
    // Nothing keeps flesh from a ceiling: a ceiling 1 cm above the standing horse's highest
    // bone has its head's flesh and its ears in it.
    Level level = scenes::flat_level(100.0f);
    float top = -1e9f;
    const auto c = std::make_shared<const Creature>(build_creature(scenes::generator().example("horse").value()).value());
    Player player(c, SplinePrototypes::defaults());
    player.animator().reset(level.spawn_ws + glm::vec2(0.0f, 1.0f), level);
    run_script(player, level, parse_script("stop:0.5").value(), 120, [](long long) {});
    const std::vector<Mat2x3>& world = player.animator().world_matrices();
    for (size_t b = 0; b < world.size(); ++b) {
      top = std::max({top, bone_start(world[b]).y, bone_end(world[b], c->skeleton.length(static_cast<int>(b))).y});
    }
    level.add_box(Box::from_corner(-100.0f, top + 0.01f, 300.0f, 50.0f));  // its top out of the reset's reach
    const SimResult r = run("horse", level, "stop:0.5", outline);
    INFO("deepest " << outline->deepest_outline_part << " " << outline->max_outline_penetration_m << " m at " << outline->deepest_outline_at_s << " s");
    CHECK(r.probe.max_penetration_m <= 0.001f);
    CHECK(outline->max_outline_penetration_m > 0.01f);
  }
  SECTION("at a riser its legs climb: the flesh rests on the tread, out of the riser") {
    // The chamois held at default.json's stairs drew its chest 3.6 cm into the riser ahead
    // before the floor held flesh up past a top's ends (BodyVertex::overhang): the straight
    // outline edge between a vertex on the tread and one below it cut the tread's corner.
    const SimResult r = run("chamois", load_level(scenes::source_path("levels/default.json")).value(), "walk:0.6:6", outline);
    INFO("deepest " << outline->deepest_outline_part << " " << outline->max_outline_penetration_m << " m at " << outline->deepest_outline_at_s << " s");
    CHECK(r.blocked_s > 0.2f);
    CHECK(r.probe.max_penetration_m <= 0.001f);
    CHECK(outline->max_outline_penetration_m <= 0.001f);
  }
  SECTION("blocked at a wall its legs cannot climb: the drawn body out of it too") {
    // The wall sweep stops the body before its drawn flesh (AnimRig::flesh) meets a wall, not
    // only its bones: the triceratops's horns went 0.5 m into slopes.json's end wall, the
    // elephant's trunk 11 cm into drops.json's, the horse's chest 12 cm into drops.json's 1 m
    // ledge as it came back to it.
    struct Case {
      const char* animal;
      const char* level;
      const char* script;
      BodyPartKind kind;
    };
    for (const Case& c : {Case{"triceratops", "levels/slopes.json", "walk:0.6:14", BodyPartKind::kHorn},
                          Case{"african elephant", "levels/drops.json", "walk:0.6:22", BodyPartKind::kTrunk},
                          Case{"horse", "levels/drops.json", "walk:0.5:6,stop:1,walk:-0.6:6", BodyPartKind::kAxial}}) {
      const SimResult r = run(c.animal, load_level(scenes::source_path(c.level)).value(), c.script, outline);
      INFO(c.animal << " on " << c.level << ": deepest " << outline->deepest_outline_part << " "
                    << outline->max_outline_penetration_m << " m at " << outline->deepest_outline_at_s << " s");
      CHECK(r.blocked_s > 0.5f);
      CHECK(r.probe.max_penetration_m <= 0.001f);
      CHECK(outline->max_by_kind[static_cast<size_t>(c.kind)] <= 0.001f);
    }
  }
  SECTION("a hoof set down at a riser's foot: its flesh kept off the riser") {
    // A foothold kept the foot's bones off a riser, 1 mm from its face, and the flesh drawn
    // about the hoof lay 1.6-2.2 cm in it. Footholds keep the foot's flesh off the level too
    // (anim_rig.h RigLeg::flesh_front).
    struct Case {
      const char* animal;
      const char* level;
      const char* script;
    };
    for (const Case& c : {Case{"horse", "levels/default.json", "walk:0.5:6,stop:1,walk:-0.6:6"},
                          Case{"dromedary", "levels/stairs.json", "walk:0.6:30"},
                          Case{"cape buffalo", "levels/stairs.json", "run:1:15"}}) {
      const SimResult r = run(c.animal, load_level(scenes::source_path(c.level)).value(), c.script, outline);
      INFO(c.animal << " on " << c.level << ": deepest " << outline->deepest_outline_part << " "
                    << outline->max_outline_penetration_m << " m at " << outline->deepest_outline_at_s << " s");
      CHECK(r.probe.max_penetration_m <= 0.001f);
      CHECK(outline->max_outline_penetration_m <= 0.001f);
    }
  }
  SECTION("a leg swinging or standing by a corner: its drawn flesh kept off it, not only its bones") {
    // The swing lifted a leg until its bones cleared a step's corner, and a stance foot behind
    // a riser lifted when its bones would cut the step above it: the flesh drawn about thigh
    // and shin lay in the corner all the same (the brachiosaurus's 4.5 cm at default.json's
    // post, the triceratops's 1.8 cm at drops.json's ledge). Both now keep the leg's drawn
    // outline (anim_rig.h RigLeg::flesh_outline) clear where some pose does.
    struct Case {
      const char* animal;
      const char* level;
    };
    for (const Case& c : {Case{"brachiosaurus", "levels/default.json"}, Case{"triceratops", "levels/drops.json"}}) {
      legs_clear(c.animal, c.level, "walk:0.6:30");
    }
    // A foot lifted for its flesh alone that finds no foothold stands, and the body does not
    // wait for it: the pigeon walking rough.json stopped for good at x 28 when the body waited
    // for such a foot to lift, as it does for one whose bones would cut the step.
    const SimResult pigeon = run("pigeon", load_level(scenes::source_path("levels/rough.json")).value(), "walk:0.6:30", outline);
    CHECK(pigeon.blocked_s < 0.5f);
    CHECK(pigeon.x_max_m > 35.0f);
  }
  SECTION("a leg's outline as drawn, its hoof and sole too: kept off a ledge it runs off") {
    // The legs' clearance took an outline that followed each leg bone rigidly (a knee's or an
    // ankle's points halfway between its bones), left out the sole and the toes, and thinned
    // it to 64 points: a hoof, which the body draws level on the ground through the foot's
    // roll (skeleton/mid_joint.h level frames), swung 1.2-1.7 cm into drops.json's first
    // ledge's face as the red deer and the wildebeest ran off it. The outline is now skinned as
    // the body skins it (anim_rig.h LimbFleshPoint; CTest "anim rig: a limb's flesh outline,
    // posed by the animator, lies on the drawn body's outline").
    for (const char* animal : {"red deer", "wildebeest"}) legs_clear(animal, "levels/drops.json", "run:1:15");
  }
  SECTION("blocked at a riser: its standing legs' drawn outline out of it") {
    // The wall sweep stops the body before its trunk's and head's flesh meet a wall; the legs
    // standing under it went on: the pigeon running default.json's stairs, blocked at a riser
    // taller than it climbs, drew its knee 1.6 cm into it (retrying the way ahead, 7.6 mm).
    // The body goes no further, and back, than keeps its standing legs' outline out of a box
    // rising above their joints (leg_geometry.h stance_flesh_advance, stance_flesh_push).
    const SimResult r = legs_clear("pigeon", "levels/default.json", "run:1:15");
    CHECK(r.blocked_s > 5.0f);
    CHECK(r.probe.max_stance_slip_m <= 0.001f);
  }
  SECTION("a foot set down where its standing leg's drawn outline clears the steps") {
    // A foot landed where its foot and its leg's bones fit, and the flesh drawn about the leg
    // above it, standing there, lay across a step's corner: the elephant's forefoot set down
    // 2 cm from the riser of default.json's stairs it steps down, its leg slanting back over
    // the step above (1.7 cm), the stegosaurus's on stairs.json (9.5 mm). A foot about to land
    // so shifts on its tread to where the standing leg clears, now and with its girdle over it.
    struct Case {
      const char* animal;
      const char* level;
    };
    for (const Case& c : {Case{"african elephant", "levels/default.json"}, Case{"stegosaurus", "levels/stairs.json"}}) {
      const SimResult r = legs_clear(c.animal, c.level, "walk:0.6:8");
      CHECK(r.probe.max_stance_slip_m <= 0.001f);
    }
  }
  SECTION("a foot hanging by a face: its leg's drawn flesh kept off the face's corner") {
    // A hanging foot (a foot left below a step its body climbs, a foreleg reaching past the
    // far wall of a gap) was kept out of the face by the line from its girdle joint, and the
    // flesh drawn about its shin and foot lay across the face's corner: the T. rex's 7.5 cm
    // climbing back up drops.json's 2 m step, the horse's 1.5 cm at its gap's far wall. The
    // lines from the joint to either side of the foot, a flesh margin apart, stop short too.
    legs_clear("tyrannosaurus", "levels/drops.json", "walk:0.5:6,stop:1,walk:-0.6:3");
    legs_clear("horse", "levels/drops.json", "walk:0.6:15");
  }
  SECTION("an arm or a flipper by a riser: its drawn flesh kept off it, not only its bones") {
    // An arm folded until its bones cleared a riser or the ground: the flipper drawn about them
    // lay in it all the same (the eared seal's 2.2 cm in stairs.json's risers, the harbour
    // seal's 1 cm on default.json). The arm's clearance takes its drawn outline
    // (RigLimb::flesh_outline) where some tuck clears it, skinned as the body skins it (while
    // it followed each bone rigidly, the eared seal's flipper still came 3.4 mm into a riser).
    struct Case {
      const char* animal;
      const char* level;
    };
    for (const Case& c : {Case{"eared seal", "levels/stairs.json"}, Case{"harbour seal", "levels/default.json"}}) {
      const SimResult r = run(c.animal, load_level(scenes::source_path(c.level)).value(), "walk:0.6:30", outline);
      INFO(c.animal << " on " << c.level << ": arm " << outline->max_by_kind[static_cast<size_t>(BodyPartKind::kArm)] << " m");
      CHECK(r.probe.max_penetration_m <= 0.001f);
      CHECK(outline->max_by_kind[static_cast<size_t>(BodyPartKind::kArm)] <= 0.001f);
    }
  }
  SECTION("a low head at a riser: its drawn snout lifted out of the face") {
    // The head's bones cleared the riser ahead, and the snout drawn about them lay 3-4 cm in
    // its face: the head now lifts on its neck until its flesh clears too.
    for (const char* animal : {"crocodile", "harbour seal", "pig"}) {
      const SimResult r = run(animal, load_level(scenes::source_path("levels/stairs.json")).value(), "run:1:15", outline);
      INFO(animal << ": axial " << outline->max_by_kind[static_cast<size_t>(BodyPartKind::kAxial)] << " m");
      CHECK(r.probe.max_penetration_m <= 0.001f);
      CHECK(outline->max_by_kind[static_cast<size_t>(BodyPartKind::kAxial)] <= 0.001f);
    }
  }
  SECTION("a body falling into a gap: its drawn head and chest kept out of the far wall") {
    // Falling into drops.json's pit, the bones that came down into the far wall's face took the
    // body back out of it, and the flesh drawn about them did not: the red deer's muzzle went
    // 2.7 cm into the wall, the eared seal's 3.8 cm, their skulls clear. The flesh takes the
    // body back too.
    struct Case {
      const char* animal;
      const char* script;
    };
    for (const Case& c : {Case{"red deer", "walk:0.6:17"}, Case{"eared seal", "walk:0.6:24"}}) {
      const SimResult r = run(c.animal, load_level(scenes::source_path("levels/drops.json")).value(), c.script, outline);
      INFO(c.animal << ": axial " << outline->max_by_kind[static_cast<size_t>(BodyPartKind::kAxial)] << " m, falls " << r.locomotion.falls);
      CHECK(r.locomotion.falls >= 1);
      CHECK(r.probe.max_penetration_m <= 0.001f);
      CHECK(outline->max_by_kind[static_cast<size_t>(BodyPartKind::kAxial)] <= 0.001f);
    }
  }
  SECTION("a whale's flukes: kept out of the ground with its tail") {
    // A whale lies along default.json's floor from its spawn on; its tail's bones lay clear
    // of the floor while the flukes drawn about them went 0.5 m into it, until the tail's
    // clearance took the tail's flesh (AnimRig::tail_flesh) along with its bones.
    for (const char* whale : {"blue whale", "sperm whale"}) {
      run(whale, load_level(scenes::source_path("levels/default.json")).value(), "walk:0.6:2", outline);
      INFO(whale);
      CHECK(outline->max_by_kind[static_cast<size_t>(BodyPartKind::kTailFin)] <= 0.001f);
    }
  }
  SECTION("a long body spawned beside an end wall: its drawn body clear of it") {
    // The spawns of the shipped levels lie 2 m from a 4 m end wall. The reset took the wall's
    // top, within its search, as ground under a long tail and did not move the body: the
    // triceratops stood with its tail on the top and its thigh's flesh 33 cm in the face, the
    // stegosaurus's 11 cm, the T. rex's and the brachiosaurus's legs hung against it. A body on
    // legs now stands on ground its legs climb onto, pushed clear of the wall.
    for (const char* file : {"default.json", "stairs.json", "rough.json"}) {
      for (const char* animal : {"triceratops", "stegosaurus", "tyrannosaurus", "brachiosaurus", "parasaurolophus"}) {
        const SimResult r = run(animal, load_level(scenes::source_path(std::string("levels/") + file)).value(), "stop:1", outline);
        INFO(animal << " on " << file << ": deepest " << outline->deepest_outline_part << " " << outline->max_outline_penetration_m
                    << " m at " << outline->deepest_outline_at_s << " s");
        CHECK(r.probe.max_penetration_m <= 0.001f);
        CHECK(outline->max_outline_penetration_m <= 0.001f);
        CHECK(r.locomotion.falls == 0);
      }
    }
  }
}
