#include "ossa/anim/body_motion.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/ground_profile.h"
#include "ossa/anim/leg_geometry.h"

namespace ossa::anim {

namespace {

// Near steps the body outruns a foot behind by at most this fraction of its leg's reach,
// unless the ground within reach is a slope (no riser) that the leg stretched straight at its
// full reach passes this many hip heights above (less within a shin's length of the foot).
constexpr float kStepReach = 0.8f;
constexpr float kLegLineMarginOfHip = 0.08f;
// The wall sweep ignores the lowest part of the body this many hip heights high (the legs'
// business); it meets walls RigScale::wall_margin early.
constexpr float kSweepFloorOfHip = 0.3f;
// The drawn flesh about the trunk (AnimRig::flesh) meets a box where it lies more than this
// many hip heights under its top (the body's floor lifts flesh so little onto a box's top:
// body_floor.h).
constexpr float kFleshRiseOfHip = 0.01f;
// ...and meets a box only where it rises above the ground the legs walk to by more than they
// step up (AnimatorParams::max_step_up of their climb height), with this much to spare: a leg
// sets its foot on the edge of a riser a little higher than its step (random creature 42 in
// the 2 m frame climbs default.json's 25 cm steps with a 24 cm step).
constexpr float kFleshClimbSlack = 1.25f;

// How far (at most `move`, along dx's sign) the segment a-b goes before a part of it lying more
// than `rise` under the top of a box comes over that box. Boxes no higher than `floor_y` (ground
// the legs step up on) do not count, nor does one the segment is nearer leaving than entering.
// A box reaching above the whole segment (a wall) is met `margin` early.
float segment_advance(const Level& level, glm::vec2 a, glm::vec2 b, float dx, float move, float rise, float floor_y,
                      float margin, std::vector<int>& hits) {
  const float lo_y = std::min(a.y, b.y), hi_y = std::max(a.y, b.y);
  const float lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
  const float reach = move + margin;
  hits.clear();
  level.overlapping(Box{{lo_x - (dx < 0.0f ? reach : 0.0f), std::max(lo_y + rise, floor_y)},
                        {hi_x + (dx > 0.0f ? reach : 0.0f), std::max(hi_y, std::max(lo_y + rise, floor_y) + 1e-3f)}},
                    hits);
  for (int index : hits) {
    const Box& box = level.box(index);
    const float under = box.top() - rise;  // the part of the segment lower than this meets the box
    float l0, l1;  // the x-range of the segment below `under`
    if (!segment_x_within(a, b, -INFINITY, under, &l0, &l1)) continue;
    // Ahead of the part: it goes as far as the box's near face. Entering it already (a slanting
    // rib at a riser's face, further in than out of it): no further. Nearer the far side: it
    // goes on out of it.
    const float gap = dx > 0.0f ? box.min_ws.x - l1 : l0 - box.max_ws.x;
    const float out = dx > 0.0f ? box.max_ws.x - l0 : l1 - box.min_ws.x;
    if (gap < 0.0f && -gap >= out) continue;
    const float early = box.top() > hi_y ? margin : 0.0f;
    move = std::min(move, std::max(0.0f, gap - early - 1e-4f));
  }
  return move;
}

// A box holding body_boxes(false, ·)'s single box, from the root and the hull's extent (no
// hull points); false if fins or arms take part.
bool body_bound_ws(const AnimRig& rig, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, Box* bound) {
  if (rig.body_slabs.empty() || !rig.fins.empty() || !rig.arms.empty()) return false;
  const Mat2x3& m = model_fs[rig.root];
  // Interval arithmetic over [body_lo, body_hi], widened by far more than the rounding of
  // apply() or of these bounds (a few ulps of the extent); rounding is monotonic, so the
  // translation, the skull's span and to_ws keep the bounds in order.
  const float extent = std::max({-rig.body_lo.x, rig.body_hi.x, -rig.body_lo.y, rig.body_hi.y});
  auto range = [&](float a, float b, float offset) {
    const float eps = 1e-5f * (std::fabs(a) + std::fabs(b)) * extent;
    const float lo = std::min(a * rig.body_lo.x, a * rig.body_hi.x) + std::min(b * rig.body_lo.y, b * rig.body_hi.y) - eps;
    const float hi = std::max(a * rig.body_lo.x, a * rig.body_hi.x) + std::max(b * rig.body_lo.y, b * rig.body_hi.y) + eps;
    return glm::vec2(lo + offset, hi + offset);
  };
  glm::vec2 x = range(m.m[0], m.m[2], m.m[4]), y = range(m.m[1], m.m[3], m.m[5]);
  if (rig.skull >= 0) {  // the skull's far end: its joint plus a span kept level
    x = {std::min(x[0], x[0] + rig.skull_span.x), std::max(x[1], x[1] + rig.skull_span.x)};
    y = {std::min(y[0], y[0] + rig.skull_span.y), std::max(y[1], y[1] + rig.skull_span.y)};
  }
  const float x0 = body.to_ws({x[0], 0.0f}).x, x1 = body.to_ws({x[1], 0.0f}).x;
  *bound = Box{{std::min(x0, x1), y[0]}, {std::max(x0, x1), y[1]}};
  return std::isfinite(x0) && std::isfinite(x1) && std::isfinite(y[0]) && std::isfinite(y[1]);
}

// Does the straight line from the anchor to the joint (facing space) pass above the ground
// profile's columns between them, away from the anchor's own tread (the first `skip` metres),
// by `margin` from `ramp` metres on (and by a share of it nearer the foot, where the shin
// meets the ground)? False where the profile does not reach.
bool leg_line_clears(const AnimContext& ctx, const BodyFrame& body, glm::vec2 anchor_fs, glm::vec2 joint_fs, float margin,
                     float skip, float ramp) {
  const GroundProfile& g = ctx.ground;
  const float run = joint_fs.x - anchor_fs.x;
  if (g.empty() || !(run > skip)) return run > 0.0f && !g.empty();
  const float xa = body.to_ws(anchor_fs).x, xj = body.to_ws(joint_fs).x;
  const float lo = std::min(xa, xj), hi = std::max(xa, xj);
  if (lo < g.x0() || hi > g.x0() + g.step() * static_cast<float>(g.size())) return false;
  const float slope = (joint_fs.y - anchor_fs.y) / run;
  for (int i = g.column_of(lo), end = g.column_of(hi); i <= end; ++i) {
    const float h = g.column(i);
    if (std::isnan(h)) continue;
    const float c0 = g.x0() + g.step() * static_cast<float>(i);
    // The column's span in facing x from the anchor, clipped to the line's run; the line is
    // lowest at its near end.
    const float d0 = std::fabs(c0 - xa), d1 = std::fabs(c0 + g.step() - xa);
    const float d = std::clamp(std::min(d0, d1), 0.0f, run);
    if (std::max(d0, d1) < skip) continue;
    const float at = std::max(d, skip);
    if (anchor_fs.y + slope * at - h < margin * std::min(at / ramp, 1.0f)) return false;
  }
  return true;
}

// Is the ground within a leg's reach of a foot behind (anchor) and of where its joint may go
// a slope (a tile hill read as a ramp: no riser in it), and does the leg stretched straight
// clear it?
bool on_slope(const AnimContext& ctx, const BodyFrame& body, const RigLeg& info, glm::vec2 anchor_fs, glm::vec2 joint_fs) {
  const SlopeReading reading = girdle_slope_reading(ctx, info.girdle);
  const float reach = info.contact_reach;
  const float xa = body.to_ws(anchor_fs - glm::vec2(reach, 0.0f)).x, xj = body.to_ws(joint_fs + glm::vec2(reach, 0.0f)).x;
  if (ctx.ground.empty() ||
      ctx.ground.largest_jump(std::min(xa, xj), std::max(xa, xj), reading) > reading.ramp) {
    return false;
  }
  return leg_line_clears(ctx, body, anchor_fs, joint_fs, kLegLineMarginOfHip * ctx.rig.hip_height, info.foot_span,
                         std::max(info.lower, 1e-3f));
}

// A rest bound relative to the root's rest joint (AnimRig::trunk_lo/trunk_hi,
// flesh_lo/flesh_hi) turned with the body, world space.
Box rest_bound_ws(const AnimRig& rig, const BodyFrame& body, glm::vec2 lo, glm::vec2 hi) {
  Box box{glm::vec2(1e30f), glm::vec2(-1e30f)};
  for (glm::vec2 c : {lo, hi, glm::vec2(lo.x, hi.y), glm::vec2(hi.x, lo.y)}) {
    const glm::vec2 w = body.body_point_ws(rig, c + glm::vec2(0.0f, rig.root_rest_y));
    box.min_ws = glm::min(box.min_ws, w);
    box.max_ws = glm::max(box.max_ws, w);
  }
  return box;
}

// The trunk's and the head's flesh (AnimRig::flesh) where the body is now, world space: the
// skull's joint at skull_fs (facing space).
Box flesh_bound_ws(const AnimRig& rig, const BodyFrame& body, glm::vec2 skull_fs) {
  Box box{glm::vec2(1e30f), glm::vec2(-1e30f)};
  if (rig.flesh_level_from > 0) box = rest_bound_ws(rig, body, rig.flesh_lo, rig.flesh_hi);
  if (rig.flesh_level_from < rig.flesh.size()) {
    const glm::vec2 a = body.to_ws(skull_fs + rig.head_flesh_lo), b = body.to_ws(skull_fs + rig.head_flesh_hi);
    box = box.united(Box{glm::min(a, b), glm::max(a, b)});
  }
  return box;
}

// The trunk's bones (AnimRig::trunk: ribs below the spine's outline too; not the head, a slab
// already) as a box each, the body rigid as at rest, put before the arms' reach boxes (which
// come last): the sweep in the air takes them in (a rib cage falling past a wall's face).
void add_trunk_boxes(const AnimRig& rig, const BodyFrame& body, std::vector<Box>* boxes) {
  const size_t at = boxes->size() - std::min(boxes->size(), rig.arms.size());
  thread_local std::vector<Box> trunk;
  trunk.clear();
  for (size_t i = 0; i < rig.trunk_level_from; ++i) {
    const glm::vec2 a = body.body_point_ws(rig, rig.trunk[i].a), b = body.body_point_ws(rig, rig.trunk[i].b);
    trunk.push_back(Box{glm::min(a, b), glm::max(a, b)});
  }
  boxes->insert(boxes->begin() + static_cast<std::ptrdiff_t>(at), trunk.begin(), trunk.end());
}

}  // namespace

void body_boxes(const AnimRig& rig, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, bool slabs, std::vector<Box>* boxes) {
  const Skeleton& sk = rig.skeleton;
  boxes->clear();
  // The open box grows in a local (stores into *boxes could alias every float read here, so
  // the compiler would reload the matrices and the box for each point) and is appended when
  // the next one begins, and at the end.
  Box box;
  bool open = false;
  auto begin = [&] {
    if (open) boxes->push_back(box);
    box = Box{glm::vec2(1e30f), glm::vec2(-1e30f)};
    open = true;
  };
  auto add_point = [&](glm::vec2 p_fs) {
    const glm::vec2 p = body.to_ws(p_fs);
    box.min_ws = glm::min(box.min_ws, p);
    box.max_ws = glm::max(box.max_ws, p);
  };
  auto add = [&](int b) {
    add_point(bone_start(model_fs[b]));
    add_point(bone_end(model_fs[b], sk.length(b)));
  };
  if (!rig.body_slabs.empty()) {
    const Mat2x3 root = model_fs[rig.root];
    if (slabs) {
      for (const std::vector<glm::vec2>& slab : rig.body_slabs) {
        begin();
        for (glm::vec2 p : slab) add_point(root.apply(p));
      }
    } else {
      begin();
      for (glm::vec2 p : rig.body_hull) add_point(root.apply(p));
    }
    if (rig.skull >= 0) {
      if (slabs) begin();
      const glm::vec2 skull = root.apply(rig.skull_rel);
      add_point(skull);
      add_point(skull + rig.skull_span);
    }
  } else {
    // (As slabs, a bone each: a legless body's, whose bones each lie over their own ground.)
    auto part = [&](int b) {
      if (slabs || !open) begin();
      add(b);
    };
    part(rig.root);
    for (int b : rig.back) part(b);
    for (int b : rig.neck) part(b);
    if (rig.skull >= 0) part(rig.skull);
  }
  // An arm's shoulder is the body's too (the arm itself folds out of the way): it meets a
  // step rising in front of a low chest.
  for (const RigLimb& arm : rig.arms) {
    if (slabs) begin();
    add_point(bone_start(model_fs[arm.bones[0]]));
  }
  for (const RigLimb& fin : rig.fins) {
    if (slabs) begin();
    for (int b : fin.bones) add(b);
  }
  // A folded wing lies along the body and meets a wall with it (one of each pair that
  // coincides in the side view).
  for (const RigLimb& wing : rig.outline_wings) {
    if (slabs) begin();
    for (int b : wing.bones) add(b);
  }
  // Arms swing: count the whole reach of each arm, forward and back, not just this pose.
  // (They come last: the sweep tests them against walls only, as they lift over the rest.)
  for (const RigLimb& arm : rig.arms) {
    const glm::vec2 shoulder = bone_start(model_fs[arm.bones[0]]);
    const float reach = sk.length(arm.bones[0]) + sk.length(arm.bones[1]) + sk.length(arm.bones[2]);
    if (slabs) begin();
    add_point(shoulder - glm::vec2(reach, reach));
    add_point(shoulder + glm::vec2(reach, 0.0f));
  }
  if (open) boxes->push_back(box);
}

BodyMotionResult sweep_body(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, float dx,
                            std::vector<Box>& boxes, bool whole) {
  BodyMotionResult out;
  out.dx = dx;
  if (dx == 0.0f) return out;
  const AnimRig& rig = ctx.rig;
  const Level& level = ctx.level;
  const int facing = body.facing;
  const float hip = rig.hip_height;
  const float step_up = ctx.params.max_step_up * hip;
  // The ground line under the body runs through the girdles' support, tilted with the body's
  // pitch. The whole body is swept first; only if that meets something, its parts one by one.
  const float support = body.root_y_ws - rig.root_rest_y * ctx.params.stance_height;
  float slope = 0.0f;  // tan(pitch); set, with `reading`, once a part is swept (below)
  // The margin lies ahead only: behind, the body moves away from what it is near (a tail
  // still beside the ledge it came down from).
  const float m = rig.scale.wall_margin;
  const glm::vec2 margin_lo(dx < 0.0f ? m : 0.0f, 0.0f), margin_hi(dx > 0.0f ? m : 0.0f, 0.0f);
  // A part's box as swept: from kSweepFloorOfHip above its bottom or a step above the ground
  // line under it (whichever is higher, at most its top). Ground the legs climb without a
  // step — a tile hill, read as a slope from the ground profile and walked from the root up to
  // the first real riser — is not a wall: a part over it rides up with it, lifted by as much
  // as the hill stands above the ground line, however low the part is (a crocodile's head).
  SlopeReading reading;
  auto swept_part = [&](Box box) {
    const float a = slope * facing * (box.min_ws.x - body.x_ws), b = slope * facing * (box.max_ws.x - body.x_ws);
    const float line = support + std::min(a, b);
    const float hill = ctx.ground.slope_top(body.x_ws, std::min(box.min_ws.x, box.min_ws.x + dx),
                                            std::max(box.max_ws.x, box.max_ws.x + dx), reading);
    if (whole) {  // in the air nothing is the legs' business
      box.max_ws = glm::max(box.max_ws, box.min_ws + glm::vec2(1e-3f));
      return box;
    }
    box.min_ws.y = std::min(std::max(box.min_ws.y + kSweepFloorOfHip * hip, line + step_up), box.max_ws.y);
    if (hill > line) {
      box.min_ws.y += hill - line;
      box.max_ws.y += hill - line;
    }
    box.max_ws = glm::max(box.max_ws, box.min_ws + glm::vec2(1e-3f));
    return box;
  };
  boxes.clear();
  bool near_something = true;
  if (whole && !rig.trunk.empty()) {
    // In the air every part is swept, and the rib cage hanging below the spine's outline
    // takes part as well (random creature 42's ribs went 1.8 cm into the far wall of
    // drops.json's pit as it fell past the face). (On the ground the trunk's bones are swept
    // below, as segments.)
    body_boxes(rig, body, model_fs, true, &boxes);
    add_trunk_boxes(rig, body, &boxes);
  } else {
    // Cheaper still, and before that: a box around the body from the root and the hull's extent
    // alone (body_bound_ws), swept as a box holding the ones swept below. Its bottom is the
    // bound's: a part lower than kSweepFloorOfHip keeps its top in the sweep, so a small low part
    // (a grazing head) may be swept from as low as the body reaches. Whatever it does not meet,
    // the body does not meet either.
    Box bound;
    if (body_bound_ws(rig, body, model_fs, &bound)) {
      const Box swept{{bound.min_ws.x - margin_lo.x, bound.min_ws.y}, {bound.max_ws.x + 1e-3f + margin_hi.x, bound.max_ws.y + 1e-3f}};
      auto hit = level.sweep_box(swept, {dx, 0.0f});
      near_something = hit && hit->t < 1.0f;
    }
    if (near_something) {
      slope = std::tan(body.pitch);
      reading = body_slope_reading(ctx);
      // (The one box is raised kSweepFloorOfHip from the body's lowest point, so it can pass a
      // small low part the parts' sweep would stop: a grazing head just under a step's top.
      // Swept from its lowest point, it stops the cape buffalo's skull 18 cm short of
      // drops.json's 1 m ledge, but also random creature 42's low skull at default.json's
      // stairs before it can jump, and scrambles the propalaeotherium's climb back up the
      // ledge: left for the issue.)
      body_boxes(rig, body, model_fs, false, &boxes);
      const Box all = swept_part(boxes[0]);
      auto hit = level.sweep_box(Box{all.min_ws - margin_lo, all.max_ws + margin_hi}, {dx, 0.0f});
      if (hit && hit->t < 1.0f) body_boxes(rig, body, model_fs, !rig.body_slabs.empty(), &boxes);
      else boxes.clear();
    }
  }
  float move = std::fabs(dx);
  const size_t first_arm = boxes.empty() ? 0 : boxes.size() - rig.arms.size();
  for (size_t k = 0; k < boxes.size(); ++k) {
    const Box box = swept_part(boxes[k]);
    const float hi_y = box.max_ws.y;
    float t = 1.0f;  // fraction of dx until the part meets something
    if (k < first_arm) {
      if (auto hit = level.sweep_box(box, {dx, 0.0f})) t = hit->t;
    }
    // Walls (reaching above the body) are met a few centimetres early: arms and head settle
    // forward a little when the body stops.
    if (auto wall = level.sweep_box(Box{box.min_ws - margin_lo, box.max_ws + margin_hi}, {dx, 0.0f});
        wall && wall->t < 1.0f && level.box(wall->index).top() > hi_y) {
      t = wall->t;
    }
    if (t < 1.0f) {
      move = std::min(move, std::max(0.0f, t * std::fabs(dx) - 1e-4f));
      out.hit_wall = true;
    }
  }
  // On the ground the trunk's bones below the spine's outline (the rib cage) meet what rises
  // more than the trunk clamp lifts them over and more than the legs step up (random creature
  // 22's 35 cm ribs, hanging below its 18 cm hips, ran 15 cm into the riser of stairs.json's
  // top step). Swept as the hull is, from kSweepFloorOfHip above their lowest point, they
  // stopped the eared seal half-way up the flight; a bone slanting over a step's corner needs
  // lifting only where it crosses it.
  if (!whole && rig.trunk_level_from > 0 && move > 0.0f) {
    const Box bound = rest_bound_ws(rig, body, rig.trunk_lo, rig.trunk_hi);
    if (auto near = level.sweep_box(Box{bound.min_ws - margin_lo, bound.max_ws + margin_hi}, {dx, 0.0f}); near && near->t < 1.0f) {
      const float pitch_slope = std::tan(body.pitch);
      for (size_t i = 0; i < rig.trunk_level_from && move > 0.0f; ++i) {
        const glm::vec2 a = body.body_point_ws(rig, rig.trunk[i].a), b = body.body_point_ws(rig, rig.trunk[i].b);
        const float line = support + pitch_slope * facing * (std::min(a.x, b.x) - body.x_ws);
        const float before = move;
        move = segment_advance(level, a, b, dx, move, kMaxTrunkRaiseOfHip * hip, std::max(line, support) + step_up, m, ctx.hits);
        if (move < before) out.hit_wall = true;
      }
    }
  }
  // Nor does the drawn body's flesh about the trunk and the head (AnimRig::flesh: a chest, a
  // horn, an elephant's trunk) go into what rises more than the legs step up: no clamp lifts
  // flesh out of a box's face (the horse's chest went 12 cm into drops.json's 1 m ledge, the
  // triceratops's horn 0.5 m into the end wall it stood at).
  if (!whole && !rig.flesh.empty() && move > 0.0f) {
    const glm::vec2 skull_ms = rig.skull >= 0 ? bone_start(rig.model_rest[rig.skull]) : glm::vec2(0.0f);
    const glm::vec2 skull_fs = body.to_fs(body.body_point_ws(rig, skull_ms));
    auto point_ws = [&](size_t i, glm::vec2 p_ms) {
      return i < rig.flesh_level_from ? body.body_point_ws(rig, p_ms) : body.to_ws(skull_fs + (p_ms - skull_ms));
    };
    const Box bound = flesh_bound_ws(rig, body, skull_fs);
    if (auto near = level.sweep_box(Box{bound.min_ws - margin_lo, bound.max_ws + margin_hi}, {dx, 0.0f}); near && near->t < 1.0f) {
      const float pitch_slope = std::tan(body.pitch);
      const float climb = kFleshClimbSlack * std::max(step_up, ctx.params.max_step_up * rig.climb_height);
      for (size_t i = 0; i < rig.flesh.size() && move > 0.0f; ++i) {
        const glm::vec2 a = point_ws(i, rig.flesh[i].a), b = point_ws(i, rig.flesh[i].b);
        const float line = support + pitch_slope * facing * (std::min(a.x, b.x) - body.x_ws);
        const float lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
        float floor_y = std::max(line, support) + climb;
        // Ground the legs walk to from under the root, no riser on the way higher than they
        // climb (a flight of small steps, a tile slope), is ground: flesh rests on it
        // (body_floor.h). (No lying range: the walk starts from the support line.)
        const float walked = ctx.ground.climbable_top(body.x_ws, std::min({body.x_ws, lo_x, lo_x + dx - margin_lo.x}),
                                                      std::max({body.x_ws, hi_x, hi_x + dx + margin_hi.x}), 1.0f, -1.0f, support, climb);
        if (walked + kFleshRiseOfHip * hip > floor_y) floor_y = walked + kFleshRiseOfHip * hip;
        const float before = move;
        move = segment_advance(level, a, b, dx, move, kFleshRiseOfHip * hip, floor_y, m, ctx.hits);
        if (move < before) out.hit_wall = true;
      }
    }
  }
  // A legless body lies along the ground: each of its bones also meets, as a wall, a box that
  // rises above the bone and more than the crawl climb above the ground under the bone itself
  // (the line above runs through the root, over the highest ground under the whole body: a
  // blue whale lying over stairs.json's 3.3 m landing, its head over the floor, passed over
  // the level's 4 m end wall). Ground up to a climb above the bone counts as under it (a bone
  // draped over a ledge's edge, or lying at the foot of a step it climbs); the body climbs by
  // as much more as its wave lifts it off the ground under its root, up to that climb again
  // (the 45 cm trout flops over rough.json's 15 cm blocks; the blue whale's running wave would
  // carry it over a 4 m wall).
  if (rig.girdles.empty() && near_something && !whole) {
    float lift = 0.0f;
    if (ctx.ground.spans(body.x_ws, body.x_ws)) {
      const float ground = ctx.ground.highest(body.x_ws, body.x_ws, support);
      if (ground < support) lift = std::min(support - ground, rig.crawl_climb);
    }
    body_boxes(rig, body, model_fs, true, &boxes);
    for (size_t k = 0; k < boxes.size(); ++k) {
      const Box& part = boxes[k];
      if (!ctx.ground.spans(part.min_ws.x, part.max_ws.x)) continue;
      const float under = ctx.ground.highest(part.min_ws.x, part.max_ws.x, part.max_ws.y + rig.crawl_climb);
      if (std::isnan(under)) continue;
      // The bone, then its drawn flesh ahead of it (AnimRig::crawl_flesh: a sperm whale's head
      // went 25 cm into default.json's 1.8 m post, its skull short of it), each from the same
      // floor; a box is a wall when it rises above the bone. (The flesh beside and behind the
      // bone is left out: it lies over the ground the bone has come over, as a perch's head
      // over the ledge it flops down from.)
      auto meet = [&](Box box) {
        // (A face the bone lies against behind it is no wall ahead: a fin along the floor below
        // the ledge the body crawls off.)
        if (dx > 0.0f) box.min_ws.x = std::min(box.min_ws.x + 1e-3f, box.max_ws.x);
        else box.max_ws.x = std::max(box.max_ws.x - 1e-3f, box.min_ws.x);
        box.min_ws.y = std::max(box.min_ws.y + kSweepFloorOfHip * hip, under + rig.crawl_climb + lift);
        box.max_ws.y = std::max(box.max_ws.y, box.min_ws.y + 1e-3f);
        if (auto wall = level.sweep_box(Box{box.min_ws - margin_lo, box.max_ws + margin_hi}, {dx, 0.0f});
            wall && wall->t < 1.0f && level.box(wall->index).top() > part.max_ws.y) {
          move = std::min(move, std::max(0.0f, wall->t * std::fabs(dx) - 1e-4f));
          out.hit_wall = true;
        }
      };
      meet(part);
      if (k < rig.crawl_flesh.size()) {
        const Box& f = rig.crawl_flesh[k];
        const Mat2x3& m = model_fs[rig.crawl_bones[k]];
        Box flesh{glm::vec2(1e30f), glm::vec2(-1e30f)};
        for (const glm::vec2 c : {f.min_ws, f.max_ws, glm::vec2(f.min_ws.x, f.max_ws.y), glm::vec2(f.max_ws.x, f.min_ws.y)}) {
          const glm::vec2 p = body.to_ws(m.apply(c));
          flesh = flesh.united(Box{p, p});
        }
        if (dx > 0.0f) flesh.min_ws.x = std::max(flesh.min_ws.x, part.max_ws.x);
        else flesh.max_ws.x = std::min(flesh.max_ws.x, part.min_ws.x);
        if (flesh.min_ws.x < flesh.max_ws.x) meet(flesh);
      }
    }
  }
  out.dx = facing * move;
  return out;
}

float limit_by_legs(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float dx, TickHandoff& handoff) {
  if (dx == 0.0f) return dx;
  const AnimRig& rig = ctx.rig;
  const int facing = body.facing;
  GirdleJointFs joints;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    const FootState& f = feet.of_leg(leg);
    if (f.air) continue;  // hanging over a drop: it holds nothing back
    const RigLeg& info = rig.legs[i];
    const glm::vec2 joint = joints.of(rig, body, info.girdle);
    const bool stance = f.state == LegState::kStance;
    const glm::vec2 contact = body.to_fs(stance ? f.pos_ws : f.to_ws);
    // The anchor lies within a foot's length of the contact point: a foot that far ahead of
    // where the joint goes cannot hold it back.
    if (contact.x - info.foot_span > joint.x + std::fabs(dx)) continue;
    float r;
    const glm::vec2 anchor = leg_anchor(ctx, body, leg, contact, joint, stance ? f.stance_clear : f.swing_clear, &r);
    const float h = joint.y - anchor.y;
    // Near steps a foot behind keeps the joint within kStepReach of the leg's reach: a leg
    // stretched back across a flight of stairs would cut the edges between.
    // How far forward the joint may go with this foot still in reach (facing x).
    const float level_reach = reach_across(r, h);
    const bool near_steps =
        anchor.x < joint.x && !(stance ? f.stance_reach_clear : f.swing_clear).clear_above(anchor.y + 0.1f * rig.hip_height) &&
        !on_slope(ctx, body, info, anchor, {anchor.x + level_reach, joint.y});
    float joint_reach = level_reach;  // (the step reach only near steps)
    if (near_steps) joint_reach = std::max(reach_across(kStepReach * r, h), 0.5f * level_reach);
    const float ahead = anchor.x + joint_reach - joint.x;
    dx = facing * std::min(std::fabs(dx), std::max(ahead, 0.0f));
    // Nor does the body leave a swinging foot behind further than its leg reaches (a foot
    // that lifted late, far back on stairs, would sweep the leg through the steps between).
    const glm::vec2 now = body.to_fs(f.pos_ws);
    if (!stance && now.x < joint.x) {
      const float R = info.contact_reach, hn = joint.y - now.y;
      const float lead = now.x + reach_across(R, hn) - joint.x;
      dx = facing * std::min(std::fabs(dx), std::max(lead, 0.0f));
    }
    // A foot left below and behind on stairs whose leg would cut the edge of a step above it
    // lifts now (the gait clock reads lift_now) rather than drag its knee through the step.
    // The body waits for it if the leg clears the steps where it is.
    // One whose drawn flesh only would cut it lifts if it finds a foothold (kLiftIfPlaced); the
    // body does not wait for it.
    if (stance && anchor.x < joint.x && !f.stance_reach_clear.clear_above(contact.y)) {
      const glm::vec2 ahead = joint + glm::vec2(std::fabs(dx), 0.0f);
      if (stance_leg_hits(ctx, body, leg, f, ahead)) {
        handoff.lift_now[feet.foot_of_leg[i]] = kLiftNow;
        if (!stance_leg_hits(ctx, body, leg, f, joint)) dx = 0.0f;
      } else if (stance_leg_hits(ctx, body, leg, f, ahead, true)) {
        handoff.lift_now[feet.foot_of_leg[i]] = std::max(handoff.lift_now[feet.foot_of_leg[i]], kLiftIfPlaced);
      }
    }
  }
  return dx;
}

bool steps_ahead(const AnimContext& ctx, const BodyFrame& body, float stride) {
  // A tenth of the hip height: a kerb, not a slope's tile.
  constexpr float kStepOfHip = 0.1f;
  const AnimRig& rig = ctx.rig;
  if (ctx.ground.empty() || rig.girdles.empty()) return false;
  const float lo = rig.body_lo_ws(body.x_ws, body.facing), hi = rig.body_hi_ws(body.x_ws, body.facing);
  const float a = body.facing > 0 ? lo : lo - stride, b = body.facing > 0 ? hi + stride : hi;
  return ctx.ground.largest_jump(a, b, girdle_slope_reading(ctx, static_cast<int>(rig.girdles.size()) - 1)) > kStepOfHip * rig.hip_height;
}

float limit_by_ledges(const AnimContext& ctx, const BodyFrame& body, const FootSet& feet, float stride, float dx) {
  const AnimRig& rig = ctx.rig;
  const GroundProfile& ground = ctx.ground;
  if (dx == 0.0f || ground.empty() || rig.girdles.empty()) return dx;
  const float up = ctx.params.max_step_up * rig.climb_height;
  const float margin = rig.scale.wall_margin;
  float move = std::fabs(dx);
  for (size_t g = 0; g < rig.girdles.size(); ++g) {
    const RigGirdle& girdle = rig.girdles[g];
    // The girdle's feet: the lowest on the ground, or where its swinging feet land when none
    // stands (a gallop's, a bound's or a hop's pair swing together; none at all: it stands
    // where its joint says).
    float feet_y = 1e30f, landing_y = 1e30f;
    for (int leg : girdle.legs) {
      const FootState& f = feet.of_leg(leg);
      if (f.air) continue;
      if (f.state == LegState::kStance) feet_y = std::min(feet_y, f.pos_ws.y);
      else landing_y = std::min(landing_y, f.to_ws.y);
    }
    if (feet_y > 1e29f) feet_y = landing_y;
    if (feet_y > 1e29f) continue;
    const glm::vec2 joint = body.girdle_ws(rig, static_cast<int>(g));
    const float x = joint.x;
    const float high = feet_y + up + kGroundEpsilon;
    // Already over higher ground: not this rule's business (a creature that climbed or landed).
    const int at = ground.column_of(x);
    if (!(ground.column(at) <= high)) continue;
    const int dir = body.facing;
    // Nothing ahead higher than the feet may climb, within the margin and as far as a knee
    // reaches ahead (the common case): no scan.
    const float ahead = x + dir * (move + margin + girdle.knee_reach + 2.0f * ground.step());
    if (!ground.may_rise_above(std::min(x, ahead), std::max(x, ahead), high, high)) continue;
    // Nor may a knee bending forward cross a face taller than a step (a wall, not a stair).
    float knees = margin;
    if (girdle.knee_reach > 0.0f) {
      for (int leg : girdle.legs) knees = std::max(knees, margin + knee_ahead(rig.legs[leg], joint.y - feet_y));
    }
    const int reach = static_cast<int>(std::ceil((move + knees) / ground.step())) + 1;
    const int span = std::max(1, static_cast<int>(std::ceil(stride / ground.step())));
    for (int k = 1; k <= reach; ++k) {
      const int i = at + dir * k;
      if (i < 0 || i >= ground.size()) break;
      if (!(ground.column(i) > high)) continue;
      // A riser: a ledge if the ground stays high for a stride beyond it (or ends: a level's
      // end wall has no ground behind it to step down to), or if it rises above the girdle's
      // joint (no foot steps over a post taller than its hip).
      bool ledge = true;
      float top = -1e30f;
      for (int j = 0; j < span && ledge; ++j) {
        const int c = i + dir * j;
        if (c < 0 || c >= ground.size()) break;
        ledge = !(ground.column(c) <= high);
        if (ledge) top = std::max(top, ground.column(c));
      }
      if (!ledge && !(top > joint.y)) continue;
      const float face = ground.x0() + ground.step() * static_cast<float>(dir > 0 ? i : i + 1);
      const float below = ground.column(i - dir);
      const bool wall = std::isnan(below) || ground.column(i) - below > up;
      move = std::min(move, std::max(0.0f, dir * (face - x) - (wall ? knees : margin)));
      break;
    }
  }
  return body.facing * move;
}

namespace {

// A blocked creature tests the way ahead again this often, seconds.
constexpr float kBlockedRetrySeconds = 0.5f;
// Below this (m/s, and of the stick) the creature stands.
constexpr float kStandingSpeed = 1e-4f;

void block(int leg, int facing, MotionState& motion) {
  MotionState::Block& b = motion.block;
  b.blocked = true;
  if (leg >= 0) b.leg = leg;
  b.dir = facing;
  b.retry = kBlockedRetrySeconds;
}

}  // namespace

void command_speed(const FootholdInputs& in, float desired_velocity, float dt, bool landing, MotionState& motion) {
  MotionState::Block& b = motion.block;
  const int want = desired_velocity > kStandingSpeed ? 1 : desired_velocity < -kStandingSpeed ? -1 : 0;
  float target = std::fabs(desired_velocity);
  b.trial = want == b.dir ? std::max(b.trial - dt, 0.0f) : 0.0f;
  if (b.blocked) {
    if (want != b.dir) {
      b.blocked = false;
    } else {
      target = 0.0f;
      b.retry -= dt;
      if (b.retry <= 0.0f && !in.ctx.rig.legs.empty()) {
        b.retry = kBlockedRetrySeconds;
        glm::vec2 landing_at;
        if (find_landing(in, b.leg, step_from(in.feet->of_leg(b.leg)), landing_x(in, b.leg, std::fabs(desired_velocity)), &landing_at)) {
          b.blocked = false;
          b.trial = kBlockedRetrySeconds;
        }
      }
    }
  }
  motion.speed = target <= kStandingSpeed || landing ? 0.0f : target;
}

float allowed_move(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model_fs, const FootSet& feet,
                   float stride, float dx, std::vector<Box>& boxes, TickHandoff& handoff) {
  const BodyMotionResult swept = sweep_body(ctx, body, model_fs, dx, boxes);
  if (swept.hit_wall) handoff.wall_ahead = true;
  dx = limit_by_legs(ctx, body, feet, swept.dx, handoff);
  if (const float kept = stance_flesh_advance(ctx, body, feet, dx); kept != dx) {
    dx = kept;
    handoff.wall_ahead = true;
  }
  const float ledge = limit_by_ledges(ctx, body, feet, stride, dx);  // a face it cannot climb
  if (ledge == 0.0f && dx != 0.0f) handoff.wall_ahead = true;
  return ledge;
}

void update_block(const TickHandoff& handoff, int facing, MotionState& motion) {
  if (handoff.wall_ahead) block(-1, facing, motion);
  if (handoff.no_foothold_leg >= 0) block(handoff.no_foothold_leg, facing, motion);
}

}  // namespace ossa::anim
