#pragma once
// Bone shapes of the SVG export [Z 7.4]: one function per bone kind, each drawing its bone in
// the bone's own frame (origin at the joint with its parent, +x along the bone to (L, 0), +y
// the bone's left side), into PathBuilder path data (svg_path.h). Internal to ossa::core's
// SVG export (export_svg.cpp); not part of the public interface.

#include <glm/vec2.hpp>

#include "ossa/gen/svg_path.h"

namespace ossa::svg {

// What the shape functions need to know about one bone besides its size.
struct BoneContext {
  float length = 0.0f;
  float width = 0.0f;
  bool headward = true;            // spine bones: +x points to the head (dorsal is +y)
  glm::vec2 forward_ls{1.0f, 0.0f};  // model +x (the creature's forward) in the bone frame
  glm::vec2 up_ls{0.0f, 1.0f};       // model +y in the bone frame
};

// Long bone: shaft with a waist and rounded knobs at both joints.
void long_bone(PathBuilder& p, float L, float w);
// Vertebra, authored headward: body, spinous process leaning to the tail (-x), transverse
// process as a small ventral-caudal lobe.
void vertebra(PathBuilder& p, float L, float w, float spine_height);
// Rib: a tapered arc bulging to side `bulge` (+1: +y).
void rib(PathBuilder& p, float L, float w, float bulge);
// Skull, authored with the snout at +x and the dorsal side at +y (variant 0 mammal, 1 bird,
// 2 reptile, 3 fish). Holes (orbit, nostril) go to `holes`.
void skull(PathBuilder& p, PathBuilder& holes, float L, float w, int variant);
// Scapula: a blade from the dorsal border (origin) narrowing to the shoulder joint at (L, 0).
void scapula(PathBuilder& p, PathBuilder& marks, float L, float w);
// Pelvis: ilium plate from the sacrum (origin) to the acetabulum at (L, 0), ischium beyond.
void pelvis(PathBuilder& p, PathBuilder& holes, float L, float w);

// The limb a hand/foot bone belongs to decides its shape.
enum class HandShape { kHoof, kPaw, kFlat, kHand, kBirdFoot, kWingHand, kFin };
// A hand or foot of `shape`, sized by the bone (b.length, b.width), facing b.forward_ls.
void hand(PathBuilder& p, PathBuilder& holes, const BoneContext& b, HandShape shape);

}  // namespace ossa::svg
