#include "ossa/game/gait_metrics.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>

#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

// A synthetic timeline: each leg touches down at `offset` cycles into every cycle of `period`
// seconds and stays down for `duty` of it; the root's height is root(t) (t in seconds).
struct SyntheticLeg {
  GaitLeg leg;
  float offset = 0.0f;  // cycles
  float duty = 0.5f;
};

constexpr float kDt = 1.0f / 120.0f;

std::vector<GaitSample> timeline(const std::vector<SyntheticLeg>& legs, float period, float seconds,
                                 const std::function<float(float)>& root = [](float) { return 0.5f; }) {
  std::vector<GaitSample> out;
  const int ticks = static_cast<int>(seconds / kDt);
  for (int t = 0; t < ticks; ++t) {
    const float time = static_cast<float>(t) * kDt;
    GaitSample s{0, root(time)};
    for (size_t i = 0; i < legs.size(); ++i) {
      float phase = time / period - legs[i].offset;
      phase -= std::floor(phase);
      if (phase < legs[i].duty) s.stance |= uint64_t{1} << i;
    }
    out.push_back(s);
  }
  return out;
}

std::vector<GaitLeg> layout(const std::vector<SyntheticLeg>& legs) {
  std::vector<GaitLeg> out;
  for (const SyntheticLeg& l : legs) out.push_back(l.leg);
  return out;
}

// Girdle 0 is the front one.
constexpr GaitLeg kForeNear{0, Side::kNear}, kForeFar{0, Side::kFar}, kHindNear{1, Side::kNear}, kHindFar{1, Side::kFar};

// A symmetric walk: hind near at 0, fore near at limb_phase, the far side half a cycle later.
std::vector<SyntheticLeg> walk(float limb_phase, float duty) {
  return {{kForeNear, limb_phase, duty},
          {kForeFar, std::fmod(limb_phase + 0.5f, 1.0f), duty},
          {kHindNear, 0.0f, duty},
          {kHindFar, 0.5f, duty}};
}

}  // namespace

TEST_CASE("measure_gait: a lateral-sequence walk has limb phase 0.25, alternating pairs and no suspension", "[game][gait]") {
  for (float period : {1.0f, 0.83f, 2.4f}) {
    INFO("period " << period);
    const std::vector<SyntheticLeg> legs = walk(0.25f, 0.75f);
    const GaitMeasure m = measure_gait(timeline(legs, period, 8.0f), layout(legs), kDt, 1.0f);
    CHECK(m.limb_phase == Approx(0.25f).margin(0.02f));
    CHECK(m.footfall_sequence == "lateral");
    CHECK(m.hind_pair_phase == Approx(0.5f).margin(0.02f));
    CHECK(m.fore_pair_phase == Approx(0.5f).margin(0.02f));
    CHECK(m.duty_factor == Approx(0.75f).margin(0.02f));
    CHECK(m.stride_period_s == Approx(period).margin(kDt));
    CHECK(m.strides >= std::floor(8.0f / period) - 2.0f);  // the first touch-down is not at tick 0
    CHECK(m.suspensions_per_stride == 0.0f);
    CHECK(m.suspension_fraction == 0.0f);
  }
}

TEST_CASE("measure_gait: a diagonal-sequence walk has limb phase 0.75", "[game][gait]") {
  const std::vector<SyntheticLeg> legs = walk(0.75f, 0.65f);
  const GaitMeasure m = measure_gait(timeline(legs, 1.1f, 8.0f), layout(legs), kDt, 1.0f);
  CHECK(m.limb_phase == Approx(0.75f).margin(0.02f));
  CHECK(m.footfall_sequence == "diagonal");
  CHECK(m.duty_factor == Approx(0.65f).margin(0.02f));
  // Leg order in the rig does not matter: the hind pair first.
  const std::vector<SyntheticLeg> hind_first = {legs[2], legs[3], legs[0], legs[1]};
  const GaitMeasure h = measure_gait(timeline(hind_first, 1.1f, 8.0f), layout(hind_first), kDt, 1.0f);
  CHECK(h.limb_phase == Approx(0.75f).margin(0.02f));
  CHECK(h.footfall_sequence == "diagonal");
}

TEST_CASE("measure_gait: a trot and a pace are couplets with no sequence, a trot with flight has two suspensions", "[game][gait]") {
  const std::vector<SyntheticLeg> trot = walk(0.5f, 0.4f);
  const GaitMeasure t = measure_gait(timeline(trot, 0.7f, 6.0f), layout(trot), kDt, 1.0f);
  CHECK(t.limb_phase == Approx(0.5f).margin(0.02f));
  CHECK(t.footfall_sequence.empty());
  CHECK(t.suspensions_per_stride == Approx(2.0f));
  CHECK(t.suspension_fraction == Approx(0.2f).margin(0.02f));
  const std::vector<SyntheticLeg> pace = walk(0.02f, 0.6f);
  const GaitMeasure p = measure_gait(timeline(pace, 0.7f, 6.0f), layout(pace), kDt, 1.0f);
  CHECK(pair_phase_gap(p.limb_phase) < 0.05f);
  CHECK(p.footfall_sequence.empty());
}

TEST_CASE("measure_gait: a biped's hop lands both feet in phase with one suspension per stride", "[game][gait]") {
  // A kangaroo: one leg pair, the feet a tick apart.
  const std::vector<SyntheticLeg> hop = {{{0, Side::kNear}, 0.0f, 0.35f}, {{0, Side::kFar}, 0.01f, 0.35f}};
  const GaitMeasure m = measure_gait(timeline(hop, 0.5f, 5.0f), layout(hop), kDt, 1.0f);
  CHECK(pair_phase_gap(m.hind_pair_phase) < 0.05f);
  CHECK(std::isnan(m.fore_pair_phase));
  CHECK(std::isnan(m.limb_phase));
  CHECK(m.footfall_sequence.empty());
  CHECK(m.suspensions_per_stride == Approx(1.0f));
  CHECK(m.duty_factor == Approx(0.35f).margin(0.02f));
  // One foot landing a tick before the other, the phase wraps (0.99 and 0.01 are both close).
  const std::vector<SyntheticLeg> early = {{{0, Side::kNear}, 0.01f, 0.35f}, {{0, Side::kFar}, 0.0f, 0.35f}};
  const GaitMeasure e = measure_gait(timeline(early, 0.5f, 5.0f), layout(early), kDt, 1.0f);
  CHECK(pair_phase_gap(e.hind_pair_phase) < 0.05f);
  // A biped's walk alternates.
  const std::vector<SyntheticLeg> biped = {{{0, Side::kNear}, 0.0f, 0.6f}, {{0, Side::kFar}, 0.5f, 0.6f}};
  const GaitMeasure w = measure_gait(timeline(biped, 1.0f, 6.0f), layout(biped), kDt, 1.0f);
  CHECK(w.hind_pair_phase == Approx(0.5f).margin(0.02f));
  CHECK(w.suspensions_per_stride == 0.0f);
}

TEST_CASE("measure_gait: a frog's or a rabbit's bound has in-phase pairs and no sequence", "[game][gait]") {
  const std::vector<SyntheticLeg> bound = {
      {kForeNear, 0.45f, 0.25f}, {kForeFar, 0.45f, 0.25f}, {kHindNear, 0.0f, 0.3f}, {kHindFar, 0.02f, 0.3f}};
  const GaitMeasure m = measure_gait(timeline(bound, 0.6f, 6.0f), layout(bound), kDt, 1.0f);
  CHECK(pair_phase_gap(m.hind_pair_phase) < 0.05f);
  CHECK(pair_phase_gap(m.fore_pair_phase) < 0.05f);
  CHECK(m.limb_phase == Approx(0.45f).margin(0.02f));
  CHECK(m.footfall_sequence.empty());  // asymmetric
  // Hind feet down 0–0.32, fore feet 0.45–0.7: two flights, 0.32–0.45 and 0.7–1.
  CHECK(m.suspensions_per_stride == Approx(2.0f));
  CHECK(m.suspension_fraction == Approx(0.43f).margin(0.03f));
}

TEST_CASE("measure_gait: a gallop with one flight per stride", "[game][gait]") {
  // Transverse gallop: hind 0 and 0.1, fore 0.4 and 0.5, each down 0.3 of the stride: the feet
  // cover 0–0.8 without a gap, the flight is 0.8–1.
  const std::vector<SyntheticLeg> gallop = {
      {kForeNear, 0.4f, 0.3f}, {kForeFar, 0.5f, 0.3f}, {kHindNear, 0.0f, 0.3f}, {kHindFar, 0.1f, 0.3f}};
  const GaitMeasure m = measure_gait(timeline(gallop, 0.45f, 6.0f), layout(gallop), kDt, 1.0f);
  CHECK(m.suspensions_per_stride == Approx(1.0f));
  CHECK(m.suspension_fraction == Approx(0.2f).margin(0.03f));
  CHECK(m.hind_pair_phase == Approx(0.1f).margin(0.02f));
  CHECK(m.fore_pair_phase == Approx(0.1f).margin(0.02f));
  CHECK(m.footfall_sequence.empty());  // asymmetric
  CHECK(m.duty_factor == Approx(0.3f).margin(0.02f));
}

TEST_CASE("measure_gait: the root's bobs per stride and its excursion, on the level and up a slope", "[game][gait]") {
  const std::vector<SyntheticLeg> legs = walk(0.25f, 0.7f);
  const float period = 0.9f, hip = 0.8f, amplitude = 0.02f;  // metres: 0.04 peak to trough
  for (float slope : {0.0f, 0.3f, -0.5f}) {  // metres of height per second
    INFO("slope " << slope);
    const auto bumps = [&](int per_stride, float wiggle) {
      return [=](float t) {
        const float w = 2.0f * std::numbers::pi_v<float> * t / period;
        return 1.0f + slope * t + amplitude * std::cos(static_cast<float>(per_stride) * w) +
               wiggle * std::sin(13.0f * w);
      };
    };
    const GaitMeasure two = measure_gait(timeline(legs, period, 8.0f, bumps(2, 0.0f)), layout(legs), kDt, hip);
    CHECK(two.bobs_per_stride == Approx(2.0f));
    CHECK(two.vertical_excursion == Approx(2.0f * amplitude / hip).epsilon(0.03));
    const GaitMeasure one = measure_gait(timeline(legs, period, 8.0f, bumps(1, 0.0f)), layout(legs), kDt, hip);
    CHECK(one.bobs_per_stride == Approx(1.0f));
    CHECK(one.vertical_excursion == Approx(2.0f * amplitude / hip).epsilon(0.03));
    // Wiggles below 10 % of the excursion (here 3 % of it, peak to trough) are not bobs.
    const GaitMeasure wiggly = measure_gait(timeline(legs, period, 8.0f, bumps(2, 0.0006f)), layout(legs), kDt, hip);
    CHECK(wiggly.bobs_per_stride == Approx(2.0f));
  }
  // A root that does not bob has an excursion of 0 and no bobs to count.
  const GaitMeasure flat = measure_gait(timeline(legs, period, 8.0f), layout(legs), kDt, hip);
  CHECK(flat.vertical_excursion == 0.0f);
  CHECK(std::isnan(flat.bobs_per_stride));
}

TEST_CASE("measure_gait: nothing to measure gives NaN and no sequence", "[game][gait]") {
  const GaitMeasure legless = measure_gait(timeline({}, 1.0f, 3.0f), {}, kDt, 1.0f);
  CHECK(legless.footfall_sequence.empty());
  CHECK(std::isnan(legless.limb_phase));
  CHECK(std::isnan(legless.duty_factor));
  CHECK(std::isnan(legless.suspensions_per_stride));
  CHECK(std::isnan(legless.vertical_excursion));
  // Standing: every foot down, never a touch-down.
  const std::vector<SyntheticLeg> standing = walk(0.25f, 1.0f);
  const GaitMeasure s = measure_gait(timeline(standing, 1.0f, 3.0f), layout(standing), kDt, 1.0f);
  CHECK(s.strides == 0.0f);
  CHECK(std::isnan(s.limb_phase));
  CHECK(std::isnan(s.duty_factor));
  CHECK(s.footfall_sequence.empty());
  // Less than one stride.
  const std::vector<SyntheticLeg> legs = walk(0.25f, 0.7f);
  const GaitMeasure short_run = measure_gait(timeline(legs, 2.0f, 1.5f), layout(legs), kDt, 1.0f);
  CHECK(std::isnan(short_run.stride_period_s));
  CHECK(short_run.footfall_sequence.empty());
}

TEST_CASE("run_script measures the horse's gait from its feet on flat ground", "[game][gait]") {
  const Level flat = scenes::flat_level(200.0f);
  auto creature = std::make_shared<const Creature>(scenes::quadruped());
  Player player(creature, SplinePrototypes::defaults());
  player.animator().reset({2.0f, 1.0f}, flat);
  const SimResult r = run_script(player, flat, parse_script("walk:0.3:8,run:1:8,walk:-0.4:8").value(), 120);
  REQUIRE(r.segments.size() == 3);
  for (const SegmentMetrics& s : r.segments) {
    INFO(s.command << ": limb phase " << s.measured.limb_phase << " (" << s.measured.footfall_sequence << "), hind pair "
                   << s.measured.hind_pair_phase << ", duty " << s.measured.duty_factor << " (target " << s.duty_factor
                   << "), suspensions " << s.measured.suspensions_per_stride << ", excursion "
                   << s.measured.vertical_excursion << ", bobs " << s.measured.bobs_per_stride);
    CHECK(s.gait_family == "cursorial");
    CHECK(s.measured.strides >= 3.0f);
    CHECK(s.measured.stride_period_s == Approx(1.0f / s.cycle_frequency).epsilon(0.1));
    CHECK(s.measured.limb_phase >= 0.0f);
    CHECK(s.measured.limb_phase < 1.0f);
    CHECK(s.measured.hind_pair_phase >= 0.0f);
    CHECK(s.measured.fore_pair_phase >= 0.0f);
    // The feet keep to the animator's duty factor.
    CHECK(s.measured.duty_factor == Approx(s.duty_factor).margin(0.05f));
    CHECK(s.measured.vertical_excursion > 0.0f);
    CHECK(s.measured.vertical_excursion < 0.2f);
    CHECK((s.measured.suspensions_per_stride > 0.0f) == s.flight_phase);
  }
  // The walk's two girdles vault a quarter cycle apart and cancel at the root (trunk_bob.h:
  // the trunk rocks instead); the run (a gallop) bobs once or twice a stride.
  CHECK(r.segments[0].measured.vertical_excursion < 0.005f);
  CHECK(r.segments[1].measured.bobs_per_stride >= 1.0f);
  CHECK(r.segments[1].measured.bobs_per_stride <= 2.0f);
  // Walks alternate within each pair and have a sequence (which one is the gait's business).
  for (const SegmentMetrics* walk : {&r.segments[0], &r.segments[2]}) {
    CHECK(walk->measured.hind_pair_phase == Approx(0.5f).margin(0.05f));
    CHECK(walk->measured.fore_pair_phase == Approx(0.5f).margin(0.05f));
    CHECK_FALSE(walk->measured.footfall_sequence.empty());
    CHECK(walk->measured.suspensions_per_stride == 0.0f);
  }
}

TEST_CASE("run_script measures at most kGaitWindowS of a long segment", "[game][gait]") {
  const Level flat = scenes::flat_level(400.0f);
  auto creature = std::make_shared<const Creature>(scenes::quadruped());
  Player player(creature, SplinePrototypes::defaults());
  player.animator().reset({2.0f, 1.0f}, flat);
  const SimResult r = run_script(player, flat, parse_script("walk:0.3:140").value(), 120);
  REQUIRE(r.segments.size() == 1);
  const SegmentMetrics& s = r.segments[0];
  const float window_strides = static_cast<float>(SegmentMetrics::kGaitWindowS) * s.cycle_frequency;
  CHECK(s.measured.strides <= window_strides + 1.0f);
  CHECK(s.measured.strides >= window_strides - 2.0f);
  CHECK(s.measured.suspensions_per_stride == 0.0f);
}
