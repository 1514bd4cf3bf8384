// Issue 28: each gait family's footfalls as the feet show them — measured from the simulated
// stance of every foot (run_script's measure_gait), not from the animator's intended offsets —
// for example animals of every family with legs, on flat ground, at a slow walk, half run and
// full run. The bands are the published patterns of ../shared/GAITS.md: lateral-sequence walks
// (Hildebrand 1965), the sprawlers' diagonal couplets (Reilly et al. 2006), hind feet together
// in hops and bounds, graviportal and heavy bipeds never all off the ground (Hutchinson et al.
// 2003), one gathered suspension per gallop stride, the pace's lateral couplets, birds'
// grounded run. Not covered here: legless and many-legged bodies (no footfall sequence), the
// kangaroo's pentapedal walk (not built: it hops at every speed).

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ossa/game/gait_metrics.h"
#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

struct Run {
  SegmentMetrics walk, half, full;  // walk:0.3, run:0.6, run:1 (8 s each)
};

Run run_family_script(const std::string& name) {
  const Level flat = scenes::flat_level(400.0f);
  auto creature = std::make_shared<const Creature>(build_creature(scenes::generator().example(name).value()).value());
  Player player(creature, SplinePrototypes::defaults());
  player.animator().reset({2.0f, 1.0f}, flat);
  // 12 s a segment: at its true size (hip 3 m) the tyrannosaurus' slow walk takes 2.5 s a
  // stride, and the measure wants three after the segment's first second.
  const SimResult r = run_script(player, flat, parse_script("walk:0.3:12,run:0.6:12,run:1:12").value(), 120);
  REQUIRE(r.segments.size() == 3);
  REQUIRE(r.probe.max_stance_slip_m <= 0.001f);
  REQUIRE(r.probe.max_stance_gap_m <= 0.001f);
  return {r.segments[0], r.segments[1], r.segments[2]};
}

std::string describe(const SegmentMetrics& s) {
  const GaitMeasure& m = s.measured;
  return s.command + ": " + s.gait + " (" + s.gait_family + "), limb phase " + std::to_string(m.limb_phase) + " " +
         m.footfall_sequence + ", hind pair " + std::to_string(m.hind_pair_phase) + ", fore pair " +
         std::to_string(m.fore_pair_phase) + ", duty " + std::to_string(m.duty_factor) + ", suspensions " +
         std::to_string(m.suspensions_per_stride) + ", strides " + std::to_string(m.strides);
}

}  // namespace

TEST_CASE("gait families: cursorial and pacer walks land in lateral sequence, gallops one suspension a stride", "[game][gait]") {
  for (const char* name : {"horse", "red deer", "giraffe"}) {
    const Run r = run_family_script(name);
    INFO(name << "\n" << describe(r.walk) << "\n" << describe(r.half) << "\n" << describe(r.full));
    CHECK(r.walk.measured.strides >= 3.0f);
    CHECK(r.walk.measured.footfall_sequence == "lateral");
    CHECK(r.walk.measured.limb_phase == Approx(0.25f).margin(0.05f));
    CHECK(r.walk.measured.suspensions_per_stride == 0.0f);
    // The full run: a gallop, the hind feet a little apart (transverse or rotary: neither in
    // phase nor alternating), one gathered suspension per stride.
    CHECK(r.full.gait == "gallop");
    CHECK(pair_phase_gap(r.full.measured.hind_pair_phase) > 0.05f);
    CHECK(pair_phase_gap(r.full.measured.hind_pair_phase) < 0.25f);
    CHECK(r.full.measured.suspensions_per_stride == Approx(1.0f).margin(0.1f));
    // The middle gait: a trot's diagonal couplets (same-side feet half a cycle apart), or the
    // giraffe's pace (same-side feet together).
    const float couplet = std::string(name) == "giraffe" ? 0.0f : 0.5f;
    CHECK(r.half.gait == (couplet == 0.0f ? "pace" : "trot"));
    CHECK(std::fabs(r.half.measured.limb_phase - couplet) < 0.05f);
  }
}

TEST_CASE("gait families: graviportal animals walk in lateral sequence and never leave the ground", "[game][gait]") {
  for (const char* name : {"african elephant", "triceratops", "brachiosaurus"}) {
    const Run r = run_family_script(name);
    INFO(name << "\n" << describe(r.walk) << "\n" << describe(r.half) << "\n" << describe(r.full));
    CHECK(r.walk.gait_family == "graviportal");
    CHECK(r.walk.measured.footfall_sequence == "lateral");
    for (const SegmentMetrics* s : {&r.walk, &r.half, &r.full}) {
      CHECK(s->measured.strides >= 2.0f);
      CHECK_FALSE(s->flight_phase);  // not a single tick with every foot up
      CHECK(s->measured.suspensions_per_stride == 0.0f);
      CHECK(s->measured.limb_phase == Approx(0.25f).margin(0.05f));  // a walk or an amble, never a trot
    }
  }
}

TEST_CASE("gait families: hoppers and bounders land their hind feet together", "[game][gait]") {
  // Kangaroo and frog hop at every speed (GAITS.md: hind feet in phase); the rabbit walks slowly
  // and bounds at full speed (its half-bound between keeps the hind feet together too).
  for (const char* name : {"kangaroo", "frog", "rabbit"}) {
    const Run r = run_family_script(name);
    INFO(name << "\n" << describe(r.walk) << "\n" << describe(r.half) << "\n" << describe(r.full));
    const bool rabbit = std::string(name) == "rabbit";
    std::vector<const SegmentMetrics*> hops{&r.half, &r.full};
    if (!rabbit) hops.push_back(&r.walk);
    for (const SegmentMetrics* s : hops) {
      CHECK(s->measured.strides >= 3.0f);
      CHECK(pair_phase_gap(s->measured.hind_pair_phase) < 0.05f);  // within 5 % of a cycle
    }
    CHECK(r.full.measured.suspensions_per_stride == Approx(1.0f).margin(0.1f));
    if (rabbit) {
      CHECK(r.walk.measured.footfall_sequence == "lateral");
      CHECK(r.full.gait == "bound");
    } else {
      CHECK(r.full.gait == "hop");
    }
  }
}

TEST_CASE("gait families: sprawlers walk in diagonal couplets and never gallop", "[game][gait]") {
  for (const char* name : {"crocodile", "tortoise", "dimetrodon"}) {
    const Run r = run_family_script(name);
    INFO(name << "\n" << describe(r.walk) << "\n" << describe(r.half) << "\n" << describe(r.full));
    CHECK(r.walk.gait_family == "sprawler");
    CHECK(r.walk.measured.limb_phase == Approx(0.4f).margin(0.05f));
    for (const SegmentMetrics* s : {&r.walk, &r.half, &r.full}) {
      CHECK(s->gait != "gallop");
      // Both pairs alternate at every speed: no asymmetric gait.
      CHECK(s->measured.hind_pair_phase == Approx(0.5f).margin(0.05f));
      CHECK(s->measured.fore_pair_phase == Approx(0.5f).margin(0.05f));
    }
  }
}

TEST_CASE("gait families: bipeds alternate, birds run grounded before they fly, heavy bipeds only walk", "[game][gait]") {
  for (const char* name : {"ostrich", "pigeon", "tyrannosaurus"}) {
    const Run r = run_family_script(name);
    INFO(name << "\n" << describe(r.walk) << "\n" << describe(r.half) << "\n" << describe(r.full));
    for (const SegmentMetrics* s : {&r.walk, &r.half, &r.full}) {
      CHECK(s->measured.strides >= 3.0f);
      CHECK(s->measured.hind_pair_phase == Approx(0.5f).margin(0.05f));
    }
    CHECK(r.walk.measured.suspensions_per_stride == 0.0f);
    if (std::string(name) == "tyrannosaurus") {
      // 1 t or more on two legs: a fast walk at most, never airborne (Hutchinson & Garcia 2002).
      for (const SegmentMetrics* s : {&r.walk, &r.half, &r.full}) CHECK_FALSE(s->flight_phase);
    } else {
      // Birds: the grounded run (no suspension, duty at or above one half), then aerial running
      // with two suspensions per stride.
      CHECK(r.half.gait == "grounded run");
      CHECK_FALSE(r.half.flight_phase);
      CHECK(r.half.measured.duty_factor >= 0.5f);
      CHECK(r.full.measured.suspensions_per_stride == Approx(2.0f).margin(0.1f));
    }
  }
}
