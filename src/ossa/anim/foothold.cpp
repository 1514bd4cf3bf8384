#include "ossa/anim/foothold.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/animator_params.h"
#include "ossa/anim/ground_profile.h"

namespace ossa::anim {

namespace {

// find_landing tries at most this many candidate spots.
constexpr int kLandingCandidates = 600;
// Candidates step back by this fraction of the stride (5 mm at least) and forward by a quarter
// of that, from at most kShortestAheadOfStride behind the planned spot to kMaxLongerOfStride
// beyond it.
constexpr float kLandingStepOfStride = 0.025f;
constexpr float kMaxLongerOfStride = 0.25f;
constexpr float kShortestAheadOfStride = 0.05f;

// Down a step the shin comes from above and behind: the ground within this fraction of the
// girdle's rest height behind a landing must stay below the line rising at kShinSlope from
// the foot, the ankle's height (or the foot's box, if more) above it. The
// ground is read from the profile as a slope where it is a run of small steps (foothold.h),
// so a tile hill is walked down like a ramp, and a real step keeps its riser.
constexpr float kRiserGapOfRest = 0.25f;
constexpr float kShinSlope = 1.0f;

// Would a foot landing at height y with its back edge at `back` have the shin cut a riser
// behind it?
bool riser_behind(const FootholdInputs& in, const RigLeg& info, float rest_height, const SlopeReading& reading, float back,
                  float y, float up) {
  const float gap = kRiserGapOfRest * rest_height;
  const int behind = -in.body.facing;
  const float lo = std::min(back, back + behind * gap), hi = std::max(back, back + behind * gap);
  const GroundProfile& ground = in.ctx.ground;
  if (!ground.covers(in.ctx.level, lo, hi, y, y + up)) {
    // Outside the profile (a level edited under a standing creature is re-sampled on the next
    // tick): no ground between a tread's height and a step above it.
    return in.ctx.level.overlaps(Box{{lo, y + in.ctx.rig.scale.foot_box}, {hi, y + up}});
  }
  // (A tenth of the rest height, as it was, let a 2 cm step right behind a hand stand under
  // random creature 25's forearm, 1.1 mm into its corner.)
  const float tol = std::max(info.ankle_rel_ms.y, in.ctx.rig.scale.foot_box);
  // A real riser behind (a step, not a slope's tile): no ground between the tread's height and
  // a step above it, as the shin would cut its edge.
  if (ground.largest_jump(lo, hi, reading) > reading.riser) return in.ctx.level.overlaps(Box{{lo, y + in.ctx.rig.scale.foot_box}, {hi, y + up}});
  const float step = ground.step();
  for (int i = ground.column_of(lo), end = ground.column_of(hi); i <= end; ++i) {
    if (std::isnan(ground.column(i))) continue;
    const float x_lo = ground.x0() + static_cast<float>(i) * step;
    const float d = std::max(0.0f, behind > 0 ? x_lo - back : back - (x_lo + step));
    const float surface = ground.surface_line(x_lo + 0.5f * step, reading);
    if (surface > y + tol + kShinSlope * d) return true;
  }
  return false;
}

}  // namespace

FootSpan foot_span_ws(const RigLeg& leg, int facing) {
  const float a = facing * std::min({0.0f, leg.ankle_rel_ms.x, leg.tip_rel_ms.x});
  const float b = facing * std::max({0.0f, leg.ankle_rel_ms.x, leg.tip_rel_ms.x});
  return {std::min(a, b), std::max(a, b)};
}

FootSpan flesh_span_ws(const RigLeg& leg, int facing) {
  const FootSpan span = foot_span_ws(leg, facing);
  return facing > 0 ? FootSpan{span.lo - leg.flesh_back, span.hi + leg.flesh_front}
                    : FootSpan{span.lo - leg.flesh_front, span.hi + leg.flesh_back};
}

float foot_height(const RigScale& scale, const RigLeg& leg) { return std::max({scale.foot_box, leg.ankle_rel_ms.y, 0.3f * leg.foot_length}); }

FootSpan support_span_ws(const RigLeg& leg, int facing) {
  const float a = facing * std::min(0.0f, leg.tip_rel_ms.x), b = facing * std::max(0.0f, leg.tip_rel_ms.x);
  return {std::min(a, b), std::max(a, b)};
}

SlopeReading slope_reading(const GroundProfile& ground, float rest_height, float foot_length) {
  SlopeReading r;
  r.tread = kSlopeTreadOfRest * rest_height;
  r.riser = kRiserOfRest * rest_height;
  r.foot = foot_length;
  // A ramp (or a tile slope read as one) rises by at most kMaxSlope per column; a larger jump
  // is a riser, however small (uneven ground of wide treads is not a slope).
  r.ramp = std::max(1.5f * GroundProfile::kMaxSlope * ground.step(), 0.5f * r.riser);
  return r;
}

SlopeReading girdle_slope_reading(const AnimContext& ctx, int girdle) {
  const RigGirdle& g = ctx.rig.girdles[girdle];
  float foot = 1e30f;
  for (int leg : g.legs) foot = std::min(foot, ctx.rig.legs[leg].foot_length);
  return slope_reading(ctx.ground, g.rest_height, g.legs.empty() ? 0.0f : foot);
}

SlopeReading body_slope_reading(const AnimContext& ctx) {
  if (ctx.rig.girdles.empty()) {
    // A legless body lies on the ground along its length and crawls over any rise the wall
    // sweep lets it (max_step_up of its height): treads up to half its half-length, rises up
    // to that step, are its slope.
    SlopeReading r = slope_reading(ctx.ground, ctx.rig.hip_height, 0.0f);
    r.tread = kSlopeTreadOfRest * ctx.rig.body_half_length;
    r.riser = ctx.params.max_step_up * ctx.rig.hip_height;
    r.ramp = std::max(r.ramp, 0.5f * r.riser);
    return r;
  }
  int lowest = 0;
  for (size_t g = 1; g < ctx.rig.girdles.size(); ++g) {
    if (ctx.rig.girdles[g].rest_height < ctx.rig.girdles[lowest].rest_height) lowest = static_cast<int>(g);
  }
  return girdle_slope_reading(ctx, lowest);
}

bool foot_fits(const FootholdInputs& in, int leg, glm::vec2 contact_ws, bool with_flesh) {
  const RigLeg& info = in.ctx.rig.legs[leg];
  const FootSpan span = with_flesh ? flesh_span_ws(info, in.body.facing) : foot_span_ws(info, in.body.facing);
  const RigScale& scale = in.ctx.rig.scale;
  const Box foot_box{{contact_ws.x + span.lo - scale.fit_side, contact_ws.y + scale.fit_lift},
                     {contact_ws.x + span.hi + scale.fit_side, contact_ws.y + foot_height(scale, info)}};
  return !in.ctx.level.overlaps(foot_box);
}

bool shin_clears_riser(const FootholdInputs& in, int leg, glm::vec2 contact_ws) {
  const RigLeg& info = in.ctx.rig.legs[leg];
  const FootSpan span = foot_span_ws(info, in.body.facing);
  const float back = contact_ws.x + (in.body.facing > 0 ? span.lo - in.ctx.rig.scale.landing_side : span.hi + in.ctx.rig.scale.landing_side);
  return !riser_behind(in, info, in.ctx.rig.girdles[info.girdle].rest_height, girdle_slope_reading(in.ctx, info.girdle), back,
                       contact_ws.y, step_limits(in, leg, contact_ws).up);
}

bool reaches(const FootholdInputs& in, int leg, glm::vec2 p_ws, float reach_use) {
  const RigLeg& info = in.ctx.rig.legs[leg];
  return glm::length(in.body.to_fs(p_ws) - in.body.to_fs(in.body.girdle_ws(in.ctx.rig, info.girdle))) <=
         reach_use * kFootReach * info.contact_reach;
}

namespace {

// The nearest spot whose flesh fits too, else the nearest whose bones do.
bool nearest_fit_within(const FootholdInputs& in, int leg, glm::vec2 near_ws, glm::vec2* spot, bool in_reach, float reach_use) {
  // Step by step (RigScale::search_step) either way, up to half a leg's length, on ground within
  // a step (one every leg pair could follow up, as in find_landing).
  const AnimRig& rig = in.ctx.rig;
  const RigLeg& info = rig.legs[leg];
  const float up = in.ctx.params.max_step_up * rig.climb_height;
  const float down = in.ctx.params.max_step_down * rig.girdles[info.girdle].rest_height;
  // A flat foot stands on the highest ground under its sole.
  const float sole = rig.flat_contact ? in.body.facing * info.foot_length : 0.0f;
  const RigScale& scale = rig.scale;
  const float sole_lo = std::min(sole, 0.0f) - scale.sole_side, sole_hi = std::max(sole, 0.0f) + scale.sole_side;
  const int n = std::max(1, static_cast<int>(0.5f * (info.reach + info.foot_length) / scale.search_step));
  bool bones_only = false;
  for (int k = 0; k <= 2 * n; ++k) {
    const float x = near_ws.x + scale.search_step * static_cast<float>(k % 2 == 0 ? k / 2 : -(k + 1) / 2);
    auto hit = ground_below(in.ctx.level, x + sole_lo, x + sole_hi, near_ws.y + up, up + down);
    if (!hit) continue;
    const glm::vec2 p(x, hit->height_ws);
    if (in_reach && !reaches(in, leg, p, reach_use)) continue;
    if (!foot_fits(in, leg, p)) continue;
    const bool flesh_fits = foot_fits(in, leg, p, true);
    if (flesh_fits || !bones_only) *spot = p;
    if (flesh_fits) return true;
    bones_only = true;
  }
  return bones_only;
}

}  // namespace

bool nearest_fit(const FootholdInputs& in, int leg, glm::vec2 near_ws, glm::vec2* spot, bool prefer_reach, float reach_use) {
  // In reach first, if asked; of those, one where the foot's flesh clears the level too
  // (as find_landing).
  return (prefer_reach && nearest_fit_within(in, leg, near_ws, spot, true, reach_use)) ||
         nearest_fit_within(in, leg, near_ws, spot, false, reach_use);
}

void note_ledge(const AnimContext& ctx, FootState& f, float ledge_y) {
  const float up = ctx.params.max_step_up * ctx.rig.climb_height;
  const float from_y = std::isnan(ledge_y) ? f.stood_y : ledge_y;
  f.stood_y = f.pos_ws.y;
  if (from_y - f.pos_ws.y > up) {
    f.ledge_y = from_y;
  } else if (!std::isnan(f.ledge_y) && f.pos_ws.y + up >= f.ledge_y) {
    f.ledge_y = NAN;
  }
}

StepLimits step_limits(const FootholdInputs& in, int leg, glm::vec2 foot_ws) {
  const AnimRig& rig = in.ctx.rig;
  const RigGirdle& girdle = rig.girdles[rig.legs[leg].girdle];
  StepLimits l;
  l.up = in.ctx.params.max_step_up * rig.climb_height;
  l.down = in.ctx.params.max_step_down * girdle.rest_height;
  // A step down counts from the foot, or from the ground its girdle stands over when the foot
  // stands higher (a foot left up on a step steps back down as far as its girdle stands).
  l.lowest = std::min(foot_ws.y, in.body.girdle_ws(rig, rig.legs[leg].girdle).y - girdle.rest_height) - l.down;
  l.top = foot_ws.y + l.up;
  const float ledge = in.feet ? in.feet->of_leg(leg).ledge_y : NAN;
  if (!std::isnan(ledge) && ledge > l.top) {
    const SlopeReading reading = girdle_slope_reading(in.ctx, rig.legs[leg].girdle);
    for (size_t j = 0; j < rig.legs.size(); ++j) {
      const FootState& o = in.feet->of_leg(static_cast<int>(j));
      const glm::vec2 on = step_from(o);  // where it stands, or stepped from
      if (o.air || on.y + l.up <= l.top || std::fabs(on.y - ledge) > l.up) continue;
      // From this foot to the whole of the other one (its toe may stand out over the edge).
      const FootSpan span = foot_span_ws(rig.legs[j], in.body.facing);
      const float a = std::min(on.x + span.lo, foot_ws.x), b = std::max(on.x + span.hi, foot_ws.x);
      if (in.ctx.ground.largest_jump(a, b, reading) > l.up) l.top = on.y + l.up;
    }
  }
  return l;
}

bool find_landing(const FootholdInputs& in, int leg, glm::vec2 foot_ws, float x_wanted, glm::vec2* landing) {
  const AnimRig& rig = in.ctx.rig;
  const RigLeg& info = rig.legs[leg];
  const RigGirdle& girdle = rig.girdles[info.girdle];
  const int facing = in.body.facing;
  const auto [up, down, lowest, top] = step_limits(in, leg, foot_ws);
  const FootSpan span = foot_span_ws(info, facing);
  const RigScale& scale = rig.scale;
  const float span_lo = span.lo - scale.landing_side, span_hi = span.hi + scale.landing_side;
  // The foot's box with its flesh (flesh_span_ws).
  const FootSpan flesh = flesh_span_ws(info, facing);
  const float flesh_lo = flesh.lo - scale.landing_side, flesh_hi = flesh.hi + scale.landing_side;
  const bool has_flesh = flesh.lo != span.lo || flesh.hi != span.hi;
  // What bears on the ground must have ground under it within the step limits (a tip does not
  // stand on the ground under its ankle: a slanted hoof bone at a gap's edge would stand over
  // the gap). The landing's height is still the highest ground under the whole foot.
  const FootSpan support = support_span_ws(info, facing);
  const float support_lo = support.lo - scale.landing_side, support_hi = support.hi + scale.landing_side;
  const float height = foot_height(scale, info);
  const SlopeReading reading = girdle_slope_reading(in.ctx, info.girdle);
  const float stride = in.stride;
  const float stepx = std::max(kLandingStepOfStride * stride, 0.005f);
  const float shortest = facing * (x_wanted - foot_ws.x) - kShortestAheadOfStride * stride;
  const float longest = kMaxLongerOfStride * stride;
  // A foot left down a ledge its body stands on (step_limits) looks for a landing back up on
  // the ledge first (ground within a step of it), and only then below it.
  const bool ledge = top > foot_ws.y + up;
  // The slope is walked from the ground under the foot's contact, which must be the ground the
  // foot stands on: a contact out over a ledge's edge, its heel on the top, read the ground
  // below the edge as its slope (the frog's forefoot stepped 1 m down drops.json's ledge, a
  // 10 g bird's foot at a riser's foot up a riser taller than its step). Asked once, if at all.
  // (A copy of the step: clang 14 lets no lambda capture a structured binding.)
  int slope_from_foot = -1;
  auto on_slope = [&, step_up = up] {
    if (slope_from_foot < 0) slope_from_foot = std::fabs(in.ctx.ground.surface_line(foot_ws.x, reading) - foot_ws.y) <= step_up;
    return slope_from_foot == 1;
  };
  // A landing whose flesh clears the level too first; where there is none (treads narrower
  // than the foot and its flesh), the first one whose bones do.
  for (int pass = ledge ? 0 : 1; pass < 2; ++pass) {
    const float floor_y = pass == 0 ? top - 2.0f * up : -1e30f;
    bool bones_only = false;
    for (int k = 0; k <= kLandingCandidates; ++k) {
      const int n = (k + 1) / 2;
      const float d = k % 2 == 1 ? -stepx * static_cast<float>(n) : 0.25f * stepx * static_cast<float>(n);
      if (-d > shortest) {
        if (k % 2 == 1) continue;
        if (d > longest) break;
      } else if (k % 2 == 0 && d > longest) {
        continue;
      }
      if (d > longest) continue;
      const float x = x_wanted + facing * d;
      // Up or down a slope (a tile hill read as a ramp, with no real riser between the foot and
      // the landing) a stride may climb or descend further than a step: the step limits count
      // from the slope's height at the landing.
      // (Asked only when the plain step limits find no ground there.)
      float slope_top = top, bottom = lowest;
      auto hit = ground_below(in.ctx.level, x + span_lo, x + span_hi, top, top - lowest);
      if (!hit && on_slope()) {
        const float along = in.ctx.ground.slope_top(foot_ws.x, x + span_lo, x + span_hi, reading);
        if (!std::isnan(along)) {
          slope_top = std::max(top, along + up);
          bottom = std::min(lowest, along - down);
          hit = ground_below(in.ctx.level, x + span_lo, x + span_hi, slope_top, slope_top - bottom);
        }
      }
      if (!hit || hit->height_ws < floor_y) continue;
      if ((support_lo > span_lo || support_hi < span_hi) &&
          !ground_below(in.ctx.level, x + support_lo, x + support_hi, slope_top, slope_top - bottom)) {
        continue;
      }
      const float y = hit->height_ws;
      const Box foot_box{{x + span_lo + scale.landing_inset, y + scale.landing_inset}, {x + span_hi - scale.landing_inset, y + height}};
      if (in.ctx.level.overlaps(foot_box)) continue;
      // Nothing between the foot and its landing rises more than a step above both: the foot
      // would have to be lifted over a wall (the swing could raise it, the leg could not).
      const float wall = std::max(foot_ws.y, y) + up;
      const float between_lo = std::min(foot_ws.x, x) + 0.001f, between_hi = std::max(foot_ws.x, x) - 0.001f;
      if (between_lo < between_hi && in.ctx.level.overlaps(Box{{between_lo, wall}, {between_hi, wall + 0.001f}})) continue;
      // Down a step the shin comes from above and behind: keep the foot off the riser it steps
      // down from, or the shin cuts the step's edge.
      const bool clear_behind = !riser_behind(in, info, girdle.rest_height, reading, facing > 0 ? x + span_lo : x + span_hi, y, up);
      if (!clear_behind && k + 1 < kLandingCandidates) continue;
      const Box flesh_box{{x + flesh_lo + scale.landing_inset, y + scale.landing_inset}, {x + flesh_hi - scale.landing_inset, y + height}};
      const bool flesh_clear = !has_flesh || (clear_behind && !in.ctx.level.overlaps(flesh_box));
      if (flesh_clear || !bones_only) *landing = {x, y};
      if (flesh_clear) return true;
      bones_only = true;
    }
    if (bones_only) return true;
  }
  return false;
}

bool drop_ahead(const FootholdInputs& in, int leg, glm::vec2 foot_ws, float x_wanted, float* hang_beyond) {
  const RigLeg& info = in.ctx.rig.legs[leg];
  const int facing = in.body.facing;
  const StepLimits limits = step_limits(in, leg, foot_ws);
  const float up = limits.up, lowest = limits.lowest, top = limits.top;
  const FootSpan span = foot_span_ws(info, facing);
  // Nothing rises a step above the foot between it and a little beyond the landing.
  const float far = x_wanted + facing * std::max(span.hi - span.lo, 0.01f);
  const float lo = std::min(foot_ws.x, far) + 0.001f, hi = std::max(foot_ws.x, far) - 0.001f;
  if (lo < hi && in.ctx.level.overlaps(Box{{lo, foot_ws.y + up}, {hi, foot_ws.y + up + 0.001f}})) return false;
  // No ground within the step limits over the landing and the shorter steps find_landing tried.
  const float near = x_wanted - facing * kShortestAheadOfStride * in.stride;
  if (ground_below(in.ctx.level, std::min(near, far), std::max(near, far), top, top - lowest)) return false;
  // The whole foot over the groundless stretch: its back edge at `near`.
  if (hang_beyond) *hang_beyond = near - (facing > 0 ? span.lo : span.hi);
  return true;
}

float landing_x(const FootholdInputs& in, int leg, float speed, float swing_phase) {
  const RigLeg& info = in.ctx.rig.legs[leg];
  // The stance is centred with the contact point under the girdle joint, where the leg's
  // reach forward and back is the same.
  if (swing_phase < 0.0f) swing_phase = 1.0f - in.duty;
  const float frequency = speed > 0.0f ? speed / std::max(in.stride, 1e-3f) : 0.0f;
  const float t_swing = frequency > 0.0f ? swing_phase / frequency : 0.0f;
  const float girdle_td = in.body.girdle_ws(in.ctx.rig, info.girdle).x + in.body.facing * speed * t_swing;
  return girdle_td + in.body.facing * 0.5f * in.duty * in.stride;
}

}  // namespace ossa::anim
