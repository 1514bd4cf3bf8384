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
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/gen/creature.h"
#include "ossa/gen/genome.h"
#include "ossa/io/result.h"
#include "ossa/level/box.h"
#include "ossa/math/transform2d.h"
#include "ossa/skeleton/mid_joint.h"

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
  float aspect = 0.25f;       // height / (distance between the anchors) at width 1
  // The fraction of the sprite's height the bone's width spans (its knobs, its shaft): the
  // drawn height is width / thickness, so a long thin bone stays thin. 0: the drawn height is
  // max(aspect × length, width) (ribs and fins, whose height is their curve or fan).
  float thickness = 0.0f;
  // Feet (paw, hoof, bird foot): the u where the contact part (toes, hoof, claws) begins; the
  // art is drawn for a vertical bone with the ground at the child anchor, the contact part at
  // u ≥ contact_from no further than the anchor's u. The builder turns that part about the
  // child anchor so it stands on the ground in the rest pose, whatever the foot's angle.
  // Negative: none.
  float contact_from = -1.0f;
  // Skulls: the u where the muzzle or beak begins; the builder stretches the art on either
  // side so the muzzle takes the creature's share of the skull (Creature::skull_snout).
  // Negative: none.
  float snout_from = -1.0f;
  glm::vec2 uv_min{0.0f}, uv_max{1.0f};  // atlas rectangle (filled in when the atlas is packed)
                              // in texture coordinates with t growing UP the image, as the
                              // textures are uploaded (Texture::from_image flips the rows):
                              // uv_min = bottom-left corner, uv_max = top-right corner.
  // How far the drawing reaches across the bone at each joint: unit-box v from the anchor's v
  // down (x) and up (y) to the last opaque pixel (alpha ≥ 50 %) over the sprite's end around
  // that anchor (u within the anchor's overhang past it, mirrored inwards). Measured from the
  // image when the atlas is packed (Atlas::build); negative: not measured, the whole box
  // (joint_reach). Smooth skinning tucks a parent's end under its child's start with it.
  glm::vec2 parent_reach{-1.0f}, child_reach{-1.0f};
};

// `info`'s reach at its parent (child_end false) or child anchor: the measured one, else the
// unit box's extent below and above the anchor's v.
glm::vec2 joint_reach(const SpriteInfo& info, bool child_end);

// The sprite set: one SpriteInfo per SpriteId, loaded from sprites.json (versioned,
// validated; errors name the file and field).
struct SpriteSet {
  std::array<SpriteInfo, static_cast<size_t>(SpriteId::kCount)> sprites;
  const SpriteInfo& operator[](SpriteId id) const { return sprites[static_cast<size_t>(id)]; }
};
// Validation: format "ossa.sprites", version 1 or 2, one entry per SpriteId name (sprite_name),
// each with file (a .png name), parent_anchor and child_anchor in [0, 1]², child u > parent u,
// and aspect > 0 consistent with the anchors (1 / aspect > |child v - parent v|); version 2 may
// add thickness in (0, 1], contact_from and snout_from between the anchors' u. Unknown sprite
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
  glm::vec2 uv;                     // atlas texture coordinates (t up, see SpriteInfo::uv_min)
  std::array<uint8_t, 4> bones{};   // bone indices within the creature (≤ 255 bones); bones[0]
                                    // is the bone whose sprite the vertex belongs to (its layer)
  std::array<float, 4> weights{};   // sum to 1; unused slots 0 (bones[0]'s may be 0 too: a
                                    // sprite's end deep in its neighbour's blend follows it)
  float shade = 1.0f;               // 1 near/body, < 1 for the far side (drawn darker)
};

struct SpriteMeshOptions {
  // Smooth skinning (DESIGN.md §9): across every chain joint (see chain_children) the two
  // sprites' vertices near the joint blend parent and child with the same weights, linear in
  // their distance along the bone, so both sprites bend alike, along one circular arc, and a
  // bent knee keeps one outline. A limb joint blends through kSmoothJointFrames mid-joint
  // frames (SpriteMesh::mid_joints) turned a quarter, half and three quarters of the way, in
  // turn along the blend, so a linear blend never spans more than a quarter of the joint's
  // turn (a 150° bend keeps 95 % of the joint's thickness, not 26 % as with parent and child
  // alone, the "candy wrapper", or 79 % through one half-way frame, which leaves a point on
  // the outside of the bend). At a limb joint the sprites get kSmoothRows rows of quads, not
  // one: each column moves by one blended matrix, and a quad as tall as the sprite between
  // two columns turned apart maps its texture with a kink along its diagonal (each triangle
  // is affine), a saw-tooth outline. And there the parent's end is squeezed across the bone
  // to within the child's start (joint_reach), which is drawn on top of it, so its outline
  // never shows as a second one beside the child's. Spine joints, which turn a few degrees,
  // blend parent and child directly. Applies when the creature asks for it
  // (Creature::smooth_skinning, the genome's options.smooth_skinning); false makes every
  // creature's sprites rigid (one bone per vertex, one quad across), e.g. for the per-bone
  // reference path.
  bool smooth_weights = true;
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
  std::vector<MidJoint> mid_joints;       // smooth skinning: palette entries after the bones
  std::vector<glm::vec2> rest_positions;  // per vertex, the rest pose as drawn (model space);
                                          // = position_ms unless smooth skinning straightened
                                          // the bind pose (empty: position_ms)

  // Palette entries a creature with this mesh needs: its bones, then its mid joints.
  int palette_size() const { return static_cast<int>(inverse_bind.size() + mid_joints.size()); }
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
// loader accepts fits (kMaxCreatureBones, gen/genome.h), with at least one mid-joint frame
// for each of its limbs' two blended joints (upper–lower, lower–hand) on both sides, and
// kSmoothJointFrames each where the indices suffice (every example creature). A skeleton
// with more bones and limb joints than that blends parent and child directly.
constexpr int kMaxSpriteMeshBones = 255;
constexpr int kSmoothJointFrames = 3;  // mid-joint frames per limb joint (odd: one half way)
static_assert(kMaxCreatureBones + 2 * 2 * kMaxLimbPairs <= kMaxSpriteMeshBones + 1,
              "genome limits allow more bones and mid joints than a sprite mesh indexes");
// Smooth skinning's blend: a joint blends over ±kSmoothBlend × the joint's half thickness
// (the mean of the two sprites' drawn half heights) along each bone, at most
// kSmoothMaxSpan × either bone's length (so a bone's two blends never meet), sampled by
// kSmoothColumns quad columns on each side of a limb joint (kSmoothSpineColumns at the
// spine) so the bent outline is a curve, not a kink, and kSmoothRows rows across a limb
// bone's sprite. kSmoothBlend, with the shipped art drawn as thick as its bones' widths
// (tests/render/smooth_skinning_test.cpp): narrower turns the joint over too short a stretch,
// folding the inside of a bent knee over itself and wrinkling the outside (0.4 leaves a notch
// outside the horse's knee at -90°); wider swells the knob and leaves gaps beside it in the
// crease (0.7 pinches pixels of background off in the kangaroo's and the magpie's at -90°).
constexpr float kSmoothBlend = 0.55f;
constexpr float kSmoothMaxSpan = 0.45f;
constexpr int kSmoothColumns = 4;        // limb joints (a multiple of (kSmoothJointFrames + 1) / 2)
constexpr int kSmoothSpineColumns = 2;   // spine joints, which turn a few degrees each
constexpr int kSmoothRows = 4;           // limb bones' sprites (rigid and spine sprites: 1)

// Per bone, the bone that continues it across its end joint — the one its end blends with
// under smooth skinning — or -1: a child of non-zero length in the same layer that starts at
// the bone's end (within 1 % of its length) in `locals`, the straightest one when several do.
// So limbs chain upper → lower → hand and the spine vertebra to vertebra to skull; ribs and
// girdles (another layer than their vertebra) stay rigid, and so does a girdle bone's end at
// the limb (a ball joint: the blade's end would bend after the limb).
std::vector<int> chain_children(const Skeleton& skeleton, const std::vector<BoneLocal>& locals);

// Builds the mesh: per bone of non-zero length a strip of quads (columns at u = 0, the parent
// anchor, the child anchor, 1, and with smooth weights the blend's columns around each chain
// joint; one row, or kSmoothRows on a smooth limb bone) mapped so the parent anchor lands on
// the bone start and the child anchor on the bone end in the bind pose; the drawn height is
// max(aspect × length, width) (a smooth limb joint's parent end squeezed, SpriteMeshOptions);
// sprite_flip_y mirrors v. Within a layer, bones are ordered ribs, girdles, spine, skull,
// upper, lower, hand (later ones draw on top). The bind pose is the rest pose
// (creature.rest_pose, or the skeleton's rest locals), with smooth weights straightened at
// every blended joint (the child's rest angle to its parent set to 0): rest_positions holds
// the rest pose as drawn.
// Precondition (asserted): bone_count() <= kMaxSpriteMeshBones — try_build_sprite_mesh
// returns an Error instead.
SpriteMesh build_sprite_mesh(const Creature& creature, const SpriteSet& sprites,
                             const SpriteMeshOptions& options = {});
Result<SpriteMesh> try_build_sprite_mesh(const Creature& creature, const SpriteSet& sprites,
                                         const SpriteMeshOptions& options = {});

// The most bones with a non-zero weight on one vertex of `mesh` (1 rigid, 2 smooth; ≤ 4).
int max_weights_per_vertex(const SpriteMesh& mesh);

// A vertex skinned by `palette` (one entry per bone, then per mid joint): Σ w_k palette[b_k] p,
// what the skinned shader computes.
glm::vec2 skin_vertex(const SpriteVertex& v, std::span<const Mat2x3> palette);

// The palette of a pose (palette_size() entries): world · inverse_bind per bone (PaletteJob),
// then the mid joints (mid_joint_palette) — what CreatureBatch::set_world uploads; `world` has
// one matrix per bone (bone frame → world). body_palette (body/body_mesh.h) is the bodies' twin.
void sprite_palette(const SpriteMesh& mesh, std::span<const Mat2x3> world, std::span<Mat2x3> palette);

// The model-space box around every vertex in the rest pose as drawn (rest_positions, else
// position_ms: whole sprites, not only the joints). An empty mesh gives a zero box at the origin.
Box sprite_mesh_bounds(const SpriteMesh& mesh);

}  // namespace ossa
