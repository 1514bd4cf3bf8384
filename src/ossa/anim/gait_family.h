#pragma once
// Gait families (../shared/GAITS.md; issue 28): what each body plan's gaits are, where they
// change (Froude numbers), how fast the family goes, and when each foot lands. The gait clock
// (gait_clock.h) blends three gaits per family — the walk, a middle gait and a fast gait —
// by Froude number; a family with fewer gaits repeats one.
//
// The auto choice reads the body plan only (leg pairs, the hind legs' length against the fore,
// the foot's share of the leg, weight, wings, skull class, tail), never an animal's name.
//
// Units: Froude numbers Fr = v²/(g·h), h the hip height; footfall times in cycles after the
// near hind foot's touch-down.

#include <array>
#include <cstdint>

#include "ossa/gen/gait_family.h"

namespace ossa {

enum class Gait : uint8_t {
  kIdle, kWalk, kRun, kTrot, kGallop, kCrawl,
  kPace,         // lateral pairs in phase (camel)
  kAmble,        // a fast lateral-sequence walk, always a foot down (elephant)
  kHalfBound,    // hind feet together, fore feet staggered (rabbit)
  kBound,        // hind pair, then fore pair (small mammals)
  kHop,          // both hind feet together (kangaroo, frog)
  kGroundedRun,  // a run's bounce without a moment in the air (birds)
  kPentapedal,   // hind feet together, swung past forelimbs and tail planted (kangaroo)
};
const char* gait_name(Gait gait);

struct AnimRig;

namespace anim {

// What a family does. Every Froude number is the middle of its blend.
struct GaitFamilyTraits {
  GaitFamily family = GaitFamily::kCursorial;
  std::array<Gait, 3> gaits{Gait::kWalk, Gait::kTrot, Gait::kGallop};  // walk, middle, fast
  float mid_froude = 0.5f;    // walk → middle gait (1e9: none)
  float fast_froude = 2.5f;   // middle → fast gait (1e9: none)
  float top_froude = 5.0f;    // the full stick with run
  // The duty factor never falls below this: 0.5 keeps two or more feet down (graviportal; a
  // bird's grounded run below aerial_froude).
  float duty_floor = 0.0f;
  float aerial_froude = 0.0f; // below it the duty keeps at least 0.5 (a grounded run)
  bool head_bob = false;      // the head holds still, then thrusts (small birds' walk)
  // How far the spine flexes and extends (radians over the arc between the girdles, either
  // way) when the fore feet land together and the hind feet together, half a stride apart (a
  // bound); a gait whose pairs land apart flexes less, a walk or trot not at all (trunk_bob.h,
  // spine_flex).
  float spine_flex = 0.0f;
  // The slow walk goes on five supports (a hopper with arms and a tail: the kangaroo): the body
  // leans down onto its forelimbs and tail, which hold it while the hind feet swing forward
  // together (pentapedal.h).
  bool pentapedal = false;
};

// The traits of `family` for this rig (its weight and tail set the heavy bipeds', the
// graviportal's and the sprawlers' top speed). kAuto resolves with choose_gait_family.
GaitFamilyTraits gait_family_traits(GaitFamily family, const AnimRig& rig);

// The family the body plan asks for (never kAuto): no legs → legless; three or more leg pairs
// → multi-leg; one pair: winged or bird-skulled → bird, a mammal with arms and a long tail →
// hopper, else biped; two pairs: hind legs twice the fore → hopper; 1 t or more on short feet
// (the foot under 0.3 of the leg: columnar limbs) → graviportal; reptile or fish skull →
// sprawler; a mammal under 5 kg → bounder; long legs against the trunk (hip height over 0.8
// of the girdles' distance) and 300 kg or more → pacer; else cursorial.
GaitFamily choose_gait_family(const AnimRig& rig);

// When leg (girdle `front` or hind, side `far`) lands in gait `index` (0 walk, 1 middle, 2 fast)
// of `family`, for a rig with `girdles` leg-carrying girdles, in cycles after the near hind
// foot (one girdle: the near foot; three or more: the back girdle's near foot).
float footfall_time(GaitFamily family, int index, int girdles, int girdle, bool far);

}  // namespace anim
}  // namespace ossa
