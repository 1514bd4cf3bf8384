#include "ossa/anim/leg_ik.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa::anim {

namespace {

constexpr int kTuckBisections = 6;
// A swinging leg's escape path: lifted to at most this many leg lengths below the joint,
// tucked this far under it, drawn back a foot's length plus this much of the leg.
constexpr float kLiftBelowJointOfLeg = 0.3f;
constexpr float kTuckBelowJointOfLeg = 0.45f;
constexpr float kDrawBackOfLeg = 0.02f;
// ... or, when none of those clears, carried forward a foot's length plus this much of the leg.
constexpr float kCarryAheadOfLeg = 0.5f;
// ... or, last, turned whole about the joint in steps of this (radians), up to this many each way.
constexpr float kWholeTurnStep = kPi / 12.0f;
constexpr float kWholeTurnSteps = 6.0f;
// The swing's candidates kept for when none clears with its flesh (leg_ik: planned, lifted,
// tucked, drawn back, carried ahead, turned whole either way), and how much less deep another
// candidate's flesh must lie than the bones-only escape's to be taken instead, metres.
constexpr size_t kTriedCandidates = 20;
constexpr float kFleshDepthGain = 1e-3f;
// A swinging leg's flesh meets boxes whose top lies this far above the ground it steps from or
// to, metres (not that ground).
constexpr float kGroundSlack = 1e-3f;
// A stance leg whose ankle lies further from the joint than the leg's length by more than this
// fraction of it is stretched (the leg IK cannot reach the foot).
constexpr float kStretchedOfLeg = 0.01f;
// A coupled leg reaches its tip with the virtual two-bone chain at most this straight, and
// bends no closer than this multiple of its fold.
constexpr float kCoupledReach = 0.999f;
constexpr float kCoupledFold = 1.02f;
// most_turn leaves the chain this fraction of the reach to spare.
constexpr float kTurnReachSlack = 1e-4f;
// A swinging foot that holds its angle folds its lower joint (hock, intertarsal joint) to no
// less than this angle between shin and foot (radians), or its rest angle where that is less.
constexpr float kLeastSwingAnkle = 0.2f;
// A foot that folded through the shin lies this far open from it (radians).
constexpr float kShutAnkle = 0.02f;


}  // namespace

namespace {

// Shared by validate() and run() (a public member function is not inlined into run()).
inline bool valid(const LegIkJob& j) {
  return j.ctx && j.body && j.feet && j.pose && j.model_fs && j.leg_dirs && j.feet->foot_of_leg.size() == j.ctx->rig.legs.size() &&
         j.leg_dirs->size() == j.ctx->rig.legs.size() && j.model_fs->size() == static_cast<size_t>(j.ctx->rig.skeleton.bone_count());
}

}  // namespace

namespace {

// v turned by the unit vector t (a complex product).
inline glm::vec2 turned(glm::vec2 v, glm::vec2 t) { return {t.x * v.x - t.y * v.y, t.y * v.x + t.x * v.y}; }
inline glm::vec2 unit(float a) { return {std::cos(a), std::sin(a)}; }

// The foot and the bone p it turns with (the thigh, hind; else the forearm) as one bone: its
// length and its direction as if p pointed along +x, for the foot turned from p by `turn`
// (cos, sin of the angle).
struct Composite {
  float length = 0.0f;
  glm::vec2 dir{1.0f, 0.0f};
};
inline Composite composite(float p, float q, glm::vec2 turn) {
  const glm::vec2 pq(p + q * turn.x, q * turn.y);
  const float a = glm::length(pq);
  return {a, a > 0.0f ? pq / a : glm::vec2(1.0f, 0.0f)};
}

// The leg reaching tip_fs with bone p (the thigh, hind_pair; else the forearm) and the foot q
// as one bone (`pq`, the foot turned from p by `turn`), then the other bone o.
bool solve_pair(const RigLeg& info, bool hind_pair, glm::vec2 joint_fs, glm::vec2 tip_fs, glm::vec2 turn, const Composite& pq,
                TwoBoneIkResult* ik, glm::vec2* foot_dir) {
  const float p = hind_pair ? info.upper : info.lower;
  const float o = hind_pair ? info.lower : info.upper;
  const float a = pq.length;
  const glm::vec2 to = tip_fs - joint_fs;
  const float dd = glm::dot(to, to), far = kCoupledReach * (a + o), near = kCoupledFold * (a - o);
  if (!(a > 0.0f) || dd > far * far || dd < near * near) return false;
  const glm::vec2 e = pq.dir;
  auto back = [&](glm::vec2 v) { return glm::vec2(e.x * v.x + e.y * v.y, e.x * v.y - e.y * v.x); };  // turned by -arg(pq)
  if (hind_pair) {  // thigh and foot as one bone, then the shin
    const TwoBoneIkResult r = solve_two_bone_ik_directions(joint_fs, a, o, tip_fs, info.bend);
    ik->upper_dir = back(r.upper_dir);
    ik->lower_dir = r.lower_dir;
    ik->middle = joint_fs + p * ik->upper_dir;
    ik->end = ik->middle + o * ik->lower_dir;
    *foot_dir = turned(ik->upper_dir, turn);
  } else {  // the upper bone, then forearm (or shin) and foot as one bone
    const TwoBoneIkResult r = solve_two_bone_ik_directions(joint_fs, o, a, tip_fs, info.bend);
    ik->upper_dir = r.upper_dir;
    ik->lower_dir = back(r.lower_dir);
    ik->middle = r.middle;
    ik->end = r.middle + p * ik->lower_dir;
    *foot_dir = turned(ik->lower_dir, turn);
  }
  return true;
}

// The most the foot may turn from p and the chain (p + q·e^(iγ), then o) still reach d:
// |p + q·e^(iγ)| >= d / kCoupledReach - o, with kTurnReachSlack to spare: solve_pair tests the
// same bound, and a turn right on it failed there by a rounding every few strides, leaving the
// leg to the plain swing pose for a tick (the giraffe's foreleg in the middle of its gallop's
// swing, its ankle thrown 20 cm forward and back). Negative: not even straight.
float most_turn(float p, float q, float o, float d) {
  const float need = d * (1.0f + kTurnReachSlack) / kCoupledReach - o;
  if (need <= std::fabs(p - q)) return kPi;
  if (!(p * q > 0.0f)) return -1.0f;
  const float c = (need * need - p * p - q * q) / (2.0f * p * q);
  return c > 1.0f ? -1.0f : std::acos(std::max(c, -1.0f));
}

}  // namespace

bool solve_straight_ankle(const RigLeg& info, glm::vec2 joint_fs, glm::vec2 tip_fs, TwoBoneIkResult* ik, glm::vec2* foot_dir) {
  return solve_pair(info, false, joint_fs, tip_fs, {1.0f, 0.0f}, {info.lower + info.foot_span, {1.0f, 0.0f}}, ik, foot_dir);
}

bool solve_coupled_leg(const RigLeg& info, glm::vec2 joint_fs, glm::vec2 tip_fs, float fold, TwoBoneIkResult* ik,
                       glm::vec2* foot_dir) {
  // (Standing, the turn and its composite bone are constants of the rig, and the reach limit is
  // worked out only when the leg does not reach: no trigonometry on the common path.)
  const float s = info.fold_sign;
  const Composite straight{info.lower + info.foot_span, {1.0f, 0.0f}};
  auto pair = [&](bool hind_pair, glm::vec2 turn) {
    return solve_pair(info, hind_pair, joint_fs, tip_fs, turn, composite(hind_pair ? info.upper : info.lower, info.foot_span, turn), ik,
                      foot_dir);
  };
  if (info.hind) {
    // The foot keeps its rest turn from the thigh (folded further in swing, turned no further
    // than the reach allows), unless that would bend the hock past straight: then the hock
    // stays straight (the same pose where the hock is just straight, so no jump).
    const float want = s * info.couple_angle + fold;
    auto hock_bent = [&] { return s * (ik->lower_dir.x * foot_dir->y - ik->lower_dir.y * foot_dir->x) >= 0.0f; };
    bool solved = fold > 0.0f ? pair(true, unit(s * want))
                              : solve_pair(info, true, joint_fs, tip_fs, info.couple_turn, {info.couple_length, info.couple_dir}, ik, foot_dir);
    if (!solved) {
      const float most = most_turn(info.upper, info.foot_span, info.lower, glm::length(tip_fs - joint_fs));
      solved = most >= 0.0f && pair(true, unit(s * std::clamp(want, -most, most)));
    }
    if (solved && hock_bent()) return true;
    return solve_pair(info, false, joint_fs, tip_fs, {1.0f, 0.0f}, straight, ik, foot_dir);
  }
  // The foot in line with the forearm, folded in swing as far as the reach allows.
  if (!(fold > 0.0f)) return solve_pair(info, false, joint_fs, tip_fs, {1.0f, 0.0f}, straight, ik, foot_dir);
  const float most = most_turn(info.lower, info.foot_span, info.upper, glm::length(tip_fs - joint_fs));
  if (most < 0.0f) return false;
  return pair(false, unit(s * std::min(fold, most)));
}

namespace {

// A stance pose that cuts the level where the plain one (what the body placement kept clear)
// may not: a hoof on a step's edge keeps the plain one.
bool clear_in_stance(const AnimContext& c, const BodyFrame& b, const Clearance& near, glm::vec2 joint, glm::vec2 contact,
                     const TwoBoneIkResult& r) {
  if (near.clear_above(std::min({joint.y, r.middle.y, r.end.y, contact.y}))) return true;
  const glm::vec2 p[4] = {b.to_ws(joint), b.to_ws(r.middle), b.to_ws(r.end), b.to_ws(contact)};
  return !polyline_hits_level(c.level, p, 4, c.hits);
}

// A foot holding its angle that would bend the ankle (hock, intertarsal joint) past straight
// (not folded through shut: the foot not turned back against the shin) has the ankle straight
// instead (the same pose where it is just straight), where `clear` allows that pose.
template <class Clear>
void straighten_ankle(const RigLeg& info, glm::vec2 joint, glm::vec2 contact, TwoBoneIkResult& ik, glm::vec2& foot_dir,
                      glm::vec2& ankle, Clear clear) {
  TwoBoneIkResult straight;
  glm::vec2 straight_dir;
  if (!info.coupled && info.foot_span > 0.0f && info.fold_sign * (ik.lower_dir.x * foot_dir.y - ik.lower_dir.y * foot_dir.x) < 0.0f &&
      glm::dot(ik.lower_dir, foot_dir) > 0.0f && solve_straight_ankle(info, joint, contact, &straight, &straight_dir) &&
      clear(straight)) {
    ik = straight;
    foot_dir = straight_dir;
    ankle = straight.end;
  }
}

}  // namespace

StanceLegPose stance_leg_pose(const AnimContext& ctx, const BodyFrame& body, int leg, glm::vec2 contact_fs, glm::vec2 joint_fs,
                              const Clearance& near) {
  const RigLeg& info = ctx.rig.legs[leg];
  auto clear = [&](const TwoBoneIkResult& r) { return clear_in_stance(ctx, body, near, joint_fs, contact_fs, r); };
  StanceLegPose s;
  if (info.coupled && solve_coupled_leg(info, joint_fs, contact_fs, 0.0f, &s.ik, &s.foot_dir) && clear(s.ik)) {
    s.ankle = s.ik.end;
    return s;
  }
  s.ankle = leg_ankle(ctx, body, leg, contact_fs, joint_fs, true, near, &s.foot_dir, nullptr, true);
  s.ik = solve_two_bone_ik_directions(joint_fs, info.upper, info.lower, s.ankle, info.bend);
  straighten_ankle(info, joint_fs, contact_fs, s.ik, s.foot_dir, s.ankle, clear);
  return s;
}

bool LegIkJob::validate() const { return valid(*this); }

bool LegIkJob::run() const {
  if (!valid(*this)) return false;
  const AnimContext& c = *ctx;
  const BodyFrame& b = *body;
  std::vector<Mat2x3>& model = *model_fs;
  for (size_t i = 0; i < c.rig.legs.size(); ++i) {
    const int leg = static_cast<int>(i);
    const RigLeg& info = c.rig.legs[i];
    const FootState& f = feet->of_leg(leg);
    const glm::vec2 joint = model[info.girdle_bone].apply(pose->locals[info.bones[0]].offset_ls);
    glm::vec2 contact = b.to_fs(f.pos_ws);
    if (f.state == LegState::kSwing) {
      // A swinging foot out of reach below stays at the lowest point the leg reaches, right
      // above its path, instead of being dragged along the line to it (into a step's corner).
      const float r = info.contact_reach;
      const float dx = contact.x - joint.x;
      const float len = glm::length(contact - joint);
      if (len > r && std::fabs(dx) < r && contact.y < joint.y) {
        contact.y = joint.y - reach_across(r, dx);
      } else if (len > r) {  // out of reach to the side: towards it, as far as the leg reaches
        contact = joint + (contact - joint) * (r / len);
      }
    }
    const Clearance& near = f.state == LegState::kStance ? f.stance_clear : f.swing_clear;
    auto leg_ik = [&](glm::vec2 target) {  // directions only: the angles are for pose() (lazily)
      return solve_two_bone_ik_directions(joint, info.upper, info.lower, target, info.bend);
    };
    // A swinging foot that holds its angle folds its lower joint no tighter than
    // kLeastSwingAnkle (or its rest angle), nor bends it past straight: random hind legs with a
    // tight rest hock folded the foot through the shin, reading 0 to 360° in the swing (the
    // plain pose, below).
    const bool hold = f.state == LegState::kSwing && !info.coupled && info.foot_span > 0.0f;
    const float most_fold = kPi - std::min(kLeastSwingAnkle, kPi - info.rest_fold);
    // The turn from shin to foot, positive the way the joint bends at rest: beyond most_fold
    // folded tighter, and beyond pi through shut (where it reads below -pi/2).
    auto fold_of = [&](glm::vec2 shin, glm::vec2 foot) {
      return std::atan2(info.fold_sign * (shin.x * foot.y - shin.y * foot.x), glm::dot(shin, foot));
    };
    auto too_tight = [&](float turn) { return hold && (turn > most_fold || turn < -0.5f * kPi); };
    // A foot folded through the shin turns back to lie against it (kShutAnkle open), about the
    // ankle: the least turn that uncrosses it.
    auto unfold = [&](glm::vec2 shin, glm::vec2 foot) {
      return hold && fold_of(shin, foot) < -0.5f * kPi ? turned(shin, unit(info.fold_sign * (kPi - kShutAnkle))) : foot;
    };
    // A three-segment leg is solved whole, its foot coupled to the leg.
    TwoBoneIkResult ik;
    glm::vec2 foot_dir, ankle;
    bool solved = false;
    if (f.state == LegState::kStance) {
      const StanceLegPose s = stance_leg_pose(c, b, leg, contact, joint, near);
      ik = s.ik, foot_dir = s.foot_dir, ankle = s.ankle;
      solved = true;
    } else if (info.coupled) {
      const float fold = info.swing_fold * std::sin(kPi * std::clamp(f.progress, 0.0f, 1.0f));
      solved = solve_coupled_leg(info, joint, contact, fold, &ik, &foot_dir);
      ankle = ik.end;
    }
    if (!solved) {  // the plain swing pose: the foot rolled about its contact, then upper and lower
      ankle = leg_ankle(c, b, leg, contact, joint, true, near, &foot_dir, nullptr, false);
      // The same for the ankle when the foot could not roll far enough.
      const float r = info.leg_reach;
      const float dx = ankle.x - joint.x;
      if (glm::length(ankle - joint) > r && std::fabs(dx) < r && ankle.y < joint.y) {
        ankle.y = joint.y - reach_across(r, dx);
      }
      // A foot lifted closer to the joint than the leg folds (short legs, high swings) moves
      // out sideways to where the folded leg reaches, not down through the ground.
      const float fold = info.fold;
      const glm::vec2 d = ankle - joint;
      if (glm::dot(d, d) < fold * fold && std::fabs(d.y) < fold) {
        ankle.x = joint.x + (d.x >= 0.0f ? 1.0f : -1.0f) * reach_across(fold, d.y);
      }
      ik = leg_ik(ankle);
      straighten_ankle(info, joint, contact, ik, foot_dir, ankle, [](const TwoBoneIkResult&) { return true; });
      // Swinging, nor does it fold tighter than most_fold, nor stay bent past straight (where
      // the straight leg reaches no pose): it turns with the shin about its ankle; where that
      // takes its contact point below its swing path (a bird's toe dipped into the ground at
      // lift-off), about the contact instead, the leg reaching the ankle there, if that holds
      // it; else not at all, unless it would fold through the shin.
      if (const float turn = hold ? fold_of(ik.lower_dir, foot_dir) : 0.0f; too_tight(turn) || turn < 0.0f) {
        const glm::vec2 held = turn < 0.0f && turn > -0.5f * kPi ? ik.lower_dir : turned(ik.lower_dir, unit(info.fold_sign * most_fold));
        auto holds = [&](float t) { return !too_tight(t) && t >= -1e-3f; };
        if ((ik.end + info.foot_span * held).y >= contact.y) {
          foot_dir = held;
        } else if (const TwoBoneIkResult r = leg_ik(contact - info.foot_span * held); holds(fold_of(r.lower_dir, held))) {
          ik = r;
          ankle = r.end;
          foot_dir = held;
        } else {
          foot_dir = unfold(ik.lower_dir, foot_dir);
        }
      }
    }
    // A stance leg the body placement stretched past its reach (its clamps 3 and 5 may, and
    // clamp 6 then releases the foot to lift on the next tick) does not reach its ankle: its
    // foot hangs from where the leg ends and may cut the step it stood by. While the creature
    // walks, such a leg, too, lifts out of the level as a swinging one does.
    const float upper_lower = info.upper + info.lower;
    const float stretch = upper_lower * (1.0f + kStretchedOfLeg);
    const bool stretched = moving && f.state == LegState::kStance && glm::dot(ankle - joint, ankle - joint) > stretch * stretch;
    if (f.state == LegState::kSwing || stretched) {
      // A knee, shin or foot swinging into a step lifts the foot until the whole leg clears.
      // Its drawn flesh too (RigLeg::flesh_outline), where some candidate keeps it clear; where
      // none does, the bones alone.
      const float F = info.foot_length;  // ankle to toe (to the contact point, or along a flat foot)
      glm::vec2 dir = foot_dir;  // the foot's direction for the candidate being tested
      bool flesh = !info.flesh_outline.empty();
      // Its flesh rests on the ground it steps from or to where it meets it (the body floor draws
      // it on it, body_floor.h), not on any box rising higher (nor, stretched, on the ground it
      // stands on).
      const float ground_over = (f.state == LegState::kStance ? f.pos_ws.y : std::min(f.from_ws.y, f.to_ws.y)) + kGroundSlack;
      // The candidates whose bones cleared but not their flesh (where none clears, the one
      // whose flesh lies least deep).
      struct Tried {
        TwoBoneIkResult ik;
        glm::vec2 dir;
      };
      std::array<Tried, kTriedCandidates> tried;
      size_t tried_count = 0;
      auto leg_hits = [&](const TwoBoneIkResult& r) {
        const glm::vec2 tip = r.end + F * dir;
        const glm::vec2 p[4] = {b.to_ws(joint), b.to_ws(r.middle), b.to_ws(r.end), b.to_ws(tip)};
        if (polyline_hits_level(c.level, p, F > 0.0f ? 4 : 3, c.hits)) return true;
        if (!flesh || !leg_flesh_hits(c, b, info, joint, r, dir, ground_over)) return false;
        if (tried_count < tried.size()) tried[tried_count++] = {r, dir};
        return true;
      };
      const float tip_y = ik.end.y + F * foot_dir.y;
      const float min_y = std::min({joint.y, ik.middle.y, ik.end.y, tip_y});
      // (The flesh lies no further below than each bone's margin: a point on a mid joint's frame
      // within it of the joint, on the level frame within it of the foot's end.)
      const float flesh_y = std::min({std::min(joint.y, ik.middle.y) - info.flesh_margin[0], std::min(ik.middle.y, ik.end.y) - info.flesh_margin[1],
                                      std::min(ik.end.y, tip_y) - info.flesh_margin[2]});
      // The first candidate (bisected) that clears, from lifted to turned whole: false if none.
      auto escape = [&] {
        // Candidates run from the planned ankle straight up, then in towards a tuck under the
        // joint; the first (bisected) that clears wins.
        const glm::vec2 up = glm::vec2(ankle.x, std::max(ankle.y, joint.y - kLiftBelowJointOfLeg * info.reach));
        const glm::vec2 tuck = joint + glm::vec2(0.0f, -kTuckBelowJointOfLeg * info.reach);
        // Last, drawn back from under the joint by a foot's length (a toe against a riser).
        const glm::vec2 back = tuck - glm::vec2(F + kDrawBackOfLeg * info.reach, 0.0f);
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
          const TwoBoneIkResult r = leg_ik(a);
          dir = unfold(r.lower_dir, d / std::max(glm::length(d), 1e-6f));
          return r;
        };
        float lo = 0.0f, hi = -1.0f;
        for (float t : {1.0f, 2.0f, 3.0f}) {
          if (!leg_hits(candidate(t))) {
            hi = t;
            break;
          }
          lo = t;
        }
        if (hi > 0.0f) {
          bisect(lo, hi, kTuckBisections, [&](float mid) { return leg_hits(candidate(mid)); });
          ik = candidate(hi);
          foot_dir = dir;
          return true;
        }
        // None clears: carried forward from under the joint instead (a foreleg whose elbow
        // points back, swinging down off a ledge's edge: drawn back, the elbow only goes
        // deeper into the ledge; the tortoise's went 2.8 cm into drops.json's first).
        const glm::vec2 ahead = tuck + glm::vec2(F + kCarryAheadOfLeg * info.reach, 0.0f);
        auto carried = [&](float s) {
          const TwoBoneIkResult r = leg_ik(glm::mix(tuck, ahead, s));
          dir = unfold(r.lower_dir, info.foot_dir_ms);
          return r;
        };
        if (!leg_hits(carried(1.0f))) {
          float from = 0.0f, to = 1.0f;
          bisect(from, to, kTuckBisections, [&](float mid) { return leg_hits(carried(mid)); });
          ik = carried(to);
          foot_dir = dir;
          return true;
        }
        // Last, the planned leg turned whole about the joint, the least turn either way that
        // clears (random creature 47, a biped running up default.json's 0.2 m step: its knee
        // points far ahead of its hip, low; no lift, tuck or carry of the foot raised it out of
        // the step's corner, 2.8 cm in; turned up, the knee rises over the tread).
        const glm::vec2 planned_ankle = ankle - joint, planned_dir = foot_dir;
        auto turned = [&](float a) {
          const TwoBoneIkResult r = leg_ik(joint + rotate(planned_ankle, a));
          dir = unfold(r.lower_dir, rotate(planned_dir, a));
          return r;
        };
        float from = 0.0f, to = 0.0f;
        for (float step = 1.0f; step <= kWholeTurnSteps && to == 0.0f; step += 1.0f) {
          for (float sign : {1.0f, -1.0f}) {
            const float a = sign * step * kWholeTurnStep;
            if (!leg_hits(turned(a))) {
              from = sign * (step - 1.0f) * kWholeTurnStep;
              to = a;
              break;
            }
          }
        }
        if (to == 0.0f) return false;
        bisect(from, to, kTuckBisections, [&](float mid) { return leg_hits(turned(mid)); });
        ik = turned(to);
        foot_dir = dir;
        return true;
      };
      // (The flesh meets only boxes rising above the ground it steps from or to: on flat
      // ground, none.)
      const bool flesh_near = flesh && !near.clear_above(flesh_y) && std::max(near.base, near.top) > ground_over;
      if ((!near.clear_above(min_y) || flesh_near) && leg_hits(ik) && !escape() && flesh) {
        // None clears with its flesh: the bones alone, unless a candidate tried whose bones
        // clear lays its flesh less deep than that (the pigeon running over rough.json's
        // blocks: a foot's flesh 7.9 mm in a block's corner, 4.0 mm with the least deep).
        const size_t with_flesh = tried_count;
        flesh = false;
        dir = foot_dir;
        if (leg_hits(ik)) escape();
        float least = leg_flesh_depth(c, b, info, joint, ik, foot_dir, ground_over) - kFleshDepthGain;
        for (size_t k = 0; k < with_flesh && least > 0.0f; ++k) {
          const float d = leg_flesh_depth(c, b, info, joint, tried[k].ik, tried[k].dir, ground_over);
          if (d < least) {
            least = d;
            ik = tried[k].ik;
            foot_dir = tried[k].dir;
          }
        }
      }
    }
    (*leg_dirs)[i] = {ik.upper_dir, ik.lower_dir, foot_dir};
    // The chain's matrices straight from the solution's directions (no trigonometry).
    const Mat2x3 upper = frame_matrix(ik.upper_dir, joint);
    const Mat2x3 lower = frame_matrix(ik.lower_dir, upper.apply(pose->locals[info.bones[1]].offset_ls));
    model[info.bones[0]] = upper;
    model[info.bones[1]] = lower;
    model[info.bones[2]] = frame_matrix(foot_dir, lower.apply(pose->locals[info.bones[2]].offset_ls));
  }
  return true;
}

}  // namespace ossa::anim
