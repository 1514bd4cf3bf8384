#include "ossa/body/body_mass.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace ossa {

double tube_volume(std::span<const glm::vec2> tops, std::span<const glm::vec2> bottoms, float depth,
                   std::span<const float> counts) {
  const size_t n = std::min(tops.size(), bottoms.size());
  double v = 0.0;
  const double k = 0.25 * 3.14159265358979 * depth;
  for (size_t i = 0; i + 1 < n; ++i) {
    const double h0 = glm::length(tops[i] - bottoms[i]), h1 = glm::length(tops[i + 1] - bottoms[i + 1]);
    const glm::vec2 m0 = 0.5f * (tops[i] + bottoms[i]), m1 = 0.5f * (tops[i + 1] + bottoms[i + 1]);
    const double ds = glm::length(m1 - m0);
    const double share = counts.empty() ? 1.0 : 0.5 * (counts[i] + counts[i + 1]);
    v += share * k * 0.5 * (h0 * h0 + h1 * h1) * ds;
  }
  return v;
}

double polygon_area(std::span<const glm::vec2> p) {
  double a = 0.0;
  for (size_t i = 0, n = p.size(); i < n; ++i) {
    const glm::vec2 u = p[i], w = p[(i + 1) % n];
    a += static_cast<double>(u.x) * w.y - static_cast<double>(w.x) * u.y;
  }
  return 0.5 * std::fabs(a);
}

bool inside_polygon(std::span<const glm::vec2> poly, glm::vec2 p) {
  bool inside = false;
  for (size_t i = 0, n = poly.size(), j = n - 1; i < n; j = i++) {
    const glm::vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

void body_mass(BodyMesh& mesh) {
  const auto pos = [&](uint32_t i) { return mesh.vertices[i].position_ms; };
  std::vector<glm::vec2> axial;
  for (const BodyPart& p : mesh.parts) {
    if (p.kind != BodyPartKind::kAxial) continue;
    for (uint32_t i : p.outline) axial.push_back(pos(i));
    break;
  }
  double mass = 0.0, area = 0.0;
  std::vector<glm::vec2> tops, bottoms, outline;
  std::vector<float> counts;
  for (BodyPart& part : mesh.parts) {
    outline.clear();
    for (uint32_t i : part.outline) outline.push_back(pos(i));
    area += polygon_area(outline);
    double volume = 0.0;
    if (!part.sections.empty()) {
      tops.clear();
      bottoms.clear();
      counts.clear();
      const bool limb = part.kind == BodyPartKind::kLeg || part.kind == BodyPartKind::kArm;
      for (const BodySection& s : part.sections) {
        tops.push_back(pos(s.top));
        bottoms.push_back(pos(s.bottom));
        const glm::vec2 mid = 0.5f * (tops.back() + bottoms.back());
        counts.push_back(limb && !axial.empty() && inside_polygon(axial, mid) ? 0.0f : 1.0f);
      }
      volume = tube_volume(tops, bottoms, part.depth, counts);
    } else if (part.kind != BodyPartKind::kEye && !outline.empty()) {
      glm::vec2 lo = outline.front(), hi = outline.front();
      for (const glm::vec2 q : outline) lo = glm::min(lo, q), hi = glm::max(hi, q);
      const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
      volume = polygon_area(outline) * part.depth * extent;
    }
    part.mass_kg = static_cast<float>(volume * kBodyDensity);
    mass += volume * kBodyDensity;
  }
  mesh.mass_kg = static_cast<float>(mass);
  mesh.area_m2 = static_cast<float>(area);
}

}  // namespace ossa
