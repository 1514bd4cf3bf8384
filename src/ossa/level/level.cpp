#include "ossa/level/level.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>

#include "ossa/assert.h"

namespace ossa {

namespace {
bool all_valid(const std::vector<Box>& boxes) {
  for (const Box& b : boxes) {
    if (!b.is_valid()) return false;
  }
  return true;
}
bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
std::uint64_t next_revision() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}
}  // namespace

Level::Level(std::vector<Box> colliders, glm::vec2 spawn, std::string level_name)
    : name(std::move(level_name)), spawn_ws(spawn), colliders_(std::move(colliders)) {
  OSSA_ASSERT(all_valid(colliders_), "Level: every collider must be a valid box");
  rebuild_index();
  revision_ = next_revision();
}

const Box& Level::box(int index) const {
  OSSA_ASSERT(index >= 0 && index < size(), "Level::box: index out of range");
  return colliders_[index];
}

Box Level::bounds() const {
  const Box b{spawn_ws, spawn_ws};
  const std::optional<Box> boxes = index_.bounds();
  return boxes ? b.united(*boxes) : b;
}

int Level::add_box(const Box& box) {
  OSSA_ASSERT(box.is_valid(), "Level::add_box: invalid box");
  colliders_.push_back(box);
  rebuild_index();
  revision_ = next_revision();
  return size() - 1;
}

void Level::remove_box(int index) {
  OSSA_ASSERT(index >= 0 && index < size(), "Level::remove_box: index out of range");
  colliders_.erase(colliders_.begin() + index);
  rebuild_index();
  revision_ = next_revision();
}

void Level::set_box(int index, const Box& box) {
  OSSA_ASSERT(index >= 0 && index < size(), "Level::set_box: index out of range");
  OSSA_ASSERT(box.is_valid(), "Level::set_box: invalid box");
  colliders_[index] = box;
  revision_ = next_revision();
  // Refitting keeps the index exact but loosens it when boxes move far; a rebuild after as
  // many refits as there are boxes keeps the amortised cost O(log n) per edit.
  if (++refits_ > std::max(64, size())) {
    rebuild_index();
  } else {
    index_.update(index, box);
  }
}

void Level::set_colliders(std::vector<Box> colliders) {
  OSSA_ASSERT(all_valid(colliders), "Level::set_colliders: every collider must be a valid box");
  colliders_ = std::move(colliders);
  rebuild_index();
  revision_ = next_revision();
}

void Level::rebuild_index() {
  index_.build(colliders_);
  refits_ = 0;
}

std::optional<GroundHit> Level::ground_height_below(float x_min, float x_max, float from_y,
                                                    float max_drop) const {
  OSSA_ASSERT(std::isfinite(x_min) && std::isfinite(x_max) && std::isfinite(from_y) &&
                  std::isfinite(max_drop),
              "ground_height_below: inputs must be finite");
  OSSA_ASSERT(x_min <= x_max && max_drop >= 0.0f, "ground_height_below: empty span or negative drop");
  return index_.ground(x_min, x_max, from_y - max_drop, from_y + kGroundEpsilon);
}

bool Level::overlaps(const Box& box) const {
  OSSA_ASSERT(finite(box.min_ws) && finite(box.max_ws), "overlaps: box must be finite");
  return index_.any_overlap(box);
}

std::optional<int> Level::first_overlap(const Box& box) const {
  OSSA_ASSERT(finite(box.min_ws) && finite(box.max_ws), "first_overlap: box must be finite");
  const int i = index_.lowest_overlap(box);
  if (i < 0) return std::nullopt;
  return i;
}

void Level::overlapping(const Box& box, std::vector<int>& out) const {
  OSSA_ASSERT(finite(box.min_ws) && finite(box.max_ws), "overlapping: box must be finite");
  index_.overlapping(box, out);
}

float Level::kill_y(float hip_height_m) const {
  if (kill_height_ws) return *kill_height_ws;
  const float margin = std::isfinite(hip_height_m) ? std::max(kKillMargin, kKillMarginOfHip * hip_height_m) : kKillMargin;
  const std::optional<Box> boxes = index_.bounds();
  return (boxes ? boxes->min_ws.y : spawn_ws.y) - margin;
}

bool Level::spawn_has_ground() const {
  const float kill = kill_y();
  if (!(spawn_ws.y > kill)) return false;
  return ground_height_below(spawn_ws.x - 0.05f, spawn_ws.x + 0.05f, spawn_ws.y + 0.01f, spawn_ws.y + 0.01f - kill).has_value();
}

glm::vec2 Level::free_point_above(glm::vec2 p_ws) const {
  OSSA_ASSERT(finite(p_ws), "free_point_above: point must be finite");
  std::vector<int> hits;
  // Each round lifts the point to the highest top among the boxes holding it, so it ends
  // after at most one round per box.
  for (int round = 0; round <= size(); ++round) {
    hits.clear();
    // A point on a box's bottom edge counts as inside it (a creature standing there would be
    // in the box): ask for a sliver just above the point.
    const float sliver = std::max(1e-6f, 1e-6f * std::abs(p_ws.y));
    index_.overlapping(Box{p_ws, p_ws + glm::vec2(0.0f, sliver)}, hits);
    if (hits.empty()) break;
    for (int i : hits) p_ws.y = std::max(p_ws.y, colliders_[i].max_ws.y);
  }
  return p_ws;
}

std::optional<SweepHit> Level::sweep_box(const Box& box, glm::vec2 delta) const {
  OSSA_ASSERT(finite(box.min_ws) && finite(box.max_ws) && finite(delta),
              "sweep_box: inputs must be finite");
  OSSA_ASSERT(box.min_ws.x <= box.max_ws.x && box.min_ws.y <= box.max_ws.y,
              "sweep_box: box min must not exceed max");
  return index_.sweep(box, delta);
}

std::optional<SweepHit> Level::raycast(glm::vec2 from_ws, glm::vec2 to_ws) const {
  return sweep_box(Box{from_ws, from_ws}, to_ws - from_ws);
}

float penetration_depth(const Level& level, glm::vec2 p) {
  std::vector<int> hits;
  level.overlapping(Box{p - glm::vec2(1e-6f), p + glm::vec2(1e-6f)}, hits);
  float depth = 0.0f;
  for (int h : hits) {
    const Box& b = level.box(h);
    const float d = std::min({p.x - b.min_ws.x, b.max_ws.x - p.x, p.y - b.min_ws.y, b.max_ws.y - p.y});
    depth = std::max(depth, d);
  }
  return depth;
}

float segment_penetration(const Level& level, glm::vec2 a, glm::vec2 b, const std::vector<int>& boxes) {
  float depth = 0.0f;
  for (int h : boxes) {
    const Box& box = level.box(h);
    // depth(t) = min of four linear functions of t along a + t (b - a): its maximum over
    // [0, 1] is at 0, 1, or where two of them are equal.
    const glm::vec2 d = b - a;
    const float c0[4] = {a.x - box.min_ws.x, box.max_ws.x - a.x, a.y - box.min_ws.y, box.max_ws.y - a.y};
    const float c1[4] = {d.x, -d.x, d.y, -d.y};
    auto at = [&](float t) {
      float m = 1e30f;
      for (int k = 0; k < 4; ++k) m = std::min(m, c0[k] + c1[k] * t);
      return m;
    };
    depth = std::max({depth, at(0.0f), at(1.0f)});
    for (int i = 0; i < 4; ++i) {
      for (int k = i + 1; k < 4; ++k) {
        const float slope = c1[i] - c1[k];
        if (std::fabs(slope) < 1e-12f) continue;
        const float t = (c0[k] - c0[i]) / slope;
        if (t > 0.0f && t < 1.0f) depth = std::max(depth, at(t));
      }
    }
  }
  return depth;
}

}  // namespace ossa
