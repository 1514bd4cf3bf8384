#include "ossa/render/rigged_batch.h"

#include <algorithm>
#include <cmath>

namespace ossa {

Skeleton rigged_skeleton(const RiggedMesh& mesh) {
  float y_min = 1e30f, y_max = -1e30f;
  for (const RiggedVertex& v : mesh.vertices) {
    y_min = std::min(y_min, v.position.y);
    y_max = std::max(y_max, v.position.y);
  }
  const float leaf = y_max > y_min ? 0.1f * (y_max - y_min) : 0.1f;
  Skeleton s;
  for (size_t i = 0; i < mesh.bones.size(); ++i) {
    const RiggedBone& b = mesh.bones[i];
    float length = leaf;
    for (size_t j = i + 1; j < mesh.bones.size(); ++j) {
      if (mesh.bones[j].parent == static_cast<int>(i)) {
        const Mat2x3& c = mesh.bones[j].rest_local;
        length = std::sqrt(c.m[4] * c.m[4] + c.m[5] * c.m[5]);
        break;
      }
    }
    BoneLocal local;
    local.offset_ls = {b.rest_local.m[4], b.rest_local.m[5]};
    local.angle_ls = std::atan2(b.rest_local.m[1], b.rest_local.m[0]);
    const int parent = b.parent < 0 ? kNoParent : b.parent;
    s.add_bone(b.name, i == 0 ? BoneKind::kRoot : BoneKind::kLowerLimb, i == 0 ? kNoParent : parent, length,
               0.2f * length, local, Layer::kBody);
  }
  return s;
}

SpriteMesh rigged_sprite_mesh(const RiggedMesh& mesh) {
  SpriteMesh out;
  out.vertices.reserve(mesh.vertices.size());
  for (const RiggedVertex& v : mesh.vertices) {
    SpriteVertex s;
    s.position_ms = v.position;
    s.uv = {v.uv.x, 1.0f - v.uv.y};
    s.bones = v.bones;
    s.weights = v.weights;
    s.shade = 1.0f;
    out.vertices.push_back(s);
  }
  out.indices = mesh.indices;
  const uint32_t n = static_cast<uint32_t>(out.indices.size());
  out.layer_begin = {0, 0, n, n};  // far: empty, body: everything, near: empty
  for (const RiggedBone& b : mesh.bones) out.inverse_bind.push_back(b.inverse_bind);
  out.bone_sprites.assign(mesh.bones.size(), SpriteId::kLongBone);
  return out;
}

}  // namespace ossa
