#pragma once
// A biped's imported skeleton and rig mapping built by hand the way Blender exports one
// (bones along their local +y, centimetres, a ground-level "root" above the hips, a bone
// beside the body), so tests of characters need no Assimp: tests/rig/character_test.cpp
// builds it, tests/game/character_walk_test.cpp walks it.

#include "ossa/rig/character.h"

namespace ossa::scenes {

struct ImportedBiped {
  ImportedSkeleton skeleton;
  RigMapping mapping;
};

// A 1.6 m biped in centimetres, standing straight, facing +x (mapping scale 0.01).
ImportedBiped imported_biped();

// A bone frame whose local +y runs from `head` towards `tail` (Blender's convention).
Mat2x3 blender_frame(glm::vec2 head, glm::vec2 tail);

}  // namespace ossa::scenes
