#pragma once
// Creature — what the generator builds from a Genome: the Skeleton, the LimbLayout (which
// bones form each limb, where it attaches and what it is for), the rest pose and the ground.
//
// Model space (DESIGN.md §3): metres, +x forward, +y up, x = 0 below the root bone, y = 0 on
// the ground the creature stands on in its rest pose. The genome's 1000×1000 frame maps to it
// by frame_to_model: p_ms = (p_frame - origin_frame) * scale.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/gen/gait_family.h"
#include "ossa/gen/look.h"
#include "ossa/skeleton/pose.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

enum class LimbKind : uint8_t { kLeg, kArm, kWing, kFin };
enum class GirdleKind : uint8_t { kNeck, kShoulder, kHip };
enum class Side : uint8_t { kNear, kFar };
// How a leg touches the ground in the rest pose [Z 7.2.1]: with the tip of the foot/hand
// (digitigrade/unguligrade) or with the whole sole flat (plantigrade, heel/wrist down).
enum class ContactMode : uint8_t { kTip, kFlat };

const char* limb_kind_name(LimbKind kind);
const char* girdle_kind_name(GirdleKind kind);
const char* contact_mode_name(ContactMode mode);

// One limb: girdle bone plus a three-bone chain (upper, lower, hand/foot).
struct Limb {
  LimbKind kind = LimbKind::kLeg;
  GirdleKind girdle = GirdleKind::kShoulder;
  int slot = 0;                 // 0 or 1: several limbs per girdle (pegasus) [Z 7.2.3]
  Side side = Side::kNear;
  int pair = 0;                 // index of the limb pair; near and far copies share it
  int girdle_bone = -1;         // scapula or pelvis bone the chain hangs from
  std::array<int, 3> bones{};   // upper, lower, hand/foot bone indices
  int bend_sign = 1;            // +1: middle joint bends counter-clockwise (forward) of root→tip
  bool front = true;            // a front-limb chain (front lengths) or a hind one
};

struct Creature {
  Skeleton skeleton;
  std::vector<Limb> limbs;      // near and far copies, pairs adjacent
  Pose rest_pose;
  ContactMode contact = ContactMode::kTip;
  int skull_variant = 0;        // 0 mammal, 1 bird, 2 reptile, 3 fish (genome.h)
  float skull_snout = 0.5f;     // the muzzle's share of the skull length (SkullShape::snout)
  float scale = 0.002f;         // metres per frame unit
  glm::vec2 origin_frame{0.0f}; // frame point that maps to the model origin
  float ground_y_ms = 0.0f;     // always 0 by construction; kept explicit for clarity
  std::string name;             // example name, or "random-<seed>"
  bool smooth_skinning = true;  // GenomeOptions::smooth_skinning: sprites blend across joints
  GaitFamily gait_family = GaitFamily::kAuto;  // the genome's choice (kAuto: from the body plan)

  // The body (body/body_mesh.h): the genome's look and appendages, its weight, and the body
  // mass the weight asks for at this creature's size (gen/true_size.h:
  // expected_body_mass_kg; nullopt when the animal's true size is unknown — the body then
  // keeps its default girths times look.fatness).
  Look look;
  std::vector<Appendage> appendages;
  float weight_kg = 0.0f;
  std::optional<float> body_mass_kg;

  // Spine chain bone indices from the head end to the tail tip (skull excluded), the root,
  // the skull, and the girdle bones (-1 when absent).
  std::vector<int> neck, back, tail;
  int root = 0;
  int skull = -1;
  int shoulder = -1;
  int hip = -1;
  int neck_girdle = -1;

  int leg_count() const;
  int count(LimbKind kind) const;

  glm::vec2 frame_to_model(glm::vec2 p_frame) const { return (p_frame - origin_frame) * scale; }
};

}  // namespace ossa
