#pragma once
// The body builder's parts, before they become a mesh (internal to src/ossa/body; see
// body_mesh.h for what a body is). A part is a tube — cross-sections along a centre line, each
// with a top and a bottom half-width — or a flat shape (a closed polygon). Half-widths come in
// two pieces: a fixed one (bone and the thin tissue over bony landmarks) and a soft one
// (muscle, fat), which the girth factor scales so the body's mass matches its weight.
//
// Files: body_rig.cpp (the chains and their skin weights), axial.cpp (head, neck, trunk,
// tail), limbs.cpp (legs, arms, wings, fins), appendages.cpp (ears … tail fins),
// tube.cpp (sections → vertices, triangles, outline), body_build.cpp (the order, the girth,
// strokes and layers).

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/creature.h"
#include "ossa/math/transform2d.h"

namespace ossa::body {

// Up to two palette entries and their weights (sum 1).
struct Skin {
  std::array<uint8_t, 2> index{};
  std::array<float, 2> weight{1.0f, 0.0f};
  static Skin rigid(int entry) {
    Skin s;
    s.index = {static_cast<uint8_t>(entry), static_cast<uint8_t>(entry)};
    return s;
  }
};

// A polyline through bone joints (rest pose, model space) with the bone of each segment.
struct Chain {
  std::vector<glm::vec2> points;  // n + 1
  std::vector<int> bones;         // n: the bone each segment lies on
  std::vector<float> start_s;     // n + 1: arc length at each point
  float length() const { return start_s.empty() ? 0.0f : start_s.back(); }
  // Segment and fraction at arc length s (clamped).
  int segment_at(float s) const;
  glm::vec2 point_at(float s) const;
  glm::vec2 tangent_at(float s) const;  // unit, the segment's direction
  float nearest_s(glm::vec2 p) const;   // arc length of the chain point nearest p
};

// Smoothstep of x from e0 (0) to e1 (1); a step at e0 when the edges meet (a trunk with no
// flank, a body with no tail: 0 / 0 gave NaN sections).
inline float smooth01(float e0, float e1, float x) {
  if (!(e1 > e0)) return x >= e0 ? 1.0f : 0.0f;
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// A joint where smooth skinning blends two palette sequences (parent … mid frames … child).
struct JointBlend {
  float s = 0.0f;            // arc length of the joint on its chain
  float half_width = 0.0f;   // metres either side
  std::vector<int> frames;   // palette entries in turn order: parent, mids…, child
};

// The skin of a point at arc length s of a chain whose joints blend as `joints` (sorted by s)
// and whose segments are skinned to `chain.bones` elsewhere.
Skin chain_skin(const Chain& chain, const std::vector<JointBlend>& joints, float s);

// A tube's cross-section (rest pose).
struct Section {
  glm::vec2 centre{0.0f};
  glm::vec2 dorsal{0.0f, 1.0f};  // unit: "top" side
  float top_fixed = 0.0f, top_soft = 0.0f;       // metres along +dorsal
  float bottom_fixed = 0.0f, bottom_soft = 0.0f; // metres along -dorsal
  float top_cap = 1e30f, bottom_cap = 1e30f;     // the most each side may reach (ground, folds)
  // The rest ground under a limb: outline points below it are lifted onto it (kept where they
  // are across the limb), so a heel spreads along the ground rather than shrink to its bone.
  float floor_y = -1e30f;
  Skin skin;
  float s = 0.0f;                                // arc length along its chain (limbs)
  glm::vec4 colour{-1.0f};                       // sRGBA of this section (negative: the part's)
  // What the ground's cap cuts off the bottom goes onto the top by this share: a low body
  // grows up rather than into the ground.
  float cut_to_top = 0.5f;
  float top(float girth) const {
    const float cut = std::max(bottom_fixed + girth * bottom_soft - bottom_cap, 0.0f);
    return std::min(top_fixed + girth * top_soft + cut_to_top * cut, top_cap);
  }
  float bottom(float girth) const { return std::min(bottom_fixed + girth * bottom_soft, bottom_cap); }
};

enum class Cap : uint8_t { kNone, kRound, kPoint };

struct TubePlan {
  BodyPartKind kind = BodyPartKind::kAxial;
  Layer layer = Layer::kBody;
  int order = 0;                       // within the layer: lower first (axial body 0)
  int limb = -1;
  float depth = 0.8f;                  // body_mass.h
  std::vector<Section> sections;       // at least 2, along the centre line
  Cap start_cap = Cap::kRound, end_cap = Cap::kRound;
  float end_cap_length = 1.0f;         // round end cap's reach / its radius (0.3: blunt)
  bool fade_start = false;             // the stroke fades in over the first sections (a limb
                                       // growing out of the trunk)
  // A part colour for every section (negative: the coat's, coat.h; a section's own colour,
  // Section::colour, wins).
  glm::vec4 colour{-1.0f};
  float pattern = 1.0f;                // pattern strength on this part
  // A leg's contact (the animator's: the foot's tip, or its heel for flat contact). Vertices
  // within contact_reach of it (rest pose) blend toward a level frame there (palette entry
  // contact_entry, skeleton/mid_joint.h), wholly within contact_inner: the flesh resting on
  // the ground around a planted contact keeps its rest shape above it however the foot and
  // shin turn over it. -1: none.
  int contact_entry = -1;
  glm::vec2 contact_point{0.0f};
  float contact_inner = 0.0f, contact_reach = 0.0f;
  float contact_height = 0.0f;         // > 0: only up to this height above the contact (a heel)
};

struct FlatPlan {
  BodyPartKind kind = BodyPartKind::kEar;
  Layer layer = Layer::kBody;
  int order = 1;                       // within the layer: lower first (axial body 0)
  float depth = 0.05f;                 // thickness / longest extent (body_mass.h)
  std::vector<glm::vec2> outline;      // closed polygon, rest pose, either orientation
  std::vector<Skin> skin;              // one per outline point
  glm::vec2 centre{0.0f};              // an interior point every outline point sees (star)
  Skin centre_skin;
  glm::vec4 colour{-1.0f};             // sRGBA; negative: the coat's
  float pattern = 0.0f;
};

// Everything a body is made of; body_build.cpp orders it by (layer, order).
struct BodyParts {
  std::vector<TubePlan> tubes;
  std::vector<FlatPlan> flats;
};

// Shared facts the part builders read.
struct BodyRig {
  const Creature* creature = nullptr;
  std::vector<Mat2x3> rest;            // model matrices of the rest pose
  Chain axial;                         // snout tip → tail tip over the skull and the spine
  int skull_segment = -1;              // the axial segment on the skull (0 when present)
  float snout_s = 0.0f;                // arc length where the skull begins (its back)
  float shoulder_s = 0.0f, hip_s = 0.0f, tail_s = 0.0f;  // arc lengths of the girdle joints
  float back_length = 1.0f;            // metres
  float skull_length = 0.0f, skull_height = 0.0f, snout = 0.5f;  // metres, metres, fraction
  int bone_count = 0;
  std::vector<MidJoint> mid_joints;    // filled by limbs.cpp (palette entries bone_count + i)
  std::vector<JointBlend> axial_joints;

  glm::vec2 bone_start(int b) const { return {rest[static_cast<size_t>(b)].m[4], rest[static_cast<size_t>(b)].m[5]}; }
  glm::vec2 bone_end(int b) const;
  glm::vec2 bone_dir(int b) const;
};

BodyRig make_rig(const Creature& creature);

// Part builders (append to plan).
void plan_axial(const BodyRig& rig, BodyParts& plan);
void plan_limbs(BodyRig& rig, BodyParts& plan);
// Appendages on the back (mane, sail, dorsal fin, plates, shell) sit on the axial body's back
// line at `girth` (build_body plans them again once the girth is known).
void plan_appendages(const BodyRig& rig, BodyParts& plan, float girth = 1.0f);

// The dorsal unit normal of a tangent: the tangent turned a quarter clockwise (a chain running
// tailward, -x, has +y dorsal).
inline glm::vec2 dorsal_of(glm::vec2 t) { return {t.y, -t.x}; }

// The outline of a tube at `girth` (rest pose): top row, end cap, bottom row, start cap —
// the points emit_tube() gives its outline, in the same order. `rows` the section count.
std::vector<glm::vec2> tube_outline(const TubePlan& tube, float girth);
// A round cap's points from the top to the bottom of an end section (no end points), in
// direction `out` (unit, away from the tube).
std::vector<glm::vec2> round_cap(glm::vec2 top, glm::vec2 bottom, glm::vec2 out, float reach, int segments);
// Section top and bottom points at `girth`.
inline glm::vec2 section_top(const Section& s, float girth) {
  const glm::vec2 p = s.centre + s.top(girth) * s.dorsal;
  return {p.x, std::max(p.y, std::min(s.floor_y, s.centre.y))};
}
inline glm::vec2 section_bottom(const Section& s, float girth) {
  const glm::vec2 p = s.centre - s.bottom(girth) * s.dorsal;
  return {p.x, std::max(p.y, std::min(s.floor_y, s.centre.y))};
}

// Paints a vertex whose position and skin are set: `v` is its fraction across a tube's
// section (0 top … 1 bottom; negative for flat parts), `override` a part colour (negative:
// the coat's), `pattern` the part's pattern strength.
using Painter = std::function<void(BodyVertex& vertex, float v, glm::vec4 override, float pattern)>;

// Appends a part's fill (vertices, triangles, outline, sections) to `mesh` and returns it
// (its stroke is added by add_stroke).
BodyPart emit_tube(const TubePlan& tube, float girth, BodyMesh& mesh, const Painter& paint);
BodyPart emit_flat(const FlatPlan& flat, BodyMesh& mesh, const Painter& paint);
// Appends `part`'s outline stroke: a strip `width` metres outside its outline, skinned with
// it, in `colour`; where `fade_inside` (a closed polygon, rest pose) contains a point of the
// outline, the stroke fades out there.
void add_stroke(BodyPart& part, BodyMesh& mesh, float width, glm::vec4 colour,
                std::span<const glm::vec2> fade_inside);

// Whether a closed loop crosses itself; the first crossing's edges (i, j) when it does.
bool first_crossing(std::span<const glm::vec2> loop, size_t& i, size_t& j);
// Shrinks the sections at each crossing of the tube's outline (at `girth`) until it crosses
// nowhere (at most 40 rounds): the inside of a bend too sharp for the flesh around it.
void untangle_tube(TubePlan& tube, float girth);

// Keeps each side of a tube from folding over itself: where the offset line of one side would
// run backwards between two sections (the inside of a bend sharper than its half-width), that
// side's caps shrink until it advances. Applies to the half-widths at `girth`.
void unfold_sections(std::vector<Section>& sections, float girth);

}  // namespace ossa::body
