#pragma once
// BodyMesh — a generated creature's body: flesh, skin and coat built on the CPU from its
// skeleton, rest pose, weight and look ([Z 10] "use the weight", [Z 10.2] skin over the
// skeleton guided by bony landmarks, [T 1.2] one sprite skinned to a skeleton; DESIGN.md §9).
// No GL here: CreatureBatch (render/creature_batch.h) uploads it and skins it on the GPU with
// the same palette path as the bone sprites; glTF export and the SVG side view read it too.
//
// Parts (body_parts.h), each one closed, non-self-intersecting outline around a filled
// triangle strip, drawn in three layers so the creature reads as one body:
//   far     the far-side limbs (legs, arms, wings, fins) and the far ear, darker
//   body    the axial body — head over the skull (muzzle, beak or snout by skull variant),
//           neck, trunk (back line over the spine, belly line below the ribs and pelvis),
//           tail tapering to its tip — and what sits on it (mane, frill, crest, horns,
//           antlers, trunk, sail, plates, shell, fins, the eye)
//   near    the near-side limbs and the near ear
// Each part's outline is stroked (a dark strip outside its fill, skinned with it); a limb's
// stroke fades out where the limb lies inside the trunk, so a leg grows out of the body.
// Tissue is thin over bony landmarks (skull, spine, joints, shins, hooves) and thick where
// muscle sits (thighs, shoulders, belly); the girths then scale so that the body's mass
// (body_mass.h) matches Creature::body_mass_kg, the genome's weight at the creature's size.
//
// The flesh rests on the floor (body_floor.h): a vertex that would lie below a box top under
// the creature is lifted onto it, in the shader and in floor_point() alike.
//
// Skinning: every vertex follows up to two palette entries — spine vertices blend the two
// vertebrae of the nearest joint, limb vertices blend through the limb joints' mid-joint
// frames (skeleton/mid_joint.h) as the bone sprites do, appendages follow their bone. The
// bind pose is the rest pose. A vertex's palette index is a bone (< bone_count) or a mid
// joint (bone_count + i).

#include <array>
#include <cstdint>
#include <span>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/body/body_floor.h"
#include "ossa/gen/creature.h"
#include "ossa/gen/look.h"
#include "ossa/io/result.h"
#include "ossa/level/box.h"
#include "ossa/skeleton/mid_joint.h"

namespace ossa {

// How a generated creature is shown (issue 30): its body (the default in the game and the
// demo), the body translucent over its bone sprites (x-ray), or the bone sprites alone.
enum class CreatureLook : uint8_t { kBody, kXray, kBones };
inline constexpr int kCreatureLookCount = 3;
const char* creature_look_name(CreatureLook look);  // "body", "xray", "bones"
std::optional<CreatureLook> creature_look_from_name(std::string_view name);
// The opacity of a body drawn over its bones in the x-ray look.
inline constexpr float kXrayBodyAlpha = 0.45f;

// One vertex as the body shader reads it (shaders/body.vert, body.frag).
struct BodyVertex {
  glm::vec2 position_ms{0.0f};         // bind (= rest) pose, model space, metres
  glm::vec2 coat_uv{0.0f};             // pattern space: rest position / pattern cell size,
                                       // plus a per-creature offset from the seed (coat.h)
  std::array<uint8_t, 4> bones{};      // palette indices within the creature
  std::array<float, 4> weights{};      // sum to 1, unused slots 0
  std::array<uint8_t, 4> colour{};     // sRGB + alpha: the coat at this point (countershaded,
                                       // far side darker), or the outline's colour
  std::array<uint8_t, 4> pattern{};    // sRGB of the pattern + its strength here (0 none)
  uint8_t pattern_kind = 0;            // CoatPattern
  // Metres past a box top's ends that the floor still holds this vertex up (body_floor.h):
  // its part's longest outline edge (with room to stretch), so that no straight edge between
  // two floored vertices cuts a top's corner. A leg's: its own outline edges' (stretched), and
  // only by the top its foot stands on (`foot`), whose hoof may stand beside a riser. 0 for
  // arms.
  float overhang = 0.0f;
  uint8_t foot = kNoFoot;              // a leg's vertex: its foot (BodyMesh::feet, BodyFloor::feet)
};

// What a part is; decides its shape, depth (body_mass.h) and layer.
enum class BodyPartKind : uint8_t {
  kAxial,      // head, neck, trunk and tail: one tube along the spine
  kLeg, kArm, kWing, kFin,
  kEar, kHorn, kAntler, kFrill, kCrest, kMane, kTrunk, kSail, kPlate, kShell, kDorsalFin, kTailFin,
  kEye,
};
inline constexpr int kBodyPartKindCount = static_cast<int>(BodyPartKind::kEye) + 1;
const char* body_part_name(BodyPartKind kind);

// A cross-section of a tube part in the rest pose: its top and bottom outline vertices (the
// vertical extent the part's volume is measured from, body_mass.h).
struct BodySection {
  uint32_t top = 0, bottom = 0;        // vertex indices
};

struct BodyPart {
  BodyPartKind kind = BodyPartKind::kAxial;
  Layer layer = Layer::kBody;
  int limb = -1;                       // index into Creature::limbs for limbs
  // Fill triangles: indices [first_index, first_index + index_count) of BodyMesh::indices.
  uint32_t first_index = 0, index_count = 0;
  // Outline stroke triangles, drawn before the fill.
  uint32_t stroke_first_index = 0, stroke_index_count = 0;
  // The closed outline, counter-clockwise in the rest pose: fill vertex indices.
  std::vector<uint32_t> outline;
  // Tube parts: their cross-sections in order along the tube (empty for flat parts).
  std::vector<BodySection> sections;
  // Lateral depth (across the side view) as a fraction of the local cross-section height:
  // an elliptic cross-section of height h and width depth·h (tubes), or a flat part's
  // thickness as a fraction of its longest extent (ears, fins, wings, plates…). body_mass.h.
  float depth = 0.8f;
  float mass_kg = 0.0f;                // this part's share, body_mass.h (overlap rules there)
};

struct BodyOptions {
  float far_shade = 0.62f;             // brightness of far-side limbs (as the bone sprites)
  float outline_width = 0.006f;        // stroke width as a fraction of the back length
  bool outline = true;                 // stroke each part's outline
  // The girth factor's range when matching the body's mass to Creature::body_mass_kg: 1 is
  // the default anatomy. A body still too heavy at min_girth is made narrower across instead
  // (every part's depth scaled, down to min_depth_scale), one too light at max_girth wider
  // (up to max_depth_scale); beyond these the mass is left unmatched (mass_matched false).
  float min_girth = 0.6f, max_girth = 2.0f;
  float min_depth_scale = 0.15f, max_depth_scale = 2.5f;
};

struct BodyMesh {
  std::vector<BodyVertex> vertices;
  std::vector<uint32_t> indices;
  std::array<uint32_t, 4> layer_begin{};  // indices [layer_begin[l], layer_begin[l+1]) per Layer
  std::vector<Mat2x3> inverse_bind;       // one per bone: model space → bone frame (rest pose)
  std::vector<MidJoint> mid_joints;       // palette entries after the bones
  std::vector<BodyPart> parts;            // in draw order
  float girth = 1.0f;                     // the factor the muscle and belly widths were scaled by
  float depth_scale = 1.0f;               // every part's depth scaled: < 1 slimmer across, > 1 wider
  float default_mass_kg = 0.0f;           // the body's mass at girth 1
  float mass_kg = 0.0f;                   // the built body's mass (body_mass.h)
  float area_m2 = 0.0f;                   // side-view area: every part's fill, overlaps counted
  bool mass_matched = true;               // false when the girth hit its range
  float reach = 0.0f;                     // metres the flesh reaches past the bones' box
                                          // (rest pose): body_floor()'s reach
  std::vector<BodyFoot> feet;             // the legs' feet, by BodyVertex::foot: body_floor()'s

  // Palette entries: the bones, the mid joints, then the floor (body_floor.h).
  int floor_entry() const { return static_cast<int>(inverse_bind.size() + mid_joints.size()); }
  int palette_size() const { return floor_entry() + kBodyFloorEntries; }
  int triangle_count() const { return static_cast<int>(indices.size() / 3); }
};

// Builds the body of `creature` (any creature build_creature makes; a skeleton without spine
// bones gives an empty mesh). Deterministic. Precondition: at most 255 palette entries
// (asserted; try_build_body returns an Error instead).
BodyMesh build_body(const Creature& creature, const BodyOptions& options = {});
Result<BodyMesh> try_build_body(const Creature& creature, const BodyOptions& options = {});

// The volume (m³) of `creature`'s body at girth 1 (BodyMesh::default_mass_kg / density,
// without building the mesh): what the size rule measures (gen/true_size.h). Hand it to the
// Generator: Generator::load(path, body_volume_m3). 0 for a body without spine bones.
double body_volume_m3(const Creature& creature);

// A vertex skinned by `palette` (one entry per bone, then per mid joint), as the shader does
// (without the floor: floor_point() after it, as the shader does).
glm::vec2 skin_body_vertex(const BodyVertex& v, std::span<const Mat2x3> palette);
// The vertex as drawn: skinned, then resting on `floor` (floor_point with its overhang), as
// the shader does.
glm::vec2 drawn_body_vertex(const BodyVertex& v, std::span<const Mat2x3> palette, const BodyFloor& floor);
// The palette of a pose: world · inverse_bind per bone, then the mid joints, then `floor`
// (none: flesh may go anywhere).
void body_palette(const BodyMesh& mesh, std::span<const Mat2x3> world, std::span<Mat2x3> palette,
                  const BodyFloor& floor = {});
// The model-space box around every vertex (rest pose). Empty mesh: a zero box at the origin.
Box body_bounds(const BodyMesh& mesh);

}  // namespace ossa
