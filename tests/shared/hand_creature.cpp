// scenes::hand_built_creature() (shared/scenes.h): a creature built bone by bone, independent
// of the generator.

#include "shared/scenes.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ossa/gen/creature.h"

namespace ossa::scenes {

namespace {

struct Builder {
  Creature c;
  std::vector<float> abs_angle;  // model-space angle of every bone so far

  // Adds a bone whose model-space angle is `angle_ms`, starting at (along, 0) in its parent's
  // frame (along < 0: at the parent's end).
  int add(const std::string& name, BoneKind kind, int parent, float length, float width,
          float angle_ms, Layer layer, float along = -1.0f) {
    BoneLocal rest;
    if (parent < 0) {
      rest.offset_ls = {0.0f, along};  // root: `along` is its height
      rest.angle_ls = angle_ms;
    } else {
      rest.offset_ls = {along < 0.0f ? c.skeleton.length(parent) : along, 0.0f};
      rest.angle_ls = angle_ms - abs_angle[static_cast<size_t>(parent)];
    }
    abs_angle.push_back(angle_ms);
    return c.skeleton.add_bone(name, kind, parent, length, width, rest, layer);
  }
};

}  // namespace

// Leg geometry: upper, lower, foot lengths and absolute angles chosen so that the foot tip of
// every leg ends on y = 0 when the spine is at `height` (checked by the tests through FK).
Creature hand_built_creature(bool winged, ContactMode contact) {
  constexpr float kPi = 3.14159265f;
  Builder b;
  Creature& c = b.c;
  c.name = winged ? "hand-bird" : "hand-quadruped";
  c.contact = contact;
  const float height = 1.0f;
  c.root = b.add("root", BoneKind::kRoot, -1, 0.0f, 0.0f, 0.0f, Layer::kBody, height);
  // Back: 4 vertebrae headward (+x) and 4 tailward, each 0.1 m; the list runs head → tail.
  std::vector<int> front_back, hind_back;
  int parent = c.root;
  for (int i = 0; i < 4; ++i) {
    parent = b.add("back_f" + std::to_string(i), BoneKind::kBackVertebra, parent, 0.1f, 0.06f,
                   0.0f, Layer::kBody, i == 0 ? 0.0f : -1.0f);
    front_back.push_back(parent);
  }
  parent = c.root;
  for (int i = 0; i < 4; ++i) {
    parent = b.add("back_h" + std::to_string(i), BoneKind::kBackVertebra, parent, 0.1f, 0.06f,
                   kPi, Layer::kBody, i == 0 ? 0.0f : -1.0f);
    hind_back.push_back(parent);
  }
  const int shoulder_vertebra = front_back.back();
  const int hip_vertebra = hind_back.back();
  // Neck rising at 50°, skull pointing forward-down.
  parent = shoulder_vertebra;
  for (int i = 0; i < 3; ++i) {
    parent = b.add("neck" + std::to_string(i), BoneKind::kNeckVertebra, parent, 0.1f, 0.05f,
                   50.0f * kPi / 180.0f, Layer::kBody);
    c.neck.insert(c.neck.begin(), parent);
  }
  c.skull = b.add("skull", BoneKind::kSkull, parent, 0.3f, 0.12f, -30.0f * kPi / 180.0f,
                  Layer::kBody);
  // Tail hanging back and down.
  parent = hip_vertebra;
  for (int i = 0; i < 4; ++i) {
    parent = b.add("tail" + std::to_string(i), BoneKind::kTailVertebra, parent, 0.09f,
                   0.04f - 0.006f * static_cast<float>(i), kPi + 0.3f + 0.1f * static_cast<float>(i),
                   Layer::kBody);
    c.tail.push_back(parent);
  }
  for (auto it = front_back.rbegin(); it != front_back.rend(); ++it) c.back.push_back(*it);
  c.back.push_back(c.root);
  for (int v : hind_back) c.back.push_back(v);
  // Ribs on the front vertebrae and the first hind one, near and far.
  std::vector<int> rib_vertebrae = front_back;
  rib_vertebrae.push_back(hind_back.front());
  for (Layer layer : {Layer::kFar, Layer::kNear}) {
    const char* side = layer == Layer::kNear ? "near" : "far";
    for (size_t i = 0; i < rib_vertebrae.size(); ++i) {
      b.add(std::string("rib") + std::to_string(i) + "_" + side, BoneKind::kRib,
            rib_vertebrae[i], 0.28f, 0.025f, -100.0f * kPi / 180.0f, layer, 0.05f);
    }
  }
  // Girdles and legs. Front leg from the scapula end, hind leg from the pelvis end.
  struct LegSpec {
    GirdleKind girdle;
    int vertebra;
    LimbKind kind;
  };
  std::vector<LegSpec> specs;
  if (winged) {
    specs = {{GirdleKind::kShoulder, shoulder_vertebra, LimbKind::kWing},
             {GirdleKind::kHip, hip_vertebra, LimbKind::kLeg}};
  } else {
    specs = {{GirdleKind::kShoulder, shoulder_vertebra, LimbKind::kLeg},
             {GirdleKind::kHip, hip_vertebra, LimbKind::kLeg}};
  }
  int pair = 0;
  for (const LegSpec& spec : specs) {
    for (Layer layer : {Layer::kFar, Layer::kNear}) {
      const bool near = layer == Layer::kNear;
      const std::string suffix = std::string(near ? "_near" : "_far") +
                                 (spec.girdle == GirdleKind::kShoulder ? "_front" : "_hind");
      const bool front = spec.girdle == GirdleKind::kShoulder;
      Limb limb;
      limb.kind = spec.kind;
      limb.girdle = spec.girdle;
      limb.side = near ? Side::kNear : Side::kFar;
      limb.pair = pair;
      limb.front = front;
      // Girdle: scapula 0.2 m down-forward, pelvis 0.2 m down-back; both end 0.15 m lower.
      limb.girdle_bone =
          b.add((front ? "scapula" : "pelvis") + suffix,
                front ? BoneKind::kScapula : BoneKind::kPelvis, spec.vertebra, 0.2f, 0.09f,
                front ? -kPi / 2.0f + 0.7f : -kPi / 2.0f - 0.7f, layer, 0.05f);
      if (front) c.shoulder = limb.girdle_bone; else c.hip = limb.girdle_bone;
      if (spec.kind == LimbKind::kWing) {
        limb.bones[0] = b.add("upper" + suffix, BoneKind::kUpperLimb, limb.girdle_bone, 0.25f, 0.04f, 2.6f, layer);
        limb.bones[1] = b.add("lower" + suffix, BoneKind::kLowerLimb, limb.bones[0], 0.3f, 0.03f, 0.3f, layer);
        limb.bones[2] = b.add("hand" + suffix, BoneKind::kHand, limb.bones[1], 0.45f, 0.03f, 2.4f, layer);
      } else {
        // The girdle end sits at y = 1.0 - 0.05 sin(...) - 0.2 * cos(0.7) ~ 0.847; the leg
        // below reaches the ground by construction (solved numerically below).
        const float knee = front ? -1.75f : -1.35f;
        limb.bones[0] = b.add("upper" + suffix, BoneKind::kUpperLimb, limb.girdle_bone, 0.38f, 0.06f, knee, layer);
        limb.bones[1] = b.add("lower" + suffix, BoneKind::kLowerLimb, limb.bones[0], 0.36f, 0.045f, front ? -1.45f : -1.85f, layer);
        limb.bones[2] = b.add("hand" + suffix, BoneKind::kHand, limb.bones[1], 0.14f, 0.04f,
                              contact == ContactMode::kFlat ? 0.0f : -1.2f, layer);
      }
      limb.bend_sign = front ? -1 : 1;
      c.limbs.push_back(limb);
    }
    ++pair;
  }
  c.rest_pose = Pose::rest(c.skeleton);
  // Lift or lower the root so the lowest leg tip touches y = 0.
  const std::vector<Mat2x3> m = model_matrices(c.skeleton, c.rest_pose.locals);
  float lowest = 1e9f;
  for (const Limb& limb : c.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    const int foot = limb.bones[2];
    lowest = std::min(lowest, bone_end(m[static_cast<size_t>(foot)], c.skeleton.length(foot)).y);
  }
  if (lowest < 1e8f) {
    BoneLocal root = c.skeleton.rest(c.root);
    root.offset_ls.y -= lowest;
    c.skeleton.set_rest(c.root, root);
    c.rest_pose = Pose::rest(c.skeleton);
  }
  return c;
}

}  // namespace ossa::scenes
