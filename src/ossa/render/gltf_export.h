#pragma once
// glTF 2.0 export of a Creature through Assimp (DESIGN.md §5.10). Lives in ossa::render, not
// in ossa::core, because Assimp is not a core dependency; ossa-gen and the creature panel use it.
//
// The file holds:
//   - a node hierarchy equal to the skeleton: one node per bone, named like the bone, with its
//     rest-pose local transform (2D → 3D: z = 0, rotation about +z), under a root node named
//     after the creature;
//   - one skinned sprite mesh ("<name>_sprites"): a quad per bone in the bind (rest) pose,
//     spanning the bone's length × width in its own frame (zero-length bones get a small square),
//     at z = -1 mm (far layer), 0 (body), +1 mm (near) plus 1 µm × bone index (a draw order,
//     and it keeps near/far vertices distinct for Assimp's enforced vertex joining),
//     UVs (0,0)–(1,1) per quad, each of its four vertices weighted 1.0 to its bone; one mesh
//     bone per skeleton bone with the inverse bind matrix as Assimp's offset matrix;
//   - one material, referencing the bone sprite atlas as its diffuse/base-colour texture when
//     `atlas_path` names an existing file (written relative to the output file's folder when
//     possible), else a plain bone-coloured material.
// Assimp's "gltf2" exporter writes F.gltf plus F.bin next to it. Both are encoded in memory
// first and then saved atomically (F.bin, then F.gltf), like every file ossa writes: a failed
// export leaves any previous files untouched.

#include <string>

#include "ossa/gen/creature.h"
#include "ossa/io/result.h"

namespace ossa {

struct GltfOptions {
  std::string atlas_path;  // PNG atlas; empty or missing file: plain material
};

// Writes `path` (".gltf") and its ".bin". Errors name the file and the reason (Assimp's, or
// why the file could not be written).
Status export_gltf(const Creature& creature, const std::string& path,
                   const GltfOptions& options = {});

}  // namespace ossa
