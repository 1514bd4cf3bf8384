#pragma once
// BodyPlan — the geometry a Genome implies before any bone exists, in the genome's
// 1000×1000 frame (units "fu", y up): the post-processed spine curves, the joint points of
// every vertebra, the girdle joints, limb lengths and the ground height [Z 7.2.1]. Shared by
// the Generator (which needs the ground and girdles to place legs) and the SkeletonBuilder.

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/gen/genome.h"
#include "ossa/math/bezier.h"

namespace ossa {

// Girdle slots: 3 girdles × 2 slots. Slot 1 exists only with GenomeOptions::multi_limb.
constexpr int kGirdleCount = 3;
constexpr int kSlotsPerGirdle = 2;

struct GirdlePlan {
  bool exists = false;
  std::array<int, kSlotsPerGirdle> spine_joint{-1, -1};  // index into BodyPlan::joints
  std::array<glm::vec2, kSlotsPerGirdle> joint_fu{};      // where the limb chain starts
  std::array<glm::vec2, kSlotsPerGirdle> girdle_start_fu{};
};

struct BodyPlan {
  // Spine after the C1 fix [Z 9.6.2]: neck (head → shoulder), back (shoulder → hip),
  // tail (hip → tip).
  CubicBezier neck, back, tail;
  float neck_length = 0.0f, back_length = 0.0f, tail_length = 0.0f;  // fu
  float body_size = 1.0f;   // fu: back length, the yardstick for widths

  // Spine joints from the head end to the tail tip: neck vertebrae, the front half of the
  // back, the root (mid-back), the rear half, the tail. joints[root_joint] is the root.
  std::vector<glm::vec2> joints;
  int shoulder_joint = 0, root_joint = 0, hip_joint = 0;
  std::vector<float> back_fraction;  // per joint: arc fraction along the back from the
                                     // shoulder (0) to the hip (1); <0 neck, >1 tail

  std::array<GirdlePlan, kGirdleCount> girdles;  // indexed by GirdleKind
  LimbLengths front, hind;  // clamped >= 0
  float ground_y = 0.0f;    // fu [Z 7.2.1]
  float pitch = 0.0f;       // radians the spine was tilted about the root to stand level
  float heel_probability = 0.0f;  // [Z 7.2.1]: chance the legs stand flat (heel/wrist down)
};

// Minimum neck length, as a fraction of the back, for a neck girdle [Z 7.2.3].
constexpr float kMinNeckGirdleRatio = 0.45f;
// Legs shorter than this many frame units are not placed but hang straight down [Z 9.8 (3)].
constexpr float kMinPlacedLegLength = 5.0f;

// Computes the plan. `limbs` decides which girdles carry legs (for the ground height).
BodyPlan plan_body(const Genome& genome);

// Lengths of the chain a limb of `kind` on `girdle` gets (front lengths at the shoulder and
// neck, hind at the hip; wings on a wingless body are lengthened, fins get a minimum size).
LimbLengths limb_lengths(const BodyPlan& plan, const Genome& genome, LimbKind kind,
                         GirdleKind girdle);

// Whether a limb of `kind` may sit on `girdle` [Z 7.2.4].
bool limb_allowed(LimbKind kind, GirdleKind girdle);

// Bend direction of a leg chain as two-bone IK takes it: hind legs carry the knee in front of
// the hip→foot line (+1, counter-clockwise of a downward line), front legs the elbow behind
// it (-1). Used by the animator's IK too.
int limb_bend_sign(GirdleKind girdle);

// [Z 7.2.2] iterative leg placement with the joint limits of [Z fig. 7.1] and the [Z 9.8]
// fixes. Returns {upper absolute angle, lower relative, foot relative} (radians, frame space)
// with the contact point (tip or heel) on plan.ground_y, or the straight-down fallback.
std::array<float, 3> place_leg(const BodyPlan& plan, glm::vec2 joint_fu, const LimbLengths& lengths,
                               GirdleKind girdle, ContactMode contact);

// Rest angles for arms (upper arm down, elbow 90°, hand forward) and fins (straight back).
std::array<float, 3> arm_rest_angles();
std::array<float, 3> fin_rest_angles();

// The contact point of a placed leg chain (tip, or heel for flat contact), frame units.
glm::vec2 leg_contact_point(glm::vec2 joint_fu, const LimbLengths& lengths,
                            const std::array<float, 3>& angles, ContactMode contact);

}  // namespace ossa
