#include "ossa/anim/animator.h"

// [SECTION] helpers
// [SECTION] construction and reset
// [SECTION] update: turn, gait clock, legs
// [SECTION] swing planning (set_new_splines) and footholds
// [SECTION] body placement
// [SECTION] pose: spine, IK, arms, tail

#include <algorithm>
#include <cmath>

#include "ossa/math/angle.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa {

// [SECTION] helpers ----------------------------------------------------------------------

namespace {

constexpr float kReachLimit = 0.985f;  // stance legs never extend beyond this fraction
constexpr float kFootReach = 0.97f;     // a foothold counts as in reach within this fraction
constexpr float kMaxPitch = 0.9f;       // the body turns no steeper than this (radians)
constexpr float kMaxPitchStep = 0.03f;  // nor by more than this in one tick to keep a foot in reach
constexpr float kMaxPitchOff = 0.25f;   // nor further than this from the pitch of the ground
constexpr float kStepReach = 0.8f;      // near steps the body outruns a foot by this much of its reach
// A crouching leg steps up as high as a straight one this fraction of its reach long.
constexpr float kStepHeightOfReach = 0.8f;
// Lowest rest height of a girdle: a fraction of its leg's reach, and at least 1 mm.
constexpr float kMinRestHeightOfReach = 0.25f;
constexpr float kMinRestHeight = 0.001f;
constexpr size_t kMaxTailBones = 48;    // keep_tail_clear curls at most this many tail bones

// Level::ground_height_below for spans and drops the animator computes from a creature's
// proportions: any body a genome may describe (a shoulder behind its girdle, a slack below
// zero) gives a span in either order and a drop that may come out negative, which mean the
// same span and no drop.
std::optional<GroundHit> ground_below(const Level& level, float x0, float x1, float from_y, float max_drop) {
  return level.ground_height_below(std::min(x0, x1), std::max(x0, x1), from_y, std::max(max_drop, 0.0f));
}

// x - floor(x) in [0, 1), without a library call for the phases' range.
float frac(float x) {
  if (!(std::fabs(x) < 1e6f)) return x - std::floor(x);
  const float f = x - static_cast<float>(static_cast<int>(x));
  return f < 0.0f ? f + 1.0f : f;
}
float smoothstep(float a, float b, float x) {
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
// Signed shortest difference b - a of two phases, in (-0.5, 0.5].
float phase_diff(float a, float b) {
  float d = frac(b - a);
  return d > 0.5f ? d - 1.0f : d;
}
float circular_lerp(float a, float b, float t) { return frac(a + t * phase_diff(a, b)); }
// Did the phase, moving from prev to now (forward by less than half a cycle), pass x?
bool crossed(float prev, float now, float x) {
  const float d = phase_diff(prev, now);
  if (d <= 0.0f) return false;
  const float to_x = frac(x - prev);
  return to_x > 0.0f && to_x <= d;
}
// Below this a decaying quantity is zero: left alone, exponential decays run into denormal
// floats after a few thousand ticks, and arithmetic on those is a hundred times slower.
constexpr float kNegligible = 1e-12f;
float flush(float x) { return std::fabs(x) < kNegligible ? 0.0f : x; }

// Exponential approach: value moves towards target, keeping a fraction `keep` = exp(-rate·dt).
float approach(float value, float target, float keep) { return target + flush((value - target) * keep); }
// The convex hull of points (Andrew's monotone chain), counter-clockwise.
std::vector<glm::vec2> convex_hull(std::vector<glm::vec2> p) {
  std::sort(p.begin(), p.end(), [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::vec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0.0f) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0.0f) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}
glm::vec2 rotate(glm::vec2 v, float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
float bone_angle(const Mat2x3& m) { return std::atan2(m.m[1], m.m[0]); }
// Does the polyline p[0] - p[1] - ... pass through the interior of a collider (shrunk by a
// millimetre)? One query for its bounds, then a Liang-Barsky clip per segment and box.
bool polyline_hits_level(const Level& level, const glm::vec2* p, int n, std::vector<int>& hits) {
  glm::vec2 lo = p[0], hi = p[0];
  for (int i = 1; i < n; ++i) {
    lo = glm::min(lo, p[i]);
    hi = glm::max(hi, p[i]);
  }
  hits.clear();
  level.overlapping(Box{lo, hi}, hits);
  for (int h : hits) {
    const Box& box = level.box(h);
    for (int i = 0; i + 1 < n; ++i) {
      const glm::vec2 a = p[i], b = p[i + 1];
      float t0 = 0.0f, t1 = 1.0f;
      bool inside = true;
      for (int axis = 0; axis < 2 && inside; ++axis) {
        const float lo_a = box.min_ws[axis] + 1e-3f, hi_a = box.max_ws[axis] - 1e-3f;
        const float d = b[axis] - a[axis];
        if (std::fabs(d) < 1e-9f) {
          inside = a[axis] > lo_a && a[axis] < hi_a;
        } else {
          float u0 = (lo_a - a[axis]) / d, u1 = (hi_a - a[axis]) / d;
          if (u0 > u1) std::swap(u0, u1);
          t0 = std::max(t0, u0);
          t1 = std::min(t1, u1);
          inside = t0 < t1;
        }
      }
      if (inside) return true;
    }
  }
  return false;
}
float bump(float s) { return std::pow(std::max(0.0f, std::sin(kPi * s)), 0.7f); }

}  // namespace

const char* gait_name(Gait gait) {
  switch (gait) {
    case Gait::kIdle: return "idle";
    case Gait::kWalk: return "walk";
    case Gait::kRun: return "run";
    case Gait::kTrot: return "trot";
    case Gait::kGallop: return "gallop";
    case Gait::kCrawl: return "crawl";
  }
  return "unknown";
}

// [SECTION] construction and reset -------------------------------------------------------

Animator::Animator(const Creature& creature, SplinePrototypes prototypes, AnimatorParams params)
    : creature_(&creature), spline_prototypes_(std::move(prototypes)), params_(params) {
  const Skeleton& sk = creature.skeleton;
  pose_ = creature.rest_pose;
  model_rest_ = ossa::model_matrices(sk, pose_.locals);
  model_ = model_rest_;
  world_dirty_ = true;
  root_rest_y_ = bone_start(model_rest_[creature.root]).y;

  // Leg groups: one per girdle slot carrying legs, front first.
  for (int i = 0; i < static_cast<int>(creature.limbs.size()); ++i) {
    const Limb& limb = creature.limbs[i];
    if (limb.kind == LimbKind::kArm) arms_.push_back(i);
    if (limb.kind == LimbKind::kWing) wings_.push_back(i);
    if (limb.kind == LimbKind::kFin) fins_.push_back(i);
    if (limb.kind != LimbKind::kLeg) continue;
    LegInfo info;
    info.limb = i;
    info.upper = sk.length(limb.bones[0]);
    info.lower = sk.length(limb.bones[1]);
    info.reach = info.upper + info.lower;
    info.fold = 1.02f * std::fabs(info.upper - info.lower);
    info.bend = static_cast<float>(limb.bend_sign);
    info.foot_length = sk.length(limb.bones[2]);
    const glm::vec2 joint = bone_start(model_rest_[limb.bones[0]]);
    const glm::vec2 ankle = bone_end(model_rest_[limb.bones[1]], sk.length(limb.bones[1]));
    const glm::vec2 tip = bone_end(model_rest_[limb.bones[2]], sk.length(limb.bones[2]));
    info.foot_angle_ms = creature.contact == ContactMode::kFlat ? 0.0f : bone_angle(model_rest_[limb.bones[2]]);
    info.foot_offset_ms = creature.contact == ContactMode::kFlat ? glm::vec2(0.0f) : tip - ankle;
    info.foot_dir_ms = {std::cos(info.foot_angle_ms), std::sin(info.foot_angle_ms)};
    info.foot_span = glm::length(info.foot_offset_ms);
    info.leg_reach = kReachLimit * info.reach;
    info.contact_reach = info.leg_reach + info.foot_span;
    int group = -1;
    for (int g = 0; g < static_cast<int>(groups_.size()); ++g) {
      const Limb& other = creature.limbs[legs_[groups_[g].legs[0]].limb];
      if (other.girdle == limb.girdle && other.slot == limb.slot) group = g;
    }
    if (group < 0) {
      group = static_cast<int>(groups_.size());
      // A genome may pose a leg pointing up, leaving its girdle at or below the rest ground:
      // the girdle still stands a quarter of the leg's reach high (and never at zero height,
      // which every height-relative threshold below divides or scales by).
      const float rest_height = std::max({joint.y, kMinRestHeightOfReach * info.reach, kMinRestHeight});
      groups_.push_back({joint, rest_height, rest_height, {}});
    }
    groups_[group].legs.push_back(static_cast<int>(legs_.size()));
    info.group = group;
    legs_.push_back(info);
  }
  // Front (largest x) first; remap the legs' group indices.
  std::vector<int> order(groups_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return groups_[a].joint_ms.x > groups_[b].joint_ms.x; });
  std::vector<Group> sorted;
  for (int g : order) sorted.push_back(groups_[g]);
  groups_ = sorted;
  for (int g = 0; g < static_cast<int>(groups_.size()); ++g) {
    for (int leg : groups_[g].legs) {
      legs_[leg].group = g;
      groups_[g].step_height = std::max(groups_[g].step_height, kStepHeightOfReach * legs_[leg].contact_reach);
    }
  }
  climb_height_ = 0.0f;
  for (size_t g = 0; g < groups_.size(); ++g) {
    climb_height_ = g == 0 ? groups_[g].step_height : std::min(climb_height_, groups_[g].step_height);
  }
  feet_.resize(legs_.size());
  foot_of_leg_.resize(legs_.size());
  for (size_t i = 0; i < legs_.size(); ++i) foot_of_leg_[i] = static_cast<int>(i);

  hip_height_ = 0.0f;
  for (const Group& g : groups_) hip_height_ += g.rest_height;
  hip_height_ = groups_.empty() ? std::max(root_rest_y_, 0.05f) : hip_height_ / static_cast<float>(groups_.size());
  hip_height_ = std::max(hip_height_, 0.02f);
  float x_min = 0.0f, x_max = 0.0f;
  for (int b = 0; b < sk.bone_count(); ++b) {
    const glm::vec2 p = bone_start(model_rest_[b]);
    x_min = std::min(x_min, p.x);
    x_max = std::max(x_max, p.x);
  }
  body_half_length_ = std::max(0.5f * (x_max - x_min), 0.05f);
  auto distinct_outlines = [&](const std::vector<int>& limbs) {
    std::vector<int> out;
    for (int a : limbs) {
      auto same = [&](int b) {
        const Limb &la = creature.limbs[a], &lb = creature.limbs[b];
        for (size_t k = 0; k < la.bones.size(); ++k) {
          const int i = la.bones[k], j = lb.bones[k];
          if (bone_start(model_rest_[i]) != bone_start(model_rest_[j]) ||
              bone_end(model_rest_[i], sk.length(i)) != bone_end(model_rest_[j], sk.length(j))) {
            return false;
          }
        }
        return true;
      };
      if (std::none_of(out.begin(), out.end(), same)) out.push_back(a);
    }
    return out;
  };
  outline_arms_ = distinct_outlines(arms_);
  outline_fins_ = distinct_outlines(fins_);
  outline_wings_ = distinct_outlines(wings_);
  if (groups_.size() == 1) {
    const Group& g = groups_[0];
    for (size_t i = 0; i < creature.limbs.size(); ++i) {
      const LimbKind kind = creature.limbs[i].kind;
      if (kind != LimbKind::kArm && kind != LimbKind::kWing) continue;
      const glm::vec2 v = bone_start(model_rest_[creature.limbs[i].bones[0]]) - g.joint_ms;
      if (v.x > front_shoulder_.x) {
        front_shoulder_ = v;
        // Its rest height above the ground, less the clearance keep_shoulder_out keeps, and
        // a little.
        front_slack_ = v.y + g.rest_height - 0.2f * hip_height_;
      }
    }
  }
  for (size_t i = 0; i < legs_.size(); ++i) feet_[i].offset = leg_target_offset(static_cast<int>(i));

  // FK caches: rest local matrices, the bones the animator moves, the limb chains.
  const int root = creature.root;
  rest_local_m_.resize(sk.bone_count());
  for (int b = 0; b < sk.bone_count(); ++b) rest_local_m_[b] = local_matrix(pose_.locals[b]);
  dynamic_bone_.assign(sk.bone_count(), legs_.empty() ? 1 : 0);  // legless bodies bend all along
  dynamic_bone_[root] = 1;
  if (creature.skull >= 0) dynamic_bone_[creature.skull] = 1;
  for (int b : creature.tail) dynamic_bone_[b] = 1;
  std::vector<uint8_t> limb_bone(sk.bone_count(), 0);
  for (const Limb& limb : creature.limbs) {
    for (int b : limb.bones) limb_bone[b] = 1;
  }
  std::vector<uint8_t> leg_ik_bone(sk.bone_count(), 0);
  for (const LegInfo& info : legs_) {
    for (int k = 0; k < 3; ++k) leg_ik_bone[creature.limbs[info.limb].bones[k]] = 1;
  }
  for (int b = 0; b < sk.bone_count(); ++b) {
    if (limb_bone[b] && !leg_ik_bone[b]) other_limb_bones_.push_back(b);
  }
  // Girdles are rigid to the root unless a bone between bends (legless bodies).
  bool rigid = sk.parent(root) < 0 && !legs_.empty();
  std::vector<uint8_t> needed(sk.bone_count(), 0), girdle(sk.bone_count(), 0);
  for (const Limb& limb : creature.limbs) {
    girdle[limb.girdle_bone] = 1;
    for (int b = limb.girdle_bone; b >= 0; b = sk.parent(b)) {
      needed[b] = 1;
      if (b != root && dynamic_bone_[b]) rigid = false;
      if (sk.parent(b) < 0 && b != root) rigid = false;
    }
  }
  needed[root] = 1;
  tick_bone_ = limb_bone;
  if (rigid) {
    const Mat2x3 root_inv = inverse(model_rest_[root]);
    needed_bones_ = {root};
    tick_bone_[root] = 1;
    for (int b = 0; b < sk.bone_count(); ++b) {
      if (!girdle[b] || b == root) continue;
      girdle_bones_.push_back(b);
      girdle_rel_.push_back(root_inv * model_rest_[b]);
      tick_bone_[b] = 1;
    }
    for (LegInfo& info : legs_) {
      const Mat2x3 rel = root_inv * model_rest_[creature.limbs[info.limb].girdle_bone];
      info.girdle_rel_angle = bone_angle(rel);
    }
    // The wall sweep's outline of the body in slabs along it (a pitched body's single box
    // would meet the stairs it climbs): the spine's segments relative to the root's frame,
    // clipped to each slab, reduced to their hull.
    std::vector<int> body = {root};
    body.insert(body.end(), creature.back.begin(), creature.back.end());
    body.insert(body.end(), creature.neck.begin(), creature.neck.end());
    std::vector<std::pair<glm::vec2, glm::vec2>> segments;
    float x0 = 1e30f, x1 = -1e30f;
    for (int b : body) {
      const glm::vec2 p = root_inv.apply(bone_start(model_rest_[b])), q = root_inv.apply(bone_end(model_rest_[b], sk.length(b)));
      segments.push_back({p, q});
      x0 = std::min({x0, p.x, q.x});
      x1 = std::max({x1, p.x, q.x});
    }
    constexpr int kSlabs = 4;
    for (int k = 0; k < kSlabs; ++k) {
      const float a = x0 + (x1 - x0) * static_cast<float>(k) / kSlabs;
      const float b = x0 + (x1 - x0) * static_cast<float>(k + 1) / kSlabs;
      std::vector<glm::vec2> points;
      for (const auto& segment : segments) {
        glm::vec2 p = segment.first, q = segment.second;  // (clang 14 lambdas cannot capture bindings)
        if (p.x > q.x) std::swap(p, q);
        if (q.x < a || p.x > b) continue;
        auto at = [&](float x) { return q.x - p.x < 1e-9f ? p : p + (q - p) * ((x - p.x) / (q.x - p.x)); };
        points.push_back(p.x < a ? at(a) : p);
        points.push_back(q.x > b ? at(b) : q);
      }
      if (!points.empty()) body_slabs_.push_back(convex_hull(points));
    }
    for (const std::vector<glm::vec2>& slab : body_slabs_) body_hull_.insert(body_hull_.end(), slab.begin(), slab.end());
    body_hull_ = convex_hull(body_hull_);
    if (creature.skull >= 0) {
      const Mat2x3& skull = model_rest_[creature.skull];
      skull_rel_ = root_inv.apply(bone_start(skull));
      skull_span_ = bone_end(skull, sk.length(creature.skull)) - bone_start(skull);
    }
    // body_bound_ws: the extent of the hull and the skull joint, and its highest hull point.
    body_lo_ = body_hi_ = body_top_ = body_hull_[0];
    for (glm::vec2 p : body_hull_) {
      body_lo_ = glm::min(body_lo_, p);
      body_hi_ = glm::max(body_hi_, p);
      if (p.y > body_top_.y) body_top_ = p;
    }
    if (creature.skull >= 0) {
      body_lo_ = glm::min(body_lo_, skull_rel_);
      body_hi_ = glm::max(body_hi_, skull_rel_);
    }
  } else {
    // The neck and head take part in the wall sweep.
    for (int b : creature.neck) needed[b] = 1;
    if (creature.skull >= 0) needed[creature.skull] = 1;
    for (int b = 0; b < sk.bone_count(); ++b) {
      if (!needed[b]) continue;
      needed_bones_.push_back(b);
      tick_bone_[b] = 1;
    }
  }
  // The tail hangs from the nearest of its ancestors that update() keeps current, through the
  // bones between (at rest in a rigid body, bent by the wave in a legless one).
  if (!creature.tail.empty()) {
    std::vector<int> between;
    int b = sk.parent(creature.tail[0]);
    while (b >= 0 && !tick_bone_[b]) {
      between.push_back(b);
      b = sk.parent(b);
    }
    if (b >= 0) {
      tail_base_bone_ = b;
      tail_between_.assign(between.rbegin(), between.rend());
      for (int t : creature.tail) tail_length_ += sk.length(t);
      // Bones that never bend: their product once.
      bool rest = true;
      for (int t : tail_between_) rest = rest && !dynamic_bone_[t];
      if (rest) {
        for (int t : tail_between_) tail_between_rest_ = tail_between_rest_ * rest_local_m_[t];
        tail_between_.clear();
      }
    }
  }
  // The joints build_pose rewrites each tick (everything else keeps its rest value).
  for (int b = 0; b < sk.bone_count(); ++b) {
    if (dynamic_bone_[b] || (limb_bone[b] && !leg_ik_bone[b])) touched_bones_.push_back(b);
  }
  group_height_.resize(groups_.size());
  group_need_.resize(groups_.size());
  group_room_.resize(groups_.size());
  group_swing_up_.resize(groups_.size());
  leg_dirs_.resize(legs_.size());
}

float Animator::walk_speed() const { return std::sqrt(0.5f * params_.gravity * hip_height_); }
float Animator::run_speed() const { return std::sqrt(2.5f * params_.gravity * hip_height_); }

const Pose& Animator::pose() const {
  if (leg_angles_dirty_) {
    // The legs' joint angles from the directions build_pose left (the matrices need none).
    const Creature& c = *creature_;
    for (size_t i = 0; i < legs_.size(); ++i) {
      const LegInfo& info = legs_[i];
      const Limb& limb = c.limbs[info.limb];
      const auto& [upper_dir, lower_dir, foot_dir] = leg_dirs_[i];
      const float girdle = std::isnan(info.girdle_rel_angle) ? bone_angle(model_[limb.girdle_bone])
                                                              : pose_.locals[c.root].angle_ls + info.girdle_rel_angle;
      const float upper = fast_atan2(upper_dir.y, upper_dir.x);
      const float lower = fast_atan2(upper_dir.x * lower_dir.y - upper_dir.y * lower_dir.x, glm::dot(upper_dir, lower_dir));
      const float foot = foot_dir == info.foot_dir_ms ? info.foot_angle_ms : fast_atan2(foot_dir.y, foot_dir.x);
      pose_.locals[limb.bones[0]].angle_ls = wrap_angle(upper - girdle);
      pose_.locals[limb.bones[1]].angle_ls = lower;
      pose_.locals[limb.bones[2]].angle_ls = wrap_angle(foot - (upper + lower));
    }
    leg_angles_dirty_ = false;
  }
  return pose_;
}

Mat2x3 Animator::model_to_world() const {
  Mat2x3 m;
  m.m[0] = static_cast<float>(facing_);
  m.m[4] = body_x_;
  return m;
}

glm::vec2 Animator::foot_ws(int leg) const {
  const Limb& limb = leg_limb(leg);
  const Skeleton& sk = creature_->skeleton;
  const int b = creature_->contact == ContactMode::kFlat ? limb.bones[1] : limb.bones[2];
  return to_world(bone_end(model_[b], sk.length(b)));
}

const std::vector<Mat2x3>& Animator::model_matrices() const {
  if (model_dirty_) {
    const Skeleton& sk = creature_->skeleton;
    const std::vector<int>& parents = sk.parents();
    for (int b = 0; b < sk.bone_count(); ++b) {
      if (tick_bone_[b]) continue;
      const Mat2x3 local = dynamic_bone_[b] ? local_matrix(pose_.locals[b]) : rest_local_m_[b];
      model_[b] = parents[b] < 0 ? local : model_[parents[b]] * local;
    }
    model_dirty_ = false;
  }
  return model_;
}

const std::vector<Mat2x3>& Animator::world_matrices() const {
  model_matrices();
  if (world_dirty_) {
    world_.resize(model_.size());
    const Mat2x3 m = model_to_world();
    for (size_t i = 0; i < model_.size(); ++i) world_[i] = m * model_[i];
    world_dirty_ = false;
  }
  return world_;
}

void Animator::body_boxes(bool slabs, std::vector<Box>* boxes) const {
  const Skeleton& sk = creature_->skeleton;
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
  auto add_point = [&](glm::vec2 p_ms) {
    const glm::vec2 p = to_world(p_ms);
    box.min_ws = glm::min(box.min_ws, p);
    box.max_ws = glm::max(box.max_ws, p);
  };
  auto add = [&](int b) {
    add_point(bone_start(model_[b]));
    add_point(bone_end(model_[b], sk.length(b)));
  };
  if (!body_slabs_.empty()) {
    const Mat2x3 root = model_[creature_->root];
    if (slabs) {
      for (const std::vector<glm::vec2>& slab : body_slabs_) {
        begin();
        for (glm::vec2 p : slab) add_point(root.apply(p));
      }
    } else {
      begin();
      for (glm::vec2 p : body_hull_) add_point(root.apply(p));
    }
    if (creature_->skull >= 0) {
      if (slabs) begin();
      const glm::vec2 skull = root.apply(skull_rel_);
      add_point(skull);
      add_point(skull + skull_span_);
    }
  } else {
    begin();
    add(creature_->root);
    for (int b : creature_->back) add(b);
    for (int b : creature_->neck) add(b);
    if (creature_->skull >= 0) add(creature_->skull);
  }
  // An arm's shoulder is the body's too (the arm itself folds out of the way): it meets a
  // step rising in front of a low chest.
  for (int a : arms_) {
    if (slabs) begin();
    add_point(bone_start(model_[creature_->limbs[a].bones[0]]));
  }
  for (int a : fins_) {
    if (slabs) begin();
    for (int b : creature_->limbs[a].bones) add(b);
  }
  // Arms swing: count the whole reach of each arm, forward and back, not just this pose.
  // (They come last: the sweep tests them against walls only, as they lift over the rest.)
  for (int a : arms_) {
    const Limb& arm = creature_->limbs[a];
    const glm::vec2 shoulder = bone_start(model_[arm.bones[0]]);
    const float reach = sk.length(arm.bones[0]) + sk.length(arm.bones[1]) + sk.length(arm.bones[2]);
    if (slabs) begin();
    add_point(shoulder - glm::vec2(reach, reach));
    add_point(shoulder + glm::vec2(reach, 0.0f));
  }
  if (open) boxes->push_back(box);
}

bool Animator::body_bound_ws(Box* bound, float* top_y) const {
  if (body_slabs_.empty() || !fins_.empty() || !arms_.empty()) return false;
  const Mat2x3& m = model_[creature_->root];
  // Interval arithmetic over [body_lo_, body_hi_], widened by far more than the rounding of
  // apply() or of these bounds (a few ulps of the extent); rounding is monotonic, so the
  // translation, the skull's span and to_world keep the bounds in order.
  const float extent = std::max({-body_lo_.x, body_hi_.x, -body_lo_.y, body_hi_.y});
  auto range = [&](float a, float b, float offset) {
    const float eps = 1e-5f * (std::fabs(a) + std::fabs(b)) * extent;
    const float lo = std::min(a * body_lo_.x, a * body_hi_.x) + std::min(b * body_lo_.y, b * body_hi_.y) - eps;
    const float hi = std::max(a * body_lo_.x, a * body_hi_.x) + std::max(b * body_lo_.y, b * body_hi_.y) + eps;
    return glm::vec2(lo + offset, hi + offset);
  };
  glm::vec2 x = range(m.m[0], m.m[2], m.m[4]), y = range(m.m[1], m.m[3], m.m[5]);
  if (creature_->skull >= 0) {  // the skull's far end: its joint plus a span kept level
    x = {std::min(x[0], x[0] + skull_span_.x), std::max(x[1], x[1] + skull_span_.x)};
    y = {std::min(y[0], y[0] + skull_span_.y), std::max(y[1], y[1] + skull_span_.y)};
  }
  const float x0 = to_world({x[0], 0.0f}).x, x1 = to_world({x[1], 0.0f}).x;
  *bound = Box{{std::min(x0, x1), y[0]}, {std::max(x0, x1), y[1]}};
  *top_y = m.apply(body_top_).y;
  return std::isfinite(x0) && std::isfinite(x1) && std::isfinite(y[0]) && std::isfinite(y[1]) && std::isfinite(*top_y);
}

void Animator::reset(glm::vec2 position_ws, const Level& level, int facing) {
  // A position inside a box (a spawn placed in the ground) stands on the ground above it.
  position_ws = level.free_point_above(position_ws);
  facing_ = facing < 0 ? -1 : 1;
  body_x_ = position_ws.x;
  speed_ = 0.0f;
  phase_ = 0.0f;
  frequency_ = 0.0f;
  moving_ = false;
  blocked_ = false;
  lean_ = 0.0f;
  pitch_ = 0.0f;
  run_factor_ = trot_factor_ = gallop_factor_ = 0.0f;
  tail_angle_ = tail_rate_ = root_vy_ = body_lift_ = 0.0f;
  steps_ = 0;
  idle_time_ = 0.0f;
  gait_ = legs_.empty() ? Gait::kCrawl : Gait::kIdle;
  const float search = std::max(2.0f * hip_height_, 1.0f);
  auto ground_at = [&](float x0, float x1, float fallback) {
    auto hit = ground_below(level, std::min(x0, x1), std::max(x0, x1), position_ws.y + search, 100.0f);
    return hit ? hit->height_ws : fallback;
  };
  root_y_ = ground_at(body_x_ - body_half_length_, body_x_ + body_half_length_, position_ws.y) + root_rest_y_;
  for (size_t i = 0; i < legs_.size(); ++i) {
    const LegInfo& info = legs_[i];
    const Limb& limb = creature_->limbs[info.limb];
    const glm::vec2 ankle = bone_end(model_rest_[limb.bones[1]], creature_->skeleton.length(limb.bones[1]));
    const glm::vec2 contact_ms = ankle + info.foot_offset_ms;
    Foot& f = feet_[foot_of_leg_[i]];
    f = Foot{};
    f.offset = leg_target_offset(static_cast<int>(i));
    const float x = to_world(contact_ms).x;
    f.pos_ws = {x, ground_at(x - 0.02f, x + 0.02f, position_ws.y)};
  }
  // Each foot stands where it fits (not across the edge of a step).
  for (size_t i = 0; i < legs_.size(); ++i) {
    glm::vec2 landing;
    Foot& f = feet_[foot_of_leg_[i]];
    if (find_landing(static_cast<int>(i), f.pos_ws.x, level, &landing)) f.pos_ws = landing;
    update_stance_clearance(f, level);
  }
  place_body(0.0f, level);
  build_pose(0.0f, level);
}

// [SECTION] update: turn, gait clock, legs ------------------------------------------------

void Animator::update(float dt, float desired_velocity, const Level& level) {
  if (!(dt > 0.0f) || !std::isfinite(desired_velocity)) return;
  const float ism = std::max(params_.interpolation_speed_multiplier, 0.01f);
  if (dt != decay_.dt || ism != decay_.ism) {
    decay_ = {dt, ism, std::exp(-6.0f * ism * dt), std::exp(-5.0f * ism * dt), std::exp(-4.0f * ism * dt),
              std::exp(-10.0f * ism * dt), std::exp(-14.0f * ism * dt)};
  }
  const int want = desired_velocity > 1e-4f ? 1 : desired_velocity < -1e-4f ? -1 : 0;
  if (want != 0 && want != facing_) reverse(level);

  float target = std::fabs(desired_velocity);
  if (blocked_) {
    if (want != blocked_dir_) {
      blocked_ = false;
    } else {
      target = 0.0f;
      blocked_retry_ -= dt;
      // Re-test the way ahead now and then: the level may have changed.
      if (blocked_retry_ <= 0.0f && !legs_.empty()) {
        blocked_retry_ = 0.5f;
        glm::vec2 landing;
        if (find_landing(blocked_leg_, landing_x(blocked_leg_, std::fabs(desired_velocity)), level, &landing)) {
          blocked_ = false;
        }
      }
    }
  }
  // The stick sets the speed precisely [T 4.1]; starting and stopping are immediate [T 5.1]
  // (the half-length first step and the eased stop make them read well).
  speed_ = target <= 1e-4f ? 0.0f : target;
  update_gait();
  lean_ = approach(lean_, -params_.max_spine_rotation * std::min(speed_ / run_speed(), 1.2f), decay_.lean);

  // Body motion, stopped by walls the body would run into.
  float dx = facing_ * speed_ * dt;
  if (dx != 0.0f) {
    // Low obstacles are the legs' business (steps); the body only meets walls. The ground
    // line under the body runs through the girdles' support, tilted with the body's pitch.
    // The whole body is swept first; only if that meets something, its parts one by one.
    const float support = root_y_ - root_rest_y_ * params_.stance_height;
    const float slope = std::tan(pitch_);
    const glm::vec2 margin(0.03f + 0.02f * hip_height_, 0.0f);
    auto ground_under = [&](const Box& box) {
      const float a = slope * facing_ * (box.min_ws.x - body_x_), b = slope * facing_ * (box.max_ws.x - body_x_);
      return support + std::min(a, b);
    };
    // Cheaper still, and before that: a box around the body from the root and the hull's
    // extent alone (body_bound_ws), swept as a box holding the one swept below (its bottom no
    // higher than theirs can be: 0.3 h above the bound's, or a point of the body). Whatever it
    // does not meet, the body does not meet either.
    Box bound;
    float top_y;
    bool near_something = true;
    if (body_bound_ws(&bound, &top_y)) {
      const Box swept{{bound.min_ws.x - margin.x, std::min(bound.min_ws.y + 0.3f * hip_height_, top_y)},
                      {bound.max_ws.x + 1e-3f + margin.x, bound.max_ws.y + 1e-3f}};
      auto hit = level.sweep_box(swept, {dx, 0.0f});
      near_something = hit && hit->t < 1.0f;
    }
    body_boxes_.clear();
    if (near_something) {
      body_boxes(false, &body_boxes_);
      Box all = body_boxes_[0];
      all.min_ws.y = std::min(std::max(all.min_ws.y + 0.3f * hip_height_, ground_under(all) + params_.max_step_up * hip_height_),
                              all.max_ws.y);
      auto hit = level.sweep_box(Box{all.min_ws - margin, glm::max(all.max_ws, all.min_ws + glm::vec2(1e-3f)) + margin}, {dx, 0.0f});
      if (hit && hit->t < 1.0f) body_boxes(!body_slabs_.empty(), &body_boxes_);
      else body_boxes_.clear();
    }
    float move = std::fabs(dx);
    const size_t first_arm = body_boxes_.empty() ? 0 : body_boxes_.size() - arms_.size();
    for (size_t k = 0; k < body_boxes_.size(); ++k) {
      Box box = body_boxes_[k];
      const float hi_y = box.max_ws.y;
      const float ground = ground_under(box);
      box.min_ws.y = std::min(std::max(box.min_ws.y + 0.3f * hip_height_, ground + params_.max_step_up * hip_height_), hi_y);
      box.max_ws = glm::max(box.max_ws, box.min_ws + glm::vec2(1e-3f));
      float t = 1.0f;  // fraction of dx until the part meets something
      if (k < first_arm) {
        if (auto hit = level.sweep_box(box, {dx, 0.0f})) t = hit->t;
      }
      // Walls (reaching above the body) are met a few centimetres early: arms and head
      // settle forward a little when the body stops.
      if (auto wall = level.sweep_box(Box{box.min_ws - margin, box.max_ws + margin}, {dx, 0.0f});
          wall && wall->t < 1.0f && level.box(wall->index).top() > hi_y) {
        t = wall->t;
      }
      if (t < 1.0f) {
        move = std::min(move, std::max(0.0f, t * std::fabs(dx) - 1e-4f));
        blocked_ = true;
        blocked_dir_ = facing_;
        blocked_retry_ = 0.5f;
      }
    }
    dx = facing_ * move;
  }
  if (dx != 0.0f) {
    for (size_t i = 0; i < legs_.size(); ++i) {
      const Foot& f = feet_[foot_of_leg_[i]];
      const LegInfo& info = legs_[i];
      const glm::vec2 joint = to_model(girdle_ws(info.group));
      const bool stance = f.state == LegState::kStance;
      const glm::vec2 contact = to_model(stance ? f.pos_ws : f.to_ws);
      // The anchor lies within a foot's length of the contact point: a foot that far ahead of
      // where the joint goes cannot hold it back.
      if (contact.x - info.foot_span > joint.x + std::fabs(dx)) continue;
      float r;
      const glm::vec2 anchor = leg_anchor(static_cast<int>(i), contact, joint, level, stance ? f.stance_clear : f.swing_clear, &r);
      const float h = joint.y - anchor.y;
      // Near steps a foot behind keeps the joint within kStepReach of the leg's reach: a leg
      // stretched back across a flight of stairs would cut the edges between.
      const bool near_steps = anchor.x < joint.x && !(stance ? f.stance_reach_clear : f.swing_clear).clear_above(anchor.y + 0.1f * hip_height_);
      // How far forward the joint may go with this foot still in reach (model x).
      const float level_reach = std::sqrt(std::max(r * r - h * h, 0.0f));
      const float near_reach = std::max(std::sqrt(std::max(kStepReach * kStepReach * r * r - h * h, 0.0f)), 0.5f * level_reach);
      const float ahead = anchor.x + (near_steps ? near_reach : level_reach) - joint.x;
      dx = facing_ * std::min(std::fabs(dx), std::max(ahead, 0.0f));
      // Nor does the body leave a swinging foot behind further than its leg reaches (a foot
      // that lifted late, far back on stairs, would sweep the leg through the steps between).
      const glm::vec2 now = to_model(f.pos_ws);
      if (!stance && now.x < joint.x) {
        const float R = info.contact_reach, hn = joint.y - now.y;
        const float lead = now.x + std::sqrt(std::max(R * R - hn * hn, 0.0f)) - joint.x;
        dx = facing_ * std::min(std::fabs(dx), std::max(lead, 0.0f));
      }
      // A foot left below and behind on stairs whose leg would cut the edge of a step above
      // it lifts now (see the gait clock below) rather than drag its knee through the step.
      // The body waits for it if the leg clears the steps where it is.
      if (stance && anchor.x < joint.x && !f.stance_reach_clear.clear_above(contact.y) &&
          stance_leg_hits(static_cast<int>(i), joint + glm::vec2(std::fabs(dx), 0.0f), level)) {
        feet_[foot_of_leg_[i]].holds_body = true;
        if (!stance_leg_hits(static_cast<int>(i), joint, level)) dx = 0.0f;
      }
    }
  }
  body_x_ += dx;

  if (legs_.empty()) {
    crawl_phase_ = frac(crawl_phase_ + speed_ * dt / std::max(body_half_length_, 0.05f));
    if (blocked_) speed_ = 0.0f;
    gait_ = speed_ > 0.0f ? Gait::kCrawl : Gait::kIdle;
    idle_time_ += dt;
    place_body(dt, level);
    build_pose(dt, level);
    return;
  }

  const float dphi = frequency_ * dt;
  if (speed_ > 0.0f && !blocked_) {
    const bool starting = !moving_;
    if (starting) {
      // Start so the lead leg lifts now; its first step is half a stride [T 4.4.1].
      moving_ = true;
      phase_ = frac(duty_ - feet_[foot_of_leg_[0]].offset);
      for (size_t i = 0; i < legs_.size(); ++i) {
        Foot& f = feet_[foot_of_leg_[i]];
        f.phase_prev = frac(phase_ + f.offset);
      }
    }
    phase_ = frac(phase_ + dphi);
    update_target_offsets();
    for (size_t i = 0; i < legs_.size(); ++i) {
      Foot& f = feet_[foot_of_leg_[i]];
      const float target_offset = target_offset_[i];
      f.offset = circular_lerp(f.offset, target_offset,
                               std::min(1.0f, 0.6f * ism * dt / std::max(std::fabs(phase_diff(f.offset, target_offset)), 1e-6f)));
      const float p = frac(phase_ + f.offset);
      if (f.state == LegState::kStance) {
        bool lift = starting ? p >= duty_ : crossed(f.phase_prev, p, duty_);
        lift |= f.holds_body;
        // A foot left behind (a gait change, a shortened step) lifts before it would slide.
        const LegInfo& info = legs_[i];
        const glm::vec2 joint = to_model(girdle_ws(info.group));
        const glm::vec2 contact = to_model(f.pos_ws);
        if (!lift && contact.x - info.foot_span < joint.x) {  // else its anchor is ahead of the joint
          float r;
          const glm::vec2 anchor = leg_anchor(static_cast<int>(i), contact, joint, level, f.stance_clear, &r);
          if (glm::length(anchor - joint) > kFootReach * r && anchor.x < joint.x) lift = true;
        }
        if (lift) set_new_splines(static_cast<int>(i), level, std::max(1.0f - p, 0.05f));
      } else if (!f.easing) {
        f.progress += f.rate * dphi;
      }
      f.phase_prev = p;
    }
  } else {
    moving_ = false;
    idle_time_ += dt;
    for (size_t i = 0; i < legs_.size(); ++i) {
      Foot& f = feet_[foot_of_leg_[i]];
      if (f.state == LegState::kSwing && !f.easing) start_ease(static_cast<int>(i), level);
    }
  }
  if (blocked_) speed_ = 0.0f;
  for (size_t i = 0; i < legs_.size(); ++i) {
    Foot& f = feet_[foot_of_leg_[i]];
    if (f.state != LegState::kSwing) continue;
    if (f.easing) f.progress += f.rate * dt;
    if (!f.easing && f.progress < 0.9f && moving_) {
      // Re-aim a swinging foot when the body has been held back (legs behind it slowed on
      // stairs): the landing stays half a stance ahead of where the girdle will be.
      const float remaining = (1.0f - f.progress) / std::max(f.rate, 1e-3f);
      const float wanted = landing_x(static_cast<int>(i), speed_, remaining);
      if (facing_ * (f.to_ws.x - wanted) > 0.08f * stride_) {
        glm::vec2 landing;
        if (find_landing(static_cast<int>(i), wanted, level, &landing) && facing_ * (landing.x - f.to_ws.x) < 0.0f) {
          const glm::vec2 old_to = f.to_ws;
          const float old_raise = f.raise;
          f.to_ws = landing;
          if (!raise_for_clearance(static_cast<int>(i), level)) {  // keep the old landing
            f.to_ws = old_to;
            f.raise = old_raise;
            update_swing_clearance(static_cast<int>(i), level);
          }
        }
      }
    }
    if (f.progress >= 1.0f && !foot_fits(static_cast<int>(i), f.to_ws, level)) {
      // Planned facing the other way (the creature turned meanwhile): the foot would reach
      // into a step. It moves on to the nearest place it fits.
      glm::vec2 spot;
      if (nearest_fit(static_cast<int>(i), f.to_ws, level, &spot, true) && glm::length(spot - f.to_ws) > 1e-4f) {
        step_to(static_cast<int>(i), spot, level);
        continue;
      }
    }
    if (f.progress >= 1.0f && !f.easing && moving_) {
      // A foot stepping down further than the leg reaches from the still-high body waits
      // above its landing point while the body comes down to it (see build_pose).
      const LegInfo& info = legs_[i];
      const glm::vec2 joint = to_model(girdle_ws(info.group));
      float r;
      const glm::vec2 anchor = leg_anchor(static_cast<int>(i), to_model(f.to_ws), joint, level, f.swing_clear, &r);
      if (glm::length(anchor - joint) > r && std::fabs(anchor.x - joint.x) < r) {
        if (f.hover < 0.5f) {
          f.hover += dt;
          f.progress = 1.0f;
          f.pos_ws = f.to_ws;
          continue;
        }
        // The body did not come down in time (other feet hold it up): set the foot down on the
        // nearest place below the joint it reaches instead, from where it hangs now.
        glm::vec2 spot;
        const glm::vec2 below_joint = to_world({joint.x, f.to_ws.y});
        if (nearest_fit(static_cast<int>(i), below_joint, level, &spot) && reaches(static_cast<int>(i), spot)) {
          const float R = info.contact_reach;
          const float dxj = to_model(f.to_ws).x - joint.x;
          const glm::vec2 hanging = to_world({to_model(f.to_ws).x, joint.y - std::sqrt(std::max(R * R - dxj * dxj, 0.0f))});
          f.pos_ws = hanging;
          start_ease(static_cast<int>(i), level, &spot);
          f.hover = 0.0f;
          continue;
        }
      }
    }
    if (f.progress >= 1.0f) {
      f.hover = 0.0f;
      f.state = LegState::kStance;
      f.pos_ws = f.to_ws;
      f.easing = false;
      update_stance_clearance(f, level);
      ++steps_;
      continue;
    }
    f.pos_ws = swing_point(f, std::clamp(f.progress, 0.0f, 1.0f));
  }
  place_body(dt, level);
  build_pose(dt, level);
}

void Animator::update_gait() {
  froude_ = speed_ * speed_ / (params_.gravity * hip_height_);
  run_factor_ = approach(run_factor_, smoothstep(params_.run_froude_start, params_.run_froude_end, froude_), decay_.run);
  float trot = smoothstep(0.7f * params_.trot_froude, 1.3f * params_.trot_froude, froude_);
  float gallop = smoothstep(0.85f * params_.gallop_froude, 1.15f * params_.gallop_froude, froude_);
  if (params_.gait_override != GaitOverride::kAuto) {
    trot = params_.gait_override == GaitOverride::kWalk ? 0.0f : 1.0f;
    gallop = params_.gait_override == GaitOverride::kGallop ? 1.0f : 0.0f;
  }
  trot_factor_ = approach(trot_factor_, trot, decay_.gait);
  gallop_factor_ = approach(gallop_factor_, gallop, decay_.gait);
  duty_ = params_.duty_walk + (params_.duty_run - params_.duty_walk) * run_factor_;

  // Stride: Alexander's relation, limited so that a stance foot half a stance ahead or
  // behind its girdle stays within reach.
  if (froude_ != stride_froude_) {
    stride_froude_ = froude_;
    stride_pow_ = std::pow(std::max(froude_, 1e-4f), 0.3f);
  }
  float stride = 2.3f * hip_height_ * stride_pow_ * params_.step_distance_multiplier;
  if (params_.stance_height != reach_x_stance_height_) {
    reach_x_stance_height_ = params_.stance_height;
    min_reach_x_ = 1e30f;
    for (const LegInfo& leg : legs_) {
      const float h = groups_[leg.group].rest_height * params_.stance_height;
      min_reach_x_ = std::min(min_reach_x_, std::sqrt(std::max(leg.contact_reach * leg.contact_reach - h * h, 0.0f)));
    }
  }
  // The shortest reach limits most: x ↦ 1.8 x / duty is monotonic also in float arithmetic.
  const float max_stride = std::min(1e30f, 2.0f * 0.9f * min_reach_x_ / std::max(duty_, 0.2f));
  stride_ = std::clamp(stride, 0.25f * hip_height_, std::max(max_stride, 0.25f * hip_height_));
  frequency_ = speed_ > 0.0f ? speed_ / stride_ : 0.0f;

  if (legs_.empty()) {
    gait_ = speed_ > 0.0f ? Gait::kCrawl : Gait::kIdle;
  } else if (speed_ <= 0.0f) {
    gait_ = Gait::kIdle;
  } else if (groups_.size() == 1) {
    gait_ = run_factor_ > 0.5f ? Gait::kRun : Gait::kWalk;
  } else {
    gait_ = gallop_factor_ > 0.5f ? Gait::kGallop : trot_factor_ > 0.5f ? Gait::kTrot : Gait::kWalk;
  }
}

void Animator::update_target_offsets() {
  // The offsets follow the gait blend; a change below 1e-4 of it moves them by less than
  // 1e-4 of a cycle, which the feet's own easing towards them swallows.
  if (std::fabs(trot_factor_ - offsets_trot_) < 1e-4f && std::fabs(gallop_factor_ - offsets_gallop_) < 1e-4f &&
      target_offset_.size() == legs_.size()) {
    return;
  }
  offsets_trot_ = trot_factor_;
  offsets_gallop_ = gallop_factor_;
  target_offset_.resize(legs_.size());
  for (size_t i = 0; i < legs_.size(); ++i) target_offset_[i] = leg_target_offset(static_cast<int>(i));
}

float Animator::leg_target_offset(int leg) const {
  const LegInfo& info = legs_[leg];
  const bool far = creature_->limbs[info.limb].side == Side::kFar;
  const int n = static_cast<int>(groups_.size());
  if (n == 1) return far ? 0.5f : 0.0f;
  if (n == 2) {
    const bool front = info.group == 0;
    // Footfall patterns as phase offsets (hind near = 0): lateral-sequence walk, trot
    // (diagonal pairs), transverse gallop.
    const float walk = front ? (far ? 0.75f : 0.25f) : (far ? 0.5f : 0.0f);
    const float trot = front ? (far ? 0.0f : 0.5f) : (far ? 0.5f : 0.0f);
    const float gallop = front ? (far ? 0.62f : 0.5f) : (far ? 0.12f : 0.0f);
    return circular_lerp(circular_lerp(walk, trot, trot_factor_), gallop, gallop_factor_);
  }
  // More pairs: a metachronal (tripod-like) wave, alternating down the body.
  const float near = (info.group % 2) * 0.5f;
  return far ? frac(near + 0.5f) : near;
}

void Animator::reverse(const Level& level) {
  // Mirror in place: leg pairs take over the feet standing where their girdle will be
  // (group i ← group n-1-i, same side), and the root shifts so the front and back girdles land
  // on each other's feet.
  const int n = static_cast<int>(groups_.size());
  if (n > 0) {
    std::vector<int> old = foot_of_leg_;
    const float shift = groups_.front().joint_ms.x + groups_.back().joint_ms.x;
    for (int g = 0; g < n; ++g) {
      const Group& mine = groups_[g];
      const Group& other = groups_[n - 1 - g];
      for (size_t k = 0; k < mine.legs.size(); ++k) {
        const int src = other.legs[std::min(k, other.legs.size() - 1)];
        foot_of_leg_[mine.legs[k]] = old[src];
      }
    }
    // Groups of unequal size could map two legs to one foot; fall back to identity then.
    std::vector<int> seen(feet_.size(), 0);
    bool ok = true;
    for (int f : foot_of_leg_) ok &= (seen[f]++ == 0);
    if (!ok) foot_of_leg_ = old;
    body_x_ += facing_ * shift;
  }
  facing_ = -facing_;
  lean_ = 0.0f;
  snap_body_ = true;  // the body takes its new height and pitch at once (feet must not jump)
  // Girdles spaced unevenly along the body (three leg pairs) cannot all land on feet: a leg
  // whose foot (standing or in the air) is now out of reach lifts from the nearest foot on the
  // ground it reaches and steps under its girdle. A foot in the air heading out of reach (to
  // where the body was going) steps under its girdle from where it is.
  for (size_t i = 0; i < legs_.size(); ++i) {
    Foot& f = feet_[foot_of_leg_[i]];
    const LegInfo& info = legs_[i];
    const float h = groups_[info.group].rest_height * params_.stance_height;
    const float reach_x = 0.95f * std::sqrt(std::max(info.contact_reach * info.contact_reach - h * h, 0.0f));
    const float joint_x = girdle_ws(info.group).x;
    const bool foot_in_reach = std::fabs(f.pos_ws.x - joint_x) <= reach_x;
    if (foot_in_reach && (f.state == LegState::kStance || std::fabs(f.to_ws.x - joint_x) <= reach_x)) continue;
    if (!foot_in_reach) {  // from the nearest foot on the ground in reach, else from where it is
      const Foot* from = nullptr;
      for (const Foot& other : feet_) {
        if (&other == &f || other.state != LegState::kStance || std::fabs(other.pos_ws.x - joint_x) > reach_x) continue;
        if (!from || std::fabs(other.pos_ws.x - joint_x) < std::fabs(from->pos_ws.x - joint_x)) from = &other;
      }
      if (from) f.pos_ws = from->pos_ws;
    }
    glm::vec2 landing;
    if (!find_landing(static_cast<int>(i), joint_x, level, &landing)) landing = f.pos_ws;
    f.from_ws = f.pos_ws;
    f.to_ws = landing;
    f.swing_x = spline_prototypes_[PrototypeId::kLegSwingX].blended(run_factor_);
    f.swing_y = spline_prototypes_[PrototypeId::kLegSwingY].blended(run_factor_);
    f.lift = 0.5f * info.reach;
    f.raise = 0.0f;
    f.progress = 0.0f;
    f.rate = 1.0f / 0.3f;
    f.easing = true;
    f.state = LegState::kSwing;
    raise_for_clearance(static_cast<int>(i), level);
  }
  // Feet now point the other way: one that would reach into a step takes a quick step to the
  // nearest place it fits (already lifted on this tick).
  for (size_t i = 0; i < legs_.size(); ++i) {
    Foot& f = feet_[foot_of_leg_[i]];
    if (f.state != LegState::kStance || foot_fits(static_cast<int>(i), f.pos_ws, level)) continue;
    glm::vec2 landing;
    if (nearest_fit(static_cast<int>(i), f.pos_ws, level, &landing, true)) step_to(static_cast<int>(i), landing, level);
  }
}

bool Animator::nearest_fit(int leg, glm::vec2 near_ws, const Level& level, glm::vec2* spot, bool prefer_reach) const {
  return (prefer_reach && nearest_fit_within(leg, near_ws, level, spot, true)) ||
         nearest_fit_within(leg, near_ws, level, spot, false);
}

bool Animator::nearest_fit_within(int leg, glm::vec2 near_ws, const Level& level, glm::vec2* spot, bool in_reach) const {
  // Centimetre by centimetre either way, up to half a leg's length, on ground within a step
  // (one every leg pair could follow up, as in find_landing).
  const LegInfo& info = legs_[leg];
  const float up = params_.max_step_up * climb_height_;
  const float down = params_.max_step_down * groups_[info.group].rest_height;
  // A flat foot stands on the highest ground under its sole.
  const float sole = creature_->contact == ContactMode::kFlat ? facing_ * info.foot_length : 0.0f;
  const float sole_lo = std::min(sole, 0.0f) - 0.005f, sole_hi = std::max(sole, 0.0f) + 0.005f;
  const int n = std::max(1, static_cast<int>(0.5f * (info.reach + info.foot_length) / 0.01f));
  for (int k = 0; k <= 2 * n; ++k) {
    const float x = near_ws.x + 0.01f * static_cast<float>(k % 2 == 0 ? k / 2 : -(k + 1) / 2);
    auto hit = ground_below(level, x + sole_lo, x + sole_hi, near_ws.y + up, up + down);
    if (!hit) continue;
    const glm::vec2 p(x, hit->height_ws);
    if (in_reach && !reaches(leg, p)) continue;
    if (foot_fits(leg, p, level)) {
      *spot = p;
      return true;
    }
  }
  return false;
}

bool Animator::reaches(int leg, glm::vec2 p_ws) const {
  return glm::length(to_model(p_ws) - to_model(girdle_ws(legs_[leg].group))) <= kFootReach * legs_[leg].contact_reach;
}

bool Animator::foot_fits(int leg, glm::vec2 contact_ws, const Level& level) const {
  const LegInfo& info = legs_[leg];
  const glm::vec2 ankle_rel = -info.foot_offset_ms;
  const glm::vec2 tip_rel = creature_->contact == ContactMode::kFlat ? glm::vec2(info.foot_length, 0.0f) : glm::vec2(0.0f);
  const float a = facing_ * std::min({0.0f, ankle_rel.x, tip_rel.x});
  const float b = facing_ * std::max({0.0f, ankle_rel.x, tip_rel.x});
  const float height = std::max({0.02f, ankle_rel.y, 0.3f * info.foot_length});
  const Box foot_box{{contact_ws.x + std::min(a, b) - 0.008f, contact_ws.y + 0.0005f},
                     {contact_ws.x + std::max(a, b) + 0.008f, contact_ws.y + height}};
  return !level.overlaps(foot_box);
}

// [SECTION] swing planning (set_new_splines) and footholds ----------------------------------

bool Animator::find_landing(int leg, float x_wanted, const Level& level, glm::vec2* landing) const {
  const LegInfo& info = legs_[leg];
  const Foot& f = feet_[foot_of_leg_[leg]];
  const float up = params_.max_step_up * climb_height_;
  const float down = params_.max_step_down * groups_[info.group].rest_height;
  // A step down counts from the foot, or from the ground its girdle stands over when the foot
  // stands higher (a foot left up on a step steps back down as far as its girdle stands).
  const float lowest = std::min(f.pos_ws.y, girdle_ws(info.group).y - groups_[info.group].rest_height) - down;
  // The foot's horizontal extent relative to its contact point (model space → world).
  const glm::vec2 ankle_rel = -info.foot_offset_ms;
  const glm::vec2 tip_rel = creature_->contact == ContactMode::kFlat ? glm::vec2(info.foot_length, 0.0f) : glm::vec2(0.0f);
  const float a = facing_ * std::min({0.0f, ankle_rel.x, tip_rel.x});
  const float b = facing_ * std::max({0.0f, ankle_rel.x, tip_rel.x});
  const float span_lo = std::min(a, b) - 0.01f, span_hi = std::max(a, b) + 0.01f;
  const float height = std::max({0.02f, ankle_rel.y, 0.3f * info.foot_length});
  // Prefer the planned spot, then the nearest shorter or slightly longer steps: as short as
  // just ahead of where the foot is now, at most 25% longer.
  const float stepx = std::max(0.025f * stride_, 0.005f);
  const float shortest = facing_ * (x_wanted - f.pos_ws.x) - 0.05f * stride_;
  for (int k = 0; k <= 600; ++k) {
    const int n = (k + 1) / 2;
    const float d = k % 2 == 1 ? -stepx * static_cast<float>(n) : 0.25f * stepx * static_cast<float>(n);
    if (-d > shortest) {
      if (k % 2 == 1) continue;
      if (d > 0.25f * stride_) break;
    } else if (k % 2 == 0 && d > 0.25f * stride_) {
      continue;
    }
    if (d > 0.25f * stride_) continue;
    const float x = x_wanted + facing_ * d;
    auto hit = ground_below(level, x + span_lo, x + span_hi, f.pos_ws.y + up, f.pos_ws.y + up - lowest);
    if (!hit) continue;
    const float y = hit->height_ws;
    const Box foot_box{{x + span_lo + 0.002f, y + 0.002f}, {x + span_hi - 0.002f, y + height}};
    if (level.overlaps(foot_box)) continue;
    // Down a step the shin comes from above and behind: keep the foot off the riser it steps
    // down from, or the shin cuts the step's edge.
    const float back = facing_ > 0 ? x + span_lo : x + span_hi;
    const float gap = 0.25f * groups_[info.group].rest_height;
    const Box behind{{std::min(back, back - facing_ * gap), y + 0.02f}, {std::max(back, back - facing_ * gap), y + up}};
    if (k + 1 < 600 && level.overlaps(behind)) continue;
    *landing = {x, y};
    return true;
  }
  return false;
}

float Animator::landing_x(int leg, float speed, float swing_phase) const {
  const LegInfo& info = legs_[leg];
  // The stance is centred with the contact point under the girdle joint, where the leg's
  // reach forward and back is the same.
  if (swing_phase < 0.0f) swing_phase = 1.0f - duty_;
  const float frequency = speed > 0.0f ? speed / std::max(stride_, 1e-3f) : 0.0f;
  const float t_swing = frequency > 0.0f ? swing_phase / frequency : 0.0f;
  // Land half a stance ahead of where the girdle will be [T 4.4.1].
  const float girdle_td = girdle_ws(info.group).x + facing_ * speed * t_swing;
  return girdle_td + facing_ * 0.5f * duty_ * stride_;
}

void Animator::set_new_splines(int leg, const Level& level, float swing_phase) {
  const LegInfo& info = legs_[leg];
  Foot& f = feet_[foot_of_leg_[leg]];
  const float x_wanted = landing_x(leg, speed_, swing_phase);
  glm::vec2 landing;
  if (!find_landing(leg, x_wanted, level, &landing)) {
    // No foothold within reach ahead: a wall too tall or a drop too deep. Stop at the edge.
    blocked_ = true;
    blocked_leg_ = leg;
    blocked_dir_ = facing_;
    blocked_retry_ = 0.5f;
    return;
  }
  f.from_ws = f.pos_ws;
  f.to_ws = landing;
  f.swing_x = spline_prototypes_[PrototypeId::kLegSwingX].blended(run_factor_);
  f.swing_y = spline_prototypes_[PrototypeId::kLegSwingY].blended(run_factor_);
  f.lift = info.reach;
  f.raise = 0.0f;
  f.progress = 0.0f;
  f.rate = 1.0f / std::max(swing_phase, 0.05f);
  f.easing = false;
  f.state = LegState::kSwing;

  if (!raise_for_clearance(leg, level)) {
    // The way to the landing is walled off: the foot stays, the creature stops.
    f.state = LegState::kStance;
    f.to_ws = f.from_ws;
    blocked_ = true;
    blocked_leg_ = leg;
    blocked_dir_ = facing_;
    blocked_retry_ = 0.5f;
  }
}

glm::vec2 Animator::leg_ankle(int leg, glm::vec2 contact_ms, glm::vec2 joint_ms, const Level* level, const Clearance& near,
                               glm::vec2* foot_dir, bool* limited) const {
  // Hooves and toes roll: with the contact point c fixed, the ankle a(θ) = c - F·u(θ) lies on
  // a circle of the foot's length F around it. The leg (joint j → ankle) reaches r, so
  // |a - j| <= r, i.e. u(θ)·d >= q with d = c - j and q = (|d|² + F² - r²) / 2F: an arc of
  // directions within β = acos(q / |d|) of d. The foot keeps its rest direction inside the
  // arc and turns to the arc's nearer end outside it (into line with d when it is empty).
  const LegInfo& info = legs_[leg];
  *foot_dir = info.foot_dir_ms;
  if (limited) *limited = false;
  const float F = info.foot_span;
  if (F <= 0.0f) return contact_ms;  // flat contact: the contact point is the ankle
  const glm::vec2 d = contact_ms - joint_ms;
  const float r = info.leg_reach;
  const float dd = glm::dot(d, d);
  const float q = (dd + F * F - r * r) / (2.0f * F);
  if (glm::dot(d, info.foot_dir_ms) < q && dd > 1e-12f) {
    const float len = std::sqrt(dd);
    const glm::vec2 n = d / len;
    const float cos_b = std::min(q / len, 1.0f);
    const float sin_b = std::sqrt(std::max(1.0f - cos_b * cos_b, 0.0f));
    // The side of d the rest direction lies on.
    const float side = n.x * info.foot_dir_ms.y - n.y * info.foot_dir_ms.x >= 0.0f ? 1.0f : -1.0f;
    *foot_dir = {cos_b * n.x - side * sin_b * n.y, side * sin_b * n.x + cos_b * n.y};
    if (level && *foot_dir != info.foot_dir_ms && !near.clear_above(std::min(contact_ms.y, contact_ms.y - F * foot_dir->y)) &&
        limit_foot_roll(leg, contact_ms, *level, foot_dir) && limited) {
      *limited = true;
    }
  }
  return contact_ms - F * *foot_dir;
}

bool Animator::limit_foot_roll(int leg, glm::vec2 contact_ms, const Level& level, glm::vec2* foot_dir) const {
  // A rolled foot must not sweep into a step: turn it back towards the rest direction
  // (bisection on the angle) until the ankle → contact segment clears every box.
  const LegInfo& info = legs_[leg];
  const float F = info.foot_span;
  auto clear = [&](glm::vec2 u) {
    const glm::vec2 seg[2] = {to_world(contact_ms - F * u), to_world(contact_ms)};
    return !polyline_hits_level(level, seg, 2, segment_hits_);
  };
  if (clear(*foot_dir)) return false;
  const glm::vec2 rest = info.foot_dir_ms;
  const float full = std::atan2(rest.x * foot_dir->y - rest.y * foot_dir->x, glm::dot(rest, *foot_dir));
  float lo = 0.0f, hi = 1.0f;  // fractions of the roll: lo clears, hi does not
  for (int k = 0; k < 6; ++k) {
    const float mid = 0.5f * (lo + hi);
    (clear(rotate(rest, mid * full)) ? lo : hi) = mid;
  }
  *foot_dir = lo > 0.0f ? rotate(rest, lo * full) : rest;
  return true;
}

Animator::Clearance Animator::clearance_in(const Box& region, float base, const Level& level) const {
  Clearance c;
  c.base = base;
  c.top = -1e30f;
  segment_hits_.clear();
  level.overlapping(region, segment_hits_);
  for (int h : segment_hits_) {
    const float top = level.box(h).top();
    if (top > base + 0.5e-3f) c.top = std::max(c.top, top);
  }
  return c;
}

void Animator::update_stance_clearance(Foot& f, const Level& level) const {
  // Any leg's foot may stand here after a turn: the longest foot's circle around the contact.
  float r = 0.05f;
  for (const LegInfo& info : legs_) r = std::max(r, glm::length(info.foot_offset_ms) + 0.05f);
  f.stance_clear = clearance_in(Box{f.pos_ws - glm::vec2(r), f.pos_ws + glm::vec2(r)}, f.pos_ws.y, level);
  // And as far as any leg reaches from it (the steps between a foot and its girdle).
  float reach = r;
  for (const LegInfo& info : legs_) reach = std::max(reach, info.contact_reach);
  f.stance_reach_clear = clearance_in(Box{f.pos_ws - glm::vec2(reach, 0.0f), f.pos_ws + glm::vec2(reach)}, f.pos_ws.y, level);
}

void Animator::update_swing_clearance(int leg, const Level& level) {
  // Everything the leg may sweep through on this swing: around the path, a leg's length
  // to either side and two above.
  Foot& f = feet_[foot_of_leg_[leg]];
  const float reach = legs_[leg].reach + glm::length(legs_[leg].foot_offset_ms);
  const glm::vec2 lo = glm::min(f.from_ws, f.to_ws), hi = glm::max(f.from_ws, f.to_ws);
  f.swing_clear = clearance_in(Box{lo - glm::vec2(1.5f * reach, reach), hi + glm::vec2(1.5f * reach, 2.0f * reach)}, lo.y, level);
}

glm::vec2 Animator::leg_anchor(int leg, glm::vec2 contact_ms, glm::vec2 joint_ms, const Level& level, const Clearance& near,
                               float* radius) const {
  glm::vec2 dir;
  bool limited = false;
  const glm::vec2 ankle = leg_ankle(leg, contact_ms, joint_ms, &level, near, &dir, &limited);
  if (!limited) {
    *radius = legs_[leg].contact_reach;
    return contact_ms;
  }
  *radius = kReachLimit * legs_[leg].reach;
  return ankle;
}

void Animator::keep_arm_above_ground(const Limb& arm, const Level& level) {
  // Long arms of a low body would reach into the ground (or a ledge): lift the wrist with
  // two-bone IK until elbow, wrist and hand clear the highest ground under the arm; an arm
  // still in a step (a riser in front) folds towards the shoulder until it clears.
  const Skeleton& sk = creature_->skeleton;
  const float l1 = sk.length(arm.bones[0]), l2 = sk.length(arm.bones[1]), l3 = sk.length(arm.bones[2]);
  struct ArmPose {
    glm::vec2 shoulder, elbow, wrist, tip;
    float hand_abs, bend;
  };
  auto current = [&] {
    const Mat2x3 upper = model_[arm.girdle_bone] * local_matrix(pose_.locals[arm.bones[0]]);
    const Mat2x3 lower = upper * local_matrix(pose_.locals[arm.bones[1]]);
    const Mat2x3 hand = lower * local_matrix(pose_.locals[arm.bones[2]]);
    ArmPose p{bone_start(upper), bone_start(lower), bone_start(hand), bone_end(hand, l3), bone_angle(hand), 1.0f};
    const glm::vec2 a = p.elbow - p.shoulder, b = p.wrist - p.shoulder;
    p.bend = a.x * b.y - a.y * b.x > 0.0f ? 1.0f : -1.0f;  // keep the elbow's side
    return p;
  };
  auto set_wrist = [&](const ArmPose& p, glm::vec2 target) {
    const TwoBoneIkResult ik = solve_two_bone_ik(p.shoulder, l1, l2, target, p.bend);
    pose_.locals[arm.bones[0]].angle_ls = wrap_angle(ik.upper_angle - bone_angle(model_[arm.girdle_bone]));
    pose_.locals[arm.bones[1]].angle_ls = ik.lower_angle;
    pose_.locals[arm.bones[2]].angle_ls = wrap_angle(p.hand_abs - (ik.upper_angle + ik.lower_angle));
  };
  for (int pass = 0; pass < 3; ++pass) {
    const ArmPose p = current();
    float x0 = 1e30f, x1 = -1e30f, low = 1e30f;
    for (glm::vec2 q : {p.elbow, p.wrist, p.tip}) {
      const float xw = to_world(q).x;
      x0 = std::min(x0, xw);
      x1 = std::max(x1, xw);
      low = std::min(low, q.y);
    }
    const auto ground = ground_below(level, x0, x1, p.shoulder.y, 100.0f);
    const float margin = 0.01f + 0.02f * hip_height_;
    if (!ground || low >= ground->height_ws + margin) break;
    set_wrist(p, p.wrist + glm::vec2(0.0f, ground->height_ws + margin - low));
  }
  const ArmPose p = current();
  auto hits = [&](const ArmPose& q) {
    const glm::vec2 pts[4] = {to_world(q.shoulder), to_world(q.elbow), to_world(q.wrist), to_world(q.tip)};
    return polyline_hits_level(level, pts, 4, segment_hits_);
  };
  if (!hits(p)) return;
  // Tucked under the shoulder, else folded up in front of the chest, else up behind it: the
  // first tuck that clears, approached only as far as needed. The hand keeps its direction,
  // else (a long hand or flipper reaching into a step ahead) it trails back and down, else
  // up behind; last, with the elbow bent the other way (a shoulder just above a tread, where
  // any elbow bent down meets the tread).
  const float tuck_len = std::max(std::fabs(l1 - l2) + 0.01f, 0.35f * (l1 + l2));
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
        for (int k = 0; k < 6; ++k) {
          const float mid = 0.5f * (lo + hi);
          set_wrist(q, glm::mix(q.wrist, tuck, mid));
          (hits(current()) ? lo : hi) = mid;
        }
        set_wrist(q, glm::mix(q.wrist, tuck, hi));
        return;
      }
    }
  }
  set_wrist(p, p.shoulder + glm::normalize(glm::vec2(-1.0f, -0.3f)) * tuck_len);
}

void Animator::keep_body_out(const Level& level) {
  // A legless body's wave bends its spine, and the roots of its fins, arms and wings, below
  // where place_body put them at rest: the whole body rises by the deepest into the ground.
  const Creature& c = *creature_;
  float raise = 0.0f;
  // (A limb's root may hang far below its girdle: the ground is looked for from the girdle.)
  auto keep_out = [&](glm::vec2 p_ms, float from_y_ms) {
    const glm::vec2 p = to_world(p_ms);
    const float from = to_world({p_ms.x, std::max(from_y_ms, p_ms.y)}).y;
    if (auto below = ground_below(level, p.x - 0.02f, p.x + 0.02f, from + hip_height_, 100.0f)) {
      raise = std::max(raise, below->height_ws - p.y);
    }
  };
  for (int b : needed_bones_) {
    const glm::vec2 p = bone_start(model_[b]);
    keep_out(p, p.y);
  }
  for (const Limb& limb : c.limbs) {
    if (!limb.bones.empty()) {
      const Mat2x3& girdle = model_[limb.girdle_bone];
      keep_out(girdle.apply(pose_.locals[limb.bones[0]].offset_ls), bone_start(girdle).y);
    }
  }
  if (raise <= 0.0f) return;
  root_y_ += raise;
  body_lift_ += raise;
  pose_.locals[c.root].offset_ls.y += raise;
  body_fk();
}

void Animator::body_fk() {
  const std::vector<int>& parents = creature_->skeleton.parents();
  for (int b : needed_bones_) {
    const Mat2x3 local = dynamic_bone_[b] ? local_matrix(pose_.locals[b]) : rest_local_m_[b];
    model_[b] = parents[b] < 0 ? local : model_[parents[b]] * local;
  }
  const Mat2x3 root = model_[creature_->root];
  for (size_t i = 0; i < girdle_bones_.size(); ++i) model_[girdle_bones_[i]] = root * girdle_rel_[i];
}

void Animator::keep_tail_clear(const Level& level) {
  // A tail hanging into a step (down a flight, or one rising behind) curls up from its root,
  // the least that clears, up to 1.6 rad over its length. Only asked when ground rises to
  // within a tail's length of its root.
  const Creature& c = *creature_;
  Mat2x3 base = model_[tail_base_bone_] * tail_between_rest_;
  for (int b : tail_between_) base = base * local_matrix(pose_.locals[b]);
  const glm::vec2 root = to_world(base.apply(pose_.locals[c.tail[0]].offset_ls));
  const float len = tail_length_;
  const auto ground = ground_below(level, root.x - len, root.x + len, root.y + len, 2.0f * len);
  if (!ground || ground->height_ws < root.y - len) return;
  const size_t n = std::min<size_t>(c.tail.size(), kMaxTailBones);
  glm::vec2 p[kMaxTailBones + 1];
  auto hits = [&](float turn) {
    Mat2x3 m = base;
    for (size_t k = 0; k < n; ++k) {
      BoneLocal local = pose_.locals[c.tail[k]];
      local.angle_ls += turn / static_cast<float>(n);
      m = m * local_matrix(local);
      p[k] = to_world(bone_start(m));
      if (k + 1 == n) p[n] = to_world(bone_end(m, c.skeleton.length(c.tail[k])));
    }
    return polyline_hits_level(level, p, static_cast<int>(n + 1), segment_hits_);
  };
  if (!hits(0.0f)) return;
  // The turn that raises the tip first; a curled tail may need the other.
  const float up = facing_ * (p[n].x - p[0].x) < 0.0f ? -1.0f : 1.0f;
  float most = 1.6f * up;
  if (hits(most) && !hits(-most)) most = -most;
  float lo = 0.0f, hi = 1.0f;  // fractions of the most: lo hits, hi clears (or is the last resort)
  for (int k = 0; k < 6; ++k) {
    const float mid = 0.5f * (lo + hi);
    (hits(mid * most) ? lo : hi) = mid;
  }
  for (size_t k = 0; k < n; ++k) pose_.locals[c.tail[k]].angle_ls += hi * most / static_cast<float>(n);
}

void Animator::keep_fin_clear(const Limb& fin, const Level& level) {
  // A fin (or folded wing) trailing into the ground or a step turns up at its root until it
  // clears.
  const Skeleton& sk = creature_->skeleton;
  const size_t n = std::min<size_t>(fin.bones.size(), 7);
  glm::vec2 p[8];
  auto chain = [&] {  // model space: the fin's joints and its tip
    Mat2x3 m = model_[fin.girdle_bone];
    for (size_t k = 0; k < n; ++k) {
      m = m * local_matrix(pose_.locals[fin.bones[k]]);
      p[k] = bone_start(m);
      if (k + 1 == n) p[n] = bone_end(m, sk.length(fin.bones[k]));
    }
  };
  auto hits = [&] {
    chain();
    glm::vec2 w[8];
    for (size_t k = 0; k <= n; ++k) w[k] = to_world(p[k]);
    return polyline_hits_level(level, w, static_cast<int>(n + 1), segment_hits_);
  };
  if (n == 0 || !hits()) return;
  const float base = pose_.locals[fin.bones[0]].angle_ls;
  const float up = p[n].x >= p[0].x ? 1.0f : -1.0f;  // the turn that raises the tip
  // The least turn that clears, raising the tip first (up to a quarter turn), then either way
  // in eighth turns up to three eighths (a step rising right in front of a folded wing).
  float turn = 0.0f;
  auto clears = [&](float t) {
    pose_.locals[fin.bones[0]].angle_ls = base + t;
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
  for (int k = 0; k < 7; ++k) {
    const float mid = 0.5f * (lo + hi);
    (clears(mid * turn) ? hi : lo) = mid;
  }
  pose_.locals[fin.bones[0]].angle_ls = wrap_angle(base + hi * turn);
}

glm::vec2 Animator::swing_point(const Foot& f, float s) {
  // The blended prototype shapes the step [T 4.4.1]; on steps the foot rises before it moves
  // forward (up) or moves over before it descends (down), so it never clips a riser's corner.
  const float up = f.to_ws.y - f.from_ws.y;
  const float sx = up > 0.0f ? std::clamp((s - 0.12f) / 0.88f, 0.0f, 1.0f)
                 : up < 0.0f ? std::clamp(s / 0.85f, 0.0f, 1.0f) : s;
  const float ease = up >= 0.0f ? smoothstep(0.0f, 0.55f, s) : smoothstep(0.45f, 1.0f, s);
  const float along = prototype_range(PrototypeId::kLegSwingX).clamp(f.swing_x.position(sx));
  const float lift = prototype_range(PrototypeId::kLegSwingY).clamp(f.swing_y.position(s));
  return {f.from_ws.x + along * (f.to_ws.x - f.from_ws.x),
          f.from_ws.y + ease * up + f.lift * lift + (f.raise != 0.0f ? f.raise * bump(s) : 0.0f)};
}

bool Animator::raise_for_clearance(int leg, const Level& level) {
  // Raise the curve until the whole foot (ankle to toe) clears every box [T 5.1e]; false when
  // no reasonable lift does (the path runs into a wall).
  const LegInfo& info = legs_[leg];
  Foot& f = feet_[foot_of_leg_[leg]];
  const glm::vec2 ankle_rel = -info.foot_offset_ms;
  const glm::vec2 tip_rel = creature_->contact == ContactMode::kFlat ? glm::vec2(info.foot_length, 0.0f) : glm::vec2(0.0f);
  // What rises near the path (kept: build_pose tests the swinging leg against it too). When
  // nothing rises above its lower end (flat ground, or down a slope), a coarse check that the
  // curve stays above that suffices.
  update_swing_clearance(leg, level);
  if (f.swing_clear.top < f.swing_clear.base) {
    const float lowest = std::min(f.from_ws.y, f.to_ws.y) - std::min(0.0f, ankle_rel.y);
    bool above = true;
    for (int k = 1; k < 12 && above; ++k) above = swing_point(f, static_cast<float>(k) / 12.0f).y >= lowest;
    if (above) return true;
  }
  constexpr int kSamples = 48;
  Box foot[kSamples];
  // A foot that stands pressed against a step (turned round on a narrow tread) only has to
  // clear it once it has left it.
  auto foot_box = [&](float s) {
    const glm::vec2 p = swing_point(f, s);
    const glm::vec2 q = p + glm::vec2(facing_ * ankle_rel.x, ankle_rel.y);
    const glm::vec2 r = p + glm::vec2(facing_ * tip_rel.x, tip_rel.y);
    // A little narrower than find_landing's test, so a landing it found clears at its end.
    return Box{glm::min(glm::min(p, q), r) - glm::vec2(0.006f, 0.0f), glm::max(glm::max(p, q), r) + glm::vec2(0.006f, 0.005f)};
  };
  foot[0] = foot_box(0.0f);
  std::vector<int>& hits = clearance_hits_;
  for (int iter = 0; iter < 8; ++iter) {
    // The foot's box at each sample, then the colliders near the whole path in one query.
    Box path{glm::vec2(1e30f), glm::vec2(-1e30f)};
    for (int k = 1; k < kSamples; ++k) {
      foot[k] = foot_box(static_cast<float>(k) / kSamples);
      path.min_ws = glm::min(path.min_ws, foot[k].min_ws);
      path.max_ws = glm::max(path.max_ws, foot[k].max_ws);
    }
    hits.clear();
    level.overlapping(path, hits);
    float need = 0.0f;
    for (int h : hits) {
      const Box& box = level.box(h);
      int k = 1;
      if (box.overlaps(foot[0])) {
        while (k < kSamples && box.overlaps(foot[k])) ++k;
      }
      for (; k < kSamples; ++k) {
        if (!box.overlaps(foot[k])) continue;
        const float depth = box.top() + 0.01f - foot[k].min_ws.y;
        need = std::max(need, depth / std::max(bump(static_cast<float>(k) / kSamples), 0.1f));
      }
    }
    if (need <= 0.0f) return true;
    f.raise += need;
    if (f.raise > 2.0f * (info.reach + info.foot_span)) break;  // a wall, not a step
  }
  return false;
}

bool Animator::stance_leg_hits(int leg, glm::vec2 joint_ms, const Level& level) const {
  const LegInfo& info = legs_[leg];
  const Foot& f = feet_[foot_of_leg_[leg]];
  const glm::vec2 contact = to_model(f.pos_ws);
  glm::vec2 dir;
  const glm::vec2 ankle = leg_ankle(leg, contact, joint_ms, &level, f.stance_clear, &dir, nullptr);
  const TwoBoneIkResult ik = solve_two_bone_ik_directions(joint_ms, info.upper, info.lower, ankle, info.bend);
  const glm::vec2 tip = ik.end + info.foot_length * dir;
  const glm::vec2 p[4] = {to_world(joint_ms), to_world(ik.middle), to_world(ik.end), to_world(tip)};
  return polyline_hits_level(level, p, info.foot_length > 0.0f ? 4 : 3, segment_hits_);
}

void Animator::step_to(int leg, glm::vec2 spot, const Level& level) {
  start_ease(leg, level, &spot);
  // Already lifted on this tick: the first sample of a path cleared from the second on.
  Foot& f = feet_[foot_of_leg_[leg]];
  f.progress = 1.0f / 48.0f;
  f.pos_ws = swing_point(f, f.progress);
}

void Animator::start_ease(int leg, const Level& level, const glm::vec2* to) {
  Foot& f = feet_[foot_of_leg_[leg]];
  glm::vec2 landing;
  if (to) {
    landing = *to;
  } else if (!find_landing(leg, f.pos_ws.x, level, &landing)) {
    landing = f.to_ws;
  }
  // Set down where the leg reaches from where the body stopped: drawn in towards the joint.
  if (!to && !reaches(leg, landing)) {
    const glm::vec2 joint = to_model(girdle_ws(legs_[leg].group));
    const float reach = kFootReach * legs_[leg].contact_reach;
    const float h = joint.y - landing.y;
    const float reach_x = 0.9f * std::sqrt(std::max(reach * reach - h * h, 0.0f));
    const float dx = std::clamp(to_model(landing).x - joint.x, -reach_x, reach_x);
    glm::vec2 spot;
    if (nearest_fit(leg, to_world({joint.x + dx, landing.y}), level, &spot, true)) landing = spot;
  }
  f.state = LegState::kSwing;
  f.from_ws = f.pos_ws;
  f.to_ws = landing;
  f.swing_x = HermiteSpline({{0.0f, 0.0f, 1.0f}, {1.0f, 1.0f, 1.0f}});
  f.swing_y = HermiteSpline({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  f.lift = 0.0f;
  f.raise = 0.0f;
  f.progress = 0.0f;
  f.rate = 1.0f / std::max(params_.stop_ease_time, 0.01f);
  f.easing = true;
  raise_for_clearance(leg, level);
}

// [SECTION] body placement ------------------------------------------------------------------

void Animator::place_body(float dt, const Level& level) {
  for (Foot& f : feet_) f.holds_body = false;
  const float old_root = root_y_;
  const glm::vec2 root_rest(0.0f, root_rest_y_);
  float target_root = root_y_, target_pitch = 0.0f;
  const float w = run_factor_;
  const PrototypeId bob_id = moving_ ? PrototypeId::kPelvisY : PrototypeId::kIdleY;
  const float bob_t = moving_ ? frac(2.0f * phase_) : frac(idle_time_ / 2.4f);
  const float bob = prototype_range(bob_id).clamp(spline_prototypes_[bob_id].value(bob_t, w)) * hip_height_;
  if (groups_.empty()) {
    // Legless: follow the highest ground under the body.
    auto hit = ground_below(level, body_x_ - body_half_length_, body_x_ + body_half_length_,
                                         root_y_ + hip_height_, 100.0f);
    // Lifted lately so that the wave keeps the body out of the ground (keep_body_out): held
    // there, settling back slowly, rather than pulled down and lifted again every tick.
    if (dt > 0.0f) body_lift_ *= std::exp(-dt);
    target_root = (hit ? hit->height_ws : root_y_ - root_rest_y_) + root_rest_y_ + body_lift_;
  } else {
    std::vector<float>& height = group_height_;
    for (size_t g = 0; g < groups_.size(); ++g) {
      float sum = 0.0f;
      for (int leg : groups_[g].legs) {
        const Foot& f = feet_[foot_of_leg_[leg]];
        sum += f.state == LegState::kStance ? f.pos_ws.y
                                            : f.from_ws.y + std::clamp(f.progress, 0.0f, 1.0f) * (f.to_ws.y - f.from_ws.y);
      }
      float ground = sum / static_cast<float>(groups_[g].legs.size());
      // On stairs the feet straddle steps; a girdle over a higher step rises with it, so the
      // knees stay clear of the step they pass over.
      const float gx = girdle_ws(static_cast<int>(g)).x;
      const float half = 0.2f * groups_[g].rest_height;
      if (auto below = ground_below(level, gx - half, gx + half, ground + params_.max_step_up * groups_[g].step_height,
                                                 params_.max_step_up * groups_[g].step_height)) {
        ground = std::max(ground, 0.5f * (ground + below->height_ws));
      }
      height[g] = ground + groups_[g].rest_height * params_.stance_height + bob;
      // A foot waiting above a lower step (see update) brings its girdle down to it, but not
      // so far that a leg on the ground folds up (its knee would reach into the ground).
      float floor = -1e30f, lowest = height[g];
      for (int leg : groups_[g].legs) {
        const Foot& f = feet_[foot_of_leg_[leg]];
        if (f.state == LegState::kStance) floor = std::max(floor, f.pos_ws.y + 0.6f * groups_[g].rest_height);
        if (f.state != LegState::kSwing || f.hover <= 0.0f) continue;
        const glm::vec2 foot = f.to_ws;
        const float r = kFootReach * legs_[leg].contact_reach;
        const float dx = std::min(std::fabs(foot.x - gx), 0.95f * r);
        lowest = std::min(lowest, foot.y + std::sqrt(r * r - dx * dx));
      }
      height[g] = std::min(height[g], std::max(lowest, floor));
    }
    const float angle_extra = lean_;
    if (groups_.size() >= 2) {
      const glm::vec2 df = groups_.front().joint_ms - root_rest, db = groups_.back().joint_ms - root_rest;
      const glm::vec2 d = df - db;  // the rest chord between the girdles
      const float len = std::sqrt(d.x * d.x + d.y * d.y);
      const float dy = height.front() - height.back();
      const float total = std::asin(std::clamp(dy / std::max(len, 1e-4f), -0.9f, 0.9f)) - fast_atan2(d.y, d.x);
      target_pitch = std::clamp(wrap_angle(total - angle_extra), -0.7f, 0.7f);
      const float a = target_pitch + angle_extra;
      const float c = std::cos(a), s = std::sin(a);
      const float df_y = s * df.x + c * df.y, db_y = s * db.x + c * db.y;  // rotate(·, a).y
      target_root = 0.5f * (height.front() - df_y + height.back() - db_y);
    } else {
      // A shoulder far ahead of the only girdle (a long-bodied bird) would run into the steps
      // of a steep flight before the legs climb them: the body pitches up so the shoulder
      // keeps its height above the ground ahead of it (a quarter second ahead).
      if (front_shoulder_.x > 0.0f) {
        const float ground = height.front() - groups_.front().rest_height * params_.stance_height;
        const float sx = girdle_ws(0).x + facing_ * front_shoulder_.x;
        const float ahead = facing_ * speed_ * 0.25f;
        const float half = 0.05f * hip_height_;
        const float top = ground + front_slack_ + 0.6f * front_shoulder_.x;  // the most a turn gets over
        if (auto below = ground_below(level, std::min(sx, sx + ahead) - half, std::max(sx, sx + ahead) + half,
                                                   top, top - ground + front_shoulder_.x)) {
          const float rise = below->height_ws - ground - front_slack_;
          if (rise > 0.0f) target_pitch = std::asin(std::min(rise / front_shoulder_.x, 0.6f));
        }
      }
      const glm::vec2 d = groups_.front().joint_ms - root_rest;
      target_root = height.front() - rotate(d, target_pitch + angle_extra).y;
    }
  }
  const bool turning = snap_body_;
  const bool snap = turning || dt <= 0.0f;
  snap_body_ = false;
  pitch_ = approach(pitch_, target_pitch, snap ? 0.0f : decay_.pitch);
  pitch_target_ = target_pitch;
  root_y_ = approach(root_y_, target_root, snap ? 0.0f : decay_.root);

  // Never over-extend a leg on the ground: lower its girdle (hard clamp, no smoothing; again
  // when that moved it, as a rolling foot's reach depends on where the joint is). The end girdles turn the body about each other, so a hind leg left on a lower step
  // pitches the body up instead of pulling the shoulders down into the steps ahead.
  const size_t n_groups = groups_.size();
  std::vector<float>& need = group_need_;
  std::vector<float>& room = group_room_;  // how far each girdle may rise with its feet in reach
  for (int pass = 0; pass < 3; ++pass) {
    std::fill(need.begin(), need.end(), 0.0f);
    std::fill(room.begin(), room.end(), 1e30f);
    for (size_t i = 0; i < legs_.size(); ++i) {
      const LegInfo& info = legs_[i];
      const Foot& f = feet_[foot_of_leg_[i]];
      // On the turn tick, swinging feet (taken over by other legs) must stay in reach too.
      if (f.state != LegState::kStance && !(turning && !f.easing)) continue;
      const glm::vec2 joint = to_model(girdle_ws(info.group));
      float r;
      const glm::vec2 anchor = leg_anchor(static_cast<int>(i), to_model(f.pos_ws), joint, level,
                                          f.state == LegState::kStance ? f.stance_clear : f.swing_clear, &r);
      const float dx = std::fabs(anchor.x - joint.x);
      if (dx >= r) continue;
      const float allowed = anchor.y + std::sqrt(r * r - dx * dx);
      need[info.group] = std::max(need[info.group], joint.y - allowed);
      room[info.group] = std::min(room[info.group], allowed - joint.y);
      // A foot left behind and below (stairs) that drags the body down lifts on the next tick
      // (see update) rather than fold the other legs into the step ahead.
      if (pass == 0 && f.state == LegState::kStance && anchor.x < joint.x &&
          joint.y - allowed > 0.05f * groups_[info.group].rest_height) {
        feet_[foot_of_leg_[i]].holds_body = true;
      }
    }
    // Turning the body moves the other girdle's joint sideways a little: the last pass lowers
    // the whole body, which keeps every joint's x.
    float most = 0.0f;
    for (float d : need) most = std::max(most, d);
    if (most <= 0.0f) break;
    for (size_t g = 0; g < n_groups; ++g) {
      if (need[g] <= 0.0f) continue;
      if (pass < 2) move_girdle(static_cast<int>(g), -need[g]);
      room[g] += need[g];
    }
    if (pass == 2) root_y_ -= most;
  }
  // Nor fold a leg on the ground tighter than it can (short legs with long shins on a low
  // body): raise the body until each stance ankle is at least the folded length away.
  float fold_raise = 0.0f;
  for (size_t i = 0; i < legs_.size(); ++i) {
    const Foot& f = feet_[foot_of_leg_[i]];
    if (f.state != LegState::kStance) continue;
    const float fold = legs_[i].fold;
    const glm::vec2 joint = to_model(girdle_ws(legs_[i].group));
    // The ankle lies within a foot's length of the contact point.
    if (glm::length(to_model(f.pos_ws) - joint) - legs_[i].foot_span >= fold) continue;
    glm::vec2 dir;
    const glm::vec2 ankle = leg_ankle(static_cast<int>(i), to_model(f.pos_ws), joint, &level, f.stance_clear, &dir, nullptr);
    const float dx = std::fabs(ankle.x - joint.x);
    if (dx < fold) fold_raise = std::max(fold_raise, ankle.y + std::sqrt(fold * fold - dx * dx) - joint.y);
  }
  if (fold_raise > 0.0f) {
    root_y_ += fold_raise;
    for (float& r : room) r = std::max(r - fold_raise, 0.0f);
  }
  // Nor kneel: a leg folded so far that its knee would touch the ground (sprawling legs on a
  // low body, or lifted in a swing) raises its girdle until the knee clears the ground under
  // it. A swinging leg's knee raises it only as far as the legs on the ground allow (their
  // feet must not slide); past that the swing itself lifts and tucks the leg (build_pose).
  // With the foot in place a raised joint lifts the knee by less than itself: up to four
  // passes, as long as some girdle moves.
  std::vector<float>& stance_up = group_need_;
  std::vector<float>& swing_up = group_swing_up_;
  for (int pass = 0; pass < 4; ++pass) {
    std::fill(stance_up.begin(), stance_up.end(), 0.0f);
    std::fill(swing_up.begin(), swing_up.end(), 0.0f);
    for (size_t i = 0; i < legs_.size(); ++i) {
      const Foot& f = feet_[foot_of_leg_[i]];
      const bool stance = f.state == LegState::kStance;
      const LegInfo& info = legs_[i];
      const glm::vec2 joint = to_model(girdle_ws(info.group));
      const float margin = 0.02f * info.reach;
      // The knee is no lower than a thigh below the joint nor a shin below the ankle: cheap
      // tests before the IK (unless steps rise near the foot).
      const bool steps_near = !(stance ? f.stance_reach_clear : f.swing_clear).clear_above(f.pos_ws.y + margin);
      if (!steps_near && joint.y - info.upper > f.pos_ws.y + margin) continue;
      glm::vec2 dir;
      const glm::vec2 ankle = leg_ankle(static_cast<int>(i), to_model(f.pos_ws), joint, &level,
                                        stance ? f.stance_clear : f.swing_clear, &dir, nullptr);
      if (!steps_near && ankle.y - info.lower > f.pos_ws.y + margin) continue;
      const TwoBoneIkResult ik = solve_two_bone_ik_directions(joint, info.upper, info.lower, ankle, info.bend);
      const glm::vec2 knee = to_world(ik.middle);
      float& up = stance ? stance_up[info.group] : swing_up[info.group];
      if (auto ground = ground_below(level, knee.x - 0.005f, knee.x + 0.005f, knee.y + info.reach, 2.0f * info.reach)) {
        up = std::max(up, ground->height_ws + margin - knee.y);
      }
      // On steps a thigh or shin may cross the edge of a step beside the knee (a swinging leg
      // far back down a flight, say), as may a shin coming up to a foot on the edge of a ledge
      // from a knee below it.
      if (steps_near || knee.y < f.pos_ws.y + margin) {
        const glm::vec2 hip = to_world(joint), heel = to_world(ik.end);
        up = std::max({up, raise_to_clear(hip, knee, level), raise_to_clear(knee, heel, level)});
      }
    }
    bool moved = false;
    for (size_t g = 0; g < n_groups; ++g) {
      const float up = std::min(std::max(stance_up[g], std::min(swing_up[g], room[g])), 0.5f * hip_height_);
      if (up <= 0.0f) continue;
      move_girdle(static_cast<int>(g), up);
      room[g] = std::max(room[g] - up, 0.0f);
      moved = true;
    }
    if (!moved) break;
  }
  // A point of the body's rest pose where the body is now (lifted by `lift`), and how far a
  // shoulder there must rise to keep a tenth of the standing height above the ground under
  // it (looked for from half a standing height, plus `extra`, above it).
  auto body_ws = [&](glm::vec2 rest_ms, float lift) {
    const glm::vec2 j = rotate_body(rest_ms - root_rest);
    return to_world({j.x, j.y + root_y_ + lift});
  };
  auto shoulder_need = [&](glm::vec2 shoulder, float extra) {
    const float half = 0.05f * hip_height_;
    auto below = ground_below(level, shoulder.x - half, shoulder.x + half, shoulder.y + 0.5f * hip_height_ + extra, 100.0f);
    return below ? below->height_ws + 0.1f * hip_height_ - shoulder.y : 0.0f;
  };
  // The shoulder far ahead of a single girdle meeting a step: the body turns up about the
  // girdle (the feet stay in reach) rather than rise (see the pitch target above, which
  // follows more slowly).
  if (front_shoulder_.x > 0.0f) {
    const glm::vec2 rel = groups_.front().joint_ms - root_rest;
    for (int pass = 0; pass < 2; ++pass) {
      const float need = shoulder_need(body_ws(groups_.front().joint_ms + front_shoulder_, 0.0f), 0.0f);
      if (need <= 0.0f) break;
      const float girdle_y = rotate_body(rel).y;
      pitch_ = std::min(pitch_ + std::asin(std::min(need / front_shoulder_.x, 0.9f)), kMaxPitch);
      root_y_ += girdle_y - rotate_body(rel).y;
    }
  }
  // Whatever the legs ask, a girdle never sinks into the ground under it: it keeps an eighth
  // of its standing height above the highest ground there (a leg may stretch, the body stays
  // out). Ground the body came down past on this tick counts too (the leg clamp above may
  // pull it down further than the queries look up).
  float raise = 0.0f;
  const float fell = groups_.empty() ? 0.0f : std::max(old_root - root_y_, 0.0f);
  for (size_t g = 0; g < groups_.size(); ++g) {
    const glm::vec2 joint = girdle_ws(static_cast<int>(g));
    const float rest = groups_[g].rest_height;
    const float half = 0.1f * rest;
    if (auto below = ground_below(level, joint.x - half, joint.x + half, joint.y + 0.5f * rest + fell, 100.0f)) {
      raise = std::max(raise, below->height_ws + 0.12f * rest - joint.y);
    }
  }
  // Shoulders carrying arms, wings or fins too (those fold and lift, but their roots must stay
  // out).
  auto keep_shoulder_out = [&](int limb) {
    raise = std::max(raise, shoulder_need(body_ws(bone_start(model_rest_[creature_->limbs[limb].bones[0]]), 0.0f), fell));
  };
  for (int a : outline_arms_) keep_shoulder_out(a);
  for (int w : outline_wings_) keep_shoulder_out(w);
  // A folded wing is part of the body's outline: it does not cut a step's corner either (a
  // wall, too high to rise over, is the sweep's business).
  for (int w : outline_wings_) {
    const auto& bones = creature_->limbs[w].bones;
    glm::vec2 a = body_ws(bone_start(model_rest_[bones[0]]), raise);
    for (int b : bones) {
      const glm::vec2 e = body_ws(bone_end(model_rest_[b], creature_->skeleton.length(b)), raise);
      const float need = raise_to_clear(a, e, level);
      if (need < 0.5f * hip_height_) raise += need;
      a = e;
    }
  }
  for (int f : outline_fins_) keep_shoulder_out(f);
  root_y_ += raise;
  root_vy_ = dt > 0.0f ? (root_y_ - old_root) / dt : 0.0f;
}

float Animator::raise_to_clear(glm::vec2 a, glm::vec2 b, const Level& level) const {
  // How far the segment must rise (straight up) to leave every box it cuts: over the part of
  // the box's width it spans, its lowest point to the box's top.
  segment_hits_.clear();
  level.overlapping(Box{glm::min(a, b) - glm::vec2(1e-4f), glm::max(a, b) + glm::vec2(1e-4f)}, segment_hits_);
  float need = 0.0f;
  for (int h : segment_hits_) {
    const Box& box = level.box(h);
    const float lo = std::max(std::min(a.x, b.x), box.min_ws.x), hi = std::min(std::max(a.x, b.x), box.max_ws.x);
    if (lo > hi) continue;
    auto y_at = [&](float x) { return std::fabs(b.x - a.x) < 1e-6f ? std::min(a.y, b.y) : a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x); };
    const float y0 = y_at(lo), y1 = y_at(hi);
    if (std::max(y0, y1) <= box.min_ws.y) continue;  // passes under it
    need = std::max(need, box.top() - std::min(y0, y1));
  }
  return need;
}

void Animator::move_girdle(int group, float dy) {
  const int n = static_cast<int>(groups_.size());
  if (n < 2 || (group != 0 && group != n - 1)) {
    root_y_ += dy;
    return;
  }
  // Turn the body about the girdle at the other end (o), which stays put; whatever a turn
  // within the pitch limits (per tick and overall) cannot give, the whole body moves.
  const glm::vec2 root_rest(0.0f, root_rest_y_);
  const glm::vec2 o = groups_[group == 0 ? n - 1 : 0].joint_ms - root_rest;
  const glm::vec2 v = groups_[group].joint_ms - root_rest - o;
  const float len = std::sqrt(v.x * v.x + v.y * v.y);
  const glm::vec2 v_before = rotate_body(v), o_before = rotate_body(o);
  if (len > 1e-4f) {
    const float phi = fast_atan2(v.y, v.x), a = pitch_ + lean_;
    const float s = std::asin(std::clamp((v_before.y + dy) / len, -0.95f, 0.95f));
    const float turned = (std::cos(a + phi) >= 0.0f ? s : kPi - s) - phi;
    const float step = std::clamp(wrap_angle(turned - a), -kMaxPitchStep, kMaxPitchStep);
    pitch_ = std::clamp(pitch_ + step, std::max(pitch_target_ - kMaxPitchOff, -kMaxPitch),
                        std::min(pitch_target_ + kMaxPitchOff, kMaxPitch));
  }
  const float moved = rotate_body(v).y - v_before.y;
  root_y_ += o_before.y - rotate_body(o).y + (dy - moved);
}

// [SECTION] pose: spine, IK, arms, tail ------------------------------------------------------

void Animator::build_pose(float dt, const Level& level) {
  const Creature& c = *creature_;
  const Skeleton& sk = c.skeleton;
  for (int b : touched_bones_) pose_.locals[b] = c.rest_pose.locals[b];
  const float body_angle = pitch_ + lean_;
  pose_.locals[c.root].offset_ls = {0.0f, root_y_};
  pose_.locals[c.root].angle_ls += body_angle;
  if (c.skull >= 0) pose_.locals[c.skull].angle_ls -= body_angle;  // the head stays level

  // Tail: damped spring driven by the body's bob and pitch.
  if (!c.tail.empty()) {
    const float target = std::clamp(-0.25f * root_vy_ / std::max(hip_height_, 0.05f), -0.4f, 0.4f) - 0.5f * body_angle;
    if (dt > 0.0f) {
      const float k = params_.tail_stiffness;
      const float damping = 2.0f * params_.tail_damping * std::sqrt(k);
      tail_rate_ = flush(tail_rate_ + (k * (target - tail_angle_) - damping * tail_rate_) * dt);
      tail_angle_ = flush(std::clamp(tail_angle_ + tail_rate_ * dt, -0.8f, 0.8f));
    }
    const float bend = tail_angle_ * 2.0f / static_cast<float>(c.tail.size());
    for (int b : c.tail) pose_.locals[b].angle_ls += bend;
  }
  // Legless bodies: a travelling wave down the spine.
  if (legs_.empty() && params_.crawl_amplitude > 0.0f) {
    std::vector<int> chain;
    chain.insert(chain.end(), c.back.begin(), c.back.end());
    chain.insert(chain.end(), c.tail.begin(), c.tail.end());
    const float n = static_cast<float>(chain.size());
    const float amp = params_.crawl_amplitude * std::min(speed_ / std::max(walk_speed(), 1e-3f), 1.0f);
    for (size_t i = 0; i < chain.size(); ++i) {
      pose_.locals[chain[i]].angle_ls += amp * std::sin(kTwoPi * (crawl_phase_ - params_.crawl_waves * static_cast<float>(i) / n));
    }
  }
  // Forward kinematics in two passes: the body first (the root, then each girdle straight from
  // it, or the chains to the girdles when the spine bends; bones whose joint values did not
  // change reuse their rest matrices), then the limb chains after IK (leaves of the tree).
  model_.resize(sk.bone_count());
  const std::vector<int>& parents = sk.parents();
  body_fk();
  if (legs_.empty()) keep_body_out(level);
  if (tail_length_ > 0.0f) keep_tail_clear(level);

  // Legs: two-bone IK in model space (the creature always faces +x there, so knees bend the
  // right way whichever way it faces in the world).
  for (size_t i = 0; i < legs_.size(); ++i) {
    const LegInfo& info = legs_[i];
    const Limb& limb = c.limbs[info.limb];
    const Foot& f = feet_[foot_of_leg_[i]];
    const glm::vec2 joint = model_[limb.girdle_bone].apply(pose_.locals[limb.bones[0]].offset_ls);
    glm::vec2 contact = to_model(f.pos_ws);
    if (f.state == LegState::kSwing) {
      // A swinging foot out of reach below stays at the lowest point the leg reaches, right
      // above its path, instead of being dragged along the line to it (into a step's corner).
      const float r = info.contact_reach;
      const float dx = contact.x - joint.x;
      const float len = glm::length(contact - joint);
      if (len > r && std::fabs(dx) < r && contact.y < joint.y) {
        contact.y = joint.y - std::sqrt(r * r - dx * dx);
      } else if (len > r) {  // out of reach to the side: towards it, as far as the leg reaches
        contact = joint + (contact - joint) * (r / len);
      }
    }
    glm::vec2 foot_dir;
    const Clearance& near = f.state == LegState::kStance ? f.stance_clear : f.swing_clear;
    glm::vec2 ankle = leg_ankle(static_cast<int>(i), contact, joint, &level, near, &foot_dir, nullptr);
    if (f.state == LegState::kSwing) {
      // The same for the ankle when the foot could not roll far enough.
      const float r = info.leg_reach;
      const float dx = ankle.x - joint.x;
      if (glm::length(ankle - joint) > r && std::fabs(dx) < r && ankle.y < joint.y) {
        ankle.y = joint.y - std::sqrt(r * r - dx * dx);
      }
      // A foot lifted closer to the joint than the leg folds (short legs, high swings) moves
      // out sideways to where the folded leg reaches, not down through the ground.
      const float fold = info.fold;
      const glm::vec2 d = ankle - joint;
      if (glm::dot(d, d) < fold * fold && std::fabs(d.y) < fold) {
        ankle.x = joint.x + (d.x >= 0.0f ? 1.0f : -1.0f) * std::sqrt(fold * fold - d.y * d.y);
      }
    }
    auto leg_ik = [&](glm::vec2 target) {  // directions only: the angles are for pose() (lazily)
      return solve_two_bone_ik_directions(joint, info.upper, info.lower, target, info.bend);
    };
    TwoBoneIkResult ik = leg_ik(ankle);
    if (f.state == LegState::kSwing) {
      // A knee, shin or foot swinging into a step lifts the foot until the whole leg clears.
      const float F = info.foot_length;  // ankle to toe (to the contact point, or along a flat foot)
      glm::vec2 dir = foot_dir;  // the foot's direction for the candidate being tested
      auto leg_hits = [&](const TwoBoneIkResult& r) {
        const glm::vec2 tip = r.end + F * dir;
        const glm::vec2 p[4] = {to_world(joint), to_world(r.middle), to_world(r.end), to_world(tip)};
        return polyline_hits_level(level, p, F > 0.0f ? 4 : 3, segment_hits_);
      };
      // Candidates run from the planned ankle straight up, then in towards a tuck under the
      // joint; the first (bisected) that clears wins.
      const glm::vec2 up = glm::vec2(ankle.x, std::max(ankle.y, joint.y - 0.3f * info.reach));
      const glm::vec2 tuck = joint + glm::vec2(0.0f, -0.45f * info.reach);
      // Last, drawn back from under the joint by a foot's length (a toe against a riser).
      const glm::vec2 back = tuck - glm::vec2(F + 0.02f * info.reach, 0.0f);
      // A lifted foot turns back from its roll to hang in its rest direction; drawn back, it
      // folds up behind the ankle.
      const glm::vec2 folded(-0.98f, 0.2f);
      auto candidate = [&](float t) {  // t in [0, 3]: 0 planned, 1 lifted, 2 tucked, 3 back
        const glm::vec2 a = t <= 1.0f   ? glm::mix(ankle, up, t)
                            : t <= 2.0f ? glm::mix(up, tuck, t - 1.0f)
                                        : glm::mix(tuck, back, t - 2.0f);
        const glm::vec2 d = t <= 1.0f   ? glm::mix(foot_dir, info.foot_dir_ms, t)
                            : t <= 2.0f ? info.foot_dir_ms
                                        : glm::mix(info.foot_dir_ms, folded, t - 2.0f);
        dir = d / std::max(glm::length(d), 1e-6f);
        return leg_ik(a);
      };
      const float min_y = std::min({joint.y, ik.middle.y, ik.end.y, ik.end.y + F * foot_dir.y});
      if (!near.clear_above(min_y) && leg_hits(ik)) {
        float lo = 0.0f, hi = -1.0f;
        for (float t : {1.0f, 2.0f, 3.0f}) {
          if (!leg_hits(candidate(t))) {
            hi = t;
            break;
          }
          lo = t;
        }
        if (hi > 0.0f) {
          for (int k = 0; k < 6; ++k) {
            const float mid = 0.5f * (lo + hi);
            (leg_hits(candidate(mid)) ? lo : hi) = mid;
          }
          ik = candidate(hi);
          foot_dir = dir;
        }
      }
    }
    leg_dirs_[i] = {ik.upper_dir, ik.lower_dir, foot_dir};
    // The chain's matrices straight from the solution's directions (no trigonometry).
    const Mat2x3 upper = frame_matrix(ik.upper_dir, joint);
    const Mat2x3 lower = frame_matrix(ik.lower_dir, upper.apply(pose_.locals[limb.bones[1]].offset_ls));
    model_[limb.bones[0]] = upper;
    model_[limb.bones[1]] = lower;
    model_[limb.bones[2]] = frame_matrix(foot_dir, lower.apply(pose_.locals[limb.bones[2]].offset_ls));
  }
  // Arms swing counter to the same-side leg; fins trail with a slow beat.
  const float motion = std::min(speed_ / std::max(walk_speed(), 1e-3f), 1.0f);
  for (int a : arms_) {
    const Limb& arm = c.limbs[a];
    float p = phase_;
    for (size_t i = 0; i < legs_.size(); ++i) {
      if (c.limbs[legs_[i].limb].side == arm.side) p = frac(phase_ + feet_[foot_of_leg_[i]].offset);
    }
    const float t = frac(p + 0.5f);
    for (int k = 0; k < 2; ++k) {
      const PrototypeId id = k == 0 ? PrototypeId::kArmSwing : PrototypeId::kArmBend;
      pose_.locals[arm.bones[k]].angle_ls += motion * prototype_range(id).clamp(spline_prototypes_[id].value(t, run_factor_));
    }
    keep_arm_above_ground(arm, level);
  }
  for (int fin : fins_) {
    const Limb& limb = c.limbs[fin];
    pose_.locals[limb.bones[0]].angle_ls += 0.12f * motion * std::sin(kTwoPi * (crawl_phase_ + phase_));
    keep_fin_clear(limb, level);
  }
  for (int wing : wings_) keep_fin_clear(c.limbs[wing], level);  // folded, but not into a step
  for (int b : other_limb_bones_) model_[b] = model_[parents[b]] * local_matrix(pose_.locals[b]);
  world_dirty_ = true;
  model_dirty_ = true;
  leg_angles_dirty_ = true;
}

}  // namespace ossa
