#include "ossa/math/two_bone_ik.h"

#include "ossa/assert.h"
#include "ossa/math/angle.h"

#include <cmath>

namespace ossa {

bool TwoBoneIkJob::validate() const { return detail::two_bone_valid(*this); }

bool TwoBoneIkJob::run() {
  if (!detail::two_bone_valid(*this)) return false;
  detail::two_bone_solve_into(root, upper_length, lower_length, target, bend_sign, soft_reach, compute_angles, result);
  return true;
}

TwoBoneIkResult solve_two_bone_ik(glm::vec2 root, float upper_length, float lower_length,
                                  glm::vec2 target, float bend_sign, float soft_reach) {
  return detail::two_bone_solve(root, upper_length, lower_length, target, bend_sign, soft_reach, true);
}

}  // namespace ossa
