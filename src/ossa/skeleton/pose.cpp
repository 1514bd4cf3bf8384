#include "ossa/skeleton/pose.h"

#include <cmath>

namespace ossa {

bool ForwardKinematicsJob::validate() const {
  if (!skeleton) return false;
  const size_t n = static_cast<size_t>(skeleton->bone_count());
  return locals.size() == n && model.size() == n && (world.empty() || world.size() == n);
}

bool ForwardKinematicsJob::run() const {
  if (!validate()) return false;
  const int n = skeleton->bone_count();
  const std::vector<int>& parents = skeleton->parents();
  for (int i = 0; i < n; ++i) {
    const Mat2x3 local = local_matrix(locals[i]);
    const int p = parents[i];
    model[i] = p < 0 ? local : model[p] * local;
  }
  if (!world.empty()) {
    for (int i = 0; i < n; ++i) world[i] = model_to_world * model[i];
  }
  return true;
}

bool PaletteJob::validate() const {
  return palette.size() == world.size() &&
         (inverse_bind.empty() || inverse_bind.size() == world.size());
}

bool PaletteJob::run() const {
  if (!validate()) return false;
  if (inverse_bind.empty()) {
    for (size_t i = 0; i < world.size(); ++i) palette[i] = world[i];
  } else {
    for (size_t i = 0; i < world.size(); ++i) palette[i] = world[i] * inverse_bind[i];
  }
  return true;
}

std::vector<Mat2x3> model_matrices(const Skeleton& skeleton, std::span<const BoneLocal> locals) {
  std::vector<Mat2x3> out(static_cast<size_t>(skeleton.bone_count()));
  ForwardKinematicsJob job;
  job.skeleton = &skeleton;
  job.locals = locals;
  job.model = out;
  job.run();
  return out;
}

Mat2x3 inverse(const Mat2x3& a) {
  const float det = a.m[0] * a.m[3] - a.m[2] * a.m[1];
  const float inv = 1.0f / det;
  Mat2x3 r;
  r.m[0] = a.m[3] * inv;
  r.m[1] = -a.m[1] * inv;
  r.m[2] = -a.m[2] * inv;
  r.m[3] = a.m[0] * inv;
  r.m[4] = -(r.m[0] * a.m[4] + r.m[2] * a.m[5]);
  r.m[5] = -(r.m[1] * a.m[4] + r.m[3] * a.m[5]);
  return r;
}

}  // namespace ossa
