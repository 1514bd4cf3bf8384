#include "ossa/anim/limb_clearance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/ground_profile.h"
#include "ossa/anim/leg_geometry.h"
#include "ossa/anim/secondary_motion.h"
#include "ossa/body/body_mass.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa::anim {

namespace {

constexpr size_t kMaxTailBones = 48;   // keep_tail_clear curls at most this many tail bones
constexpr float kMaxTailCurl = 1.6f;   // radians over the tail's length
constexpr float kMaxTailLift = 1.6f;   // radians at the tail's root, when curling is not enough
constexpr int kTailLiftSteps = 4;      // ... tried in this many steps of the most lift
constexpr int kTailCurlSteps = 4;      // ... each with this many steps of the most curl, either way
constexpr float kTailClearSettle = 2.0f;    // 1/s: a tail's held clearance turn settles back
constexpr float kTailClearSettled = 1e-3f;  // radians: ... and is let go below this
// The body floor's reach (body_floor.h), as keep_tail_clear tests the flesh: a top holds flesh
// up past its ends by the outline's longest edge times this (body_build.cpp's
// kOverhangStretch), and a top up to kFloorMargin metres above the bone over it still counts
// (the floor itself takes tops up to half the flesh's reach above the bones: the test is the
// stricter, a tail sunk that deep curls out rather than rests on the top).
constexpr float kFleshOverhangStretch = 1.25f;
constexpr float kFloorMargin = 1e-3f;
constexpr size_t kMaxFinBones = 7;
constexpr float kMaxHeadLift = 1.2f;    // radians at the neck's base
constexpr float kHeadKeepOfHip = 0.005f;  // keep_head_clear: each head bone this clear of the level
constexpr int kClearBisections = 6;
constexpr int kFinBisections = 7;

}  // namespace

void keep_arm_above_ground(const AnimContext& ctx, const BodyFrame& body, const RigLimb& arm, const std::vector<Mat2x3>& model,
                           float margin, Pose& pose, bool with_flesh) {
  // Long arms of a low body would reach into the ground (or a ledge): lift the wrist with
  // two-bone IK until elbow, wrist and hand clear the highest ground under the arm; an arm
  // still in a step (a riser in front) folds towards the shoulder until it clears.
  const Skeleton& sk = ctx.rig.skeleton;
  const float l1 = sk.length(arm.bones[0]), l2 = sk.length(arm.bones[1]), l3 = sk.length(arm.bones[2]);
  struct ArmPose {
    glm::vec2 shoulder, elbow, wrist, tip;
    float hand_abs, bend;
    std::array<Mat2x3, 3> m;  // upper, lower, hand
  };
  auto current = [&] {
    const Mat2x3 upper = model[arm.girdle_bone] * local_matrix(pose.locals[arm.bones[0]]);
    const Mat2x3 lower = upper * local_matrix(pose.locals[arm.bones[1]]);
    const Mat2x3 hand = lower * local_matrix(pose.locals[arm.bones[2]]);
    ArmPose p{bone_start(upper), bone_start(lower), bone_start(hand), bone_end(hand, l3), bone_angle(hand), 1.0f, {upper, lower, hand}};
    // Keep the elbow's side: solve_two_bone_ik's bend is +1 for an elbow on the left of the
    // line from the shoulder to the wrist. (Read the other way round, every lift of the wrist
    // put the elbow on the other side: the eared seal's elbow, its fore flipper laid on the
    // ground, went 0.3 m behind its shoulder one tick and 0.3 m in front of it the next: an
    // arm joint moved more than half a hip height in a tick 14-147 times in 14 s running each
    // shipped level, the harbour seal's 19-221; README, Known limits.)
    const glm::vec2 a = p.elbow - p.shoulder, b = p.wrist - p.shoulder;
    p.bend = b.x * a.y - b.y * a.x > 0.0f ? 1.0f : -1.0f;
    return p;
  };
  // The arm's drawn outline (RigLimb::flesh_outline) posed with the arm, in frame space.
  const size_t n = with_flesh ? arm.flesh_outline.size() : 0;
  // The farthest its flesh lies from its bones (0: bones alone).
  const float reach = n > 1 ? std::max({arm.flesh_margin[0], arm.flesh_margin[1], arm.flesh_margin[2]}) : 0.0f;
  std::array<glm::vec2, kLimbFleshPoints + 1> flesh_pts;
  auto pose_flesh = [&](const ArmPose& q) {
    if (n == 0) return;
    Mat2x3 frames[kLimbSkinFrames] = {q.m[0], q.m[1], q.m[2]};
    limb_skin_frames(arm.flesh_mids, frames);
    for (size_t i = 0; i < n; ++i) flesh_pts[i] = posed_flesh(arm.flesh_outline[i], frames);
  };
  auto set_wrist = [&](const ArmPose& p, glm::vec2 target) {
    const TwoBoneIkResult ik = solve_two_bone_ik(p.shoulder, l1, l2, target, p.bend);
    pose.locals[arm.bones[0]].angle_ls = wrap_angle(ik.upper_angle - bone_angle(model[arm.girdle_bone]));
    pose.locals[arm.bones[1]].angle_ls = ik.lower_angle;
    pose.locals[arm.bones[2]].angle_ls = wrap_angle(p.hand_abs - (ik.upper_angle + ik.lower_angle));
  };
  for (int pass = 0; pass < 3; ++pass) {
    const ArmPose p = current();
    float x0 = 1e30f, x1 = -1e30f, low = 1e30f;
    auto take = [&](glm::vec2 q) {
      const float xw = body.to_ws(q).x;
      x0 = std::min(x0, xw);
      x1 = std::max(x1, xw);
      low = std::min(low, q.y);
    };
    for (glm::vec2 q : {p.elbow, p.wrist, p.tip}) take(q);
    // Its flesh too, below the shoulder (its drawn hand or flipper laid on the ground): the
    // ground under wherever it may lie, and its points only where they may come down to it.
    const auto ground = ground_below(ctx.level, x0 - reach, x1 + reach, p.shoulder.y, ctx.rig.scale.search_depth);
    if (!ground) break;
    if (n > 1 && low - reach < ground->height_ws + margin) {
      pose_flesh(p);
      for (size_t i = 0; i < n; ++i) {
        if (flesh_pts[i].y < p.shoulder.y) take(flesh_pts[i]);
      }
    }
    if (low >= ground->height_ws + margin) break;
    set_wrist(p, p.wrist + glm::vec2(0.0f, ground->height_ws + margin - low));
  }
  const ArmPose p = current();
  bool flesh = n > 1;  // the drawn outline too, while some tuck clears it; else the bones alone
  auto hits = [&](const ArmPose& q) {
    const glm::vec2 pts[4] = {body.to_ws(q.shoulder), body.to_ws(q.elbow), body.to_ws(q.wrist), body.to_ws(q.tip)};
    if (polyline_hits_level(ctx.level, pts, 4, ctx.hits)) return true;
    if (!flesh) return false;
    // (No box within its flesh's reach of the bones: none the flesh meets.)
    Box near{glm::min(glm::min(pts[0], pts[1]), glm::min(pts[2], pts[3])), glm::max(glm::max(pts[0], pts[1]), glm::max(pts[2], pts[3]))};
    ctx.hits.clear();
    ctx.level.overlapping(Box{near.min_ws - glm::vec2(reach), near.max_ws + glm::vec2(reach)}, ctx.hits);
    if (ctx.hits.empty()) return false;
    pose_flesh(q);
    for (size_t i = 0; i < n; ++i) flesh_pts[i] = body.to_ws(flesh_pts[i]);
    flesh_pts[n] = flesh_pts[0];
    return polyline_hits_level(ctx.level, flesh_pts.data(), static_cast<int>(n + 1), ctx.hits);
  };
  if (!hits(p)) return;
  // Tucked under the shoulder, else folded up in front of the chest, else up behind it: the
  // first tuck that clears, approached only as far as needed. The hand keeps its direction,
  // else (a long hand or flipper reaching into a step ahead) it trails back and down, else
  // up behind; last, with the elbow bent the other way (a shoulder just above a tread, where
  // any elbow bent down meets the tread).
  const float tuck_len = std::max(std::fabs(l1 - l2) + 0.01f, 0.35f * (l1 + l2));
  auto tuck_clear = [&] {
    for (float bend : {p.bend, -p.bend}) {
      for (float hand : {p.hand_abs, kPi + 0.3f, kPi - 0.8f}) {
        ArmPose q = p;
        q.hand_abs = hand;
        q.bend = bend;
        for (glm::vec2 dir : {glm::vec2(-1.0f, -0.3f), glm::vec2(0.4f, 1.0f), glm::vec2(-0.6f, 1.0f)}) {
          const glm::vec2 tuck = q.shoulder + glm::normalize(dir) * tuck_len;
          set_wrist(q, tuck);
          if (hits(current())) continue;
          float lo = 0.0f, hi = 1.0f;  // fractions of the way to the tuck: lo hits, hi clears
          bisect(lo, hi, kClearBisections, [&](float mid) {
            set_wrist(q, glm::mix(q.wrist, tuck, mid));
            return hits(current());
          });
          set_wrist(q, glm::mix(q.wrist, tuck, hi));
          return true;
        }
      }
    }
    return false;
  };
  // An outline that encloses the shoulder, no nearer to it than r, crosses the ray straight
  // down from it r or more below it: with a box top under the shoulder less than r below it
  // (a body lying lower than its arm's root is thick), no tuck clears the flesh, and the arm
  // keeps its bones out alone without trying. (Random creature 7919, legless, its shoulders
  // 2.8 cm over the ground and the flesh about them 3.7 cm: 18 tucks tried on every tick, none
  // clearing, cost it 44 % more time a tick on flat ground.)
  auto shoulder_buried = [&] {
    pose_flesh(p);
    if (!inside_polygon(std::span<const glm::vec2>(flesh_pts.data(), n), p.shoulder)) return false;
    float r = 1e30f;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
      const glm::vec2 a = flesh_pts[i], ab = flesh_pts[j] - a;
      const float t = std::clamp(glm::dot(p.shoulder - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
      r = std::min(r, glm::distance(a + t * ab, p.shoulder));
    }
    const glm::vec2 shoulder = body.to_ws(p.shoulder);
    const auto under = ground_below(ctx.level, shoulder.x, shoulder.x, shoulder.y, r);
    return under && under->height_ws > shoulder.y - r;
  };
  if (flesh && shoulder_buried()) {
    flesh = false;
    if (!hits(p)) return;
  }
  const float planned[3] = {pose.locals[arm.bones[0]].angle_ls, pose.locals[arm.bones[1]].angle_ls, pose.locals[arm.bones[2]].angle_ls};
  if (tuck_clear()) return;
  if (flesh) {
    flesh = false;
    for (int k = 0; k < 3; ++k) pose.locals[arm.bones[k]].angle_ls = planned[k];
    if (!hits(p) || tuck_clear()) return;
  }
  // Nothing clears (the shoulder itself against a face ahead: a body falling beside a gap's
  // far wall): tucked back under the shoulder, the hand trailing back, away from the face.
  ArmPose q = p;
  q.hand_abs = kPi + 0.3f;
  set_wrist(q, p.shoulder + glm::normalize(glm::vec2(-1.0f, -0.3f)) * tuck_len);
}

float body_out_of_ground(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model, const Pose& pose) {
  // Where the drape could not keep a legless body out of the ground (a step, a gap's edge),
  // the whole body rises by its deepest point: every bone's two ends and the roots of its
  // fins, arms and wings.
  float raise = 0.0f;
  const GroundProfile& ground = ctx.ground;
  const float span = ctx.rig.scale.ground_span;
  // The ground under a point is looked for from above the body (a point may lie deeper in the
  // ground than the body is high): in the profile where it holds the span, else in the level.
  const float top = body.root_y_ws + ctx.rig.hip_height + ctx.rig.root_rest_y;
  // Level ground under the whole body (the common case) is one height.
  float flat = NAN;
  {
    const float a = ctx.rig.body_lo_ws(body.x_ws, body.facing) - ctx.rig.body_half_length - span;
    const float b = ctx.rig.body_hi_ws(body.x_ws, body.facing) + ctx.rig.body_half_length + span;
    if (!ground.covers(ctx.level, a, b, body.root_y_ws - ctx.rig.body_half_length, top) || !ground.level_over(a, b, &flat) ||
        !(flat <= top)) {
      flat = NAN;
    }
  }
  auto keep_out = [&](glm::vec2 p_fs, float from_y_fs) {
    if (!std::isnan(flat)) {
      raise = std::max(raise, flat - p_fs.y);  // (facing space y is world y)
      return;
    }
    const glm::vec2 p = body.to_ws(p_fs);
    if (ground.covers(ctx.level, p.x - span, p.x + span, std::min(p.y, top), top)) {
      const float h = ground.highest(p.x - span, p.x + span, top);
      if (h - p.y > raise) raise = h - p.y;  // (NaN: none)
      return;
    }
    const float from = std::max(top, body.to_ws({p_fs.x, std::max(from_y_fs, p_fs.y)}).y + ctx.rig.hip_height);
    if (auto below = ground_below(ctx.level, p.x - span, p.x + span, from, ctx.rig.scale.search_depth + (from - p.y))) {
      raise = std::max(raise, below->height_ws - p.y);
    }
  };

  // Every bone of the body, both ends: those the drape placed from their matrices, what hangs
  // from them (ribs, the skull, the limbs' roots) from the rest shape they keep (the limbs' own
  // clearance keeps the limbs out).
  const AnimRig& rig = ctx.rig;
  for (int b : rig.drape_fk) {
    if (rig.limb_bone[b]) continue;
    const glm::vec2 p = bone_start(model[b]), e = bone_end(model[b], rig.skeleton.length(b));
    keep_out(p, p.y);
    keep_out(e, e.y);
    // Over steps a long bone (a whale's skull) may cut a riser's corner between its ends (the
    // profile first: no ground above the bone, no level query).
    if (std::isnan(flat)) {
      const glm::vec2 a = body.to_ws(p), c = body.to_ws(e);
      if (ground.may_rise_above(std::min(a.x, c.x), std::max(a.x, c.x), std::min(a.y, c.y), top)) {
        raise = std::max(raise, raise_to_clear(a, c, ctx.level, ctx.hits, top));
      }
    }
  }
  // What hangs from a bone: its points, and over steps each hanging bone whole (a rib
  // slanting across a block's corner, its ends clear: the ichthyosaurus's, 1.1 cm into
  // rough.json's blocks for a tick as its body rose onto one).
  auto keep_hangers_out = [&](const Mat2x3& m, const glm::vec2* q, int n, int pairs) {
    for (int k = 0; k < n; ++k) {
      const glm::vec2 p = m.apply(q[k]);
      keep_out(p, p.y);
    }
    if (!std::isnan(flat)) return;
    for (int k = pairs; k + 1 < n; k += 2) {
      const glm::vec2 a = body.to_ws(m.apply(q[k])), c = body.to_ws(m.apply(q[k + 1]));
      if (ground.may_rise_above(std::min(a.x, c.x), std::max(a.x, c.x), std::min(a.y, c.y), top)) {
        raise = std::max(raise, raise_to_clear(a, c, ctx.level, ctx.hits, top));
      }
    }
  };
  for (size_t i = 0; i < rig.drape_bones.size(); ++i) {
    const int begin = rig.hang_begin[i];
    keep_hangers_out(model[rig.drape_bones[i]], rig.hang_points.data() + begin, rig.hang_begin[i + 1] - begin, rig.hang_pairs[i] - begin);
  }
  keep_hangers_out(model[rig.root], rig.root_hang_points.data(), static_cast<int>(rig.root_hang_points.size()), rig.root_hang_pairs);
  if (rig.skull >= 0) {
    keep_hangers_out(model[rig.skull], rig.skull_hang_points.data(), static_cast<int>(rig.skull_hang_points.size()), 0);
  }
  for (const std::vector<RigLimb>* limbs : {&ctx.rig.arms, &ctx.rig.fins, &ctx.rig.wings}) {
    for (const RigLimb& limb : *limbs) {
      const Mat2x3& girdle = model[limb.girdle_bone];
      keep_out(girdle.apply(pose.locals[limb.bones[0]].offset_ls), bone_start(girdle).y);
    }
  }
  return raise;
}

void keep_tail_clear(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model, float dt, TailSpring& tail,
                     Pose& pose) {
  // A tail hanging into a step (down a flight, or one rising behind) curls up from its root,
  // the least that clears, up to kMaxTailCurl over its length (or, if that is not enough,
  // lifts at its root). Only asked when a box comes within a tail's length of its root: ground,
  // or a wall rising higher (the tarsier falling down drops.json's 1 m ledge trailed its tail
  // 3.3 cm into the face, whose top lay more than a tail above the tail's root).
  const AnimRig& rig = ctx.rig;
  Mat2x3 base = model[rig.tail_base_bone];
  if (body.flex != 0.0f && !rig.tail_flex_between.empty()) {  // the spine it hangs from flexes
    for (int b : rig.tail_flex_between) base = base * local_matrix(pose.locals[b]);
  } else {
    base = base * rig.tail_between_rest;
    for (int b : rig.tail_between) base = base * local_matrix(pose.locals[b]);
  }
  const glm::vec2 root = body.to_ws(base.apply(pose.locals[rig.tail[0]].offset_ls));
  const size_t n = std::min<size_t>(rig.tail.size(), kMaxTailBones);
  const float len = rig.tail_reach;  // (with its flesh)
  // The turn taken lately, settling back (a tail that cleared a step's corner by a curl one
  // tick and by none the next, as a crawling body rose and sank with its wave, flicked up and
  // down: the whales' by up to 8 m, 28-88 times in 14 s running default.json and stairs.json).
  const float keep = dt > 0.0f ? std::exp(-kTailClearSettle * dt) : 1.0f;
  const auto settled = [&](float turn) { return std::fabs(turn * keep) < kTailClearSettled ? 0.0f : turn * keep; };
  const float held_curl = settled(tail.curl), held_lift = settled(tail.lift);
  auto turn = [&](float curl, float lift) {
    tail.curl = curl, tail.lift = lift;
    for (size_t k = 0; k < n; ++k) pose.locals[rig.tail[k]].angle_ls += curl / static_cast<float>(n) + (k == 0 ? lift : 0.0f);
  };
  if (!ctx.level.first_overlap(Box{root - glm::vec2(len), root + glm::vec2(len)})) {
    turn(held_curl, held_lift);  // (nothing it could meet)
    return;
  }
  glm::vec2 p[kMaxTailBones + 1];
  // The tail's flesh (AnimRig::tail_flesh) as one closed outline: along the boxes' lower
  // edges, round the tip, back along their upper edges. The flesh of a T. rex's tail lying on
  // default.json's end wall, bones clear, went 11 cm into the wall's corner.
  bool flesh = rig.tail_flesh.size() >= n;
  glm::vec2 outline[4 * kMaxTailBones + 1];
  auto hits = [&](float turn, float lift = 0.0f) {
    Mat2x3 m = base;
    for (size_t k = 0; k < n; ++k) {
      BoneLocal local = pose.locals[rig.tail[k]];
      local.angle_ls += turn / static_cast<float>(n) + (k == 0 ? lift : 0.0f);
      m = m * local_matrix(local);
      p[k] = body.to_ws(bone_start(m));
      if (k + 1 == n) p[n] = body.to_ws(bone_end(m, rig.skeleton.length(rig.tail[k])));
      if (flesh) {
        const Box& f = rig.tail_flesh[k];
        outline[2 * k] = body.to_ws(m.apply(f.min_ws));
        outline[2 * k + 1] = body.to_ws(m.apply({f.max_ws.x, f.min_ws.y}));
        outline[4 * n - 1 - 2 * k] = body.to_ws(m.apply({f.min_ws.x, f.max_ws.y}));
        outline[4 * n - 2 - 2 * k] = body.to_ws(m.apply(f.max_ws));
      }
    }
    if (polyline_hits_level(ctx.level, p, static_cast<int>(n + 1), ctx.hits)) return true;
    if (!flesh) return false;
    // (Flattening only raises points onto the tops under them: an outline that meets nothing
    // as it is would meet nothing flattened, but for a point raised near a box above it, which
    // this skips; most ticks stop here.)
    outline[4 * n] = outline[0];
    if (!polyline_hits_level(ctx.level, outline, static_cast<int>(4 * n + 1), ctx.hits)) return false;
    // Flesh below the top of a box under its bone is drawn on that top (body_floor.h: soft
    // tissue flattens on the ground), so it is tested there: a whale's tail lying on the ground,
    // its flesh deeper than its bones are high, stood on end to clear the floor. A top holds
    // it up past its ends too, as far as the body floor does (BodyVertex::overhang: the
    // outline's longest edge, stretched).
    float edge = 0.0f;
    for (size_t j = 0; j < 4 * n; ++j) edge = std::max(edge, glm::length(outline[j + 1 == 4 * n ? 0 : j + 1] - outline[j]));
    const float overhang = kFleshOverhangStretch * edge;
    // (Only tops no higher than the bones over the point count, or past the bones the nearer
    // end's: body_floor.h. A tail fin lying at the foot of a higher block is drawn into its
    // face. The point's bone and its neighbours are asked.)
    auto bones_over = [&](size_t k, float x) {
      float y = -INFINITY;
      for (size_t i = k > 0 ? k - 1 : 0; i <= std::min(k + 1, n - 1); ++i) {
        const glm::vec2 a = p[i], b = p[i + 1];
        if ((x - a.x) * (x - b.x) > 0.0f) continue;
        const float t = std::fabs(b.x - a.x) > 1e-6f ? (x - a.x) / (b.x - a.x) : 0.0f;
        y = std::max(y, a.y + t * (b.y - a.y));
      }
      if (y > -INFINITY) return y;
      return std::fabs(x - p[k].x) < std::fabs(x - p[k + 1].x) ? p[k].y : p[k + 1].y;
    };
    for (size_t j = 0; j < 4 * n; ++j) {
      const size_t k = j < 2 * n ? j / 2 : (4 * n - 1 - j) / 2;
      glm::vec2& q = outline[j];
      if (q.y >= std::max(p[k].y, p[k + 1].y)) continue;
      const float over = bones_over(k, q.x) + kFloorMargin;
      if (q.y >= over) continue;
      float top = NAN;
      if (ctx.ground.spans(q.x - overhang, q.x + overhang)) {
        top = ctx.ground.highest(q.x - overhang, q.x + overhang, over);
      } else if (auto below = ground_below(ctx.level, q.x - overhang, q.x + overhang, over, over - q.y)) {
        top = below->height_ws;
      }
      if (q.y < top) q.y = top;  // (NaN: no ground under it)
    }
    outline[4 * n] = outline[0];
    return polyline_hits_level(ctx.level, outline, static_cast<int>(4 * n + 1), ctx.hits);
  };
  float curl = 0.0f, lift = 0.0f;
  auto solve = [&] {
    // The turn that raises the tip first; a curled tail may need the other.
    const float up = body.facing * (p[n].x - p[0].x) < 0.0f ? -1.0f : 1.0f;
    float most = kMaxTailCurl * up;
    if (hits(most) && !hits(-most)) most = -most;
    float lo = 0.0f, hi = 1.0f;  // fractions of the most: lo hits, hi clears (or is the last resort)
    bisect(lo, hi, kClearBisections, [&](float mid) { return hits(mid * most); });
    curl = hi * most, lift = 0.0f;
    if (hi == 1.0f && hits(most)) {
      // Curled as far as it goes and still in the step (a ledge's face right behind a body that
      // came down it): the tail lifts at its root instead, straight, the least that clears; if
      // nothing does, lifted and curled.
      const float most_lift = kMaxTailLift * (most > 0.0f ? 1.0f : -1.0f);
      if (!hits(0.0f, most_lift)) {
        curl = 0.0f;
        lo = 0.0f, hi = 1.0f;
        bisect(lo, hi, kClearBisections, [&](float mid) { return hits(0.0f, mid * most_lift); });
        lift = hi * most_lift;
      } else {
        // Lifted and curled: the least lift, then the least curl either way (up to twice the
        // most: the tail coils), that clears. A chameleon turned round at drops.json's 1 m
        // riser, its tail's root 8 cm from the face, held its tail up the face with the tip
        // curled back into it, 4.6 mm; it now coils under its body. If nothing clears, lifted
        // and curled as far as they go.
        lift = most_lift;
        bool found = false;
        for (int l = 1; l <= kTailLiftSteps && !found; ++l) {
          const float try_lift = most_lift * static_cast<float>(l) / kTailLiftSteps;
          for (int c = 0; c <= kTailCurlSteps && !found; ++c) {
            for (const float sign : {1.0f, -1.0f}) {
              const float try_curl = 2.0f * sign * most * static_cast<float>(c) / kTailCurlSteps;
              if (!hits(try_curl, try_lift)) {
                curl = try_curl, lift = try_lift, found = true;
                break;
              }
              if (c == 0) break;  // (no curl: one try)
            }
          }
        }
      }
    }
  };
  if (hits(0.0f)) {
    solve();
    // Flesh no curl nor lift clears (the tail's root lies in it: a body spawned by an end
    // wall) is left where it is: the bones alone are kept out, as the tail would otherwise
    // stand on end.
    if (flesh && hits(curl, lift)) {
      flesh = false;
      curl = lift = 0.0f;
      if (hits(0.0f)) solve();
    }
  }
  // The turn held from lately, where it turns the same way and as far or further: as much of
  // the way from the least that clears to it as still clears.
  const bool further = held_curl * curl >= 0.0f && std::fabs(held_curl) >= std::fabs(curl) && held_lift * lift >= 0.0f &&
                       std::fabs(held_lift) >= std::fabs(lift);
  if ((held_curl != 0.0f || held_lift != 0.0f) && further && (held_curl != curl || held_lift != lift)) {
    float lo = 0.0f, hi = 1.0f;  // fractions of the way to the held turn: lo clears, hi may not
    if (hits(held_curl, held_lift)) {
      bisect(lo, hi, kClearBisections,
             [&](float mid) { return !hits(curl + mid * (held_curl - curl), lift + mid * (held_lift - lift)); });
    } else {
      lo = 1.0f;
    }
    curl += lo * (held_curl - curl), lift += lo * (held_lift - lift);
  }
  turn(curl, lift);
}

void keep_head_clear(const AnimContext& ctx, const BodyFrame& body, const std::vector<Mat2x3>& model, Pose& pose) {
  const AnimRig& rig = ctx.rig;
  const Skeleton& sk = rig.skeleton;
  const int base = rig.nod_bones[0];
  if (base < 0 || rig.head_kept_bone < 0) return;
  // The neck's base hangs from the spine: from the nearest bone the body's pass keeps current.
  Mat2x3 parent = model[rig.head_kept_bone];
  for (int b : rig.head_between) parent = parent * local_matrix(pose.locals[b]);
  // Each bone kept kHeadKeepOfHip clear: its segment tested that much lower.
  const glm::vec2 keep(0.0f, kHeadKeepOfHip * rig.hip_height);
  thread_local std::vector<Mat2x3> m;  // facing space, by bone (the head's only)
  m.resize(static_cast<size_t>(sk.bone_count()));
  auto pose_head = [&](int b, float lift) {
    BoneLocal local = pose.locals[b];
    if (b == base) local.angle_ls += lift;
    if (b == rig.skull) local.angle_ls -= lift;  // the head stays level
    m[b] = (b == base ? parent : m[sk.parent(b)]) * local_matrix(local);
  };
  // The head as it is, bounded: where the ground profile says no ground rises into that
  // bound (flat ground, the common case), no level query.
  glm::vec2 bound_lo(1e30f), bound_hi(-1e30f);
  for (const int b : rig.head_bones) {
    pose_head(b, 0.0f);
    for (glm::vec2 q : {body.to_ws(bone_start(m[b])), body.to_ws(bone_end(m[b], sk.length(b)))}) {
      bound_lo = glm::min(bound_lo, q);
      bound_hi = glm::max(bound_hi, q);
    }
  }
  // The head's drawn flesh (AnimRig::flesh from flesh_level_from on: level with the skull) keeps
  // out of what rises above the skull (the body floor draws flesh on the ground under the head,
  // not into a face: a crocodile's and a harbour seal's snouts went 4 cm into stairs.json's
  // risers, their skulls clear).
  const bool head_flesh = rig.skull >= 0 && rig.flesh_level_from < rig.flesh.size();
  const glm::vec2 skull_ms = rig.skull >= 0 ? bone_start(rig.model_rest[rig.skull]) : glm::vec2(0.0f);
  float wall_over = INFINITY;
  if (head_flesh) {
    const glm::vec2 skull = bone_start(m[rig.skull]);
    wall_over = std::min(body.to_ws(skull).y, body.to_ws(bone_end(m[rig.skull], sk.length(rig.skull))).y);
    for (glm::vec2 q : {body.to_ws(skull + rig.head_flesh_lo), body.to_ws(skull + rig.head_flesh_hi)}) {
      bound_lo = glm::min(bound_lo, q);
      bound_hi = glm::max(bound_hi, q);
    }
  }
  if (!ctx.ground.may_rise_above(bound_lo.x, bound_hi.x, bound_lo.y - keep.y, bound_hi.y)) return;
  auto hits = [&](float lift, bool flesh) {
    for (const int b : rig.head_bones) {
      pose_head(b, lift);
      const float len = sk.length(b);
      if (!(len > 0.0f)) continue;
      const glm::vec2 seg[2] = {body.to_ws(bone_start(m[b])) - keep, body.to_ws(bone_end(m[b], len)) - keep};
      if (polyline_hits_level(ctx.level, seg, 2, ctx.hits)) return true;
    }
    if (flesh) {
      const glm::vec2 skull = bone_start(m[rig.skull]);
      for (size_t i = rig.flesh_level_from; i < rig.flesh.size(); ++i) {
        const glm::vec2 seg[2] = {body.to_ws(skull + (rig.flesh[i].a - skull_ms)), body.to_ws(skull + (rig.flesh[i].b - skull_ms))};
        if (polyline_hits_level(ctx.level, seg, 2, ctx.hits, -INFINITY, wall_over)) return true;
      }
    }
    return false;
  };
  if (!hits(0.0f, head_flesh)) return;
  // Turned up: towards the way the neck reaches from its base at rest (forward, for almost
  // every neck; a neck curled back under the body turns the other way).
  const float most = rig.nod_reach[0].x >= 0.0f ? kMaxHeadLift : -kMaxHeadLift;
  // Flesh that no lift clears (a muzzle in a wall ahead) leaves the head to its bones: lifted
  // all the way, a random creature's skull went 6.6 mm into a block above it.
  const bool flesh = head_flesh && !hits(most, true);
  if (!flesh && head_flesh && !hits(0.0f, false)) return;
  float lo = 0.0f, hi = 1.0f;  // fractions of the most: lo hits, hi clears (or is the last resort)
  bisect(lo, hi, kClearBisections, [&](float mid) { return hits(mid * most, flesh); });
  pose.locals[base].angle_ls += hi * most;
  pose.locals[rig.skull].angle_ls -= hi * most;
}

void keep_fin_clear(const AnimContext& ctx, const BodyFrame& body, const RigLimb& fin, const std::vector<Mat2x3>& model, Pose& pose) {
  // A fin (or folded wing) trailing into the ground or a step turns up at its root until it
  // clears.
  const Skeleton& sk = ctx.rig.skeleton;
  const size_t n = std::min<size_t>(fin.bones.size(), kMaxFinBones);
  glm::vec2 p[kMaxFinBones + 1];
  auto chain = [&] {  // facing space: the fin's joints and its tip
    Mat2x3 m = model[fin.girdle_bone];
    for (size_t k = 0; k < n; ++k) {
      m = m * local_matrix(pose.locals[fin.bones[k]]);
      p[k] = bone_start(m);
      if (k + 1 == n) p[n] = bone_end(m, sk.length(fin.bones[k]));
    }
  };
  auto hits = [&] {
    chain();
    glm::vec2 w[kMaxFinBones + 1];
    for (size_t k = 0; k <= n; ++k) w[k] = body.to_ws(p[k]);
    return polyline_hits_level(ctx.level, w, static_cast<int>(n + 1), ctx.hits);
  };
  if (n == 0 || !hits()) return;
  const float base = pose.locals[fin.bones[0]].angle_ls;
  const float up = p[n].x >= p[0].x ? 1.0f : -1.0f;  // the turn that raises the tip
  // The least turn that clears, raising the tip first (up to a quarter turn), then either way
  // in eighth turns up to three eighths (a step rising right in front of a folded wing).
  float turn = 0.0f;
  auto clears = [&](float t) {
    pose.locals[fin.bones[0]].angle_ls = base + t;
    return !hits();
  };
  for (float t : {0.5f * kPi * up, 0.25f * kPi * -up, 0.75f * kPi * up, 0.5f * kPi * -up, 0.75f * kPi * -up}) {
    if (clears(t)) {
      turn = t;
      break;
    }
  }
  if (turn == 0.0f) turn = 0.5f * kPi * up;  // nothing clears: the tip up, as before
  float lo = 0.0f, hi = 1.0f;  // fractions of the turn: lo hits, hi clears (or is the last resort)
  bisect(lo, hi, kFinBisections, [&](float mid) { return !clears(mid * turn); });
  pose.locals[fin.bones[0]].angle_ls = wrap_angle(base + hi * turn);
}

}  // namespace ossa::anim
