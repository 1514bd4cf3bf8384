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
  // At most kMaxColumns columns: a wider window gets coarser ones.
  step_ = std::max(step_, (x1_ws - x0_ws) / static_cast<float>(kMaxColumns - 1));
  x0_ = x0_ws;
  top_ = top_ws;
  depth_ = std::max(depth, 0.0f);
  level_ = &level;
  revision_ = level.revision();
  const int n = std::clamp(static_cast<int>(std::ceil((x1_ws - x0_ws) / step_)), 1, kMaxColumns);
  // The columns' heights, in a scratch buffer (the profile keeps only the treads).
  thread_local std::vector<float> heights;
  heights.assign(n, kNoGround);
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
      if (!(heights[i] >= y)) heights[i] = y;
    }
  }
  // The treads: runs of columns at one height (a gap's columns are runs of one: NaN != NaN).
  treads_.clear();
  tread_of_.resize(n);
  for (int i = 0; i < n; ++i) {
    if (i == 0 || heights[i - 1] != heights[i]) treads_.push_back({i, i, heights[i]});
    treads_.back().last = i;
    tread_of_[i] = static_cast<std::uint16_t>(treads_.size() - 1);
  }
  treads_.shrink_to_fit();  // (kept until the next build; most profiles hold a few treads)
}

GroundProfile::Span GroundProfile::tread_at(int i, int most) const {
  // The columns either side of i at its height, no further than `most` columns to the left
  // and then `most` in all (as walking left first, then right, would find them).
  const Tread& tread = treads_[tread_of_[i]];
  Span t;
  t.first = std::max(tread.first, i - most);
  t.last = std::min(tread.last, t.first + most);
  return t;
}

// Does a narrow tread (height y, width w) join its neighbour (height yn, width wn; wide: flat
// ground) as a slope? Its rise is a slope's (SlopeReading), and no steeper than kMaxSlope from
// middle to middle (a wide neighbour's knot lies half the narrow tread's width inside it).
bool GroundProfile::joins(float y, float w, float yn, float wn, bool n_wide, const SlopeReading& reading) const {
  const bool under_foot = w < reading.foot && (n_wide || wn < reading.foot);
  if (std::fabs(yn - y) > (under_foot ? kUnderFootRiser : 1.0f) * reading.riser) return false;
  // A tread's width in columns is off by up to a column either way (a column holds the
  // highest box touching it): the run gets a column's benefit of the doubt.
  const float run = (n_wide ? w : 0.5f * (w + wn)) + step_;
  return std::fabs(yn - y) <= kMaxSlope * run;
}

float GroundProfile::surface_line(float x_ws, const SlopeReading& reading) const {
  const int i = column_of(x_ws);
  const float y = column(i);
  if (std::isnan(y)) return y;
  const int most = static_cast<int>(reading.tread / step_) + 1;
  const Span own = tread_at(i, most);
  const float width = static_cast<float>(own.last - own.first + 1) * step_;
  auto middle = [&](const Span& t) { return x0_ + (static_cast<float>(t.first + t.last + 1) * 0.5f) * step_; };
  if (width <= reading.tread) {
    // A narrow tread: the line from its middle to the knot on the side of x — the next
    // tread's middle, or, where that one is wide (the flat top of a hill, the floor of a
    // valley), a point half this tread's width inside it, so the line runs on into the flat
    // ground at the slope's own steepness and without a jump.
    const float mid = middle(own);
    const int dir = x_ws >= mid ? 1 : -1;
    const int j = dir > 0 ? own.last + 1 : own.first - 1;
    if (j < 0 || j >= size() || std::isnan(column(j))) return y;
    const float y2 = column(j);
    const Span next = tread_at(j, most);
    const float next_width = static_cast<float>(next.last - next.first + 1) * step_;
    const bool next_wide = next_width > reading.tread;
    if (!joins(y, width, y2, next_width, next_wide, reading)) return y;
    const float edge = x0_ + static_cast<float>(dir > 0 ? j : own.first) * step_;
    const float knot = next_wide ? edge + static_cast<float>(dir) * 0.5f * width : middle(next);
    return y + (x_ws - mid) / (knot - mid) * (y2 - y);
  }
  // A wide tread is flat, but for the half-width of a narrow neighbour that joins it as a
  // slope (the same knot seen from this side).
  const int near = static_cast<int>(0.5f * reading.tread / step_) + 1;
  for (int dir : {-1, 1}) {
    // The tread's end on this side, if it is within `near` columns.
    const int end = dir > 0 ? treads_[tread_of_[i]].last : treads_[tread_of_[i]].first;
    if ((end - i) * dir >= near) continue;
    const int k = end;
    const int j = k + dir;
    if (j < 0 || j >= size() || column(j) == y || std::isnan(column(j))) continue;
    const Span next = tread_at(j, most);
    const float next_width = static_cast<float>(next.last - next.first + 1) * step_;
    if (next_width > reading.tread) continue;  // two wide treads: a riser between them
    const float edge = x0_ + static_cast<float>(dir > 0 ? j : k) * step_;
    const float knot = edge - static_cast<float>(dir) * 0.5f * next_width;
    if ((x_ws - knot) * static_cast<float>(dir) <= 0.0f) continue;  // further in: flat
    const float y2 = column(j);
    if (!joins(y2, next_width, y, width, true, reading)) continue;
    return y + (x_ws - knot) / (middle(next) - knot) * (y2 - y);
  }
  return y;
}

int GroundProfile::flat_until(int i, int dir, const SlopeReading& reading) const {
  // As surface_line reads a wide tread: flat where both its ends are `near` columns or more
  // away; wide when tread_at finds more than `most` columns.
  const Tread& t = treads_[tread_of_[i]];
  const int most = static_cast<int>(reading.tread / step_) + 1;
  if (std::isnan(t.height) || t.last - t.first < most) return i;
  const int near = static_cast<int>(0.5f * reading.tread / step_) + 1;
  const int lo = t.first + near, hi = t.last - near;
  if (i < lo || i > hi) return i;
  return dir > 0 ? hi : lo;
}

float GroundProfile::largest_jump(float a_ws, float b_ws, const SlopeReading& reading) const {
  if (a_ws > b_ws) std::swap(a_ws, b_ws);
  auto line = [&](int i) { return surface_line(x0_ + (static_cast<float>(i) + 0.5f) * step_, reading); };
  float most = 0.0f;
  const int first = column_of(a_ws), end = column_of(b_ws);
  float prev = line(first);
  // (Columns up to flat_until read the same height: no jump among them.)
  for (int i = std::min(flat_until(first, 1, reading), end) + 1; i <= end; ++i) {
    const float y = line(i);
    if (!std::isnan(y) && !std::isnan(prev)) most = std::max(most, std::fabs(y - prev));
    prev = y;
    i = std::min(flat_until(i, 1, reading), end);
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
  // Columns i .. j (towards dir) all reading y: y counts where they meet [lo, hi]; returns j
  // (i for a gap, whose NaN counts nowhere).
  auto pass_flat = [&](int i, int dir, int last, float y) {
    const int j = dir > 0 ? std::min(flat_until(i, dir, reading), last) : std::max(flat_until(i, dir, reading), last);
    if (j != i && std::max(std::min(i, j), lo) <= std::min(std::max(i, j), hi) && !(top >= y)) top = y;
    return j;
  };
  // Either way from the start as far as [lo, hi] reaches, each stopping at a real riser.
  for (int dir : {-1, 1}) {
    const int last = dir > 0 ? hi : lo;
    float prev = first;
    if ((last - start) * dir < 0) continue;
    for (int i = pass_flat(start, dir, last, first) + dir; (last - i) * dir >= 0; i += dir) {
      const float y = line(i);
      if (std::isnan(y)) continue;  // a gap is no jump
      if (!std::isnan(prev) && std::fabs(y - prev) > reading.ramp) break;
      if (i >= lo && i <= hi && !(top >= y)) top = y;
      prev = y;
      i = pass_flat(i, dir, last, y);
    }
  }
  return top;
}

float GroundProfile::climbable_top(float from_ws, float a_ws, float b_ws, float lying_lo_ws, float lying_hi_ws, float from_height,
                                  float climb) const {
  if (a_ws > b_ws) std::swap(a_ws, b_ws);
  if (!spans(a_ws, b_ws) || from_ws < a_ws || from_ws > b_ws) return kNoGround;
  const int lo = tread_of_[column_of(a_ws)], hi = tread_of_[column_of(b_ws)], start = tread_of_[column_of(from_ws)];
  // The tread under from_ws, unless a gap or a wall itself, is where the walk starts.
  const float first = treads_[start].height;
  const bool first_ground = first <= from_height + climb;
  float top = first_ground ? first : kNoGround;
  for (int dir : {-1, 1}) {
    float prev = first_ground ? first : from_height;
    for (int t = start + dir; t >= lo && t <= hi; t += dir) {
      const Tread& tread = treads_[t];
      const float y = tread.height;
      if (std::isnan(y)) continue;  // a gap: bridged
      const bool lying = x0_ + static_cast<float>(tread.first) * step_ <= lying_hi_ws &&
                         x0_ + static_cast<float>(tread.last + 1) * step_ >= lying_lo_ws;
      if (y > std::max(prev, lying ? from_height : -INFINITY) + climb) break;  // a wall
      if (!(top >= y)) top = y;
      prev = y;
    }
  }
  return top;
}

namespace anim {

namespace {

// The ground profile: columns a tenth of the shortest foot-or-leg size wide (at least 5 mm,
// at most 2 cm); its window reaches this many body lengths plus strides either side and
// this many hip heights above and below the root.
constexpr float kProfileStepOfFoot = 0.1f, kProfileSpanStrides = 2.0f;
// ...of strides at least this many hip heights long (a walk's: a creature setting off needs
// no wider window at once).
constexpr float kProfileStrideOfHip = 2.5f, kProfileAboveOfHip = 1.0f, kProfileBelowOfHip = 4.0f;

}  // namespace

void refresh_ground_profile(const Level& level, const AnimRig& rig, const BodyFrame& body, float stride, GroundProfile& ground) {
  // The root need not be the middle of the body: a whole body length either side.
  const float reach = 2.0f * rig.body_half_length + rig.longest_contact_reach;
  const float span = reach + kProfileSpanStrides * std::max(stride, kProfileStrideOfHip * rig.hip_height);
  const float x0 = body.x_ws - span, x1 = body.x_ws + span;
  // Above the root: a hip height, or as high as the steepest slope rises over the body and a
  // leg's reach (a long, low body meets the hill ahead above its own height).
  const float above = std::max(kProfileAboveOfHip * rig.hip_height, GroundProfile::kMaxSlope * reach);
  // Below the root: a few hip heights; a legless body lying over lower ground, its length.
  const float below = rig.legs.empty() ? std::max(kProfileBelowOfHip * rig.hip_height, rig.body_half_length)
                                       : kProfileBelowOfHip * rig.hip_height;
  const float lo = body.root_y_ws - 0.75f * below;
  const float hi = body.root_y_ws + 0.5f * above;
  if (ground.covers(level, x0, x1, lo, hi)) return;
  float size = 1e30f;
  for (const RigLeg& leg : rig.legs) size = std::min(size, std::max(leg.foot_length, 0.25f * leg.reach));
  if (rig.legs.empty()) size = rig.hip_height;
  const float step = std::clamp(kProfileStepOfFoot * size, 0.005f, 0.02f);
  // Twice the window, so that it lasts for a while.
  ground.build(level, x0 - span, x1 + span, body.root_y_ws + above, above + below, step);
}

}  // namespace anim

}  // namespace ossa
