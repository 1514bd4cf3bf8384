#include "ossa/gen/body_plan.h"

#include <algorithm>
#include <cmath>

#include "ossa/gen/pca_model.h"
#include "ossa/math/angle.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa {

namespace {

constexpr float kHalfPi = 0.5f * kPi;
// [Z 7.2.1] legs reach the ground at this fraction of their length. The seed uses 0.8, which
// folds a standing quadruped into a crouch (its own elephant and brachiosaurus); at 0.9 the
// knees stay visibly bent and the stance reads as standing.
constexpr float kGroundFraction = 0.9f;
constexpr float kScapulaAngle = -1.05f;  // abs, frame space: down and forward
constexpr float kPelvisAngle = -2.05f;   // abs: down and back
constexpr int kBackFront = 13;           // [Z 7.3] of 25 back vertebrae in front of the root
constexpr float kMaxPitch = 0.6f;        // radians: the most the body tilts to stand
constexpr int kSpineTableSamples = 24;

glm::vec2 rotate(glm::vec2 v, float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// [Z 9.6.2]: make two curves meeting at `junction` C1 by rotating the neighbouring control
// points `in` (the previous curve's) and `out` (the next curve's) by equal and opposite
// angles until they are collinear with the junction. Degenerate sides are left alone.
void make_c1(glm::vec2& in, glm::vec2 junction, glm::vec2& out) {
  const glm::vec2 din = in - junction, dout = out - junction;
  if (glm::dot(din, din) < 1e-6f || glm::dot(dout, dout) < 1e-6f) return;
  const float a_in = std::atan2(din.y, din.x), a_out = std::atan2(dout.y, dout.x);
  const float delta = wrap_angle(a_in + kPi - a_out);
  out = junction + rotate(dout, 0.5f * delta);
  in = junction + rotate(din, -0.5f * delta);
}

// n+1 points along the curve at arc fractions (or parameters) u0 + i/n * (u1 - u0).
void sample_curve(const CubicBezier& curve, const ArcLengthTable& table, bool arc_length, float u0,
                  float u1, int n, std::vector<glm::vec2>& out, bool skip_first) {
  for (int i = skip_first ? 1 : 0; i <= n; ++i) {
    const float u = u0 + (u1 - u0) * static_cast<float>(i) / static_cast<float>(n);
    out.push_back(curve.eval(arc_length ? table.t_at_fraction(u) : u));
  }
}

struct LegLimits {
  float lo[3], hi[3];
};

LegLimits leg_limits(GirdleKind girdle) {
  // [Z fig. 7.1]: upper bones stay on their side of the vertical; lower bones range from the
  // extension of their parent to fully folded onto it. The front hand may also turn forward
  // (a flat hand), the hind foot folds forward.
  if (girdle == GirdleKind::kHip) return {{-kHalfPi, -kPi, 0.0f}, {0.0f, 0.0f, kPi}};
  return {{-kPi, 0.0f, -kPi}, {-kHalfPi, kPi, kHalfPi}};
}

struct Chain {
  glm::vec2 p[4];  // joint, middle, heel, tip
};

Chain chain_points(glm::vec2 joint, const LimbLengths& l, const float a[3]) {
  Chain c;
  c.p[0] = joint;
  const float a1 = a[0], a2 = a1 + a[1], a3 = a2 + a[2];
  c.p[1] = c.p[0] + static_cast<float>(l.upper) * glm::vec2(std::cos(a1), std::sin(a1));
  c.p[2] = c.p[1] + static_cast<float>(l.lower) * glm::vec2(std::cos(a2), std::sin(a2));
  c.p[3] = c.p[2] + static_cast<float>(l.distal) * glm::vec2(std::cos(a3), std::sin(a3));
  return c;
}

}  // namespace

bool limb_allowed(LimbKind kind, GirdleKind girdle) {
  switch (kind) {
    case LimbKind::kLeg: return girdle != GirdleKind::kNeck;
    case LimbKind::kArm:
    case LimbKind::kWing: return girdle != GirdleKind::kHip;
    case LimbKind::kFin: return true;
  }
  return false;
}

int limb_bend_sign(GirdleKind girdle) { return girdle == GirdleKind::kHip ? 1 : -1; }

namespace {

// Everything but the ground, from the (C1-fixed, possibly pitched) spine control points.
BodyPlan plan_geometry(const Genome& g, const Animal& a, const std::array<glm::vec2, kSpinePoints>& p) {
  BodyPlan plan;
  plan.neck = CubicBezier{{p[0], p[1], p[2], p[3]}};
  plan.back = CubicBezier{{p[3], p[4], p[5], p[6]}};
  plan.tail = CubicBezier{{p[6], p[7], p[8], p[9]}};
  // Spine curves are gentle: 24 table intervals keep vertebra spacing within 0.1% of a
  // vertebra and make the table (the generator's main cost) cheap.
  const ArcLengthTable neck_t(plan.neck, kSpineTableSamples), back_t(plan.back, kSpineTableSamples),
      tail_t(plan.tail, kSpineTableSamples);
  plan.neck_length = neck_t.length();
  plan.back_length = back_t.length();
  plan.tail_length = tail_t.length();
  plan.body_size = std::max(plan.back_length, 20.0f);
  const bool arc = g.options.arc_length_vertebrae;

  auto clamp_len = [](LimbLengths l) {
    l.upper = std::max(0.0, l.upper);
    l.lower = std::max(0.0, l.lower);
    l.distal = std::max(0.0, l.distal);
    return l;
  };
  plan.front = clamp_len(a.front);
  plan.hind = clamp_len(a.hind);

  // Spine joints, head end first.
  const int n_neck = plan.neck_length > 1.0f ? g.neck_vertebrae : 0;
  const int n_tail = plan.tail_length > 1.0f ? g.tail_vertebrae : 0;
  if (n_neck > 0) {
    sample_curve(plan.neck, neck_t, arc, 0.0f, 1.0f, n_neck, plan.joints, false);
  } else {
    plan.joints.push_back(p[3]);
  }
  plan.shoulder_joint = static_cast<int>(plan.joints.size()) - 1;
  const int front = std::max(1, g.back_vertebrae * kBackFront / 25);
  const int rear = std::max(1, g.back_vertebrae - front);
  sample_curve(plan.back, back_t, arc, 0.0f, 0.5f, front, plan.joints, true);
  plan.root_joint = static_cast<int>(plan.joints.size()) - 1;
  sample_curve(plan.back, back_t, arc, 0.5f, 1.0f, rear, plan.joints, true);
  plan.hip_joint = static_cast<int>(plan.joints.size()) - 1;
  if (n_tail > 0) sample_curve(plan.tail, tail_t, arc, 0.0f, 1.0f, n_tail, plan.joints, true);

  const int n_joints = static_cast<int>(plan.joints.size());
  plan.back_fraction.resize(n_joints);
  for (int i = 0; i < n_joints; ++i) {
    if (i < plan.shoulder_joint) {
      plan.back_fraction[i] = -1.0f;
    } else if (i > plan.hip_joint) {
      plan.back_fraction[i] = 2.0f;
    } else if (i <= plan.root_joint) {
      plan.back_fraction[i] = 0.5f * (i - plan.shoulder_joint) / static_cast<float>(front);
    } else {
      plan.back_fraction[i] = 0.5f + 0.5f * (i - plan.root_joint) / static_cast<float>(rear);
    }
  }

  // Girdles: the girdle bone starts at a spine joint, the limb chain at the girdle bone's end.
  auto setup = [&](GirdleKind kind, int slot, int joint) {
    GirdlePlan& gp = plan.girdles[static_cast<int>(kind)];
    joint = std::clamp(joint, 0, n_joints - 1);
    gp.exists = true;
    gp.spine_joint[slot] = joint;
    gp.girdle_start_fu[slot] = plan.joints[joint];
    float length, angle;
    if (kind == GirdleKind::kHip) {
      length = std::clamp(0.45f * static_cast<float>(plan.hind.upper), 0.04f * plan.body_size,
                          0.25f * plan.body_size);
      angle = kPelvisAngle;
    } else {
      length = std::clamp(0.8f * static_cast<float>(plan.front.upper), 0.05f * plan.body_size,
                          0.3f * plan.body_size);
      angle = kScapulaAngle;
    }
    gp.joint_fu[slot] = plan.joints[joint] + length * glm::vec2(std::cos(angle), std::sin(angle));
  };
  const int slots = g.options.multi_limb ? 2 : 1;
  setup(GirdleKind::kShoulder, 0, plan.shoulder_joint);
  setup(GirdleKind::kHip, 0, plan.hip_joint);
  if (slots == 2) {
    setup(GirdleKind::kShoulder, 1, plan.shoulder_joint + std::max(2, front / 4));
    setup(GirdleKind::kHip, 1, plan.hip_joint - std::max(2, rear / 4));
  }
  if (g.options.neck_girdle && n_neck >= 3 &&
      plan.neck_length >= kMinNeckGirdleRatio * plan.back_length) {
    const int j = std::max(1, n_neck / 4);
    setup(GirdleKind::kNeck, 0, j);
    if (slots == 2) setup(GirdleKind::kNeck, 1, std::min(j + 2, plan.shoulder_joint - 1));
  }

  return plan;
}

// Reach of a leg down to its contact point: the whole chain for tip contact, the heel (upper
// and lower bone) for flat contact.
float leg_reach(const LimbLengths& l, ContactMode contact) {
  return static_cast<float>(contact == ContactMode::kFlat ? l.upper + l.lower : l.total());
}

}  // namespace

BodyPlan plan_body(const Genome& g) {
  const Animal a = from_vector(Eigen::Map<const PcaVector>(g.pca.data()));
  std::array<glm::vec2, kSpinePoints> p = a.spine;
  make_c1(p[2], p[3], p[4]);
  make_c1(p[5], p[6], p[7]);
  BodyPlan plan = plan_geometry(g, a, p);

  // Pitch: with legs on both shoulder and hip, tilt the body about the root so both girdles
  // stand at the same fraction of their legs' reach — short front legs put the nose down
  // (rabbit, kangaroo) instead of leaving a girdle under the ground [Z 9.8 (4)].
  const LimbGene* front_leg = nullptr;
  const LimbGene* hind_leg = nullptr;
  for (const LimbGene& limb : g.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    if (limb.girdle == GirdleKind::kShoulder && !front_leg) front_leg = &limb;
    if (limb.girdle == GirdleKind::kHip && !hind_leg) hind_leg = &limb;
  }
  if (front_leg && hind_leg) {
    const glm::vec2 s = plan.girdles[static_cast<int>(GirdleKind::kShoulder)].joint_fu[front_leg->slot];
    const glm::vec2 h = plan.girdles[static_cast<int>(GirdleKind::kHip)].joint_fu[hind_leg->slot];
    const float ls = leg_reach(limb_lengths(plan, g, LimbKind::kLeg, GirdleKind::kShoulder), g.contact);
    const float lh = leg_reach(limb_lengths(plan, g, LimbKind::kLeg, GirdleKind::kHip), g.contact);
    const glm::vec2 d = s - h;
    const float dist = std::sqrt(d.x * d.x + d.y * d.y);
    if (dist > 1.0f) {
      // Solve (R(θ) d).y = kGroundFraction (ls - lh) for the smallest |θ|.
      const float want = std::clamp(kGroundFraction * (ls - lh) / dist, -1.0f, 1.0f);
      const float phi = std::atan2(d.y, d.x);
      const float theta = std::clamp(wrap_angle(std::asin(want) - phi), -kMaxPitch, kMaxPitch);
      if (std::fabs(theta) > 1e-3f) {
        const glm::vec2 pivot = plan.joints[plan.root_joint];
        for (glm::vec2& q : p) q = pivot + rotate(q - pivot, theta);
        plan = plan_geometry(g, a, p);
        plan.pitch = theta;
      }
    }
  }

  // Ground [Z 7.2.1]: every leg reaches it at kGroundFraction of its length; it moves up
  // from the frame bottom when the legs are too short. Measured from the real girdle joint
  // (the seed measured from the curve's control point and lists the gap as a problem, 9.8).
  // When the girdles stand at very different heights, the ground is lowered (never below
  // full reach of any leg) so that no girdle ends up crouched under 35% of its reach, which
  // would leave the folded start of [Z 7.2.2] under the ground [Z 9.8 (4)].
  bool any_leg = false;
  float ground = 0.0f;
  float lowest_allowed = -1e30f, highest_allowed = 1e30f;
  for (const LimbGene& limb : g.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    const GirdlePlan& gp = plan.girdles[static_cast<int>(limb.girdle)];
    if (!gp.exists) continue;
    const float reach = leg_reach(limb_lengths(plan, g, limb.kind, limb.girdle), g.contact);
    const float joint_y = gp.joint_fu[limb.slot].y;
    ground = std::max(ground, joint_y - kGroundFraction * reach);
    lowest_allowed = std::max(lowest_allowed, joint_y - 0.98f * reach);
    highest_allowed = std::min(highest_allowed, joint_y - 0.35f * reach);
    any_leg = true;
  }
  if (any_leg && lowest_allowed <= highest_allowed) {
    ground = std::clamp(ground, lowest_allowed, highest_allowed);
  }
  if (!any_leg) {
    // Legless bodies lie on the ground: just below their lowest spine joint.
    float lowest = plan.joints[0].y;
    for (const glm::vec2& j : plan.joints) lowest = std::min(lowest, j.y);
    ground = lowest - 0.03f * plan.body_size;
  }
  plan.ground_y = ground;

  // Heel/wrist contact probability [Z 7.2.1], judged with the whole leg (tip contact).
  float p_sum = 0.0f;
  int p_count = 0;
  for (const LimbGene& limb : g.limbs) {
    if (limb.kind != LimbKind::kLeg || !any_leg) continue;
    const GirdlePlan& gp = plan.girdles[static_cast<int>(limb.girdle)];
    if (!gp.exists) continue;
    const LimbLengths l = limb_lengths(plan, g, limb.kind, limb.girdle);
    float p_leg = 0.0f;
    const float tip_ground = gp.joint_fu[limb.slot].y - kGroundFraction * static_cast<float>(l.total());
    if (tip_ground <= 0.0f && l.distal > 0.0) {
      p_leg = std::clamp(static_cast<float>((l.total() - gp.joint_fu[limb.slot].y) / l.distal), 0.0f, 1.0f);
    }
    p_sum += p_leg;
    ++p_count;
  }
  plan.heel_probability = p_count ? p_sum / static_cast<float>(p_count) : 0.0f;
  return plan;
}

LimbLengths limb_lengths(const BodyPlan& plan, const Genome& g, LimbKind kind, GirdleKind girdle) {
  LimbLengths l = girdle == GirdleKind::kHip ? plan.hind : plan.front;
  if (kind == LimbKind::kWing && g.pca[kWings] < 0.5) {
    // A wing on a wingless body (pegasus): its front limb is a leg; wings need more span.
    l.upper *= 1.5;
    l.lower *= 1.5;
    l.distal *= 2.0;
  }
  const double min_total = 0.12 * plan.body_size;
  if (kind != LimbKind::kLeg && l.total() < min_total) {
    // Fins and arms of bodies whose PCA limb is (near) absent still get a visible size.
    l = LimbLengths{0.45 * min_total, 0.3 * min_total, 0.25 * min_total};
  }
  return l;
}

glm::vec2 leg_contact_point(glm::vec2 joint, const LimbLengths& l, const std::array<float, 3>& a,
                            ContactMode contact) {
  const Chain c = chain_points(joint, l, a.data());
  return contact == ContactMode::kFlat ? c.p[2] : c.p[3];
}

std::array<float, 3> arm_rest_angles() { return {-kHalfPi, kHalfPi, 0.0f}; }
std::array<float, 3> fin_rest_angles() { return {-kPi + 0.25f, 0.0f, 0.0f}; }

std::array<float, 3> place_leg(const BodyPlan& plan, glm::vec2 joint, const LimbLengths& l,
                               GirdleKind girdle, ContactMode contact) {
  const bool hind = girdle == GirdleKind::kHip;
  const float ground = plan.ground_y;
  const float total = static_cast<float>(l.total());
  const bool flat = contact == ContactMode::kFlat;
  // Flat contact keeps the foot/hand on the ground pointing forward (absolute angle 0).
  auto flat_foot = [&](float a[3]) {
    if (flat) a[2] = wrap_angle(0.0f - (a[0] + a[1]));
  };
  const std::array<float, 3> straight_down = {-kHalfPi, 0.0f, flat ? kHalfPi : 0.0f};

  // [Z 9.8 (3)]: legs too short to see are not placed.
  if (total < kMinPlacedLegLength) return straight_down;

  const LegLimits lim = leg_limits(girdle);
  // Start fully bent: every joint at its folded limit [Z 7.2.2].
  float a[3] = {hind ? lim.hi[0] : lim.lo[0], hind ? lim.lo[1] : lim.hi[1],
                hind ? lim.hi[2] : lim.lo[2]};
  flat_foot(a);
  const int target = flat ? 2 : 3;
  const float tolerance = 0.002f * total;

  auto valid = [&](const float x[3]) {
    for (int j = 0; j < 3; ++j) {
      if (j == 2 && flat) continue;
      if (x[j] < lim.lo[j] - 1e-6f || x[j] > lim.hi[j] + 1e-6f) return false;
    }
    const Chain c = chain_points(joint, l, x);
    for (int k = 1; k < 4; ++k) {
      if (c.p[k].y < ground - 1e-4f * total) return false;
    }
    return true;
  };

  // [Z 9.8 (4)]: the start position already below the ground → straight down, flat foot.
  if (!valid(a)) {
    // The folded chain can dip below the ground only when the joint itself is very low.
    return {-kHalfPi, 0.0f, kHalfPi};
  }

  // Two phases of the same iteration. Phase 1 swings each bone toward a natural standing
  // direction (zig-zag: hind femur forward-down, shank back-down, foot near vertical; front
  // humerus back-down, forearm and hand down) — the seed's pure "toward vertical" rule makes
  // whichever bone moves first hang straight and leaves the next one flat (its elephant and
  // brachiosaurus examples). Phase 2 is [Z 7.2.2] as written: toward vertical, to extend a
  // leg that still does not reach. Every step is undone when it breaks a joint limit or puts
  // a joint under the ground; steps start at 40° and shrink by 6/7 per round.
  const float natural[3] = {
      hind ? (flat ? -1.25f : -0.95f) : (flat ? -1.85f : -2.05f),
      hind ? (flat ? -1.85f : -2.2f) : (flat ? -1.45f : -1.57f),
      hind ? -1.4f : -1.6f};
  const int joints = flat ? 2 : 3;
  for (int phase = 0; phase < 2; ++phase) {
    float step = 40.0f * kPi / 180.0f;
    for (int iter = 0; iter < 300 && step > 1e-6f; ++iter) {
      const float gap = chain_points(joint, l, a).p[target].y - ground;
      if (gap < tolerance) break;
      int undone = 0;
      for (int j = 0; j < joints; ++j) {
        float abs_angle = a[0];
        for (int k = 1; k <= j; ++k) abs_angle += a[k];
        const float goal = phase == 0 ? natural[j] : -kHalfPi;
        const float diff = wrap_angle(goal - abs_angle);
        if (std::fabs(diff) < 1e-7f) {
          ++undone;
          continue;
        }
        // Never across the goal direction (for phase 2: the vertical).
        const float delta = std::copysign(std::min(step, std::fabs(diff)), diff);
        float trial[3] = {a[0], a[1], a[2]};
        trial[j] += delta;
        // Swinging a bone keeps the bones below it pointing the same way: a standing leg
        // moves one joint, not the whole chain below it.
        if (j + 1 < 3) trial[j + 1] -= delta;
        flat_foot(trial);
        if (valid(trial)) {
          a[0] = trial[0];
          a[1] = trial[1];
          a[2] = trial[2];
        } else {
          ++undone;
        }
      }
      // [Z 9.8 (2)] fix: shrink faster when every rotation of this round was undone (count
      // undone steps, not the change of distance, which is tiny for short bones anyway).
      step *= undone == joints ? 0.5f : 6.0f / 7.0f;
    }
  }

  std::array<float, 3> result = {a[0], a[1], a[2]};
  const float gap = chain_points(joint, l, a).p[target].y - ground;
  if (gap <= 0.005f * total) return result;

  // The greedy placement can stall with a knee on the ground [Z 9.8 (5)]. Fallback: fix the
  // foot at a natural angle and put the heel on the ground with analytic two-bone IK.
  const float foot_abs = flat ? 0.0f : (hind ? -1.2f : -1.75f);
  const glm::vec2 foot = flat ? glm::vec2(0.0f)
                              : static_cast<float>(l.distal) *
                                    glm::vec2(std::cos(foot_abs), std::sin(foot_abs));
  const float reach = static_cast<float>(l.upper + l.lower);
  const float drop = joint.y - (ground - foot.y);
  if (drop > 0.0f && drop < reach) {
    const float dx = std::sqrt(std::max(0.0f, 0.81f * reach * reach - drop * drop));
    const glm::vec2 heel = {joint.x + (hind ? 0.25f : -0.25f) * dx, ground - foot.y};
    const TwoBoneIkResult ik = solve_two_bone_ik(joint, static_cast<float>(l.upper),
                                                 static_cast<float>(l.lower), heel,
                                                 static_cast<float>(limb_bend_sign(girdle)));
    if (ik.reached) {
      result[0] = ik.upper_angle;
      result[1] = ik.lower_angle;
      result[2] = wrap_angle(foot_abs - (ik.upper_angle + ik.lower_angle));
      return result;
    }
  }
  // [Z 9.8 (1)]: ground out of reach → fully extended straight down.
  return straight_down;
}

}  // namespace ossa
