// Skinning of rigged meshes (rigged_mesh.h): rest pose, forward kinematics and palette,
// CPU skinning of a vertex.

#include <cmath>

#include "ossa/render/rigged_mesh.h"

namespace ossa {

std::vector<Mat2x3> rest_locals(const RiggedMesh& mesh) {
  std::vector<Mat2x3> locals;
  locals.reserve(mesh.bones.size());
  for (const RiggedBone& b : mesh.bones) locals.push_back(b.rest_local);
  return locals;
}

Mat2x3 rotated_local(const Mat2x3& local, float angle) {
  Mat2x3 r;
  r.m[0] = std::cos(angle);
  r.m[1] = std::sin(angle);
  r.m[2] = -r.m[1];
  r.m[3] = r.m[0];
  return local * r;
}

bool RiggedPaletteJob::validate() const {
  if (!mesh) return false;
  const size_t n = mesh->bones.size();
  if (locals.size() != n || world.size() != n || palette.size() != n) return false;
  for (size_t i = 0; i < n; ++i) {
    if (mesh->bones[i].parent >= static_cast<int>(i)) return false;
  }
  return true;
}

bool RiggedPaletteJob::run() const {
  if (!validate()) return false;
  // Parents precede children, so one pass gives every world matrix (pose.h FK).
  for (size_t i = 0; i < mesh->bones.size(); ++i) {
    const int p = mesh->bones[i].parent;
    world[i] = (p < 0 ? model_to_world : world[static_cast<size_t>(p)]) * locals[i];
    palette[i] = world[i] * mesh->bones[i].inverse_bind;
  }
  return true;
}

std::vector<Mat2x3> rigged_palette(const RiggedMesh& mesh, std::span<const Mat2x3> locals,
                                   const Mat2x3& model_to_world) {
  std::vector<Mat2x3> world(mesh.bones.size()), palette(mesh.bones.size());
  RiggedPaletteJob job{&mesh, locals, model_to_world, world, palette};
  OSSA_ASSERT(job.run(), "rigged_palette: one local per bone expected");
  return palette;
}

glm::vec2 skin_position(const RiggedVertex& vertex, std::span<const Mat2x3> palette) {
  glm::vec2 p{0.0f};
  for (int k = 0; k < kMaxRiggedWeights; ++k) {
    if (vertex.weights[k] == 0.0f) continue;
    OSSA_ASSERT(vertex.bones[k] < palette.size(), "skin_position: bone index outside the palette");
    p += vertex.weights[k] * palette[vertex.bones[k]].apply(vertex.position);
  }
  return p;
}

}  // namespace ossa
