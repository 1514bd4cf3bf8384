#pragma once
// Rigged characters as the game, the tools and the editors load and draw them: a rig mapping
// (`*.rig.json`, anim/rig_mapping.h), the skinned mesh it names (glTF, FBX or DAE through
// Assimp, rigged_mesh.h) and the core Character built from both (anim/character.h), plus the
// batch geometry that skins the mesh from the animator's matrices.
//
//   Result<LoadedCharacter> c = load_character("assets/characters/humanoid.rig.json");
//   Player player(c->character, prototypes);                  // walks like any creature
//   int id = batch.add(c->sprite_mesh, c->character->skeleton, texture_slot);
//   batch.set_world(id, player.animator().world_matrices());  // palette = world · inverse_bind
//
// The sprite mesh's bone indices are the character's (ossa) bones, and its inverse binds fold
// the constant ossa → mesh bone binding in: inverse_bind[b] = to_mesh[b] · mesh inverse bind.

#include <memory>
#include <string>
#include <vector>

#include "ossa/rig/character.h"
#include "ossa/io/result.h"
#include "ossa/render/rigged_mesh.h"
#include "ossa/draw/sprite_mesh.h"

namespace ossa {

struct LoadedCharacter {
  std::shared_ptr<const Character> character;
  RiggedMesh mesh;          // as imported (its texture decoded when the file has one)
  SpriteMesh sprite_mesh;   // batch geometry in the character's bone order
};

// The mesh's skeleton as the core reads it: names, parents, rest transforms from the file's
// nodes, and per bone the box of the vertices it moves most.
ImportedSkeleton imported_skeleton(const RiggedMesh& mesh);

// The batch geometry of a character built from `mesh` (every triangle in the body layer, back
// to front as imported).
SpriteMesh character_sprite_mesh(const Character& character, const RiggedMesh& mesh);

// Loads the mapping, the mesh it names (and its texture: a missing texture is logged by the
// renderer, not an error here) and builds the character. Errors name the rig file, the field
// and the bone, or the mesh file.
Result<LoadedCharacter> load_character(const std::string& rig_path);
// The same with the mapping and the mesh already loaded (tests: one mapping over the same
// character exported to glTF, DAE and FBX).
Result<LoadedCharacter> make_loaded_character(RiggedMesh mesh, const RigMapping& mapping, const std::string& rig_path);

// The rig files of the shipped characters (assets/characters/*.rig.json, data_path()): the
// humanoid first, then the others by name (the order C cycles them in).
std::vector<std::string> shipped_characters();

}  // namespace ossa
