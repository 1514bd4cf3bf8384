#include "ossa/draw/sprite_mesh.h"

// Smooth skinning's frames and weights, shared by whoever skins a sprite mesh: the chain joints
// that blend (chain_children), the mid-joint frames and their palette entries, a vertex
// skinned on the CPU as the skinned shader does it, and the weight count of a mesh.

#include <algorithm>
#include <cmath>

#include "ossa/assert.h"
#include "ossa/math/angle.h"
#include "ossa/skeleton/pose.h"

#include <glm/geometric.hpp>

namespace ossa {

std::vector<int> chain_children(const Skeleton& s, const std::vector<BoneLocal>& locals) {
  const int n = s.bone_count();
  std::vector<int> child(static_cast<size_t>(n), -1);
  std::vector<float> turn(static_cast<size_t>(n), 0.0f);
  const auto drawn = [&](int b) { return s.length(b) > 1e-6f && std::isfinite(s.length(b)); };
  for (int c = 0; c < n; ++c) {
    const int p = s.parent(c);
    if (p < 0 || !drawn(p) || !drawn(c) || s.layer(c) != s.layer(p)) continue;
    // A girdle's flat blade meets the limb at a ball joint, not a hinge: blending would bend
    // the blade's end (the pelvis's hook, the scapula's neck) after the limb.
    if (s.kind(p) == BoneKind::kScapula || s.kind(p) == BoneKind::kPelvis) continue;
    const BoneLocal& l = locals[static_cast<size_t>(c)];
    if (glm::length(l.offset_ls - glm::vec2(s.length(p), 0.0f)) > 0.01f * s.length(p)) continue;
    const float t = std::fabs(wrap_angle(l.angle_ls));
    const auto pi = static_cast<size_t>(p);
    if (child[pi] < 0 || t < turn[pi]) child[pi] = c, turn[pi] = t;
  }
  return child;
}

glm::vec2 skin_vertex(const SpriteVertex& v, std::span<const Mat2x3> palette) {
  glm::vec2 p(0.0f);
  for (size_t k = 0; k < 4; ++k) {
    if (v.weights[k] != 0.0f) p += v.weights[k] * palette[v.bones[k]].apply(v.position_ms);
  }
  return p;
}

void sprite_palette(const SpriteMesh& mesh, std::span<const Mat2x3> world, std::span<Mat2x3> palette) {
  OSSA_ASSERT(palette.size() == static_cast<size_t>(mesh.palette_size()) && world.size() == mesh.inverse_bind.size(),
              "sprite_palette: one world matrix per bone, palette_size() entries");
  PaletteJob job;
  job.world = world;
  job.inverse_bind = mesh.inverse_bind;
  job.palette = palette.first(world.size());
  const bool ok = job.run();
  OSSA_ASSERT(ok, "sprite_palette: palette job failed");
  (void)ok;
  if (!mesh.mid_joints.empty()) mid_joint_palette(mesh.mid_joints, world, palette);
}

int max_weights_per_vertex(const SpriteMesh& mesh) {
  int most = 0;
  for (const SpriteVertex& v : mesh.vertices) {
    int count = 0;
    for (float w : v.weights) count += w > 0.0f;
    most = std::max(most, count);
  }
  return most;
}

}  // namespace ossa
