#pragma once
// Level probes — the exact geometric questions the animator's stages ask of the level (the
// ground profile answers the approximate ones): ground below a span, whether a polyline of
// bones cuts a collider, how far a segment must rise to clear, and what may rise near a foot.
// Inputs and outputs in world space (_ws), metres.

#include <cmath>
#include <optional>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "ossa/level/level.h"

namespace ossa::anim {

// Level::ground_height_below for spans and drops computed from a creature's proportions: any
// body a genome may describe (a shoulder behind its girdle, a slack below zero) gives a span
// in either order and a drop that may come out negative, which mean the same span and no drop.
std::optional<GroundHit> ground_below(const Level& level, float x0, float x1, float from_y, float max_drop);

// The ground a body over [lo, hi] stands on with its root at x: the highest box top below
// `from_y` (down to max_drop below it) in that span — with a finite `climb` (a legless body's
// AnimRig::crawl_climb; INFINITY for a body on legs) only what is reached from the ground under
// x by risers no higher than climb (GroundProfile::climbable_top: a flight of steps is ground,
// an end wall beside its tail is not). nullopt: no ground in the span.
std::optional<float> standing_ground(const Level& level, float x, float lo, float hi, float from_y, float max_drop, float climb);

// Where a body may stand near x: the root x nearest to `x` at which the body's extent
// [x + back, x + front] (world offsets, back < front), standing on its standing_ground (with
// `climb`) and rising `top` above it, meets no box — a wall taller than the search, a wall
// higher than it climbs, or a platform at the body's height. Tries pushing the body clear to
// either side and takes the shorter shift (a side with no ground under the body is no place);
// `x` itself when it fits, or when no place within `reach` does.
float clear_standing_x(const Level& level, float x, float back, float front, float top, float from_y, float max_drop,
                       float climb, float reach, std::vector<int>& hits);

// Does the polyline p[0] - p[1] - ... pass through the interior of a collider (shrunk by a
// little under a millimetre, 0.99 mm)? One query for its bounds, then a Liang-Barsky clip per segment and box.
// Only colliders whose bottom lies at or above `above_y` and whose top lies above `top_over`
// count (the defaults: every one). `hits` is scratch.
bool polyline_hits_level(const Level& level, const glm::vec2* p, int n, std::vector<int>& hits, float above_y = -INFINITY,
                         float top_over = -INFINITY);

// The least height a point at x must have to stay `keep` above the ground within `half` of it
// (boxes whose tops lie in [from_y - max_drop, from_y]): the ground within `half` counts in
// full, the ground up to `half` further away less and less (its claim fades to `fade` below
// its top), so that the height changes smoothly as the point moves sideways past the edge of a
// step instead of jumping by the step's height. -1e30 where there is no ground.
float keep_out_height(const Level& level, float x, float half, float keep, float fade, float from_y, float max_drop,
                      std::vector<int>& hits);

// The x-range [*x0, *x1] of the part of segment a-b whose height lies in (y0, y1); false when
// none does.
bool segment_x_within(glm::vec2 a, glm::vec2 b, float y0, float y1, float* x0, float* x1);

// How far the segment a-b must rise (straight up) to leave every box it cuts whose top is no
// higher than max_top (a higher one is a wall, which rising does not clear).
float raise_to_clear(glm::vec2 a, glm::vec2 b, const Level& level, std::vector<int>& hits, float max_top = INFINITY);

// What a limb near a foot can meet: colliders whose tops are at most `base` (the ground the
// foot stands or steps on) and, above that, none higher than `top`. A limb entirely above
// both meets nothing, so the level need not be asked. The default knows nothing.
struct Clearance {
  float base = -1e30f;  // world y, metres
  float top = 1e30f;    // world y, metres
  bool clear_above(float min_y) const { return min_y >= base - 0.5e-3f && min_y >= top + 1e-3f; }
};
// The clearance of the colliders in `region` above `base`.
Clearance clearance_in(const Box& region, float base, const Level& level, std::vector<int>& hits);

}  // namespace ossa::anim
