#include "ossa/anim/ground_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ossa {

namespace {
constexpr float kNoGround = std::numeric_limits<float>::quiet_NaN();
}  // namespace

void GroundProfile::build(const Level& level, float x0_ws, float x1_ws, float top_ws, float depth, float step) {
  step_ = std::max(step, 1e-4f);
  x0_ = x0_ws;
  top_ = top_ws;
  depth_ = std::max(depth, 0.0f);
  level_ = &level;
  revision_ = level.revision();
  const int n = std::max(1, static_cast<int>(std::ceil((x1_ws - x0_ws) / step_)));
  heights_.assign(n, kNoGround);
  thread_local std::vector<int> hits;
  hits.clear();
  const float x_end = x0_ + static_cast<float>(n) * step_;
  level.overlapping(Box{{x0_ - step_, top_ - depth_ - 1.0f}, {x_end + step_, top_ + 1.0f}}, hits);
  for (int h : hits) {
    const Box& box = level.box(h);
    const float y = box.top();
    if (y > top_ + kGroundEpsilon || y < top_ - depth_) continue;
    // Columns whose closed interval [x0 + i·step, x0 + (i+1)·step] touches the box's x-range.
    int i0 = static_cast<int>(std::floor((box.min_ws.x - x0_) / step_)) - 1;
    int i1 = static_cast<int>(std::floor((box.max_ws.x - x0_) / step_)) + 1;
    i0 = std::max(i0, 0);
    i1 = std::min(i1, n - 1);
    for (int i = i0; i <= i1; ++i) {
      const float lo = x0_ + static_cast<float>(i) * step_, hi = x0_ + static_cast<float>(i + 1) * step_;
      if (box.max_ws.x < lo || box.min_ws.x > hi) continue;
      if (!(heights_[i] >= y)) heights_[i] = y;
    }
  }
}

bool GroundProfile::covers(const Level& level, float x0_ws, float x1_ws, float lo_ws, float hi_ws) const {
  return !heights_.empty() && level_ == &level && revision_ == level.revision() && x0_ws >= x0_ &&
         x1_ws <= x0_ + static_cast<float>(size()) * step_ && hi_ws <= top_ && lo_ws >= top_ - depth_;
}

int GroundProfile::column_of(float x_ws) const {
  const float i = std::floor((x_ws - x0_) / step_);
  return static_cast<int>(std::clamp(i, 0.0f, static_cast<float>(size() - 1)));
}

GroundProfile::Tread GroundProfile::tread_at(int i, int most) const {
  // The columns either side of i at its height, walked no further than `most` columns.
  const float y = heights_[i];
  Tread t{i, i};
  while (t.first > 0 && heights_[t.first - 1] == y && t.last - t.first < most) --t.first;
  while (t.last + 1 < size() && heights_[t.last + 1] == y && t.last - t.first < most) ++t.last;
  return t;
}

float GroundProfile::surface_line(float x_ws, const SlopeReading& reading) const {
  const int i = column_of(x_ws);
  const float y = heights_[i];
  if (std::isnan(y)) return y;
  const int most = static_cast<int>(reading.tread / step_) + 1;
  const Tread own = tread_at(i, most);
  const float width = static_cast<float>(own.last - own.first + 1) * step_;
  if (width > reading.tread) return y;  // a wide tread is flat ground
  const float mid = x0_ + (static_cast<float>(own.first + own.last + 1) * 0.5f) * step_;
  // The knot on the side of x from the middle: the neighbouring tread's middle, or, where that
  // tread is wide (the flat top of a hill, the floor of a valley), its corner at the shared
  // edge, so that the line runs on into the flat ground without a jump.
  const bool right = x_ws >= mid;
  const int j = right ? own.last + 1 : own.first - 1;
  if (j < 0 || j >= size() || std::isnan(heights_[j])) return y;
  const float y2 = heights_[j];
  const Tread next = tread_at(j, most);
  const float next_width = static_cast<float>(next.last - next.first + 1) * step_;
  const bool next_wide = next_width > reading.tread;
  // Treads narrower than the foot may rise by any amount no steeper than kMaxSlope (tested below).
  const bool under_foot = width < reading.foot && (next_wide || next_width < reading.foot);
  if (!under_foot && std::fabs(y2 - y) > reading.riser) return y;
  const float edge = x0_ + static_cast<float>(right ? j : own.first) * step_;
  const float mid2 = next_wide ? edge : x0_ + (static_cast<float>(next.first + next.last + 1) * 0.5f) * step_;
  // Too steep is a flight of steps (a corner knot is half a tread away: the slope of treads
  // as wide as this one is half of that segment's).
  const float run = std::fabs(mid2 - mid) * (next_wide ? 2.0f : 1.0f);
  if (std::fabs(y2 - y) > kMaxSlope * run) return y;
  const float t = (x_ws - mid) / (mid2 - mid);
  return y + t * (y2 - y);
}

float GroundProfile::largest_jump(float a_ws, float b_ws, const SlopeReading& reading) const {
  if (a_ws > b_ws) std::swap(a_ws, b_ws);
  float most = 0.0f;
  float prev = surface_line(x0_ + (static_cast<float>(column_of(a_ws)) + 0.5f) * step_, reading);
  for (int i = column_of(a_ws) + 1, end = column_of(b_ws); i <= end; ++i) {
    const float y = surface_line(x0_ + (static_cast<float>(i) + 0.5f) * step_, reading);
    if (!std::isnan(y) && !std::isnan(prev)) most = std::max(most, std::fabs(y - prev));
    prev = y;
  }
  return most;
}

float GroundProfile::slope_top(float from_ws, float a_ws, float b_ws, const SlopeReading& reading) const {
  if (empty()) return kNoGround;
  if (a_ws > b_ws) std::swap(a_ws, b_ws);
  const float end_x = x0_ + static_cast<float>(size()) * step_;
  if (from_ws < x0_ || from_ws > end_x || a_ws < x0_ || b_ws > end_x) return kNoGround;  // cannot vouch beyond
  const int lo = column_of(a_ws), hi = column_of(b_ws), start = column_of(from_ws);
  auto line = [&](int i) { return surface_line(x0_ + (static_cast<float>(i) + 0.5f) * step_, reading); };
  const float first = line(start);
  float top = start >= lo && start <= hi ? first : kNoGround;
  // Either way from the start as far as [lo, hi] reaches, each stopping at a real riser.
  for (int dir : {-1, 1}) {
    const int last = dir > 0 ? hi : lo;
    float prev = first;
    for (int i = start + dir; (last - i) * dir >= 0; i += dir) {
      const float y = line(i);
      if (std::isnan(y)) continue;  // a gap is no jump
      if (!std::isnan(prev) && std::fabs(y - prev) > reading.ramp) break;
      if (i >= lo && i <= hi && !(top >= y)) top = y;
      prev = y;
    }
  }
  return top;
}

}  // namespace ossa
