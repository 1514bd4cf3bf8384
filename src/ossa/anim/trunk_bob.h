#pragma once
// Trunk bob (DESIGN.md §7 "body"; computed before body placement, stage 10 of
// Animator::update): how high each girdle rides over its standing height while the creature
// moves, from the gait's own footfall timing — not a shape drawn per animal or per gait.
//
// Each girdle is a mass carried by its own legs. A leg in stance pushes up with a force that
// rises and falls over its stance, f(u) = sin(πu) + b·sin(3πu) (u: the fraction of its stance
// gone): b > 0 dips the force at mid-stance, the walk's two humps (the body vaults over the
// leg); b = 0 is the run's single hump (a spring). The girdle's legs together carry its weight
// on average, so the girdle accelerates by g·(F(φ)/mean F − 1) over the cycle φ; integrated
// twice over one period T = 1/frequency, that is its height (Fourier series in φ, exact for
// these kernels: no sampling). Out of the timing alone it follows that walks and trots rise and
// fall twice per stride (each leg of the pair in turn), gallops, bounds and hops once (the
// pair lands together), that a walk is highest at mid-stance and a run lowest, that the
// girdles of a quadruped rise and fall at different times (the trunk pitches), and that a
// foot always down (graviportal) keeps the bob small.
//
// Below the walk-to-run Froude number 0.5 the force's swing grows with speed as the
// centripetal force over the leg does (∝ Fr), so a creeping walk barely bobs and a creature
// setting off starts from no bob at all (the height then tends to 2λ²/h·(…), not to ∞ as
// T grows). The girdles show a share of it (kTrunkShare, trunk_bob.cpp: half, for the jolt
// limit).
//
// Heights in metres, relative to the girdle's standing height.

#include <cstdint>
#include <span>
#include <vector>

#include "ossa/anim/anim_rig.h"
#include "ossa/anim/anim_state.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/spline_prototypes.h"

namespace ossa::anim {


// The walk's force dip at mid-stance (b of the kernel above; the run's is 0): a walking leg's
// vertical force falls to about 0.6–0.7 of its peaks at mid-stance (human and horse force
// plates; e.g. Biewener 2003, "Animal Locomotion", ch. 3).
inline constexpr float kWalkForceDip = 0.45f;

// The footfall bob of every girdle this tick at gait.phase, into gait.girdle_bob (zeros while
// the creature stands), and what every girdle adds besides into gait.extra_bob, which body
// placement smooths with the root (steps, the designer's shapes may jump): the pelvis_y
// prototype (twice per stride; none by default) while moving, the idle breathing (kIdleY over
// params.idle_period) while standing. gait.bob_weight eases, at kBobEaseRate,
// to 1 while the gait is `steady` — the feet step in rhythm on ground the legs walk like flat
// ground — and to 0 on steps, at a ledge (a foot waiting for ground or hanging over a drop) or
// blocked: there the feet keep no rhythm and the body placement's clamps hold the legs in
// reach and out of the steps, which a bob would fight. The bob also fades
// in over the first half of the walk speed (`speed`, m/s): a creature setting off or stopping
// has none (the stride the clock keeps at a crawl would otherwise keep a walk's bob).
void trunk_bob(const AnimRig& rig, const AnimatorParams& params, const SplinePrototypes& prototypes, const FootSet& feet,
               float speed, bool steady, float dt, GaitState& gait);

// The head's part (run by trunk_bob, with its fade): gait.head_rise, the nod of a cursorial,
// pacing or graviportal quadruped's walk — the fore girdle's own bob, scaled to a few per cent
// of the hip height, so the head drops as each fore foot takes the weight, twice per stride —
// and gait.head_shift, a small bird's head-bob in the walk (GaitFamilyTraits::head_bob): the
// head holds still in the world for most of each step, then thrusts forward. The pose turns
// the neck about its base for both (pose_head, pose_stage.h).
void head_motion(const AnimRig& rig, const FootSet& feet, float fade, GaitState& gait);

// The spine's part (run by trunk_bob, with its fade): gait.spine_flex, how far the back
// arches. The spine flexes as the hind feet swing forward under the body while the fore feet
// push back, and extends as the fore feet reach forward and the hind feet push off: the
// flexion follows the fore feet's mean place ahead of their girdle less the hind feet's, each
// foot's place taken as the first harmonic of its travel (back in stance, forward in swing).
// In a walk, trot or pace each pair's feet are half a cycle apart and their places cancel:
// the back stays still; the closer each pair lands together the more it flexes, up to the
// family's spine_flex when both pairs do, half a cycle apart. In the fast gait only (gallop,
// bound: gait.fast_factor), where the back's flexion drives the stride.
void spine_flex(const AnimRig& rig, const FootSet& feet, float fade, GaitState& gait);

// Do the feet keep a rhythm on ground walked like flat ground: not on steps (body motion's
// on_steps), not blocked, no foot hanging over a drop or waiting for ground (`waiting`,
// TickHandoff::waiting)?
bool steady_gait(bool on_steps, bool blocked, const FootSet& feet, std::span<const uint8_t> waiting);  // (cache: per girdle, the caller keeps it)

// The footfall bob alone (metres) of a girdle whose legs' stances begin at `stance_start`
// (cycles), each lasting `duty` cycles, with the walk's dip b, at `phase` of a cycle of
// `frequency` cycles per second, stride `stride` metres, for a creature of hip height h.
void footfall_series(std::span<const float> stance_start, float duty, float b, float frequency, float stride, float h, float gravity,
                     BobSeries& series);
float footfall_bob(std::span<const float> stance_start, float duty, float b, float phase, float frequency, float stride, float h,
                   float gravity);

}  // namespace ossa::anim
