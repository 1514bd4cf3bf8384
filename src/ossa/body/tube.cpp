// Parts into mesh data: a tube's sections become rows of vertices (top, two between, bottom)
// with quads between neighbouring sections and fans for its caps; a flat part's polygon a fan
// from its centre; every part's outline a closed loop of its fill vertices, counter-clockwise,
// and its stroke a strip outside it (body_parts.h).

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "ossa/body/body_mass.h"
#include "ossa/body/body_parts.h"
#include "ossa/body/coat.h"

namespace ossa::body {

namespace {

constexpr int kRows = 4;            // vertices across a section: top, 1/3, 2/3, bottom
constexpr int kCapSegments = 8;     // a round cap's arc

float signed_area(std::span<const glm::vec2> p) {
  double a = 0.0;
  for (size_t i = 0, n = p.size(); i < n; ++i) {
    const glm::vec2 u = p[i], w = p[(i + 1) % n];
    a += static_cast<double>(u.x) * w.y - static_cast<double>(w.x) * u.y;
  }
  return static_cast<float>(0.5 * a);
}

float smooth_step(float e0, float e1, float x) {
  if (!(e1 > e0)) return x < e0 ? 0.0f : 1.0f;
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec2 end_direction(const TubePlan& t, bool at_end) {
  const size_t n = t.sections.size();
  const glm::vec2 d = at_end ? t.sections[n - 1].centre - t.sections[n - 2].centre : t.sections[0].centre - t.sections[1].centre;
  const float len = glm::length(d);
  if (len > 1e-9f) return d / len;
  // Coincident centres: the dorsal normal turned back into the tangent.
  const glm::vec2 dorsal = at_end ? t.sections[n - 1].dorsal : t.sections[0].dorsal;
  const glm::vec2 tangent(-dorsal.y, dorsal.x);
  return at_end ? tangent : -tangent;
}

// Cap points from the top to the bottom of an end section.
std::vector<glm::vec2> cap_points(const TubePlan& t, float girth, bool at_end) {
  const Section& s = at_end ? t.sections.back() : t.sections.front();
  const Cap cap = at_end ? t.end_cap : t.start_cap;
  const glm::vec2 top = section_top(s, girth), bottom = section_bottom(s, girth);
  const glm::vec2 out = end_direction(t, at_end);
  const float reach = at_end ? t.end_cap_length : 1.0f;
  if (cap == Cap::kNone) return {};
  if (cap == Cap::kPoint) {
    const float r = 0.5f * glm::length(top - bottom);
    if (r < 1e-7f) return {};
    return {0.5f * (top + bottom) + out * (r * reach)};
  }
  return round_cap(top, bottom, out, reach, kCapSegments);
}

}  // namespace

std::vector<glm::vec2> round_cap(glm::vec2 top, glm::vec2 bottom, glm::vec2 out, float reach, int segments) {
  std::vector<glm::vec2> pts;
  const glm::vec2 c = 0.5f * (top + bottom), up = 0.5f * (top - bottom);
  const float r = glm::length(up);
  if (r < 1e-7f) return pts;
  for (int k = 1; k < segments; ++k) {
    const float a = 3.14159265f * static_cast<float>(k) / static_cast<float>(segments);  // 0 top … π bottom
    pts.push_back(c + std::cos(a) * up + std::sin(a) * r * reach * out);
  }
  return pts;
}

std::vector<glm::vec2> tube_outline(const TubePlan& t, float girth) {
  std::vector<glm::vec2> loop;
  if (t.sections.size() < 2) return loop;
  for (const Section& s : t.sections) loop.push_back(section_top(s, girth));
  for (const glm::vec2 p : cap_points(t, girth, true)) loop.push_back(p);
  for (size_t i = t.sections.size(); i-- > 0;) loop.push_back(section_bottom(t.sections[i], girth));
  std::vector<glm::vec2> start = cap_points(t, girth, false);
  for (size_t i = start.size(); i-- > 0;) loop.push_back(start[i]);
  return loop;
}

void unfold_sections(std::vector<Section>& sections, float girth) {
  const size_t n = sections.size();
  if (n < 3) return;
  for (int pass = 0; pass < 24; ++pass) {
    bool changed = false;
    for (size_t i = 0; i + 1 < n; ++i) {
      Section& a = sections[i];
      Section& b = sections[i + 1];
      const glm::vec2 step = b.centre - a.centre;
      const float len = glm::length(step);
      if (len < 1e-9f) continue;
      const glm::vec2 t = step / len;
      for (int side = 0; side < 2; ++side) {
        const glm::vec2 pa = side == 0 ? section_top(a, girth) : section_bottom(a, girth);
        const glm::vec2 pb = side == 0 ? section_top(b, girth) : section_bottom(b, girth);
        if (glm::dot(pb - pa, t) > 0.05f * len) continue;
        // The side runs backwards between a and b: shrink it on both.
        for (Section* s : {&a, &b}) {
          float& cap = side == 0 ? s->top_cap : s->bottom_cap;
          const float now = side == 0 ? s->top(girth) : s->bottom(girth);
          cap = 0.8f * now;
        }
        changed = true;
      }
    }
    if (!changed) break;
  }
}

namespace {

double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

bool crossing(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  const glm::dvec2 p(a), r(glm::dvec2(b) - glm::dvec2(a)), q(c), sd(glm::dvec2(d) - glm::dvec2(c));
  const double rxs = cross2(r, sd);
  if (std::fabs(rxs) < 1e-20) return false;
  const double t = cross2(q - p, sd) / rxs, u = cross2(q - p, r) / rxs;
  return t > 1e-7 && t < 1.0 - 1e-7 && u > 1e-7 && u < 1.0 - 1e-7;
}

}  // namespace

bool first_crossing(std::span<const glm::vec2> loop, size_t& i_out, size_t& j_out) {
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::vec2 a = loop[i], b = loop[(i + 1) % n];
    const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b);
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      const glm::vec2 c = loop[j], d = loop[(j + 1) % n];
      if (std::max(c.x, d.x) < lo.x || std::min(c.x, d.x) > hi.x || std::max(c.y, d.y) < lo.y || std::min(c.y, d.y) > hi.y) continue;
      if (crossing(a, b, c, d)) {
        i_out = i;
        j_out = j;
        return true;
      }
    }
  }
  return false;
}

void untangle_tube(TubePlan& t, float girth) {
  const size_t n = t.sections.size();
  if (n < 2) return;
  for (int round = 0; round < 40; ++round) {
    const std::vector<glm::vec2> loop = tube_outline(t, girth);
    size_t i = 0, j = 0;
    if (!first_crossing(loop, i, j)) return;
    // Outline index → (section, side): tops 0..n-1, then the end cap, bottoms n-1..0, the
    // start cap. Cap points belong to their end section (both sides).
    const size_t end_caps = loop.size() - 2 * n;
    const size_t end_cap = t.end_cap == Cap::kNone ? 0 : (t.end_cap == Cap::kPoint ? (end_caps > 0 ? 1 : 0) : 0);
    (void)end_cap;
    const size_t start_cap_count = [&] {
      size_t k = 0;
      if (t.start_cap == Cap::kRound) k = static_cast<size_t>(round_cap(section_top(t.sections[0], girth), section_bottom(t.sections[0], girth), glm::vec2(1.0f, 0.0f), 1.0f, 8).size());
      else if (t.start_cap == Cap::kPoint) k = 1;
      return std::min(k, end_caps);
    }();
    const size_t end_cap_count = end_caps - start_cap_count;
    const auto shrink = [&](size_t k) {
      k %= loop.size();
      const auto cut = [&](Section& s, bool top) {
        float& cap = top ? s.top_cap : s.bottom_cap;
        cap = 0.85f * (top ? s.top(girth) : s.bottom(girth));
      };
      if (k < n) {
        cut(t.sections[k], true);
      } else if (k < n + end_cap_count) {
        cut(t.sections[n - 1], true);
        cut(t.sections[n - 1], false);
      } else if (k < 2 * n + end_cap_count) {
        cut(t.sections[2 * n + end_cap_count - 1 - k], false);
      } else {
        cut(t.sections[0], true);
        cut(t.sections[0], false);
      }
    };
    if (round < 24) {
      for (size_t k : {i, i + 1, j, j + 1}) shrink(k);
      continue;
    }
    // Still crossing (sides already at the bone, or a fold the caps cannot open): drop the
    // sections the crossing spans on one side, so the outline runs straight past them.
    const auto section_of = [&](size_t k) -> long {
      k %= loop.size();
      if (k < n) return static_cast<long>(k);
      if (k >= n + end_cap_count && k < 2 * n + end_cap_count) return static_cast<long>(2 * n + end_cap_count - 1 - k);
      return -1;
    };
    const long a = section_of(i), b = section_of(j + 1);
    if (a < 0 || b < 0 || t.sections.size() <= 3) return;
    const long lo = std::max(1L, std::min(a, b) + 1), hi = std::min(static_cast<long>(t.sections.size()) - 2, std::max(a, b));
    if (lo >= hi) {
      // Neighbours: drop the inner one.
      const long drop = std::clamp(std::max(a, b), 1L, static_cast<long>(t.sections.size()) - 2);
      t.sections.erase(t.sections.begin() + drop);
    } else {
      t.sections.erase(t.sections.begin() + lo, t.sections.begin() + hi);
    }
    return untangle_tube(t, girth);
  }
}

BodyPart emit_tube(const TubePlan& t, float girth, BodyMesh& mesh, const Painter& paint) {
  BodyPart part;
  part.kind = t.kind;
  part.layer = t.layer;
  part.limb = t.limb;
  part.depth = t.depth;
  if (t.sections.size() < 2) return part;
  const auto first = static_cast<uint32_t>(mesh.vertices.size());
  const auto vertex = [&](glm::vec2 p, const Skin& skin, float v, glm::vec4 over) {
    BodyVertex bv;
    bv.position_ms = p;
    bv.bones = {skin.index[0], skin.index[1], 0, 0};
    bv.weights = {skin.weight[0], skin.weight[1], 0.0f, 0.0f};
    if (skin.index[0] == skin.index[1]) bv.weights = {1.0f, 0.0f, 0.0f, 0.0f};
    if (t.contact_entry >= 0) {
      const float d = glm::length(p - t.contact_point);
      float w = 1.0f - smooth_step(t.contact_inner, t.contact_reach, d);
      // A heel anchors only its sole: what lies lower than contact_height above the contact.
      if (t.contact_height > 0.0f) w *= 1.0f - smooth_step(0.5f * t.contact_height, t.contact_height, p.y - t.contact_point.y);
      if (w > 0.0f) {
        for (float& x : bv.weights) x *= 1.0f - w;
        bv.bones[2] = static_cast<uint8_t>(t.contact_entry);
        bv.weights[2] = w;
      }
    }
    paint(bv, v, over, t.pattern);
    mesh.vertices.push_back(bv);
    return static_cast<uint32_t>(mesh.vertices.size() - 1);
  };
  const size_t n = t.sections.size();
  for (size_t i = 0; i < n; ++i) {
    const Section& s = t.sections[i];
    const glm::vec2 top = section_top(s, girth), bottom = section_bottom(s, girth);
    const glm::vec4 over = s.colour.r >= 0.0f ? s.colour : t.colour;
    for (int r = 0; r < kRows; ++r) {
      const float v = static_cast<float>(r) / static_cast<float>(kRows - 1);
      vertex(top + v * (bottom - top), s.skin, v, over);
    }
    part.sections.push_back({first + static_cast<uint32_t>(i * kRows), first + static_cast<uint32_t>(i * kRows + kRows - 1)});
  }
  part.first_index = static_cast<uint32_t>(mesh.indices.size());
  for (uint32_t i = 0; i + 1 < n; ++i) {
    for (uint32_t r = 0; r + 1 < static_cast<uint32_t>(kRows); ++r) {
      const uint32_t a = first + i * kRows + r, b = a + kRows;
      mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
    }
  }
  // Caps: a fan from the end section's middle vertex.
  std::vector<uint32_t> cap_ids[2];
  for (int end = 0; end < 2; ++end) {
    const bool at_end = end == 1;
    const size_t si = at_end ? n - 1 : 0;
    const Section& s = t.sections[si];
    const std::vector<glm::vec2> pts = cap_points(t, girth, at_end);
    const glm::vec4 over = s.colour.r >= 0.0f ? s.colour : t.colour;
    const uint32_t top = first + static_cast<uint32_t>(si * kRows), bottom = top + kRows - 1;
    const uint32_t centre = top + 1;  // a row inside the section
    std::vector<uint32_t> fan{top};
    for (size_t k = 0; k < pts.size(); ++k) {
      const float v = pts.size() > 1 ? static_cast<float>(k + 1) / static_cast<float>(pts.size() + 1) : 0.5f;
      const uint32_t id = vertex(pts[k], s.skin, v, over);
      fan.push_back(id);
      cap_ids[end].push_back(id);
    }
    fan.push_back(bottom);
    for (size_t k = 0; k + 1 < fan.size(); ++k) {
      if (fan[k] == centre || fan[k + 1] == centre) continue;
      mesh.indices.insert(mesh.indices.end(), {centre, fan[k], fan[k + 1]});
    }
  }
  part.index_count = static_cast<uint32_t>(mesh.indices.size()) - part.first_index;

  // Outline: top row, end cap, bottom row back, start cap back; stored counter-clockwise.
  for (size_t i = 0; i < n; ++i) part.outline.push_back(first + static_cast<uint32_t>(i * kRows));
  for (uint32_t id : cap_ids[1]) part.outline.push_back(id);
  for (size_t i = n; i-- > 0;) part.outline.push_back(first + static_cast<uint32_t>(i * kRows + kRows - 1));
  for (size_t k = cap_ids[0].size(); k-- > 0;) part.outline.push_back(cap_ids[0][k]);
  std::vector<glm::vec2> loop;
  for (uint32_t id : part.outline) loop.push_back(mesh.vertices[id].position_ms);
  if (signed_area(loop) < 0.0f) std::reverse(part.outline.begin(), part.outline.end());
  return part;
}

// Triangles of a simple polygon (counter-clockwise), by ear clipping: indices into `p`.
std::vector<uint32_t> ear_clip(std::span<const glm::vec2> p) {
  std::vector<uint32_t> out;
  std::vector<uint32_t> left(p.size());
  for (uint32_t i = 0; i < left.size(); ++i) left[i] = i;
  const auto cross3 = [&](uint32_t a, uint32_t b, uint32_t c) {
    return (p[b].x - p[a].x) * (p[c].y - p[a].y) - (p[b].y - p[a].y) * (p[c].x - p[a].x);
  };
  size_t guard = 0;
  while (left.size() > 3 && guard++ < 4 * p.size() * p.size()) {
    bool clipped = false;
    for (size_t k = 0; k < left.size(); ++k) {
      const uint32_t a = left[(k + left.size() - 1) % left.size()], b = left[k], c = left[(k + 1) % left.size()];
      if (cross3(a, b, c) <= 0.0f) continue;  // reflex (or flat): not an ear
      bool empty = true;
      for (const uint32_t q : left) {
        if (q == a || q == b || q == c) continue;
        if (cross3(a, b, q) >= 0.0f && cross3(b, c, q) >= 0.0f && cross3(c, a, q) >= 0.0f) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.insert(out.end(), {a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
      break;
    }
    if (!clipped) {  // degenerate leftovers (collinear points): clip the flattest corner
      size_t best = 0;
      float flat = 1e30f;
      for (size_t k = 0; k < left.size(); ++k) {
        const float c = std::fabs(cross3(left[(k + left.size() - 1) % left.size()], left[k], left[(k + 1) % left.size()]));
        if (c < flat) flat = c, best = k;
      }
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
    }
  }
  if (left.size() == 3 && cross3(left[0], left[1], left[2]) > 0.0f) out.insert(out.end(), {left[0], left[1], left[2]});
  return out;
}

BodyPart emit_flat(const FlatPlan& f, BodyMesh& mesh, const Painter& paint) {
  BodyPart part;
  part.kind = f.kind;
  part.layer = f.layer;
  part.depth = f.depth;
  if (f.outline.size() < 3) return part;
  // Counter-clockwise, without repeated points.
  std::vector<size_t> order;
  for (size_t k = 0; k < f.outline.size(); ++k) {
    if (!order.empty() && glm::length(f.outline[k] - f.outline[order.back()]) < 1e-9f) continue;
    order.push_back(k);
  }
  while (order.size() > 1 && glm::length(f.outline[order.front()] - f.outline[order.back()]) < 1e-9f) order.pop_back();
  std::vector<glm::vec2> loop;
  for (size_t k : order) loop.push_back(f.outline[k]);
  if (signed_area(loop) < 0.0f) {
    std::reverse(order.begin(), order.end());
    std::reverse(loop.begin(), loop.end());
  }
  if (loop.size() < 3) return part;
  const auto first = static_cast<uint32_t>(mesh.vertices.size());
  for (size_t k : order) {
    const Skin& skin = k < f.skin.size() ? f.skin[k] : f.centre_skin;
    BodyVertex bv;
    bv.position_ms = f.outline[k];
    bv.bones = {skin.index[0], skin.index[1], 0, 0};
    bv.weights = {skin.weight[0], skin.weight[1], 0.0f, 0.0f};
    if (skin.index[0] == skin.index[1]) bv.weights = {1.0f, 0.0f, 0.0f, 0.0f};
    paint(bv, -1.0f, f.colour, f.pattern);
    mesh.vertices.push_back(bv);
    part.outline.push_back(static_cast<uint32_t>(mesh.vertices.size() - 1));
  }
  part.first_index = static_cast<uint32_t>(mesh.indices.size());
  for (const uint32_t i : ear_clip(loop)) mesh.indices.push_back(first + i);
  part.index_count = static_cast<uint32_t>(mesh.indices.size()) - part.first_index;
  return part;
}

void add_stroke(BodyPart& part, BodyMesh& mesh, float width, glm::vec4 colour, std::span<const glm::vec2> fade_inside) {
  const size_t n = part.outline.size();
  if (n < 3 || !(width > 0.0f)) return;
  std::vector<glm::vec2> p(n);
  for (size_t k = 0; k < n; ++k) p[k] = mesh.vertices[part.outline[k]].position_ms;
  const auto first = static_cast<uint32_t>(mesh.vertices.size());
  for (size_t k = 0; k < n; ++k) {
    // Outward normal of a counter-clockwise loop: the neighbours' chord turned clockwise.
    const glm::vec2 chord = p[(k + 1) % n] - p[(k + n - 1) % n];
    const float len = glm::length(chord);
    const glm::vec2 out = len > 1e-9f ? glm::vec2(chord.y, -chord.x) / len : glm::vec2(0.0f);
    float alpha = colour.a;
    if (!fade_inside.empty() && inside_polygon(fade_inside, p[k])) alpha = 0.0f;
    BodyVertex inner = mesh.vertices[part.outline[k]];
    inner.colour = to_rgba8(glm::vec4(glm::vec3(colour), alpha));
    inner.pattern = {0, 0, 0, 0};
    BodyVertex outer = inner;
    outer.position_ms = p[k] + out * width;
    mesh.vertices.push_back(inner);
    mesh.vertices.push_back(outer);
  }
  part.stroke_first_index = static_cast<uint32_t>(mesh.indices.size());
  for (uint32_t k = 0; k < n; ++k) {
    const uint32_t a = first + 2 * k, b = first + 2 * ((k + 1) % static_cast<uint32_t>(n));
    mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1});
  }
  part.stroke_index_count = static_cast<uint32_t>(mesh.indices.size()) - part.stroke_first_index;
}

}  // namespace ossa::body
