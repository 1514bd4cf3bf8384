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

float GroundProfile::surface_line(float x_ws, float tread, float riser) const {
  const int i = column_of(x_ws);
  const float y = heights_[i];
  if (std::isnan(y)) return y;
  // The tread under x: the columns either side at the same height (walked no further than a
  // tread may be wide).
  const int most = static_cast<int>(tread / step_) + 1;
  int a = i, b = i;
  while (a > 0 && heights_[a - 1] == y && b - a < most) --a;
  while (b + 1 < size() && heights_[b + 1] == y && b - a < most) ++b;
  const float width = static_cast<float>(b - a + 1) * step_;
  if (width > tread) return y;
  const float mid = x0_ + (static_cast<float>(a + b + 1) * 0.5f) * step_;
  // The neighbouring tread on the side of x from the middle.
  const bool right = x_ws >= mid;
  const int j = right ? b + 1 : a - 1;
  if (j < 0 || j >= size() || std::isnan(heights_[j]) || std::fabs(heights_[j] - y) > riser) return y;
  const float y2 = heights_[j];
  int c = j, d = j;
  while (c > 0 && heights_[c - 1] == y2 && d - c < most) --c;
  while (d + 1 < size() && heights_[d + 1] == y2 && d - c < most) ++d;
  if (static_cast<float>(d - c + 1) * step_ > tread) return y;
  const float mid2 = x0_ + (static_cast<float>(c + d + 1) * 0.5f) * step_;
  if (std::fabs(y2 - y) > kMaxSlope * std::fabs(mid2 - mid)) return y;  // too steep: steps
  const float t = (x_ws - mid) / (mid2 - mid);
  return y + t * (y2 - y);
}

float GroundProfile::largest_jump(float a_ws, float b_ws, float tread, float riser) const {
  if (a_ws > b_ws) std::swap(a_ws, b_ws);
  float most = 0.0f;
  float prev = surface_line(x0_ + (static_cast<float>(column_of(a_ws)) + 0.5f) * step_, tread, riser);
  for (int i = column_of(a_ws) + 1, end = column_of(b_ws); i <= end; ++i) {
    const float y = surface_line(x0_ + (static_cast<float>(i) + 0.5f) * step_, tread, riser);
    if (!std::isnan(y) && !std::isnan(prev)) most = std::max(most, std::fabs(y - prev));
    prev = y;
  }
  return most;
}


}  // namespace ossa
