#pragma once
// SplinePrototypes — the normalised Hermite splines that shape every step [T 4.4.1]: leg
// swing, pelvis bob, arm swing and idle, each in a walk and a run version that the animator
// blends by the walk→run factor. Designers edit them live (spline editor) and save them as
// assets/animation/prototypes.json:
//
//   { "format": "ossa.prototypes", "version": 1,
//     "prototypes": {
//       "leg_swing_x": { "walk": [ {"t": 0, "p": 0, "m": 0}, ... ], "run": [ ... ] },
//       "leg_swing_y": { ... }, "pelvis_y": { ... }, "arm_swing": { ... },
//       "arm_bend": { ... }, "idle_y": { ... } } }
//
// Every spline runs over normalised time t in [0, 1]; keys are {t, p, m} (time, value,
// tangent dp/dt). A walk/run pair must have the same number of keys (the animator blends key
// by key, HermiteSpline::blend). What each value means:
//   leg_swing_x  fraction of the step covered by the swinging foot (0 → 1) over the swing;
//   leg_swing_y  foot lift above the line from lift-off to touch-down, in leg lengths;
//   pelvis_y     girdle bob over one step, in leg lengths (added to the standing height);
//   arm_swing    upper-arm angle offset (radians, + forward) over one stride;
//   arm_bend     extra elbow flexion (radians) over one stride;
//   idle_y       body bob over one idle breath cycle, in leg lengths.

#include <array>
#include <string>
#include <string_view>

#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"
#include "ossa/math/hermite.h"

namespace ossa {

struct PrototypePair {
  HermiteSpline walk;
  HermiteSpline run;

  // The spline blended by the walk→run factor w in [0, 1] (key-wise).
  HermiteSpline blended(float w) const { return HermiteSpline::blend(walk, run, w); }
  // Value of the blended spline at t without building it.
  float value(float t, float w) const { return (1.0f - w) * walk.position(t) + w * run.position(t); }
};

enum class PrototypeId : int { kLegSwingX, kLegSwingY, kPelvisY, kArmSwing, kArmBend, kIdleY, kCount };
constexpr int kPrototypeCount = static_cast<int>(PrototypeId::kCount);
const char* prototype_name(PrototypeId id);

// The values each prototype may take, in its own unit (see above). The loader and the spline
// editor keep keys inside it, and the animator clamps the evaluated value to it (tangents can
// overshoot between keys), so no accepted prototype can break the walk: the stance feet stay
// planted within 1 mm however the keys are set (tests/game/animator_end_to_end_test.cpp,
// "prototypes at the loader's limits").
//   leg_swing_x [-0.5, 1.5]  the foot may reach past its landing and come back;
//   leg_swing_y [0, 1]       a foot never dips below the line from lift-off to touch-down;
//   pelvis_y, idle_y [-0.0625, 0.0625] leg lengths: a bob the stance legs can always follow;
//   arm_swing, arm_bend [-3, 3] radians.
struct PrototypeRange {
  float min, max;
  float clamp(float v) const { return v >= min ? (v <= max ? v : max) : min; }  // NaN → min
};
// (Inline: the swing reads it twice per foot and tick.)
inline constexpr PrototypeRange prototype_range(PrototypeId id) {
  // Bounds exact in binary, so a file holding the bound itself ("0.0625") reads back.
  switch (id) {
    case PrototypeId::kLegSwingX: return {-0.5f, 1.5f};
    case PrototypeId::kLegSwingY: return {0.0f, 1.0f};
    case PrototypeId::kPelvisY:
    case PrototypeId::kIdleY: return {-0.0625f, 0.0625f};
    case PrototypeId::kArmSwing:
    case PrototypeId::kArmBend: return {-3.0f, 3.0f};
    case PrototypeId::kCount: break;
  }
  return {0.0f, 0.0f};
}
// Bound on key tangents (|m|, value units per unit time).
inline constexpr float kMaxPrototypeTangent = 1000.0f;

struct SplinePrototypes {
  std::array<PrototypePair, kPrototypeCount> pairs;

  PrototypePair& operator[](PrototypeId id) { return pairs[static_cast<int>(id)]; }
  const PrototypePair& operator[](PrototypeId id) const { return pairs[static_cast<int>(id)]; }

  // The tuned defaults (the same values as the shipped prototypes.json).
  static SplinePrototypes defaults();
  // Every spline valid, t within [0, 1], walk/run key counts equal.
  bool is_valid() const;
};

Json prototypes_to_json(const SplinePrototypes& prototypes);
Result<SplinePrototypes> prototypes_from_json(const Json& doc, std::string_view file);
Result<SplinePrototypes> load_prototypes(const std::string& path);
Status save_prototypes(const std::string& path, const SplinePrototypes& prototypes);  // atomic

}  // namespace ossa
