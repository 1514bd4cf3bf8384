#pragma once
// Ground profile (DESIGN.md §7, stage 1): the level's top surface around the creature, from
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

#include <cstdint>
#include <vector>

#include "ossa/level/level.h"

namespace ossa {

class GroundProfile {
 public:
  // Samples [x0_ws, x1_ws] every `step` metres (> 0), boxes whose tops lie in
  // [top_ws - depth, top_ws].
  void build(const Level& level, float x0_ws, float x1_ws, float top_ws, float depth, float step);

  // Does the profile hold [x0_ws, x1_ws] with its vertical band around [lo_ws, hi_ws], sampled
  // from this revision of the level?
  bool covers(const Level& level, float x0_ws, float x1_ws, float lo_ws, float hi_ws) const;

  bool empty() const { return heights_.empty(); }
  int size() const { return static_cast<int>(heights_.size()); }
  float step() const { return step_; }
  float x0() const { return x0_; }
  float top() const { return top_; }
  // Column i's ground height, or NaN where there is none.
  float column(int i) const { return heights_[i]; }
  // The column holding x (clamped to the profile).
  int column_of(float x_ws) const;

  // The surface under x read as a slope: the height of the line through the middles of the
  // treads either side (a tread is a run of columns at one height), when the two treads are
  // each narrower than `tread` metres, the rise between them at most `riser` metres and the
  // line no steeper than kMaxSlope; else the column's own height (a real step, or a steep
  // flight of small ones, keeps its risers). NaN over a gap.
  static constexpr float kMaxSlope = 0.7f;  // rise over run, about 35°
  float surface_line(float x_ws, float tread, float riser) const;

  // The largest jump (metres) between neighbouring columns over [a_ws, b_ws] of the surface
  // read as a slope (surface_line with the same tread and riser): 0 on flat ground and on a
  // tile slope read as a ramp, a riser's height at a real step; a gap counts as no jump.
  float largest_jump(float a_ws, float b_ws, float tread, float riser) const;

 private:
  std::vector<float> heights_;
  float x0_ = 0.0f, step_ = 1.0f, top_ = 0.0f, depth_ = 0.0f;
  std::uint64_t revision_ = 0;
  const Level* level_ = nullptr;
};

}  // namespace ossa
