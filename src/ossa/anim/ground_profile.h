#pragma once
// Ground profile (DESIGN.md §7; stage 1 of Animator::update): the level's top surface around the creature, from
// behind its hind feet to beyond its next landings, sampled into a 1D height profile. Column
// i covers [x0 + i·step, x0 + (i+1)·step] (closed) and holds the highest box top that touches
// it between top - depth and top (exactly what Level::ground_height_below answers for that
// span), or no ground (a gap). Risers are jumps in height between columns; a run of small
// steps reads as a slope (surface_line), so a tile hill is walked like a ramp.
//
// The animator keeps one per creature and refreshes it when the creature nears the edge of
// its window, moves up or down past its margin, or the level changes (Level::revision): the
// same as sampling it every tick, at a fraction of the cost. Later stages ask the profile about
// the surface's shape; exact clearance checks (does a foot or a bone cut a box) still ask the
// level. World space (_ws), metres.
//
// Storage: the profile keeps its treads (runs of columns at one height; each gap column is a
// tread of its own) and, per column, the index of its tread in two bytes — about 2 bytes per
// column on ground of few treads instead of a height and two run ends per column (12 bytes),
// which made the profile most of a creature's memory (issue 31: 16 KB of a horse's 23 KB).
// A profile holds at most kMaxColumns columns; a wider window gets coarser columns.

#include <cstddef>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "ossa/anim/anim_state.h"
#include "ossa/level/level.h"

namespace ossa {

// How the profile is read as a slope (surface_line): treads up to `tread` wide whose rises are
// up to `riser` high — or, between treads narrower than `foot` (a foot cannot stand on one),
// up to GroundProfile::kUnderFootRiser risers high — and no steeper than
// GroundProfile::kMaxSlope make a slope; a jump of more than `ramp` between neighbouring
// columns of that reading is a riser. Metres.
struct SlopeReading {
  float tread = 0.0f;
  float riser = 0.0f;
  float foot = 0.0f;
  float ramp = 0.0f;
};

class GroundProfile {
 public:
  // Samples [x0_ws, x1_ws] every `step` metres (> 0), boxes whose tops lie in
  // [top_ws - depth, top_ws].
  void build(const Level& level, float x0_ws, float x1_ws, float top_ws, float depth, float step);

  // Does the profile hold [x0_ws, x1_ws] with its vertical band around [lo_ws, hi_ws], sampled
  // from this revision of the level?
  bool covers(const Level& level, float x0_ws, float x1_ws, float lo_ws, float hi_ws) const {  // (inline: every tick)
    return !tread_of_.empty() && level_ == &level && revision_ == level.revision() && x0_ws >= x0_ &&
           x1_ws <= x0_ + static_cast<float>(size()) * step_ && hi_ws <= top_ && lo_ws >= top_ - depth_;
  }

  static constexpr int kMaxColumns = 65535;  // (tread indices are 16 bits)

  bool empty() const { return tread_of_.empty(); }
  // Its arrays, for Animator::prefetch.
  std::span<const std::byte> tread_bytes() const { return std::as_bytes(std::span(treads_)); }
  std::span<const std::byte> column_bytes() const { return std::as_bytes(std::span(tread_of_)); }
  int size() const { return static_cast<int>(tread_of_.size()); }
  int tread_count() const { return static_cast<int>(treads_.size()); }
  // Heap bytes the profile holds.
  std::size_t bytes() const { return treads_.capacity() * sizeof(Tread) + tread_of_.capacity() * sizeof(std::uint16_t); }
  float step() const { return step_; }
  float x0() const { return x0_; }
  float top() const { return top_; }
  const Level* level() const { return level_; }  // the level it was built from (null: none yet)
  // Column i's ground height, or NaN where there is none.
  float column(int i) const { return treads_[tread_of_[i]].height; }
  // Does the profile hold the columns of [a_ws, b_ws]?
  bool spans(float a_ws, float b_ws) const {
    return !tread_of_.empty() && a_ws >= x0_ && b_ws <= x0_ + static_cast<float>(size() - 1) * step_;
  }
  // The highest ground no higher than `below` in the columns holding [a_ws, b_ws] (NaN: none),
  // a tread at a time.
  float highest(float a_ws, float b_ws, float below = INFINITY) const {
    float h = NAN;
    for (int t = tread_of_[column_of(a_ws)], end = tread_of_[column_of(b_ws)]; t <= end; ++t) {
      const float y = treads_[t].height;
      if (y <= below && !(y <= h)) h = y;
    }
    return h;
  }
  // Is the ground over [a_ws, b_ws] one height with no gap (into *height)? (Inside the profile.)
  bool level_over(float a_ws, float b_ws, float* height) const {
    const int first = tread_of_[column_of(a_ws)], last = tread_of_[column_of(b_ws)];
    const float h = treads_[first].height;
    for (int t = first; t <= last; ++t) {
      if (!(treads_[t].height == h)) return false;  // (NaN: a gap)
    }
    *height = h;
    return true;
  }
  // The column holding x (clamped to the profile).
  int column_of(float x_ws) const {
    // floor, then clamp to the columns: compared before the floor (t < 0 exactly when
    // floor(t) < 0, t >= n - 1 exactly when floor(t) >= n - 1, and between them truncation is
    // the floor), which spares the floor's long sequence; NaN converts as before.
    const float t = (x_ws - x0_) / step_;
    const int last = size() - 1;
    if (t < 0.0f) return 0;
    if (t >= static_cast<float>(last)) return last;
    return static_cast<int>(t);
  }
  // May the level have ground higher than y over [a_ws, b_ws] (a box top in y .. up_to)? False
  // only when every column touching the span is known and no higher: a cheap test before an
  // exact level query for tops up to up_to (a span or a band the profile does not hold gives
  // true).
  // (Inline: asked a few times per girdle and tick.)
  bool may_rise_above(float a_ws, float b_ws, float y, float up_to) const {
    if (tread_of_.empty() || a_ws < x0_ || b_ws > x0_ + static_cast<float>(size() - 1) * step_ || up_to > top_) return true;
    const int last = column_of(b_ws);
    for (int t = tread_of_[column_of(a_ws)], end = tread_of_[last]; t <= end; ++t) {
      if (treads_[t].height > y) return true;  // (NaN, no ground, is not higher)
    }
    return false;
  }

  // The surface under x read as a slope: the height of the line through the middles of the
  // treads either side (a tread is a run of columns at one height), when x's tread is narrower
  // than reading.tread, the rise to the next one a slope's (SlopeReading) and the line no
  // steeper than kMaxSlope; else the column's own height (a real step, or a steep flight of small
  // ones, keeps its risers). Where the next tread is wide (the flat top of a tile hill, the
  // floor of a valley) the line runs half a tile into it, so the slope meets the flat without
  // a jump or a steeper piece. NaN over a gap.
  static constexpr float kMaxSlope = 0.7f;  // rise over run, about 35°
  static constexpr float kUnderFootRiser = 2.0f;
  float surface_line(float x_ws, const SlopeReading& reading) const;

  // The largest jump (metres) between neighbouring columns over [a_ws, b_ws] of the surface
  // read as a slope (surface_line): 0 on flat ground and on a
  // tile slope read as a ramp, a riser's height at a real step; a gap counts as no jump.
  float largest_jump(float a_ws, float b_ws, const SlopeReading& reading) const;

  // The surface read as a slope (surface_line), walked from x = from_ws either way over
  // [a_ws, b_ws] for as long as no jump between neighbouring columns exceeds reading.ramp (a real
  // riser; a gap is none): its highest point over the part of [a_ws, b_ws] walked. NaN when
  // the walk ends before [a_ws, b_ws], finds no ground there, or the range leaves the
  // profile. What the legs climb without a step (the hill ahead) — the wall sweep's floor.
  float slope_top(float from_ws, float a_ws, float b_ws, const SlopeReading& reading) const;

  // The ground as it stands (no slope reading), walked a tread at a time from x = from_ws
  // either way over [a_ws, b_ws], for as long as no tread rises more than `climb` above the last
  // ground walked (a gap is bridged, a drop taken) — or, over [lying_lo_ws, lying_hi_ws] (where
  // the body lies now), above `from_height` (the ground it lies on now: the ledge a body came
  // down from stays ground under its tail, and under its head once it turns): the highest tread
  // walked. What a body lying along the ground can have under it without climbing a wall (a
  // legless body nearing a level's end wall). NaN when the range leaves the profile or holds no
  // ground the walk reaches.
  float climbable_top(float from_ws, float a_ws, float b_ws, float lying_lo_ws, float lying_hi_ws, float from_height,
                      float climb) const;

 private:
  struct Span {
    int first = 0, last = 0;  // columns
  };
  struct Tread {
    int first = 0, last = 0;  // its columns
    float height = 0.0f;      // NaN: a gap (one column)
  };
  Span tread_at(int i, int most) const;
  // The furthest column from i towards dir (±1) up to which surface_line is column i's own
  // height: i in the inside of a wide tread (more than half a narrow tread from its ends,
  // where a neighbour's slope may bend the line) gives that inside's end; any other i gives i.
  // Lets largest_jump and slope_top pass flat ground a tread at a time, not a column.
  int flat_until(int i, int dir, const SlopeReading& reading) const;
  bool joins(float y, float w, float yn, float wn, bool n_wide, const SlopeReading& reading) const;

  std::vector<Tread> treads_;            // left to right
  std::vector<std::uint16_t> tread_of_;  // per column: its tread
  float x0_ = 0.0f, step_ = 1.0f, top_ = 0.0f, depth_ = 0.0f;
  std::uint64_t revision_ = 0;
  const Level* level_ = nullptr;
};

namespace anim {

// Stage 1: keeps `ground` covering the creature at `body`: the body, a leg's reach and
// kProfileSpanStrides strides (of `stride` metres, at least a walk's) either side, from a hip
// height above the root to four below, in columns a tenth of the shortest foot or quarter leg
// (5 mm to 2 cm). Rebuilt, twice that window wide, only when the creature nears its edge or
// the level changed.
void refresh_ground_profile(const Level& level, const AnimRig& rig, const BodyFrame& body, float stride, GroundProfile& ground);

}  // namespace anim

}  // namespace ossa
