#pragma once
// build_character's phases (character.cpp), shared by its two files (not a public header):
// the Builder with what each phase found, in the order build_character runs them:
//   find_parts     (1) every mapped bone looked up, the limbs chains, everything hanging
//                      from the root (character_parts.cpp)
//   place_joints   (2) the joints in ossa model space: scaled, the root at x = 0, the lowest
//                      contact point at y = 0 (character_parts.cpp)
//   aim_bones      (3) each ossa bone's direction, length and width (character_parts.cpp)
//   check_legs     (4) the rest pose can walk: feet below hips, the knees' bend, sizes
//   build_skeleton (5) the ossa skeleton re-rooted at the mapped root, and the binding
//   stand          (5b) the standing pose
//   assign_roles   (6) the roles and the AnimRig

#include <array>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/rig/character.h"

namespace ossa::character_build {

inline std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// A limb's chain of mesh bones: upper, lower, foot or hand, and its field in the mapping.
struct Chain {
  std::array<int, 3> bones{};
  std::string path;
  const char* end_key;
};

struct Builder {
  Builder(const ImportedSkeleton& skeleton, const RigMapping& mapping, const std::string& rig_file)
      : in(skeleton), map(mapping), file(rig_file) {}
  const ImportedSkeleton& in;
  const RigMapping& map;
  const std::string& file;
  int n = 0;
  // (1) the mapped parts, as mesh bone indices
  int root = -1, head = -1;
  std::vector<int> spine, neck, tail;
  std::vector<Chain> legs, arms;
  // (2)
  std::vector<glm::vec2> joint;    // per mesh bone: its joint, ossa model space
  std::vector<glm::vec2> contacts; // per leg: its contact point, ossa model space
  Mat2x3 s;                        // mesh model → ossa model
  float size = 1.0f;               // metres: the skeleton's extent, for tolerances
  float min_len = 0.0f;            // a bone shorter than this has no length
  // (3)
  std::vector<glm::vec2> dir;      // per mesh bone: ossa direction (unit)
  std::vector<float> length;       // per mesh bone
  std::vector<int> next;           // per mesh bone: the joint it points at (-1: none)
  std::vector<float> width;
  // (4)
  std::vector<int> bend;           // per leg: the knee's bend sign
  // (5)
  std::vector<int> order;          // ossa bone k is mesh bone order[k]
  std::vector<int> ossa_of;        // per mesh bone: its ossa bone

  Error err(const std::string& field, const std::string& what) const { return Error::at(file, field, what); }
  bool descends(int bone, int ancestor) const {
    for (int b = bone; b >= 0; b = in.bones[static_cast<size_t>(b)].parent) {
      if (b == ancestor) return true;
    }
    return false;
  }
  int ossa(int mesh) const { return ossa_of[static_cast<size_t>(mesh)]; }
};

// The phases (above). Each returns the first problem as an Error naming the field and bone.
Status check_bones(const Builder& b);
Status find_parts(Builder& b);
Status place_joints(Builder& b);
Status aim_bones(Builder& b);

}  // namespace ossa::character_build
