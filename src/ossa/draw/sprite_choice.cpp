#include "ossa/draw/sprite_mesh.h"

// Sprite choice: which sprite a bone gets — BoneKind + limb + contact + skull variant →
// SpriteId (the rule is documented at sprite_for_bone in sprite_mesh.h).

#include <algorithm>
#include <cmath>

namespace ossa {

SpriteId sprite_for_bone(const Creature& creature, int bone) {
  const Skeleton& s = creature.skeleton;
  OSSA_ASSERT(bone >= 0 && bone < s.bone_count(), "sprite_for_bone: bone index out of range");
  switch (s.kind(bone)) {
    case BoneKind::kRoot:
    case BoneKind::kBackVertebra: return SpriteId::kVertebra;
    // Neck vertebrae are long spools with low spines, like tail vertebrae: the tall-spined
    // back vertebra stretched to a neck segment's length reads as a row of spikes.
    case BoneKind::kNeckVertebra:
    case BoneKind::kTailVertebra: return SpriteId::kTailVertebra;
    case BoneKind::kSkull:
      return static_cast<SpriteId>(static_cast<int>(SpriteId::kSkullMammal) +
                                   std::clamp(creature.skull_variant, 0, 3));
    case BoneKind::kRib: return SpriteId::kRib;
    case BoneKind::kScapula: return SpriteId::kScapula;
    case BoneKind::kPelvis: return SpriteId::kPelvis;
    case BoneKind::kUpperLimb:
    case BoneKind::kLowerLimb: return SpriteId::kLongBone;
    case BoneKind::kHand: break;
  }
  const Limb* limb = nullptr;
  for (const Limb& l : creature.limbs) {
    if (l.bones[2] == bone) limb = &l;
  }
  if (!limb) return SpriteId::kFlatFoot;
  switch (limb->kind) {
    case LimbKind::kWing: return SpriteId::kWingHand;
    case LimbKind::kFin: return SpriteId::kFin;
    case LimbKind::kArm: return SpriteId::kFlatFoot;
    case LimbKind::kLeg: break;
  }
  if (creature.contact == ContactMode::kFlat) return SpriteId::kFlatFoot;
  // Tip contact: the rest-pose direction of the bone is the sum of the joint angles up the
  // chain (rest locals carry no scale or mirror). Same rule as export_svg's hand_shape. A foot
  // lying nearly flat on the ground (a kangaroo's, a resting bird's tarsus) is drawn flat, its
  // sole on the ground; the animator stands it so (anim_rig.cpp kSteepFootAtRest, the same rule).
  const std::vector<BoneLocal>& locals =
      creature.rest_pose.locals.size() == static_cast<size_t>(s.bone_count()) ? creature.rest_pose.locals
                                                                             : s.rest_locals();
  float angle = 0.0f;
  for (int b = bone; b >= 0; b = s.parent(b)) angle += locals[static_cast<size_t>(b)].angle_ls;
  const float steep = std::fabs(std::sin(angle));
  if (steep < 0.5f) return SpriteId::kFlatFoot;
  if (creature.count(LimbKind::kWing) > 0) return SpriteId::kBirdFoot;
  const int lower = limb->bones[1];
  const bool cannon = lower >= 0 && s.length(bone) >= 0.45f * s.length(lower);
  return steep > 0.7f && cannon ? SpriteId::kHoof : SpriteId::kPaw;
}

}  // namespace ossa
