#pragma once
// RigMapping — which bones of an imported, skinned character play which part for the animator
// (DESIGN.md §7 "Rigged characters"; [T 4.2.4]: [T]'s character was an imported FBX). The
// mapping names bones; character.h turns it and the mesh's skeleton into the same AnimRig a
// generated creature gets. No mesh is read here (Assimp import stays in ossa::render).
//
// File (`*.rig.json`, saved atomically; every field checked, errors name file and field):
//
//   { "format": "ossa.rig", "version": 1,
//     "mesh": "humanoid.gltf",          // the skinned mesh, relative to this file (glTF, FBX, DAE)
//     "scale": 1,                       // optional: metres per mesh unit (0.01 for centimetres)
//     "root": "pelvis",                 // the body's root: it carries every girdle
//     "spine": ["spine", "chest"],      // optional: root → head order
//     "neck": ["neck"],                 // optional: one name or a list, body → head
//     "head": "head",                   // optional (kept level while the body pitches)
//     "tail": ["tail_1", "tail_2"],     // optional: base → tip
//     "legs": [ { "side": "near",       // near: drawn in front of the body; far: behind
//                 "upper": "thigh_l", "lower": "shin_l", "foot": "foot_l",
//                 "contact": [0.19, 0.0],  // optional: where the foot meets the ground in the
//                                          // mesh's rest pose (mesh units); default: the
//                                          // foot's lowest front point (see character.h)
//                 "pair": 0,            // optional: legs with one pair share a girdle
//                                       // (default: legs[0], legs[1] are pair 0; 2, 3 pair 1 ...)
//                 "knee": "forward" },  // optional: which way the middle joint bends when
//                                       // the rest pose is straight (default forward)
//               ... ],                  // at least one leg
//     "arms": [ { "side": "near", "upper": "upper_arm_l", "lower": "lower_arm_l",
//                 "hand": "hand_l" }, ... ] }   // optional
//
// A bone plays at most one part (a bone named twice is an error naming both fields). Whether
// the bones exist and form chains, and whether the rest pose can walk (a foot above its hip),
// is checked against the mesh's skeleton by build_character (character.h).

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/gen/creature.h"
#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"

namespace ossa {

inline constexpr const char* kRigFormat = "ossa.rig";
inline constexpr int kRigVersion = 1;

// A leg (upper, lower, foot) or an arm (upper, lower, hand).
struct RigChain {
  Side side = Side::kNear;
  std::string upper;                 // thigh / upper arm
  std::string lower;                 // shin / forearm
  std::string end;                   // foot / hand ("foot" or "hand" in the file)
  // Legs only:
  std::optional<glm::vec2> contact;  // mesh units, the mesh's rest model space
  int pair = -1;                     // -1: index / 2
  int knee = 1;                      // +1 forward, -1 back (only for a straight rest pose)
};

struct RigMapping {
  std::string mesh;                  // as written, relative to the rig file
  std::string mesh_path;             // `mesh` resolved against the rig file's folder
  float scale = 1.0f;                // metres per mesh unit, (0, 1000]
  std::string root;
  std::vector<std::string> spine;    // root → head
  std::vector<std::string> neck;     // body → head
  std::string head;                  // empty: none
  std::vector<std::string> tail;     // base → tip
  std::vector<RigChain> legs;
  std::vector<RigChain> arms;

  // The pair leg i belongs to.
  int leg_pair(size_t i) const { return legs[i].pair >= 0 ? legs[i].pair : static_cast<int>(i / 2); }
};

// Reads and checks the JSON: format, version, types, non-empty bone names, sides, one part per
// bone. `file` names the file in errors and resolves `mesh`.
Result<RigMapping> parse_rig_mapping(std::string_view text, const std::string& file);
Result<RigMapping> rig_mapping_from_json(const Json& doc, const std::string& file);
Result<RigMapping> load_rig_mapping(const std::string& path);

// The file's JSON (format and version first); what it writes, the loader reads.
Json rig_mapping_to_json(const RigMapping& mapping);
// Writes atomically (temporary file, fsync, rename).
Status save_rig_mapping(const std::string& path, const RigMapping& mapping);

// Every (field, bone) the mapping names, in file order: "root", "spine[1]", "legs[0].foot" ...
std::vector<std::pair<std::string, std::string>> rig_mapping_bones(const RigMapping& mapping);

}  // namespace ossa
