#pragma once
// Rigged meshes made in other tools (rigged_mesh.h) in the same CreatureBatch as the bone
// sprites: the mesh becomes a one-layer SpriteMesh and its bones a Skeleton, so one skinned
// shader draws both.

#include "ossa/render/rigged_mesh.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

// The rig's bones as a Skeleton: parents first, rest locals from the bind pose, each bone's
// length reaching to its first child (a leaf gets a tenth of the mesh's height).
Skeleton rigged_skeleton(const RiggedMesh& mesh);

// The mesh as batch geometry: every triangle in the body layer (the importer already sorted
// them back to front), UVs flipped to GL's bottom-up convention, inverse binds from the rig.
SpriteMesh rigged_sprite_mesh(const RiggedMesh& mesh);

}  // namespace ossa
