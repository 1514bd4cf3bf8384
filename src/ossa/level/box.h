#pragma once
// Box — an axis-aligned rectangle in world space, the only collider shape of a level
// (DESIGN.md §6, [T 4.3]: "colliders made of rectangles aligned with the global x and y axes").
//
// Units are metres, +x right, +y up. A valid box is finite with min_ws < max_ws on both axes.
// Boxes are treated as open sets when testing overlap: two boxes that only touch along an
// edge do not overlap (a creature standing on the ground does not overlap it).

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ossa {

struct Box {
  glm::vec2 min_ws{0.0f};  // bottom-left corner, metres
  glm::vec2 max_ws{0.0f};  // top-right corner, metres

  // From the bottom-left corner and a size (metres, > 0 for a valid box).
  static Box from_corner(glm::vec2 corner_ws, glm::vec2 size) { return {corner_ws, corner_ws + size}; }
  static Box from_corner(float x, float y, float w, float h) { return {{x, y}, {x + w, y + h}}; }
  // From the centre and half extents.
  static Box from_center(glm::vec2 center_ws, glm::vec2 half_size) {
    return {center_ws - half_size, center_ws + half_size};
  }

  float width() const { return max_ws.x - min_ws.x; }
  float height() const { return max_ws.y - min_ws.y; }
  glm::vec2 size() const { return max_ws - min_ws; }
  glm::vec2 center() const { return 0.5f * (min_ws + max_ws); }
  float top() const { return max_ws.y; }

  bool is_valid() const {
    return std::isfinite(min_ws.x) && std::isfinite(min_ws.y) && std::isfinite(max_ws.x) &&
           std::isfinite(max_ws.y) && min_ws.x < max_ws.x && min_ws.y < max_ws.y;
  }
  // Interiors intersect (touching edges do not count).
  bool overlaps(const Box& o) const {
    return min_ws.x < o.max_ws.x && o.min_ws.x < max_ws.x && min_ws.y < o.max_ws.y &&
           o.min_ws.y < max_ws.y;
  }
  // Closed containment: points on the edge count.
  bool contains(glm::vec2 p_ws) const {
    return p_ws.x >= min_ws.x && p_ws.x <= max_ws.x && p_ws.y >= min_ws.y && p_ws.y <= max_ws.y;
  }
  // Smallest box holding both.
  Box united(const Box& o) const {
    return {{std::min(min_ws.x, o.min_ws.x), std::min(min_ws.y, o.min_ws.y)},
            {std::max(max_ws.x, o.max_ws.x), std::max(max_ws.y, o.max_ws.y)}};
  }
  Box translated(glm::vec2 d) const { return {min_ws + d, max_ws + d}; }

  friend bool operator==(const Box& a, const Box& b) {
    return a.min_ws == b.min_ws && a.max_ws == b.max_ws;
  }
};

// Tolerance of ground queries above the query height: a foot resting on a box top may sit a
// rounding error below it and must still find it. Metres.
inline constexpr float kGroundEpsilon = 1e-3f;

// The ground found below an x-span: the top of box `index` at `height_ws` (metres).
struct GroundHit {
  float height_ws = 0.0f;
  int index = -1;
};

// A swept box's first contact: the box moved by t * delta touches collider `index`.
struct SweepHit {
  float t = 0.0f;              // time of impact in [0, 1] along the sweep
  glm::vec2 normal{0.0f};      // unit normal of the face hit, pointing out of the collider;
                               // (0, 0) when the box started inside the collider
  int index = -1;              // collider index in Level::colliders(), -1 from sweep_against()
  bool started_inside = false; // the box already overlapped the collider at t = 0
};

// Does `box` count as ground for the span [x_min, x_max] between heights lo and hi? Its top
// must lie in [lo, hi] and its x-range must touch the span (closed intervals: a span ending
// exactly on a box edge counts, so a foot on a step edge finds the step).
inline bool is_ground_candidate(const Box& box, float x_min, float x_max, float lo, float hi) {
  return box.min_ws.x <= x_max && box.max_ws.x >= x_min && box.max_ws.y >= lo && box.max_ws.y <= hi;
}

// Swept-AABB slab test of `moving` translated by t * delta, t in [0, 1], against `collider`.
// A hit needs the interiors to overlap for some t in [0, 1): boxes sliding along a shared face
// or separating from it do not hit; a box touching a face and moving into it hits at t = 0.
// When both axes are entered at the same time (a corner), the normal is the y face.
inline std::optional<SweepHit> sweep_against(const Box& moving, glm::vec2 delta, const Box& collider) {
  float t0 = -std::numeric_limits<float>::infinity();
  float t1 = std::numeric_limits<float>::infinity();
  int axis = -1;
  for (int a = 0; a < 2; ++a) {
    // Minkowski difference: offsets at which the interiors overlap on this axis.
    const float emin = collider.min_ws[a] - moving.max_ws[a];
    const float emax = collider.max_ws[a] - moving.min_ws[a];
    const float d = delta[a];
    if (d == 0.0f) {
      if (!(emin < 0.0f && 0.0f < emax)) return std::nullopt;
      continue;
    }
    const float enter = (d > 0.0f ? emin : emax) / d;
    const float exit = (d > 0.0f ? emax : emin) / d;
    if (enter > t0 || (enter == t0 && a == 1)) { t0 = enter; axis = a; }
    t1 = std::min(t1, exit);
  }
  if (!(t0 < t1) || !(t0 < 1.0f) || !(t1 > 0.0f)) return std::nullopt;
  SweepHit hit;
  if (t0 < 0.0f || axis < 0) {
    hit.started_inside = true;
    return hit;
  }
  hit.t = t0;
  hit.normal[axis] = delta[axis] > 0.0f ? -1.0f : 1.0f;
  return hit;
}

}  // namespace ossa
