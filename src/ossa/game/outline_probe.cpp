#include "ossa/game/outline_probe.h"

#include <algorithm>
#include <span>

#include "ossa/body/body_floor.h"
#include "ossa/game/sim.h"

namespace ossa {

OutlineProbe::OutlineProbe(const Creature& creature) : mesh_(build_body(creature)) {
  palette_.resize(static_cast<size_t>(mesh_.palette_size()));
  drawn_.resize(mesh_.vertices.size());
}

void OutlineProbe::observe(const Animator& animator, const Level& level, float t_s) {
  if (mesh_.parts.empty()) return;
  const std::vector<Mat2x3>& world = animator.world_matrices();
  body_palette(mesh_, world, palette_, body_floor(level, animator.rig().skeleton, world, mesh_.reach, mesh_.feet));
  const BodyFloor floor = decode_floor(std::span<const Mat2x3>(palette_).subspan(static_cast<size_t>(mesh_.floor_entry()), kBodyFloorEntries));
  Box all{glm::vec2(1e30f), glm::vec2(-1e30f)};
  for (const BodyPart& part : mesh_.parts) {
    for (uint32_t i : part.outline) {
      drawn_[i] = drawn_body_vertex(mesh_.vertices[i], palette_, floor);
      all = all.united(Box{drawn_[i], drawn_[i]});
    }
  }
  if (!(all.min_ws.x <= all.max_ws.x)) return;
  hits_.clear();
  level.overlapping(all, hits_);
  if (hits_.empty()) return;
  for (const BodyPart& part : mesh_.parts) {
    const size_t n = part.outline.size();
    for (size_t k = 0; k < n; ++k) {
      const glm::vec2 a = drawn_[part.outline[k]], b = drawn_[part.outline[(k + 1) % n]];
      const float d = segment_penetration(level, a, b, hits_);
      float& of_kind = max_by_kind[static_cast<size_t>(part.kind)];
      of_kind = std::max(of_kind, d);
      if (d > max_outline_penetration_m) {
        max_outline_penetration_m = d;
        deepest_outline_part = body_part_name(part.kind);
        deepest_outline_at_s = t_s;
      }
    }
  }
}

std::vector<std::vector<glm::vec2>> OutlineProbe::drawn_outlines() const {
  std::vector<std::vector<glm::vec2>> out;
  out.reserve(mesh_.parts.size());
  for (const BodyPart& part : mesh_.parts) {
    std::vector<glm::vec2>& o = out.emplace_back();
    for (uint32_t i : part.outline) o.push_back(drawn_[i]);
  }
  return out;
}

}  // namespace ossa
