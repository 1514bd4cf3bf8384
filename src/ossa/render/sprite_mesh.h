#pragma once
// SpriteMesh — the bone-sprite mesh of one creature [Z 7.4], built on the CPU from its
// Skeleton and the bone sprite set (assets/sprites/bones/sprites.json), ready for GPU
// skinning. No GL here: CreatureBatch uploads it.
//
// Every bone gets the sprite of its kind, placed by the sprite's parent and child joint
// anchors so that the anchors land on the bone's start and end, whatever its length; the
// sprite's height follows the bone's width. Positions are in creature model space of the
// rest pose (the bind pose); a vertex is skinned by palette = world · inverse_bind of its
// bones (pose.h PaletteJob), so smooth weights across a joint are possible.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/gen/creature.h"
#include "ossa/gen/genome.h"
#include "ossa/io/result.h"
#include "ossa/level/box.h"
#include "ossa/math/transform2d.h"

namespace ossa {

// Which sprite a bone gets; chosen from BoneKind, limb kind, contact mode and skull variant.
enum class SpriteId : uint8_t {
  kSkullMammal, kSkullBird, kSkullReptile, kSkullFish,
  kVertebra, kTailVertebra, kRib, kScapula, kPelvis,
  kLongBone,      // upper and lower limb bones
  kPaw, kHoof, kFlatFoot, kBirdFoot, kWingHand, kFin,
  kCount
};
const char* sprite_name(SpriteId id);

// One sprite of the set: its rectangle in the atlas and its joint anchors in the sprite's
// unit box (u right along the bone, v up; (0,0) bottom-left, (1,1) top-right).
struct SpriteInfo {
  std::string name;           // "vertebra", file stem of its PNG/SVG
  std::string file;           // PNG file name relative to the sprites.json folder ("vertebra.png")
  glm::vec2 parent_anchor{0.0f, 0.5f};  // unit box: where the joint to the parent sits
  glm::vec2 child_anchor{1.0f, 0.5f};   // unit box: where the joint to the child sits
  float aspect = 0.25f;       // height / (distance between the anchors) at width 1 — a
                              // bone's drawn height is max(aspect * length, bone width)
  glm::vec2 uv_min{0.0f}, uv_max{1.0f};  // atlas rectangle (filled in when the atlas is packed)
                              // in texture coordinates with t growing DOWN the image (t = 0 is
                              // the first PNG row, as glTexImage2D receives an unflipped PNG):
                              // uv_min = top-left corner, uv_max = bottom-right corner.
};

// The sprite set: one SpriteInfo per SpriteId, loaded from sprites.json (versioned,
// validated; errors name the file and field).
struct SpriteSet {
  std::array<SpriteInfo, static_cast<size_t>(SpriteId::kCount)> sprites;
  const SpriteInfo& operator[](SpriteId id) const { return sprites[static_cast<size_t>(id)]; }
};
// Validation: format "ossa.sprites", version 1, one entry per SpriteId name (sprite_name), each
// with file (a .png name), parent_anchor and child_anchor in [0, 1]², child u > parent u, and
// aspect > 0 consistent with the anchors (1 / aspect > |child v - parent v|). Unknown sprite
// names are errors (typos would otherwise fall back silently).
Result<SpriteSet> load_sprite_set(const std::string& path);
// The built-in anchors (used by tests and when no file is given): the same values as the
// shipped assets/sprites/bones/sprites.json (tools/make-bone-sprites writes both from the SVGs;
// a test checks they agree).
SpriteSet default_sprite_set();
// The SpriteId named `name` ("long_bone"), or SpriteId::kCount.
SpriteId sprite_id_from_name(std::string_view name);

// One vertex as the skinned shader reads it.
struct SpriteVertex {
  glm::vec2 position_ms;            // bind-pose model space, metres
  glm::vec2 uv;                     // atlas texture coordinates (t down, see SpriteInfo::uv_min)
  std::array<uint8_t, 4> bones{};   // bone indices within the creature (≤ 255 bones)
  std::array<float, 4> weights{};   // sum to 1
  float shade = 1.0f;               // 1 near/body, < 1 for the far side (drawn darker)
};

struct SpriteMeshOptions {
  bool smooth_weights = false;      // blend vertices near a joint with the parent bone: the
                                    // part of the sprite behind the parent anchor and the first
                                    // kSmoothSpan of the anchor span go 50 % → 100 % to the bone
  float far_shade = 0.62f;          // brightness of far-side bones
};

// Triangles in three index ranges, one per Layer (far first, then body, then near), so one
// draw call per layer draws every creature of a batch in the right order.
struct SpriteMesh {
  std::vector<SpriteVertex> vertices;
  std::vector<uint32_t> indices;
  std::array<uint32_t, 4> layer_begin{};  // indices [layer_begin[l], layer_begin[l+1])
  std::vector<Mat2x3> inverse_bind;       // one per bone: model space → bone frame
  std::vector<SpriteId> bone_sprites;     // one per bone
};

// Sprite choice (documented rule, same as the SVG exporter's shapes):
//   skull → skull variant (creature.skull_variant: 0 mammal, 1 bird, 2 reptile, 3 fish);
//   back vertebrae → kVertebra; neck and tail vertebrae → kTailVertebra (long, low-spined);
//   rib, scapula, pelvis → theirs;
//   upper and lower limb bones → kLongBone (also in fins: only the distal bone is a fin fan);
//   hand bone by its limb: wing → kWingHand, fin → kFin, arm → kFlatFoot (a flat hand);
//   leg → kBirdFoot on a winged creature, kFlatFoot for ContactMode::kFlat, else (tip contact)
//   by the rest-pose direction of the bone: nearly level (|sin| < 0.5, e.g. a kangaroo's foot)
//   kFlatFoot, steep (|sin| > 0.7) and at least 0.45 × the lower bone long (a cannon bone)
//   kHoof, otherwise kPaw. A hand bone in no limb → kFlatFoot; the root → kVertebra (no quad).
SpriteId sprite_for_bone(const Creature& creature, int bone);

// Bone indices are uint8: a creature may have at most this many bones. Every genome the
// loader accepts fits (kMaxCreatureBones, gen/genome.h).
constexpr int kMaxSpriteMeshBones = 255;
static_assert(kMaxCreatureBones <= kMaxSpriteMeshBones, "genome limits allow more bones than a sprite mesh holds");
// Fraction of a sprite's anchor span over which smooth weights fade to the bone alone.
constexpr float kSmoothSpan = 0.15f;

// Builds the mesh: per bone of non-zero length a strip of quads (columns at u = 0, the parent
// anchor, parent anchor + kSmoothSpan of the span, the child anchor, 1) mapped so the parent
// anchor lands on the bone start and the child anchor on the bone end in the rest pose
// (creature.rest_pose, or the skeleton's rest locals); the drawn height is
// max(aspect × length, width); sprite_flip_y mirrors v. Within a layer, bones are ordered
// ribs, girdles, spine, skull, upper, lower, hand (later ones draw on top).
// Precondition (asserted): bone_count() <= kMaxSpriteMeshBones — try_build_sprite_mesh
// returns an Error instead.
SpriteMesh build_sprite_mesh(const Creature& creature, const SpriteSet& sprites,
                             const SpriteMeshOptions& options = {});
Result<SpriteMesh> try_build_sprite_mesh(const Creature& creature, const SpriteSet& sprites,
                                         const SpriteMeshOptions& options = {});

// The model-space box around every vertex (the bind pose as drawn: whole sprites, not only
// the joints). An empty mesh gives a zero box at the origin.
Box sprite_mesh_bounds(const SpriteMesh& mesh);

}  // namespace ossa
