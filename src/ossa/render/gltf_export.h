#pragma once
// glTF 2.0 export of a Creature through Assimp (DESIGN.md §5.10). Lives in ossa::render, not
// in ossa::core, because Assimp is not a core dependency; ossa-gen and the creature panel use it.
//
// The file holds:
//   - a node hierarchy equal to the skeleton: one node per bone, named like the bone, with its
//     rest-pose local transform (2D → 3D: z = 0, rotation about +z), under a root node named
//     after the creature;
//   - one skinned sprite mesh ("<name>_sprites") in the rest pose, which is its bind pose: for
//     a creature with smooth skinning (Creature::smooth_skinning) its sprite mesh
//     (sprite_mesh.h, `GltfOptions::sprites`, UVs as the sprite set gives them) as drawn at
//     rest, each vertex with the sprite mesh's weights — up to two bones near a limb or spine
//     joint (glTF's JOINTS_0/WEIGHTS_0 hold four), summing to 1, a mid-joint frame folded into
//     its two bones by its turn (glTF skins have no computed joints; at rest the pose is exact
//     either way); else a quad per bone spanning the bone's length × width in its own frame
//     (zero-length bones get a small square), UVs (0,0)–(1,1) per quad, each of its four
//     vertices weighted 1.0 to its bone. Depth z = -1 mm (far layer), 0 (body), +1 mm (near)
//     plus 1 µm × bone index (a draw order, and it keeps near/far vertices distinct for
//     Assimp's enforced vertex joining). One mesh bone per skeleton bone with the inverse bind
//     matrix as Assimp's offset matrix;
//   - one material, referencing the bone sprite atlas as its diffuse/base-colour texture when
//     `atlas_path` names an existing file (written relative to the output file's folder when
//     possible), else a plain bone-coloured material.
// Assimp's "gltf2" exporter writes F.gltf plus F.bin next to it. Both are encoded in memory
// first and then saved atomically (F.bin, then F.gltf), like every file ossa writes: a failed
// export leaves any previous files untouched.

#include <string>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/creature.h"
#include "ossa/io/result.h"

namespace ossa {

struct SpriteSet;

struct GltfOptions {
  // Which meshes: the bone sprites (kBones, the default: "<name>_sprites" as above), the
  // body (kBody: "<name>_body", body/body_mesh.h in its rest pose, each part's outline stroke
  // just behind its fill, far limbs behind and near limbs in front by 1 mm, vertex colours
  // (COLOR_0, linear) the coat with its pattern sampled at the vertices, a white "coat"
  // material; weights as for the sprites, a foot's level frame folded into the foot), or
  // both (kXray).
  CreatureLook look = CreatureLook::kBones;
  std::string atlas_path;             // PNG atlas; empty or missing file: plain material
  const SpriteSet* sprites = nullptr;  // a smooth creature's sprite anchors, sizes and UVs
                                       // (an Atlas's set: its rectangles); null: the
                                       // built-in set, each sprite UVs (0,0)–(1,1)
};

// Writes `path` (".gltf") and its ".bin". Errors name the file and the reason (Assimp's, or
// why the file could not be written).
Status export_gltf(const Creature& creature, const std::string& path,
                   const GltfOptions& options = {});

}  // namespace ossa
