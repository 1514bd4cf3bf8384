#include "ossa/anim/gait_family.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/anim_rig.h"

namespace ossa {

const char* gait_name(Gait gait) {
  switch (gait) {
    case Gait::kIdle: return "idle";
    case Gait::kWalk: return "walk";
    case Gait::kRun: return "run";
    case Gait::kTrot: return "trot";
    case Gait::kGallop: return "gallop";
    case Gait::kCrawl: return "crawl";
    case Gait::kPace: return "pace";
    case Gait::kAmble: return "amble";
    case Gait::kHalfBound: return "half-bound";
    case Gait::kBound: return "bound";
    case Gait::kHop: return "hop";
    case Gait::kGroundedRun: return "grounded run";
    case Gait::kPentapedal: return "pentapedal";
  }
  return "unknown";
}

namespace anim {

namespace {

constexpr float kNone = 1e9f;

// Body-plan thresholds of the auto choice (GAITS.md, "Repertoires by body plan").
constexpr float kHopperHindToFore = 2.0f;      // a frog's hind legs are about 3× its fore legs
constexpr float kHopperTailOfBody = 0.5f;      // a kangaroo's tail is as long as its body
constexpr float kGraviportalKg = 1000.0f;      // elephants, sauropods, ceratopsians
constexpr float kColumnarFootOfLeg = 0.3f;     // foot of the whole leg: elephant 0.22, giraffe 0.44
constexpr float kBounderKg = 5.0f;             // rabbits, hyraxes, shrews (Gambaryan 1974)
constexpr float kPacerHipOfTrunk = 0.8f;       // camel, giraffe: legs long against the trunk
constexpr float kPacerKg = 300.0f;
constexpr float kSmallSprawlerKg = 5.0f;       // only small sprawlers gallop (Renous et al. 2002)
constexpr float kHeavyBipedKg = 1000.0f;       // T. rex could not run (Hutchinson & Garcia 2002)
constexpr float kSmallBirdKg = 5.0f;           // pigeons, magpies bob their heads (Frost 1978)
// Skull variants (genome.h): 0 mammal, 1 bird, 2 reptile, 3 fish.
constexpr int kMammalSkull = 0, kBirdSkull = 1;

float mean_leg_reach(const AnimRig& rig, int girdle) {
  float sum = 0.0f;
  int n = 0;
  for (const RigLeg& leg : rig.legs) {
    if (leg.girdle != girdle) continue;
    sum += leg.reach + leg.foot_span;
    ++n;
  }
  return n ? sum / static_cast<float>(n) : 0.0f;
}

// The share of a leg (thigh, shin, foot) that is foot: long in unguligrade and digitigrade
// legs, short in columnar ones.
float foot_share(const AnimRig& rig) {
  float foot = 0.0f, whole = 0.0f;
  for (const RigLeg& leg : rig.legs) {
    foot += leg.foot_length;
    whole += leg.reach + leg.foot_length;
  }
  return whole > 0.0f ? foot / whole : 0.0f;
}

float tail_of_body(const AnimRig& rig) { return rig.tail_length / std::max(2.0f * rig.body_half_length, 1e-3f); }

}  // namespace

GaitFamily choose_gait_family(const AnimRig& rig) {
  const size_t girdles = rig.girdles.size();
  if (rig.legs.empty() || girdles == 0) return GaitFamily::kLegless;
  if (girdles >= 3) return GaitFamily::kMultiLeg;
  if (girdles == 1) {
    if (!rig.wings.empty() || rig.skull_variant == kBirdSkull) return GaitFamily::kBird;
    if (rig.skull_variant == kMammalSkull && !rig.arms.empty() && tail_of_body(rig) >= kHopperTailOfBody) return GaitFamily::kHopper;
    return GaitFamily::kBiped;
  }
  const float fore = mean_leg_reach(rig, 0), hind = mean_leg_reach(rig, 1);
  if (hind >= kHopperHindToFore * fore) return GaitFamily::kHopper;
  if (rig.weight_kg >= kGraviportalKg && foot_share(rig) < kColumnarFootOfLeg) return GaitFamily::kGraviportal;
  if (rig.skull_variant != kMammalSkull && rig.skull_variant != kBirdSkull) return GaitFamily::kSprawler;
  if (rig.weight_kg > 0.0f && rig.weight_kg < kBounderKg) return GaitFamily::kBounder;
  const float trunk = std::fabs(rig.girdles[0].joint_ms.x - rig.girdles[1].joint_ms.x);
  if (rig.weight_kg >= kPacerKg && rig.hip_height >= kPacerHipOfTrunk * trunk) return GaitFamily::kPacer;
  return GaitFamily::kCursorial;
}

GaitFamilyTraits gait_family_traits(GaitFamily family, const AnimRig& rig) {
  if (family == GaitFamily::kAuto) family = choose_gait_family(rig);
  if (rig.traits_kept && family == rig.traits.family) return rig.traits;
  GaitFamilyTraits t;
  t.family = family;
  const float kg = rig.weight_kg;
  switch (family) {
    case GaitFamily::kAuto:
    case GaitFamily::kCursorial:
    case GaitFamily::kPacer:
      // Walk → trot near Fr 0.5, trot → gallop near Fr 2–3 (Alexander 1989); camels pace where
      // horses trot (Dagg 1974). The full run at Fr 3 (faster gallops are not tested on the
      // shipped levels yet).
      t.gaits = {Gait::kWalk, family == GaitFamily::kPacer ? Gait::kPace : Gait::kTrot, Gait::kGallop};
      t.mid_froude = 0.5f;
      t.fast_froude = 2.0f;
      t.top_froude = 3.0f;
      // Hoofed animals gallop on a stiff back: about 10° from flexed to extended, a chosen
      // figure of the order measured in the horse's canter (Faber et al. 2001).
      t.spine_flex = 0.09f;
      break;
    case GaitFamily::kGraviportal:
      // A lateral-sequence walk and amble at every speed, always a foot down; elephants reach
      // Fr ≈ 2 (Hutchinson et al. 2003), heavier bodies less (∝ M^−½ above 5 t: dinosaur
      // trackways show walking at 1.0–3.6 m/s).
      t.gaits = {Gait::kWalk, Gait::kAmble, Gait::kAmble};
      t.mid_froude = 0.5f;
      t.fast_froude = kNone;
      t.top_froude = 2.0f * std::min(1.0f, std::sqrt(5000.0f / std::max(kg, 1.0f)));
      t.duty_floor = 0.5f;
      break;
    case GaitFamily::kBounder:
      // Half-bound and bound (Gambaryan 1974; Hildebrand 1977).
      t.gaits = {Gait::kWalk, Gait::kHalfBound, Gait::kBound};
      t.mid_froude = 0.5f;
      t.fast_froude = 1.5f;
      t.top_froude = 3.0f;
      // Small mammals bound on their backs: the lumbar spine flexes and extends by tens of
      // degrees each stride (Schilling & Hackert 2006); about 30° from flexed to extended, chosen.
      t.spine_flex = 0.25f;
      break;
    case GaitFamily::kHopper:
      // Both hind feet in phase at every speed (Dawson & Taylor 1973; Ahn et al. 2004); slowly
      // a kangaroo walks on five supports, its forelimbs and tail planted while the hind feet
      // swing (Dawson & Taylor 1973; O'Connor et al. 2014), up to the hop at Fr 0.5 (chosen).
      t.pentapedal = rig.girdles.size() == 1 && !rig.arms.empty() && !rig.tail.empty();
      t.gaits = {t.pentapedal ? Gait::kPentapedal : Gait::kHop, Gait::kHop, Gait::kHop};
      t.mid_froude = 0.5f;
      t.fast_froude = kNone;
      t.top_froude = 3.0f;
      break;
    case GaitFamily::kSprawler: {
      // Walk and trot, the footfall pattern kept (Reilly et al. 2006); a gallop only in small
      // animals. The tail carries the caudofemoralis, the reptile's main retractor of the
      // thigh: a short tail (a tortoise's) means a slow animal (giant tortoises walk at
      // 0.16 m/s, Fr ≈ 0.01: Zani et al. 2005); a long one Fr 1.5.
      const bool small = kg > 0.0f && kg < kSmallSprawlerKg;
      t.gaits = {Gait::kWalk, Gait::kTrot, small ? Gait::kGallop : Gait::kTrot};
      t.mid_froude = 0.5f;
      t.fast_froude = small ? 1.2f : kNone;
      t.top_froude = 0.03f + 1.47f * smoothstep(0.2f, 0.5f, tail_of_body(rig));
      break;
    }
    case GaitFamily::kBiped:
      // Walk → run; a heavy biped walks fast at Fr ≈ 1 and never leaves the ground
      // (Hutchinson & Garcia 2002).
      t.gaits = {Gait::kWalk, Gait::kRun, Gait::kRun};
      t.mid_froude = 0.5f;
      t.fast_froude = kNone;
      t.top_froude = kg >= kHeavyBipedKg ? 1.0f : 2.5f;
      t.duty_floor = kg >= kHeavyBipedKg ? 0.5f : 0.0f;
      if (kg >= kHeavyBipedKg) t.gaits = {Gait::kWalk, Gait::kWalk, Gait::kWalk};
      break;
    case GaitFamily::kBird:
      // Walk → grounded run → aerial run, a continuum (Rubenson et al. 2004).
      t.gaits = {Gait::kWalk, Gait::kGroundedRun, Gait::kRun};
      t.mid_froude = 0.5f;
      t.fast_froude = 1.5f;
      t.aerial_froude = 1.5f;
      t.top_froude = 2.5f;
      t.head_bob = kg > 0.0f && kg < kSmallBirdKg;
      break;
    case GaitFamily::kMultiLeg:
      t.gaits = {Gait::kWalk, Gait::kWalk, Gait::kWalk};
      t.mid_froude = t.fast_froude = kNone;
      t.top_froude = 2.5f;
      break;
    case GaitFamily::kLegless:
      t.gaits = {Gait::kCrawl, Gait::kCrawl, Gait::kCrawl};
      t.mid_froude = t.fast_froude = kNone;
      t.top_froude = 2.5f;
      break;
  }
  return t;
}

float footfall_time(GaitFamily family, int index, int girdles, int girdle, bool far) {
  if (girdles <= 0) return 0.0f;
  if (girdles == 1) {
    // One pair alternates, or hops with both feet together.
    return family == GaitFamily::kHopper ? 0.0f : (far ? 0.5f : 0.0f);
  }
  if (girdles >= 3) {
    // A metachronal (tripod-like) wave, alternating down the body.
    const float near = static_cast<float>(girdle % 2) * 0.5f;
    return far ? frac(near + 0.5f) : near;
  }
  const bool front = girdle == 0;
  // Per gait: near hind, far hind, near fore, far fore.
  struct Pattern {
    float hn, hf, fn, ff;
  };
  // Lateral-sequence walk (limb phase 0.25: the same-side fore foot lands a quarter cycle
  // after its hind foot; Hildebrand 1965), the sprawlers' diagonal-couplet walk (limb phase
  // 0.4; Reilly et al. 2006), the trot (diagonal pairs), the pace (lateral pairs), the
  // transverse and rotary gallops (hind pair, then fore pair, one gathered suspension), the
  // half-bound (hind feet together, fore feet staggered), the bound and the hop (hind pair,
  // then fore pair).
  constexpr Pattern kWalk{0.0f, 0.5f, 0.25f, 0.75f}, kDiagonalCouplets{0.0f, 0.5f, 0.4f, 0.9f};
  constexpr Pattern kTrot{0.0f, 0.5f, 0.5f, 0.0f}, kPace{0.0f, 0.5f, 0.0f, 0.5f};
  constexpr Pattern kTransverse{0.0f, 0.1f, 0.45f, 0.55f}, kRotary{0.0f, 0.1f, 0.55f, 0.45f};
  constexpr Pattern kHalfBound{0.0f, 0.0f, 0.6f, 0.7f}, kBound{0.0f, 0.0f, 0.65f, 0.65f};
  Pattern p = kWalk;
  switch (family) {
    case GaitFamily::kPacer: p = index == 0 ? kWalk : index == 1 ? kPace : kRotary; break;
    case GaitFamily::kGraviportal: p = kWalk; break;
    case GaitFamily::kBounder: p = index == 0 ? kWalk : index == 1 ? kHalfBound : kBound; break;
    case GaitFamily::kHopper: p = kBound; break;
    case GaitFamily::kSprawler: p = index == 0 ? kDiagonalCouplets : index == 1 ? kTrot : kTransverse; break;
    default: p = index == 0 ? kWalk : index == 1 ? kTrot : kTransverse; break;
  }
  return front ? (far ? p.ff : p.fn) : (far ? p.hf : p.hn);
}

}  // namespace anim
}  // namespace ossa
