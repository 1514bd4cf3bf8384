#pragma once
// Gait measured from the feet and the trunk as simulated (issue #28): which feet are on the
// ground tick by tick and the root's height give the footfall sequence, Hildebrand's limb
// phase, the phase within each leg pair, the measured duty factor, suspensions per stride and
// the trunk's vertical excursion. A pure function over a recorded timeline, so it is tested on
// synthetic timelines with no animator (tests/game/gait_metrics_test.cpp); SimProbe's caller
// (run_script) records the timeline of each segment's window.
//
// Terms (GAITS.md; Hildebrand 1965, 1977):
//   touch-down  a leg's swing → stance transition (its first stance tick)
//   stride      one cycle of the reference leg, touch-down to its next touch-down; the
//               reference leg is the first leg (in rig order) of the hind pair
//   limb phase  (t_touchdown(fore, same side) − t_touchdown(hind)) / the hind foot's stride
//               period, cycles in [0, 1): about 0.25 in a lateral-sequence walk, 0.75 in a
//               diagonal-sequence one, 0.5 in a trot, 0 in a pace

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "ossa/gen/creature.h"

namespace ossa {

// Where a leg sits: its girdle (0 the front one, as AnimRig::girdles) and its side.
struct GaitLeg {
  int girdle = 0;
  Side side = Side::kNear;
};

// One tick of the timeline.
struct GaitSample {
  uint64_t stance = 0;  // bit i set: leg i is in stance (on the ground); legs past 63 are ignored
  float root_y = 0.0f;  // the root's world height, metres
};

// What measure_gait finds. NaN (JSON null) where a value does not apply or could not be
// measured: no leg pair for it, or fewer than one whole stride of the reference leg.
struct GaitMeasure {
  // The footfall sequence of a symmetric gait of a creature with exactly two leg pairs:
  // "lateral" (limb_phase in (0, 0.5)) or "diagonal" (in (0.5, 1)). "" where it does not apply:
  // bipeds, legless or many-legged creatures, no strides; asymmetric gaits (either pair's feet
  // not alternating: a pair phase off 0.5 by more than kSymmetricPairTolerance, as in a gallop
  // or a bound); couplets (limb_phase within kCoupletTolerance of 0 or 0.5: a pace or a trot,
  // whose sequence is a tick's rounding).
  std::string footfall_sequence;
  static constexpr float kSymmetricPairTolerance = 0.1f;  // cycles
  static constexpr float kCoupletTolerance = 0.05f;       // cycles
  // Hildebrand's limb phase, cycles in [0, 1): the circular mean over hind strides and both
  // sides (two leg pairs only).
  float limb_phase = NAN;
  // Phase of the far foot's touch-down after the near foot's in the hind pair (the last girdle)
  // and the fore pair (girdle 0, creatures with two or more pairs), cycles in [0, 1), per
  // stride of the near foot, circular mean: 0 in phase (hop, bound), 0.5 alternating (walk,
  // trot). A biped's one pair is its hind pair. pair_phase_gap gives the distance from in phase.
  float hind_pair_phase = NAN;
  float fore_pair_phase = NAN;
  // Stance time / cycle period per leg over its whole cycles (touch-down to touch-down), the
  // mean over legs with at least one whole cycle.
  float duty_factor = NAN;
  float stride_period_s = NAN;  // s, mean stride of the reference leg
  float strides = 0.0f;         // whole strides of the reference leg measured
  // Distinct intervals with every foot off the ground that begin within the measured strides,
  // per stride (0 for a walk, 1 for a gallop or a hop, 2 for a trot with flight).
  float suspensions_per_stride = NAN;
  // The share of those strides' time with every foot off the ground, in [0, 1]: tells a real
  // suspension from a one-tick gap where one foot lifts a tick before another lands.
  float suspension_fraction = NAN;
  // The root's peak-to-trough height per stride, detrended by the line through its heights at
  // the stride's two touch-downs (so a slope adds nothing), the mean over strides, as a
  // fraction of hip_height.
  float vertical_excursion = NAN;
  // Maxima of the detrended root height per stride (1 for a gallop or a hop, 2 for a walk or
  // a trot): maxima confirmed by a rise and a fall of at least 10 % of the mean excursion
  // (smaller wiggles do not count). NaN when the excursion is below 0.1 mm (no bob to count).
  float bobs_per_stride = NAN;
};

// Measures the timeline `samples` (one per tick, dt seconds apart) of legs laid out as `legs`
// (leg i is bit i of GaitSample::stance), hip_height in metres (> 0). The timeline should hold
// no turn (a turn hands feet between legs: FootSet::foot_of_leg). O(ticks × legs).
GaitMeasure measure_gait(const std::vector<GaitSample>& samples, const std::vector<GaitLeg>& legs, float dt,
                         float hip_height);

// How far a pair phase (cycles) is from in phase: min(p, 1 − p) for p in [0, 1), in [0, 0.5]
// (NaN stays NaN). "Hind feet touch down within 5 % of a cycle of each other":
// pair_phase_gap(m.hind_pair_phase) < 0.05.
inline float pair_phase_gap(float phase) { return std::fmin(phase, 1.0f - phase); }

}  // namespace ossa
