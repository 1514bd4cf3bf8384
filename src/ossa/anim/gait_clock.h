#pragma once
// Gait clock (DESIGN.md §7; stage 6 of Animator::update, and stage 8 where the clock ticks):
// one phase φ ∈ [0, 1) per creature advancing at f = v/λ,
// the gait blend by Froude number Fr = v²/(g·h) between the gait family's walk, middle and
// fast gaits (gait_family.h), the duty factor β, the stride λ and each leg's phase offset.
// Needs no level.
//
// Inputs: the rig (girdles, legs, reach), AnimatorParams, the speed (m/s) and the per-tick
// smoothing factors. Output: GaitState. Stride in metres, frequency in cycles per second,
// phases in cycles.

#include <array>
#include <cstdint>
#include <vector>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/anim_rig.h"
#include "ossa/anim/anim_state.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/gait_family.h"

namespace ossa {
namespace anim {

// (trunk_bob.h) One girdle's footfall bob as a Fourier series in the phase (kBobHarmonics complex
// coefficients, the constant term 0), kept with the timing it was made for.
inline constexpr int kBobHarmonics = 6;
struct BobKey {
  float duty = -1.0f, b = 0.0f, frequency = 0.0f, stride = 0.0f;
  int legs = 0;
  std::array<float, 4> starts{};
  bool operator==(const BobKey&) const = default;
};
struct BobSeries {
  std::array<std::array<float, 2>, kBobHarmonics> coef{};
  BobKey key;
  float at(float phase) const;  // metres
};

// Owned by the gait clock (stage 6 of Animator::update): the clock's phase and blends, each
// foot's phase offset, and the clocks of a standing or legless creature.
struct GaitState {
  float phase = 0.0f;          // cycles, [0, 1)
  float frequency = 0.0f;      // cycles per second
  float stride = 0.0f;         // metres per cycle
  float duty = 0.65f;          // fraction of a cycle a foot is on the ground
  float froude = 0.0f;
  float run_factor = 0.0f;     // walk→run blend in [0, 1] (swing shapes, duty factor)
  float mid_factor = 0.0f;     // walk → the family's middle gait (trot, pace, half-bound …)
  float fast_factor = 0.0f;    // middle → fast gait (gallop, bound, aerial run …)
  Gait gait = Gait::kIdle;
  bool moving = false;         // the clock runs (legs step)
  // Per foot (FootSet::feet, not per leg: a foot keeps its offset when a turn hands it to
  // another leg): its phase offset, easing towards its leg's target, and its local phase on
  // the last tick, cycles.
  std::vector<float> foot_offset, foot_phase_prev;
  float idle_time = 0.0f;      // seconds the creature has stood (idle breathing)
  float crawl_phase = 0.0f;    // cycles of a legless creature's travelling wave
  // Per girdle: how high it rides over its standing height this tick (trunk_bob.h), metres.
  std::vector<float> girdle_bob;
  float bob_weight = 0.0f;     // how much of the footfall bob applies (trunk_bob.h), eased
  std::vector<BobSeries> bob_series;  // per girdle: its bob's series (trunk_bob.h), a cache
  float extra_bob = 0.0f;      // every girdle: the pelvis_y prototype's bob or idle breathing, metres
  // The head this tick (trunk_bob.h, head_motion): how far it rises over its rest place with
  // the walk's nod and how far forward of it a small bird's head-bob holds it, metres.
  float head_rise = 0.0f, head_shift = 0.0f;
  // The spine's flexion this tick (trunk_bob.h, spine_flex): radians over the arc between
  // the girdles, > 0 arched (flexed), < 0 hollowed (extended).
  float spine_flex = 0.0f;
  // How far the body has gone down onto its forelimbs and tail for the pentapedal walk
  // (pentapedal.h): 0 upright, 1 all the way, eased; and how fast it changes (1/s).
  float pentapedal = 0.0f, pentapedal_rate = 0.0f;
  // The family's walk and full-run speeds (walk_speed(), run_speed()), m/s, as update_gait
  // last found them.
  float walk_speed = 0.0f, run_speed = 0.0f;

  // Caches: the family's traits (for `traits_family`), the legs' target offsets at
  // (offsets_mid, offsets_fast) of offsets_family, Fr^0.3 at stride_froude, the shortest
  // stance reach at reach_stance_height.
  GaitFamilyTraits traits;
  GaitFamily traits_family = GaitFamily::kAuto;
  std::vector<float> target_offset;
  float offsets_mid = -1.0f, offsets_fast = -1.0f;
  GaitFamily offsets_family = GaitFamily::kAuto;
  float stride_froude = -1.0f, stride_pow = 0.0f;
  float reach_stance_height = NAN, min_reach_x = 0.0f;
};

// The gait family the animator uses: params.gait_family, or the rig's when that is kAuto.
inline GaitFamily gait_family(const AnimRig& rig, const AnimatorParams& params) {
  return params.gait_family == GaitFamily::kAuto ? rig.gait_family : params.gait_family;
}

// Froude, walk→run and gait blends, duty factor, stride, frequency and gait name for `speed`.
// keep_run and keep_gait are the smoothing factors exp(-rate·dt) of the run and gait blends.
// On steps (body motion's MotionState::on_steps) the fast gait eases back to the middle one.
void update_gait(const AnimRig& rig, const AnimatorParams& params, float speed, bool on_steps, float keep_run, float keep_gait,
                 GaitState& gait);

// Leg `leg`'s phase offset for the gait blend of `family` (mid and fast factors): minus the
// time its foot lands (footfall_time), so that a foot whose offset is larger lands earlier.
float leg_phase_offset(const AnimRig& rig, GaitFamily family, int leg, float mid_factor, float fast_factor);

// gait.target_offset of every leg, when the gait blend moved.
void update_target_offsets(const AnimRig& rig, GaitFamily family, GaitState& gait);

// Every foot's offset at the start of the blend given (a reset: feet in leg order).
void reset_offsets(const AnimRig& rig, GaitFamily family, const FootSet& feet, GaitState& gait);

// Starts the clock so that leg `lead`'s foot lifts now (its first step is half a stride).
void start_clock(GaitState& gait, const FootSet& feet, int lead);

// A standing creature's clock: it stops, and the idle time runs on.
void rest(GaitState& gait, float dt);
// The clock stops (a landing: the legs start again from standing).
inline void stop_clock(GaitState& gait) { gait.moving = false; }
// Stage 8 for a legless creature: its travelling wave advances with the speed asked (one cycle
// per half body; it runs on against a wall), its gait is a crawl unless it is blocked, and the
// idle time runs.
void tick_crawl(const AnimRig& rig, float speed, bool blocked, float dt, GaitState& gait);

// Stage 8: the clock ticks. While the creature moves (speed > 0, m/s) and is not blocked: the
// clock starts if it stood (the lead leg lifts now; GaitState::moving), the phase advances by
// f·dt, and every foot's phase and lift-off go to leg_phase (per leg). Else it rests.
void tick_clock(const AnimRig& rig, GaitFamily family, const FootSet& feet, float speed, bool blocked, float dt, float ism, GaitState& gait,
                std::vector<LegPhase>& leg_phase);

// Advances foot `foot`'s phase by one tick of the running clock: its offset eases towards its
// leg's target (interpolation speed `ism`), and it returns the foot's local phase and whether
// the phase crossed the duty factor while the foot stands (lift-off is due). `starting`: the
// clock started this tick. end_leg_phase keeps the phase for the next tick's crossing test.
// (Inline: once per leg and tick.)
inline LegPhase advance_leg_phase(GaitState& gait, int foot, bool stance, float target_offset, bool starting, float ism, float dt) {
  // Phase offsets ease towards their targets at this many cycles per second (× the
  // interpolation speed multiplier).
  constexpr float kOffsetEaseRate = 0.6f;
  float& offset = gait.foot_offset[foot];
  if (offset != target_offset) {
    offset = circular_lerp(offset, target_offset,
                           std::min(1.0f, kOffsetEaseRate * ism * dt / std::max(std::fabs(phase_diff(offset, target_offset)), 1e-6f)));
  }
  LegPhase out;
  out.phase = frac(gait.phase + offset);
  if (stance) out.lift_due = starting ? out.phase >= gait.duty : crossed(gait.foot_phase_prev[foot], out.phase, gait.duty);
  return out;
}
inline void end_leg_phase(GaitState& gait, int foot, const LegPhase& p) { gait.foot_phase_prev[foot] = p.phase; }

// Walk and run reference speeds, m/s: the walk at Froude 0.5 (or 0.4 of the family's top
// Froude where that is less: a tortoise), the full run at the family's top Froude.
float walk_speed(const AnimRig& rig, const AnimatorParams& params);
float run_speed(const AnimRig& rig, const AnimatorParams& params);

// Where the family's gaits change, m/s (the middles of their blends; 0 where the family has
// no such change or it lies beyond the full run), their names, and the full run. For the HUD
// and the tuning window.
struct GaitBands {
  float mid = 0.0f;       // walk → middle gait
  float fast = 0.0f;      // middle → fast gait
  float full_run = 0.0f;  // run_speed()
  GaitFamily family = GaitFamily::kCursorial;
  std::array<Gait, 3> gaits{};
};
GaitBands gait_bands(const AnimRig& rig, const AnimatorParams& params);

}  // namespace anim
}  // namespace ossa
