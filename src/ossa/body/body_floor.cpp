// The floor a body rests on (body_floor.h).

#include "ossa/body/body_floor.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ossa/assert.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

namespace {

// The top the foot whose ground-bearing ends are `points` stands on (body_floor), with the tops
// of one height joining it, within `window` metres of those ends; unused when it stands on none.
glm::vec3 foot_top(const Level& level, std::span<const glm::vec2> points, float window, std::vector<int>& hits) {
  glm::vec3 top(1.0f, 0.0f, 0.0f);
  float lo = 1e30f, hi = -1e30f;
  for (const glm::vec2 p : points) lo = std::min(lo, p.x - window), hi = std::max(hi, p.x + window);
  for (const glm::vec2 p : points) {
    hits.clear();
    level.overlapping(Box{{p.x, p.y - kFootOnTop}, {p.x, p.y + kFootOnTop}}, hits);
    for (const int h : hits) {
      const Box& box = level.box(h);
      if (std::fabs(box.max_ws.y - p.y) > kFootOnTop || (top.x <= top.y && box.max_ws.y <= top.z)) continue;
      top = {box.min_ws.x, box.max_ws.x, box.max_ws.y};
    }
  }
  if (top.x > top.y) return top;
  // Boxes of one height side by side (a tread of tiles) are one top.
  hits.clear();
  level.overlapping(Box{{lo, top.z - 1e-5f}, {hi, top.z + 1e-5f}}, hits);
  for (bool grew = true; grew;) {
    grew = false;
    for (const int h : hits) {
      const Box& box = level.box(h);
      if (box.max_ws.y != top.z || box.min_ws.x > top.y || box.max_ws.x < top.x) continue;
      if (box.min_ws.x < top.x || box.max_ws.x > top.y) {
        top.x = std::min(top.x, box.min_ws.x), top.y = std::max(top.y, box.max_ws.x);
        grew = true;
      }
    }
  }
  top.x = std::max(top.x, lo), top.y = std::min(top.y, hi);
  return top;
}

}  // namespace

BodyFloor body_floor(const Level& level, const Skeleton& skeleton, std::span<const Mat2x3> world, float reach,
                     std::span<const BodyFoot> feet) {
  BodyFloor floor;
  OSSA_ASSERT(static_cast<int>(world.size()) == skeleton.bone_count(), "body_floor: one matrix per bone");
  if (world.empty() || level.empty() || !(reach >= 0.0f) || !std::isfinite(reach)) return floor;
  // The bones, sampled at their ends and middles.
  std::vector<glm::vec2> samples;
  samples.reserve(world.size() * 3);
  for (size_t b = 0; b < world.size(); ++b) {
    const glm::vec2 a = bone_start(world[b]), e = bone_end(world[b], skeleton.length(static_cast<int>(b)));
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(e.x) || !std::isfinite(e.y)) return floor;
    samples.insert(samples.end(), {a, 0.5f * (a + e), e});
  }
  glm::vec2 lo = samples.front(), hi = samples.front();
  for (const glm::vec2 p : samples) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const float x0 = lo.x - reach, x1 = hi.x + reach;
  std::vector<int> hits;
  level.overlapping(Box{{x0, lo.y - reach - 1.0f}, {x1, hi.y}}, hits);
  std::vector<glm::vec3> tops;
  for (const int h : hits) {
    const Box& box = level.box(h);
    // The highest bone over the box, or past the bones' ends the nearest one: a floor has it
    // above its top, or sunk into it by less than half the flesh's reach (a legless
    // creature's crawl wave); a ceiling or a wall higher than the creature has not.
    float ref = -1e30f, nearest = 1e30f, nearest_y = 0.0f;
    for (const glm::vec2 p : samples) {
      if (p.x >= box.min_ws.x && p.x <= box.max_ws.x) ref = std::max(ref, p.y);
      const float dx = p.x < box.min_ws.x ? box.min_ws.x - p.x : p.x - box.max_ws.x;
      if (dx < nearest) nearest = dx, nearest_y = p.y;
    }
    if (ref < -1e29f) ref = nearest_y;
    if (box.max_ws.y > ref + std::max(0.001f, 0.5f * reach)) continue;
    tops.push_back({std::max(box.min_ws.x, x0), std::min(box.max_ws.x, x1), box.max_ws.y});
  }
  std::sort(tops.begin(), tops.end(), [](const glm::vec3& a, const glm::vec3& b) { return a.x < b.x || (a.x == b.x && a.z > b.z); });
  std::vector<glm::vec3> merged;
  for (const glm::vec3& t : tops) {
    if (!merged.empty() && merged.back().z == t.z && t.x <= merged.back().y) {
      merged.back().y = std::max(merged.back().y, t.y);
    } else {
      merged.push_back(t);
    }
  }
  // Too many tops (a long body over stairs or a slope of small boxes): neighbours merge, at
  // the higher top, where that lifts the least flesh (height step times the lower top's width).
  // A dropped top would leave the flesh over it hanging inside its box.
  while (merged.size() > static_cast<size_t>(kBodyFloorSegments)) {
    size_t best = 0;
    float least = 1e30f;
    for (size_t k = 0; k + 1 < merged.size(); ++k) {
      const glm::vec3 &a = merged[k], &b = merged[k + 1];
      const float lifted = std::fabs(a.z - b.z) * (a.z < b.z ? a.y - a.x : b.y - b.x);
      if (lifted < least) least = lifted, best = k;
    }
    glm::vec3& a = merged[best];
    const glm::vec3 b = merged[best + 1];
    a = {std::min(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
    merged.erase(merged.begin() + static_cast<std::ptrdiff_t>(best) + 1);
  }
  floor.count = static_cast<int>(merged.size());
  for (size_t k = 0; k < merged.size(); ++k) floor.segments[k] = merged[k];
  for (size_t f = 0; f < std::min(feet.size(), static_cast<size_t>(kBodyFloorFeet)); ++f) {
    glm::vec2 points[2];
    size_t n = 0;
    for (const int b : {feet[f].toe_bone, feet[f].heel_bone}) {
      if (b >= 0 && b < skeleton.bone_count()) points[n++] = bone_end(world[static_cast<size_t>(b)], skeleton.length(b));
    }
    // (Within a foot's length of its ends: a swinging foot's toe touching a top near its
    // edge does not hold up the knee beyond the edge.)
    floor.feet[f] = foot_top(level, std::span<const glm::vec2>(points, n), n > 0 ? skeleton.length(feet[f].toe_bone) : 0.0f, hits);
  }
  return floor;
}

BodyFloor flat_floor(float top) {
  BodyFloor floor;
  floor.count = 1;
  floor.segments[0] = {-1e30f, 1e30f, top};
  return floor;
}

glm::vec2 floor_point(glm::vec2 p, const BodyFloor& floor, float overhang, uint8_t foot) {
  const bool leg = foot < kBodyFloorFeet;
  const float past = leg ? 0.0f : overhang;
  for (int k = 0; k < kBodyFloorSegments; ++k) {
    const glm::vec3& s = floor.segments[static_cast<size_t>(k)];
    if (s.x > s.y) continue;
    if (p.x >= s.x - past && p.x <= s.y + past && p.y < s.z) p.y = s.z;
  }
  if (leg) {
    const glm::vec3& s = floor.feet[foot];
    if (s.x <= s.y && p.x >= s.x - overhang && p.x <= s.y + overhang && p.y < s.z && p.y > s.z - overhang) p.y = s.z;
  }
  return p;
}

void encode_floor(const BodyFloor& floor, std::span<Mat2x3> entries) {
  OSSA_ASSERT(entries.size() == static_cast<size_t>(kBodyFloorEntries), "encode_floor: kBodyFloorEntries entries");
  for (int k = 0; k < kBodyFloorEntries; ++k) {
    const bool seg = 2 * k < kBodyFloorSegments;
    const size_t i = static_cast<size_t>(seg ? 2 * k : 2 * k - kBodyFloorSegments);
    const glm::vec3& a = seg ? floor.segments[i] : floor.feet[i];
    const glm::vec3& b = seg ? floor.segments[i + 1] : floor.feet[i + 1];
    Mat2x3& m = entries[static_cast<size_t>(k)];
    m.m[0] = a.x, m.m[1] = a.y, m.m[2] = a.z;
    m.m[3] = b.x, m.m[4] = b.y, m.m[5] = b.z;
  }
}

BodyFloor decode_floor(std::span<const Mat2x3> entries) {
  OSSA_ASSERT(entries.size() == static_cast<size_t>(kBodyFloorEntries), "decode_floor: kBodyFloorEntries entries");
  BodyFloor floor;
  for (int k = 0; k < kBodyFloorEntries; ++k) {
    const Mat2x3& m = entries[static_cast<size_t>(k)];
    const bool seg = 2 * k < kBodyFloorSegments;
    const size_t i = static_cast<size_t>(seg ? 2 * k : 2 * k - kBodyFloorSegments);
    (seg ? floor.segments[i] : floor.feet[i]) = {m.m[0], m.m[1], m.m[2]};
    (seg ? floor.segments[i + 1] : floor.feet[i + 1]) = {m.m[3], m.m[4], m.m[5]};
  }
  floor.count = 0;
  for (const glm::vec3& s : floor.segments) floor.count += s.x <= s.y;
  return floor;
}

}  // namespace ossa
