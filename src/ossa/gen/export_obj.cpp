#include "ossa/gen/export_obj.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ossa/skeleton/pose.h"

namespace ossa {
namespace {

bool box_bone(const Skeleton& s, const std::vector<Mat2x3>& m, int i) {
  if (!(s.length(i) > 0.0f) || !std::isfinite(s.length(i)) || !std::isfinite(s.width(i))) {
    return false;
  }
  for (float v : m[static_cast<size_t>(i)].m) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

std::vector<Mat2x3> rest_matrices(const Creature& c) {
  const Skeleton& s = c.skeleton;
  const bool posed = c.rest_pose.locals.size() == static_cast<size_t>(s.bone_count());
  return model_matrices(s, posed ? c.rest_pose.locals : s.rest_locals());
}

std::string obj_name(const std::string& name) {
  std::string out = name.empty() ? "bone" : name;
  for (char& ch : out) {
    if (static_cast<unsigned char>(ch) <= ' ') ch = '_';
  }
  return out;
}

}  // namespace

int creature_obj_box_count(const Creature& creature) {
  const std::vector<Mat2x3> m = rest_matrices(creature);
  int count = 0;
  for (int i = 0; i < creature.skeleton.bone_count(); ++i) count += box_bone(creature.skeleton, m, i);
  return count;
}

std::string creature_obj(const Creature& creature, const ObjOptions& options) {
  const Skeleton& s = creature.skeleton;
  const std::vector<Mat2x3> m = rest_matrices(creature);

  float side = options.side_offset;
  if (side < 0.0f) {
    float longest_rib = 0.0f, widest_vertebra = 0.0f;
    for (int i = 0; i < s.bone_count(); ++i) {
      if (s.kind(i) == BoneKind::kRib) longest_rib = std::max(longest_rib, s.length(i));
      if (s.kind(i) == BoneKind::kBackVertebra) widest_vertebra = std::max(widest_vertebra, s.width(i));
    }
    side = longest_rib > 0.0f ? 0.5f * longest_rib : 1.5f * widest_vertebra;
  }
  const float depth_ratio = options.depth_ratio > 0.0f ? options.depth_ratio : 1.0f;

  std::string out = "# ossa creature \"" + obj_name(creature.name) +
                    "\": box proxies [Z 7.4], one per bone, model space in metres\n";
  char line[160];
  int next_vertex = 1;
  for (int i = 0; i < s.bone_count(); ++i) {
    if (!box_bone(s, m, i)) continue;
    const Mat2x3& mi = m[static_cast<size_t>(i)];
    const float L = s.length(i);
    const float h = 0.5f * std::max(s.width(i), 1e-4f);
    const float d = 0.5f * std::max(s.width(i) * depth_ratio, 1e-4f);
    const float zc = s.layer(i) == Layer::kNear ? side : s.layer(i) == Layer::kFar ? -side : 0.0f;
    const std::string name = obj_name(s.name(i));
    out += "o " + name + "\ng " + name + "\n";
    // Vertex k: bit 0 → x = L, bit 1 → y = +h, bit 2 → z = front.
    for (int k = 0; k < 8; ++k) {
      const glm::vec2 p = mi.apply({(k & 1) ? L : 0.0f, (k & 2) ? h : -h});
      const float z = zc + ((k & 4) ? d : -d);
      std::snprintf(line, sizeof line, "v %.6g %.6g %.6g\n", static_cast<double>(p.x),
                    static_cast<double>(p.y), static_cast<double>(z));
      out += line;
    }
    // Faces, counter-clockwise seen from outside (for a matrix without mirror).
    static constexpr int kFaces[6][4] = {
        {0, 2, 3, 1},  // back  (z-)
        {4, 5, 7, 6},  // front (z+)
        {0, 1, 5, 4},  // bottom (y-)
        {2, 6, 7, 3},  // top (y+)
        {0, 4, 6, 2},  // start (x = 0)
        {1, 3, 7, 5},  // end (x = L)
    };
    for (const auto& f : kFaces) {
      std::snprintf(line, sizeof line, "f %d %d %d %d\n", next_vertex + f[0], next_vertex + f[1],
                    next_vertex + f[2], next_vertex + f[3]);
      out += line;
    }
    next_vertex += 8;
  }
  return out;
}

}  // namespace ossa
