#pragma once
// Character — a designer's own skinned character (made in Blender, Spine-like tools or
// tools/ossa-make-character) driven by the same animator as a generated creature (DESIGN.md
// §7 "Rigged characters", [T 4.2.4], [T 4.4]). Built from two descriptions:
//   ImportedSkeleton  the mesh's bones: names, parents, rest transforms (ossa::render's
//                     Assimp import fills it; an embedder may fill it from its own engine);
//   RigMapping        which bones are root, spine, neck, head, tail, legs and arms
//                     (rig_mapping.h, `*.rig.json`).
// build_character checks them against each other and gives an ossa Skeleton, its rest pose,
// the roles and the shared AnimRig, plus the constant binding the renderer needs to skin the
// mesh from the animator's matrices.
//
// Bones and frames
// ----------------
// An imported bone's frame may point anywhere (Blender's bones run along their local +y, other
// tools along +x) and says nothing of the bone's length. The animator needs ossa frames: +x
// along the bone, the child's joint at (length, 0). So every mesh bone gets an ossa bone with
// the same joint and
//   * for the parts the mapping names, the direction to the next joint of its chain: root →
//     spine[0] → … → neck → head, tail[i] → tail[i+1], upper → lower → foot (legs and arms);
//   * a foot's bone runs from the ankle to the foot's ground contact point, so the leg IK's
//     tip contact rolls the foot about it (the heel lifts as the leg trails);
//   * any other bone points at its first child's joint; a leaf at the middle of the vertices
//   it moves (ImportedBone::extent) with the length they reach, else along its parent with a
//   tenth of its length.
// to_mesh[b] = inverse(ossa rest frame) · S · mesh rest frame maps an ossa bone's frame to its
// mesh bone's frame; it is constant, so mesh bone world = ossa bone world · to_mesh[b], and the
// renderer's palette is ossa world · (to_mesh · mesh inverse bind). S maps the mesh's model
// space to ossa model space: × mapping.scale (metres per mesh unit), the root moved to x = 0 and
// the lowest foot contact to y = 0 (DESIGN.md §3). The ossa skeleton is re-rooted at the
// mapped root (bones above it or beside it hang from it rigidly), so bone indices differ from
// the mesh's: mesh_bone[b] says which mesh bone ossa bone b is.
//
// Errors (Error naming the rig file, the field and the bone): a bone the mesh lacks; a limb
// that is not a chain (lower not a child of upper, foot/hand not a child of lower); a leg or
// arm bone of no length (a leg of one bone); a spine, neck, head, tail or limb that does not
// hang from the root; a foot whose contact point is not below its hip in the rest pose; a
// contact point at the ankle; a non-finite or degenerate rest transform.

#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/anim/anim_rig.h"
#include "ossa/rig/rig_mapping.h"
#include "ossa/io/result.h"
#include "ossa/math/transform2d.h"
#include "ossa/skeleton/pose.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

struct ImportedBone {
  std::string name;                 // unique within the skeleton
  int parent = -1;                  // index of the parent (< own index), -1 for a root
  Mat2x3 rest_mesh;                 // bone frame → the mesh's model space, rest pose (mesh units)
  // The box around the vertices this bone moves most (their largest weight), rest pose, mesh
  // units; empty (min > max) when it moves none.
  glm::vec2 extent_min{1e30f}, extent_max{-1e30f};
  bool has_extent() const { return extent_min.x <= extent_max.x && extent_min.y <= extent_max.y; }
};

struct ImportedSkeleton {
  std::string source;               // the mesh file, for messages
  std::vector<ImportedBone> bones;  // parents first
  int find(const std::string& name) const;
};

struct Character {
  std::string name;                 // the rig file's name without ".rig.json" ("humanoid")
  std::string rig_path;             // the rig file it was built from
  RigMapping mapping;
  Skeleton skeleton;                // ossa bones (see above): root first, parents first
  // The standing pose the animator starts from (model space: y = 0 on the rest ground, the
  // root at x = 0): the skeleton's rest pose (the mesh's), with the body lowered and the knees
  // bent when the legs are straight there (a stance leg stops short of full reach).
  Pose rest_pose;
  RigRoles roles;
  std::shared_ptr<const AnimRig> rig;
  std::vector<int> mesh_bone;       // per ossa bone: its index in the ImportedSkeleton
  std::vector<Mat2x3> to_mesh;      // per ossa bone: ossa bone frame → mesh bone frame
  Mat2x3 mesh_to_model;             // S: the mesh's model space → ossa model space
  // Per leg (mapping order): its contact point in the rest pose, model space (metres).
  std::vector<glm::vec2> contacts_ms;
  // Things a designer may want to look at that do not stop it walking ("legs[1] stands
  // 4 cm above the ground in the rest pose").
  std::vector<std::string> warnings;
};

// Checks the mapping against the skeleton and builds the character. `rig_file` names the
// mapping in errors (and gives Character::name and rig_path).
Result<Character> build_character(const ImportedSkeleton& skeleton, const RigMapping& mapping, const std::string& rig_file);

// The character's name from its rig file: "assets/characters/dog.rig.json" → "dog".
std::string character_name(const std::string& rig_file);

}  // namespace ossa
