#pragma once
// AnimRig — the immutable description of what the animator drives (DESIGN.md §7), built once
// per creature and shared by every animator of it: the legs (bone chains, lengths, bend sign,
// contact shape, reach), the girdles carrying them in front-to-back order, the arms, fins,
// wings and tail, the body's outline for the wall sweep, and which bones each stage writes.
//
// Nothing here assumes a generated skeleton: a rig is bones, their rest pose and the roles
// assigned to them (RigRoles). build_anim_rig(skeleton, rest, roles) is the one builder;
// build_anim_rig(creature) reads the roles from a Creature's LimbLayout, and a rig mapping of
// an imported mesh gives the same roles (character.h).
//
// Spaces: _ms is model space (DESIGN.md §3): the rest frame, metres, +x forward, y = 0 on the
// rest ground. Lengths are metres; angles radians.

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/anim/gait_family.h"
#include "ossa/anim/rig_scale.h"
#include "ossa/gen/creature.h"
#include "ossa/level/box.h"
#include "ossa/skeleton/mid_joint.h"
#include "ossa/skeleton/pose.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

// Stance legs never extend beyond this fraction of their reach (upper + lower).
inline constexpr float kReachLimit = 0.985f;

struct LimbFleshPoint {             // a point of a leg's or an arm's drawn outline
  // Skinned as the drawn body skins it (body_mesh.h): a blend of up to four of the limb's skin
  // frames (limb_skin_frames: 0 upper, 1 lower, 2 foot or hand, 3 on its mid joints), each
  // weight with the point in that frame at rest. Weights sum to 1.
  int count = 0;
  std::array<uint8_t, 4> frame{};
  std::array<float, 4> weight{};
  std::array<glm::vec2, 4> local{};
};
// A limb's skin frames: its three bones' and at most this many mid joints' (knee, ankle, the
// foot's level frame: skeleton/mid_joint.h).
inline constexpr size_t kLimbMidFrames = 9;
inline constexpr size_t kLimbSkinFrames = 3 + kLimbMidFrames;
// A limb's outline keeps at most this many points (the examples' legs have up to 75; thinned
// to 64, the triceratops's shoulder lost the points about its corner, 2 cm of flesh).
inline constexpr size_t kLimbFleshPoints = 96;

struct RigLeg {
  std::array<int, 3> bones{};       // upper, lower, foot
  int girdle_bone = -1;             // the bone the chain hangs from
  int girdle = 0;                   // index into AnimRig::girdles (front first)
  Side side = Side::kNear;
  float upper = 0.0f, lower = 0.0f; // thigh and shin lengths, metres
  float reach = 0.0f;               // upper + lower, metres
  // The least the chain reaches, |upper - lower|: the ankle comes no closer to the joint (a
  // random leg may have a bone of length 0: it reaches its other bone's length only).
  float least_reach = 0.0f;
  float fold = 0.0f;                // 1.02 least_reach (at most leg_reach): the ankle stays this far from the joint
  float bend = 1.0f;                // the chain's bend sign
  float foot_length = 0.0f;         // foot bone, metres
  glm::vec2 foot_offset_ms{0.0f};   // ankle → contact point in the rest pose
  float foot_angle_ms = 0.0f;       // rest absolute angle of the foot bone
  glm::vec2 foot_dir_ms{1.0f, 0.0f};// (cos, sin) of foot_angle_ms
  float girdle_rel_angle = NAN;     // girdle angle relative to the root (NaN: the spine bends)
  float foot_span = 0.0f;           // |foot_offset_ms|: ankle to contact point
  float leg_reach = 0.0f;           // kReachLimit * reach, at least least_reach
  // Farthest the contact point gets from the girdle joint: the leg at kReachLimit and, for
  // tip contact, the foot pivoted into line with it.
  float contact_reach = 0.0f;
  int contact_bone = -1;            // the bone whose end is the contact point
  // The foot's extent relative to its contact point, facing +x: back to the ankle, forward to
  // the toe (a flat foot's whole sole).
  glm::vec2 ankle_rel_ms{0.0f}, tip_rel_ms{0.0f};
  // The drawn leg's flesh about the foot (RigRoles::flesh at rest, the outline within the
  // foot's box height above the contact point, foothold.h foot_height): how far it reaches
  // behind the bones' span above and ahead of it, facing +x, metres (0: no drawn body). A
  // foothold keeps it off the level, not only the bones (foothold.h flesh_span_ws).
  float flesh_back = 0.0f, flesh_front = 0.0f;
  // The drawn leg's outline, its sole too (RigRoles::flesh, in order round the leg's own
  // part), each point skinned as the body skins it (LimbFleshPoint: the leg's bones, the
  // knee's and ankle's mid joints, a hoof's or toes' level frame). Posed with the leg's bones,
  // it is the outline the swing and the stance keep off the level, not only the bones
  // (leg_geometry.h leg_flesh_hits; a standing leg's against boxes rising above its foot). Empty: no
  // drawn body. At most kLimbFleshPoints.
  std::vector<LimbFleshPoint> flesh_outline;
  // Per bone (upper, lower, foot): the farthest a point of flesh_outline lies from it in a
  // frame on it, metres (a bound below the posed bones: leg_ik.cpp's quick test).
  std::array<float, 3> flesh_margin{};
  // The mid joints flesh_outline follows (skin frames 3, 4, …), their parent and child the
  // limb's bone slots (0 upper, 1 lower, 2 foot), not bones.
  std::vector<MidJoint> flesh_mids;
  // Three-segment legs (a long foot standing on its tip: hooves, paws, bird feet; issue 29):
  // the foot bone is coupled to the leg instead of keeping its rest angle. A fore foot lies in
  // line with the forearm (the carpus straight under load); a hind foot keeps its rest angle to
  // the thigh (the hock bends and straightens with the knee, as the ungulate's reciprocal
  // apparatus makes it), and where that would bend the hock past straight, the hock stays
  // straight. In swing the lower joint folds further, up to swing_fold at mid-swing (the carpus
  // flexes, the hoof tucks). leg_ik.h solve_coupled_leg.
  bool coupled = false;
  bool hind = false;                // on the rearmost girdle (or the only one)
  float couple_angle = 0.0f;        // hind: the foot's rest turn from the thigh, radians
  glm::vec2 couple_turn{1.0f, 0.0f};// (cos, sin) of couple_angle
  // Hind: the thigh and the foot at that turn as one bone, its length and direction with the
  // thigh along +x (leg_ik.cpp; constant while the foot stands).
  float couple_length = 0.0f;
  glm::vec2 couple_dir{1.0f, 0.0f};
  float fold_sign = 1.0f;           // the turn that flexes the lower joint (carpus, hock), as at rest
  float rest_fold = 0.0f;           // radians that joint turns at rest, shin to foot (0: in line)
  float swing_fold = 0.0f;          // radians, at mid-swing
};

struct RigGirdle {                  // a girdle slot carrying a leg pair
  glm::vec2 joint_ms{0.0f};         // rest girdle joint
  float rest_height = 0.0f;         // joint height above the rest ground, metres
  // What max_step_up is a fraction of: the rest height, or more for crouching legs that
  // reach further than they stand tall.
  float step_height = 0.0f;
  std::vector<int> legs;            // leg indices (near first)
  // The farthest a knee of its legs reaches ahead of the joint, metres: the thigh's length for
  // a knee that bends forward, 0 for knees that bend back.
  float knee_reach = 0.0f;
  // How the joint moves with the spine's flexion f (radians, AnimRig::flex_count):
  // joint_ms + f·flex_d1 + f²·flex_d2 (zero when the spine never flexes).
  glm::vec2 flex_d1{0.0f}, flex_d2{0.0f};
};

struct RigLimb {                    // an arm, fin or wing: a chain hanging from a girdle bone
  int girdle_bone = -1;
  std::array<int, 3> bones{};
  Side side = Side::kNear;
  // An arm's drawn outline on its bones, and each bone's margin (as RigLeg's, the whole arm):
  // its clearance keeps it off the level, not only the bones (limb_clearance.h). Empty: none.
  std::vector<LimbFleshPoint> flesh_outline;
  std::array<float, 3> flesh_margin{};
  std::vector<MidJoint> flesh_mids;
};

struct AnimRig {
  Skeleton skeleton;
  Pose rest_pose;
  int root = 0;
  int skull = -1;                   // -1: none
  std::vector<int> back, neck, tail;// spine chains (head end first), as in Creature
  bool flat_contact = false;        // feet touch with the whole sole (else with the tip)
  // The roles' legs cannot hold the back off the ground (the back reaches below their feet
  // in the rest pose): the rig has no legs, it crawls on its belly (kLegless) and holds them
  // as fins, turned out of the ground as they need.
  bool legs_as_fins = false;

  std::vector<RigLeg> legs;
  std::vector<RigGirdle> girdles;   // front (largest x) to back
  std::vector<RigLimb> arms, fins, wings;
  // The same, one of each left/right pair whose rest poses coincide in the side view: the
  // body's keep-outs test each outline once.
  std::vector<RigLimb> outline_arms, outline_fins, outline_wings;

  float hip_height = 1.0f;          // h of the Froude number: mean girdle rest height, metres
  RigScale scale;                   // the stages' lengths in this creature's size (rig_scale.h)
  // The least step_height of any girdle: a step up more than max_step_up of it is a wall (the
  // other girdles could not follow).
  float climb_height = 0.0f;
  float root_rest_y = 0.0f;         // model-space y of the root in the rest pose
  float body_half_length = 0.5f;    // half the rest pose's extent along x, metres
  // The rest pose's extent along x from the root (_fs: + ahead), metres; a long tail makes it
  // lopsided (a snake's root is near its head).
  float body_back = -0.5f, body_front = 0.5f;
  // The rest pose's highest point above the ground it stands on, metres.
  float body_top = 1.0f;
  // A legless body crawls onto a riser no higher than this (metres); a higher one is a wall:
  // twice the height its root rests at (it lifts its front end onto the step), and no more
  // than a quarter of its length (it falls off a drop that deep, locomotion.cpp). A snake climbs
  // stairs; a whale stops at a level's end wall. 0 for a rig with legs.
  float crawl_climb = 0.0f;
  // World x range the rest pose covers with the root at x_ws, facing `facing`.
  float body_lo_ws(float x_ws, int facing) const { return x_ws + (facing > 0 ? body_back : -body_front); }
  float body_hi_ws(float x_ws, int facing) const { return x_ws + (facing > 0 ? body_front : -body_back); }
  // One girdle only: the foremost arm or wing shoulder ahead of it (rest, relative to the
  // girdle joint), and how much higher the ground under it may be than under the girdle
  // before the body pitches up.
  glm::vec2 front_shoulder{0.0f};
  float front_slack = 0.0f;
  float longest_foot_reach = 0.05f; // the largest foot circle (foot_span + 5 cm)
  float longest_contact_reach = 0.05f;

  // Rest matrices and which bones each stage writes.
  std::vector<Mat2x3> model_rest;   // model-space rest matrices
  std::vector<Mat2x3> rest_local_m; // rest local matrix per bone
  std::vector<uint8_t> dynamic_bone;// joint values the animator changes (spine, skull, tail)
  std::vector<uint8_t> tick_bone;   // bones kept current every tick
  std::vector<int> needed_bones;    // chain-computed each tick, parents first
  std::vector<int> girdle_bones;    // computed directly from the root each tick (rigid body)
  std::vector<Mat2x3> girdle_rel;   // their rest matrices relative to the root bone
  // Spine flexion (the gallop's and the bound's, GaitState::spine_flex): between two leg
  // girdles rigid to the root, the spine bends as one arc. Each bone of the chains from the
  // root to the girdles turns by flex_sign[b]·f/flex_count for a flexion f (radians, the whole
  // arc): −1 on the way to the front girdle, +1 to the back one, so f > 0 arches the back
  // (flexion) and f < 0 hollows it (extension). flex_chains[i]: girdle_bones[i]'s chain below
  // the root, root side first. flex_count 0: the spine never flexes (one girdle, three or
  // more, legless bodies, a spine that bends already).
  std::vector<int8_t> flex_sign;
  std::vector<std::vector<int>> flex_chains;
  int flex_count = 0;
  // The neck's base (-1: none that the pose turns) turns back by flex_neck_turn·f/flex_count,
  // what the chain it hangs from turned: the head keeps its place as the back flexes.
  int flex_neck = -1;
  float flex_neck_turn = 0.0f;
  // The pentapedal walk's posture (pentapedal.h; one leg girdle with arms): the body pitched
  // nose down by pentapedal_pitch (radians) about its girdle, the girdle pentapedal_crouch
  // (metres) lower, so the shoulders come within most of the arms' reach of the ground
  // (build_pentapedal). 0: no arms.
  float pentapedal_pitch = 0.0f, pentapedal_crouch = 0.0f;
  // Girdle bone i's matrix relative to the root's with each flexing bone turned by
  // flex_sign·step.
  Mat2x3 flexed_girdle_rel(size_t i, float step) const;
  // Girdle g's joint with the spine flexed by `flex` (model space, rest otherwise).
  glm::vec2 girdle_joint(int g, float flex) const {
    const RigGirdle& girdle = girdles[static_cast<size_t>(g)];
    if (flex == 0.0f) return girdle.joint_ms;
    return girdle.joint_ms + flex * (girdle.flex_d1 + flex * girdle.flex_d2);
  }
  std::vector<int> touched_bones;   // bones whose joint values the pose rewrites each tick
  std::vector<int> other_limb_bones;// limb bones not placed by the leg IK, parents first
  std::vector<uint8_t> limb_bone;   // per bone: a limb's (legs, arms, fins, wings and what hangs from them)
  // A legless body lies along the ground (drape_legless, secondary_motion.h): its spine bones
  // other than the root and the skull, parents first (drape_bones), each laid so that the point it ends at — its
  // spine child's joint, or its own far end at a tip (drape_next −1) — stands its belly's depth
  // over the ground: belly[b], the depth below bone b's joint of the bones hanging from it (ribs,
  // the skull; not the next spine bone or a limb, but a limb's root) or half its own width, at rest; tip_belly[i] the
  // same below the far end of a tip. A legless rig's root_rest_y is the height its root rests at.
  std::vector<int> drape_bones, drape_next;
  std::vector<float> belly, tip_belly;
  // Per drape bone i: the roots of the limbs hanging from it, then the two ends of each bone
  // hanging from it (from hang_pairs[i]), in its own frame at rest
  // (hang_points[hang_begin[i] .. hang_begin[i + 1]]).
  std::vector<glm::vec2> hang_points;
  std::vector<int> hang_begin, hang_pairs;
  std::vector<glm::vec2> root_hang_points;   // the same for the root, in its frame
  int root_hang_pairs = 0;
  std::vector<glm::vec2> skull_hang_points;  // and for the skull (a jaw), in its frame: pairs
  // The bones the drape places each tick, parents first: the spine, the skull and the chains to
  // the limbs' girdles (what hangs from them follows on demand, as their rest shape).
  std::vector<int> drape_fk;
  int head_owner = -1;              // the spine bone the skull hangs from (kept level)
  float skull_rest_angle = 0.0f;    // the skull's rest angle (model space)
  // Per drape bone: from its joint to the point it ends at, the length and direction in its
  // own frame.
  std::vector<float> drape_length, drape_along;
  // The head's nod and a small bird's head-bob bend the neck at its base (nod_bones[0], -1:
  // none; a legged body's first neck bone, off the girdles' chains) and halfway up
  // (nod_bones[1], -1 for a one-bone neck), so moving the skull (kept level), nod_reach[i]
  // from those joints at rest (model space).
  std::array<int, 2> nod_bones{-1, -1};
  std::array<glm::vec2, 2> nod_reach{};
  // nod_bones[0] and every bone hanging from it (the neck, its ribs, the skull, the jaw),
  // parents first: the head lifts out of the ground about the neck's base (keep_head_clear).
  // None is kept every tick (the nod needs a rigid body); the matrices start from
  // head_kept_bone, the nearest bone above them that is, through head_between (parents first).
  std::vector<int> head_bones;
  int head_kept_bone = -1;
  std::vector<int> head_between;

  // Wall sweep: hulls of the root, back and neck in slabs along the body, relative to the root
  // bone's frame, and the skull (kept level) as its joint in that frame plus its rest span.
  // Empty when the spine bends.
  std::vector<std::vector<glm::vec2>> body_slabs;
  std::vector<glm::vec2> body_hull;
  glm::vec2 skull_rel{0.0f}, skull_span{0.0f};
  glm::vec2 body_lo{0.0f}, body_hi{0.0f};  // extent of the hull and the skull joint

  // The trunk's own bones — the root, back, neck and what hangs from them (ribs), the skull
  // and its jaw; no limb, no tail — as segments at rest (model space), one of each pair that
  // coincides in the side view, zero-length bones left out: body placement keeps them out of
  // the ground (clamp 5). The skull's (from trunk_level_from on) stay level with the head:
  // they turn with the skull, not with the body. trunk_lo/trunk_hi bound them relative to the
  // root's rest joint. Legged rigs only.
  struct TrunkSegment {
    glm::vec2 a{0.0f}, b{0.0f};
  };
  std::vector<TrunkSegment> trunk;
  size_t trunk_level_from = 0;
  glm::vec2 trunk_lo{0.0f}, trunk_hi{0.0f};
  // The drawn body's outline where it follows the trunk's bones (RigRoles::flesh: the chest,
  // the neck, the hump), then from flesh_level_from on where it follows the skull's (the
  // muzzle, horns, an elephant's trunk; level with the head), thinned to segments at rest
  // (model space): the wall sweep stops the body before them meet a wall. flesh_lo/flesh_hi
  // bound the first relative to the root's rest joint, head_flesh_lo/head_flesh_hi the others
  // relative to the skull's. Legged rigs with a generated body only.
  std::vector<TrunkSegment> flesh;
  size_t flesh_level_from = 0;
  glm::vec2 flesh_lo{0.0f}, flesh_hi{0.0f}, head_flesh_lo{0.0f}, head_flesh_hi{0.0f};

  // Tail: it hangs from the nearest ancestor kept current each tick through the bones between
  // (or their rest product when none bends).
  int tail_base_bone = -1;
  std::vector<int> tail_between;
  Mat2x3 tail_between_rest;
  // The bones between when tail_between was folded into its rest product but the spine's
  // flexion bends one of them (empty otherwise).
  std::vector<int> tail_flex_between;
  float tail_length = 0.0f;         // > 0: the tail is kept out of the level
  // Per tail bone, the box its flesh fills (RigRoles::flesh; fins and flukes too) in its frame
  // at rest: x along the bone, y across. Empty: the tail's bones alone are kept out.
  std::vector<Box> tail_flesh;
  // A legless body's flesh about each bone its wall sweep takes (crawl_bones: the root, the
  // back, the neck and the skull, as body_boxes), in the bone's frame at rest as tail_flesh:
  // it meets walls with them (a sperm whale's head reaches 1.5 m past its skull). Empty for a
  // body with legs.
  std::vector<int> crawl_bones;
  std::vector<Box> crawl_flesh;
  float tail_reach = 0.0f;          // tail_length and as far as its flesh reaches past a bone
  // The body plan's gait (anim/gait_family.h): never kAuto here (the builder resolves it with
  // choose_gait_family), and what the choice reads besides the bones.
  GaitFamily gait_family = GaitFamily::kCursorial;
  float weight_kg = 0.0f;           // 0: unknown
  int skull_variant = 0;            // 0 mammal, 1 bird, 2 reptile, 3 fish (genome.h)
  // gait_family's traits, kept by the builder (gait_family_traits answers from them: the
  // walk and run speeds are asked several times a tick).
  anim::GaitFamilyTraits traits;
  bool traits_kept = false;
};

// Which bones play which part, for build_anim_rig: a generated creature's LimbLayout
// (rig_roles(creature)) or a rig mapping of an imported mesh (character.h).
struct RigLimbRole {
  LimbKind kind = LimbKind::kLeg;
  int girdle_bone = -1;             // the bone the chain hangs from: the parent of bones[0]
  std::array<int, 3> bones{};       // upper, lower, hand/foot; each the parent of the next
  Side side = Side::kNear;
  int bend_sign = 1;                // legs: +1 the knee bends counter-clockwise of hip→ankle
  int girdle_group = 0;             // legs: legs with the same group share one girdle slot
};

struct RigRoles {
  int root = 0;                     // a bone without a parent, at x = 0 in the rest pose
  int skull = -1;                   // -1: none
  std::vector<int> back, neck, tail;// spine chains, head end first (tail: base first)
  bool flat_contact = false;        // feet touch with the whole sole (else with the foot's tip)
  std::vector<RigLimbRole> limbs;   // legs, arms, fins and wings in any order
  // How it moves: a gait family, or kAuto to choose from the body plan (the bones, the weight
  // and the skull's class; weight 0: unknown).
  GaitFamily gait_family = GaitFamily::kAuto;
  float weight_kg = 0.0f;
  int skull_variant = 0;
  // The drawn body's outline at rest (model space), each point with the bone it follows most
  // (-1: a limb's mid joint) and the body part whose closed outline it lies on, in order
  // along it: the tail's is kept out of the level with its bones (AnimRig::tail_flesh), the
  // trunk's and the head's meet walls (AnimRig::flesh). rig_roles reads it from a generated
  // creature's body (body_mesh.h); empty: the bones alone (a rigged character's sprites).
  // With each point its skinning (palette entries: the bones, then mid_joints; weights), from
  // which the limbs' outlines are posed as the body draws them (RigLeg::flesh_outline).
  struct FleshPoint {
    int bone = -1;
    glm::vec2 position_ms{0.0f};
    int part = 0;
    std::array<uint8_t, 4> entries{};
    std::array<float, 4> weights{};
  };
  std::vector<FleshPoint> flesh;
  std::vector<MidJoint> mid_joints;
};

// The roles of a generated creature: its spine chains, skull and LimbLayout (legs grouped by
// girdle and slot), and its body's outline (build_body).
RigRoles rig_roles(const Creature& creature);

// Builds a rig from bones, their rest pose (model space: y = 0 on the rest ground, the root at
// x = 0, facing +x) and their roles. The roles must be consistent with the skeleton (indices in
// range, chains parent to child); character.h checks a mapping before it gets here.
std::shared_ptr<const AnimRig> build_anim_rig(const Skeleton& skeleton, const Pose& rest_pose, const RigRoles& roles);

// Builds the rig of a generated creature: build_anim_rig(skeleton, rest pose, rig_roles).
std::shared_ptr<const AnimRig> build_anim_rig(const Creature& creature);

// How far ahead of its girdle joint (facing +x) leg's knee lies with the contact point
// `height` metres straight below the joint (the ankle clamped to what the leg reaches): < 0
// for a knee that bends back.
float knee_ahead(const RigLeg& leg, float height);

}  // namespace ossa
