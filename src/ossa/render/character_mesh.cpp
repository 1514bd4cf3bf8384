#include "ossa/render/character_mesh.h"

#include <algorithm>
#include <filesystem>

#include "ossa/io/data_dir.h"
#include "ossa/render/gl.h"
#include "ossa/render/rigged_batch.h"

namespace ossa {

ImportedSkeleton imported_skeleton(const RiggedMesh& mesh) {
  ImportedSkeleton out;
  out.source = mesh.source;
  const std::vector<Mat2x3> locals = rest_locals(mesh);
  for (size_t i = 0; i < mesh.bones.size(); ++i) {
    ImportedBone b;
    b.name = mesh.bones[i].name;
    b.parent = mesh.bones[i].parent;
    b.rest_mesh = b.parent >= 0 ? out.bones[static_cast<size_t>(b.parent)].rest_mesh * locals[i] : locals[i];
    out.bones.push_back(b);
  }
  // Weights are sorted descending: the first influence moves the vertex most.
  for (const RiggedVertex& v : mesh.vertices) {
    if (v.weights[0] <= 0.0f || v.bones[0] >= out.bones.size()) continue;
    ImportedBone& b = out.bones[v.bones[0]];
    b.extent_min = glm::min(b.extent_min, v.position);
    b.extent_max = glm::max(b.extent_max, v.position);
  }
  return out;
}

SpriteMesh character_sprite_mesh(const Character& character, const RiggedMesh& mesh) {
  SpriteMesh out = rigged_sprite_mesh(mesh);
  std::vector<uint8_t> ossa_of(mesh.bones.size(), 0);
  for (size_t k = 0; k < character.mesh_bone.size(); ++k) ossa_of[static_cast<size_t>(character.mesh_bone[k])] = static_cast<uint8_t>(k);
  for (SpriteVertex& v : out.vertices) {
    for (uint8_t& b : v.bones) b = ossa_of[b];
  }
  out.inverse_bind.clear();
  out.bone_sprites.assign(character.mesh_bone.size(), SpriteId::kLongBone);
  for (size_t k = 0; k < character.mesh_bone.size(); ++k) {
    out.inverse_bind.push_back(character.to_mesh[k] * mesh.bones[static_cast<size_t>(character.mesh_bone[k])].inverse_bind);
  }
  return out;
}

Result<LoadedCharacter> make_loaded_character(RiggedMesh mesh, const RigMapping& mapping, const std::string& rig_path) {
  Result<Character> c = build_character(imported_skeleton(mesh), mapping, rig_path);
  if (!c.ok()) return c.error();
  LoadedCharacter out;
  out.sprite_mesh = character_sprite_mesh(*c, mesh);
  out.character = std::make_shared<const Character>(std::move(c.value()));
  out.mesh = std::move(mesh);
  return out;
}

Result<LoadedCharacter> load_character(const std::string& rig_path) {
  Result<RigMapping> mapping = load_rig_mapping(rig_path);
  if (!mapping.ok()) return mapping.error();
  Result<RiggedMesh> mesh = load_rigged_mesh(mapping->mesh_path);
  if (!mesh.ok()) return Error{rig_path + ": mesh: " + mesh.message()};
  if (mesh->texture_rgba.empty() && !mesh->texture_path.empty()) {
    if (Status t = load_rigged_texture(*mesh); !t.ok()) render_log(t.message() + " (drawing with the checker texture)");
  }
  return make_loaded_character(std::move(mesh.value()), *mapping, rig_path);
}

std::vector<std::string> shipped_characters() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(data_path("assets/characters"), ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 9 && name.compare(name.size() - 9, 9, ".rig.json") == 0) out.push_back(e.path().string());
  }
  // The humanoid first (the README's order: humanoid, dog), the others by name.
  const auto humanoid = [](const std::string& path) { return std::filesystem::path(path).filename() == "humanoid.rig.json"; };
  std::sort(out.begin(), out.end(), [&](const std::string& a, const std::string& b) {
    if (humanoid(a) != humanoid(b)) return humanoid(a);
    return a < b;
  });
  return out;
}

}  // namespace ossa
