#pragma once
// A starting rig mapping from bone names (ossa-rig guess, the editors' Rig window): the common
// naming conventions of rigs made elsewhere, matched case- and separator-insensitively:
//
//   Blender / Rigify   thigh.L shin.L foot.L  upper_arm.L forearm.L hand.L  spine neck head
//   Mixamo             mixamorig:LeftUpLeg LeftLeg LeftFoot  LeftArm LeftForeArm LeftHand
//                      Hips Spine Spine1 Neck Head
//   Unreal             thigh_l calf_l foot_l  upperarm_l lowerarm_l hand_l  pelvis spine_01
//   plain              left_leg_upper left_leg_lower left_foot  left_arm_upper ...
//   (and animals)      hind / front legs, paws, tail_1 ... ; "_l" / "left" / ".L" is the near
//                      side (a character facing +x shows its left side).
//
// Names find each limb's upper bone; the hierarchy finds the rest of the chain (its child,
// preferring a matching name, and that one's child). Arms whose hand reaches the ground in the
// rest pose are front legs (a quadruped rigged with arm names). The root is the bone named
// pelvis / hips (else the bone all legs hang from); the spine is the path from the root to
// the neck or head; the tail is the chain of bones named tail.

#include <string>
#include <vector>

#include "ossa/rig/character.h"
#include "ossa/rig/rig_mapping.h"

namespace ossa {

struct RigGuess {
  RigMapping mapping;              // mesh = the mesh file name as given
  std::vector<std::string> notes;  // what was not found or was decided by rule ("no head found")
};

// The part a name suggests, with its side; used by the guess and the Rig window's hints.
enum class BoneRole : uint8_t {
  kNone, kRoot, kSpine, kNeck, kHead, kTail, kLegUpper, kLegLower, kFoot, kArmUpper, kArmLower, kHand
};
struct NamedRole {
  BoneRole role = BoneRole::kNone;
  int side = 0;                    // -1 left (near), +1 right (far), 0 none
  bool front = false;              // "front" / "fore" in the name (a quadruped's front leg)
};
NamedRole role_from_name(const std::string& bone_name);
const char* bone_role_name(BoneRole role);

// Guesses a mapping for `skeleton`; `mesh` is written into the mapping's "mesh" field.
// Legs are the mapping's only hard requirement: without any the notes say so and legs is empty
// (the mapping does not load until the designer adds one).
RigGuess guess_rig_mapping(const ImportedSkeleton& skeleton, const std::string& mesh);

}  // namespace ossa
