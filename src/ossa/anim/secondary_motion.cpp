#include "ossa/anim/secondary_motion.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "ossa/anim/anim_math.h"
#include "ossa/anim/ground_profile.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/level_probe.h"
#include "ossa/math/angle.h"

namespace ossa::anim {

void swing_tail(const AnimRig& rig, const AnimatorParams& params, float dt, float root_vy, float body_angle, TailSpring& tail,
                Pose& pose) {
  if (rig.tail.empty()) return;
  // The tail lags the body's bob (a quarter radian per hip height per second of vertical
  // speed, within ±0.4) and holds half the body's pitch back.
  const float target = std::clamp(-0.25f * root_vy / std::max(rig.hip_height, 0.05f), -0.4f, 0.4f) - 0.5f * body_angle;
  if (dt > 0.0f) {
    const float k = params.tail_stiffness;
    const float damping = 2.0f * params.tail_damping * std::sqrt(k);
    tail.rate = flush(tail.rate + (k * (target - tail.angle) - damping * tail.rate) * dt);
    tail.angle = flush(std::clamp(tail.angle + tail.rate * dt, -params.tail_max_swing, params.tail_max_swing));
  }
  const float bend = tail.angle * 2.0f / static_cast<float>(rig.tail.size());
  for (int b : rig.tail) pose.locals[b].angle_ls += bend;
}

bool drape_legless(const AnimContext& ctx, const BodyFrame& body, float crawl_phase, float speed, Pose& pose,
                   std::vector<Mat2x3>& model_fs) {
  constexpr float kMaxDrapeBend = 0.3f;   // radians from a bone's rest angle
  constexpr float kHangTolerance = 1e-4f;  // metres: a rib's end resting on the ground is clear
  const AnimRig& rig = ctx.rig;
  const AnimatorParams& params = ctx.params;
  const Skeleton& sk = rig.skeleton;
  const GroundProfile& ground = ctx.ground;
  const float motion = std::min(speed / std::max(walk_speed(rig, params), 1e-3f), 1.0f);
  const float wave = std::max(params.crawl_amplitude, 0.0f) * rig.body_half_length * motion;
  const float n = static_cast<float>(std::max<size_t>(rig.drape_bones.size(), 1));
  // The ground as the body lies on it: the highest within `reach` either side, so that the
  // body ramps up to a step (at kDrapeSlope) before it reaches the riser rather than meet it.
  const float reach = std::min(rig.root_rest_y / kDrapeSlope, 0.5f * rig.body_half_length);
  // Level ground under the whole body and beyond (the common case) is one height.
  float flat = NAN;
  {
    const float a = rig.body_lo_ws(body.x_ws, body.facing) - rig.body_half_length - reach;
    const float b = rig.body_hi_ws(body.x_ws, body.facing) + rig.body_half_length + reach;
    if (!ground.spans(a, b) || !ground.level_over(a, b, &flat)) {
      flat = NAN;
    }
  }
  auto ground_at = [&](float x_fs, float reach) {  // NaN: none the profile holds
    if (!std::isnan(flat)) return flat;
    const float x = body.to_ws({x_fs, 0.0f}).x;
    return ground.spans(x - reach, x + reach) ? ground.highest(x - reach, x + reach) : NAN;
  };
  // A bone laid along the ground, or at rest where there is none, can still meet a box over
  // it: a slab overhanging the drop a long neck reaches out over (random creature 13's neck
  // went 0.35 m into drops.json's). Of the turns from `turn` outwards, in steps of kClearStep
  // either way up to kMaxClearTurn, the first whose segment from `start` in direction
  // base + turn meets no box whose bottom lies above `start` (or within kJointOnBox below it:
  // a joint lying against the box's underside). A box below or beside it is ground, which the
  // body rises from (body_out_of_ground). `bent` tells that a box lay within a hip height over
  // a bone: the body rising after the drape would carry the bone into it.
  constexpr float kClearStep = 0.05f, kMaxClearTurn = 1.5f;  // radians
  constexpr float kJointOnBox = 2e-3f;                        // metres
  bool bent = false;
  auto turn_clear_of_level = [&](glm::vec2 start, float length, float base, float turn) {
    if (length <= 1e-6f) return turn;
    const glm::vec2 a = body.to_ws(start);
    const float above = a.y - kJointOnBox;
    auto end = [&](float t) { return body.to_ws(start + length * glm::vec2(std::cos(base + t), std::sin(base + t))); };
    {
      const glm::vec2 e = end(turn);
      ctx.hits.clear();
      ctx.level.overlapping(Box{glm::min(a, e), glm::max(a, e) + glm::vec2(0.0f, rig.hip_height)}, ctx.hits);
      if (std::none_of(ctx.hits.begin(), ctx.hits.end(), [&](int h) { return ctx.level.box(h).min_ws.y >= above; })) return turn;
    }
    bent = true;
    auto hits = [&](float t) {
      const glm::vec2 p[2] = {a, end(t)};
      return polyline_hits_level(ctx.level, p, 2, ctx.hits, above);
    };
    if (!hits(turn)) return turn;
    for (float d = kClearStep; d <= kMaxClearTurn + 1e-4f; d += kClearStep) {
      for (const float t : {turn - d, turn + d}) {
        if (!hits(t)) return t;
      }
    }
    return turn;
  };
  const std::vector<int>& parents = sk.parents();
  // Each bone's angle in facing space, kept alongside its matrix (no atan2 per bone).
  thread_local std::vector<float> angle;
  angle.resize(static_cast<size_t>(sk.bone_count()));
  size_t next_drape = 0;
  for (int b : rig.drape_fk) {
    const int parent = parents[b];
    if (next_drape < rig.drape_bones.size() && rig.drape_bones[next_drape] == b && parent >= 0) {
      const size_t i = next_drape++;
      const Mat2x3& up = model_fs[parent];
      const float parent_angle = angle[parent];
      const glm::vec2 start = up.apply(pose.locals[b].offset_ls);
      const float length = rig.drape_length[i], along = rig.drape_along[i];
      const int next = rig.drape_next[i];
      float clearance = next >= 0 ? rig.belly[next] : rig.tip_belly[i];
      if (b == rig.head_owner && rig.skull >= 0) clearance += kHeadLiftOfSkull * sk.length(rig.skull);
      const float least = clearance;  // (what the bone's end needs without the wave)
      if (wave > 0.0f) clearance += wave * std::max(0.0f, std::sin(kTwoPi * (crawl_phase - params.crawl_waves * static_cast<float>(i) / n)));
      const float rest = rig.rest_pose.locals[b].angle_ls;
      float dir = parent_angle + rest + along;  // the segment's direction (facing space)
      const bool forward = std::cos(dir) >= 0.0f;
      bool placed = length > 1e-6f;
      for (int k = 0; k < (std::isnan(flat) ? 2 : 1) && placed; ++k) {  // (level ground: x does not matter)
        const float g = ground_at(start.x + length * std::cos(dir), reach);
        if (!(g <= start.y + length)) {  // a gap, or higher than the bone reaches: as at rest
          placed = false;
          break;
        }
        const float s = std::clamp((g + clearance - start.y) / length, -kDrapeSlope, kDrapeSlope);
        dir = forward ? std::asin(s) : kPi - std::asin(s);
      }
      float turn = placed ? std::clamp(wrap_angle(dir - along - parent_angle - rest), -kMaxDrapeBend, kMaxDrapeBend) : 0.0f;
      // What hangs from the bone (ribs, a jaw) turns with it: of the turn, as much as keeps
      // them out of the ground (none: the rest of the body then rises, body_out_of_ground).
      auto hangers_depth = [&](float t) {  // how deep the deepest goes into the ground
        const float a = parent_angle + rest + t, c = std::cos(a), sn = std::sin(a);
        float depth = 0.0f;
        for (int k = rig.hang_begin[i]; k < rig.hang_begin[i + 1]; ++k) {
          const glm::vec2 q = rig.hang_points[k];
          const glm::vec2 w = start + glm::vec2(c * q.x - sn * q.y, sn * q.x + c * q.y);
          depth = std::max(depth, ground_at(w.x, 0.0f) - w.y);  // (NaN: no ground, clear)
        }
        return depth;
      };
      auto hangers_clear = [&](float t) { return !(hangers_depth(t) > kHangTolerance); };
      // Nor may a turn that clears them leave the bone's end below its belly's depth over the
      // ground: the next bone's hangers would start as much too low, the one after it turn down
      // to clear its own, and so on down the body, which the deepest would then lift as a whole
      // (a jolt of several g, every wave). So of the turns tried, the one whose worse of the two
      // — its hangers' depth in the ground, its end's shortfall under its belly's depth — is
      // least; the turn it wanted first, then nearer the rest angle, then out to the largest bend.
      auto end_short = [&](float t) {
        if (!placed) return 0.0f;
        const float a = parent_angle + rest + t + along;
        const glm::vec2 end = start + length * glm::vec2(std::cos(a), std::sin(a));
        const float short_by = ground_at(end.x, reach) + least - end.y;
        return short_by > 0.0f ? short_by : 0.0f;  // (NaN: no ground, none)
      };
      if (!hangers_clear(turn)) {
        constexpr float kTries[] = {1.0f, 0.5f, 0.0f, 0.25f, -0.25f, 0.5f, -0.5f, 0.75f, -0.75f, 1.0f, -1.0f};
        float best = 1e30f, chosen = turn;
        for (size_t k = 0; k < std::size(kTries); ++k) {
          const float t = k < 3 ? kTries[k] * turn : kTries[k] * kMaxDrapeBend;
          const float deepest = hangers_depth(t);
          const float depth = deepest > kHangTolerance ? deepest : 0.0f;
          // (Off level ground, the first turn that clears the hangers: a body lifted as a whole
          // by the bones after it is how a legless body gets up a flight of steps today.)
          const float worst = std::isnan(flat) ? (depth > 0.0f ? 1.0f : 0.0f) : std::max(depth, end_short(t));
          if (worst < best - kHangTolerance) best = worst, chosen = t;
        }
        turn = chosen;
      }
      turn = turn_clear_of_level(start, length, parent_angle + rest + along, turn);
      pose.locals[b].angle_ls = rest + turn;
    }
    if (b == rig.skull && parent >= 0) {
      // Level, as at rest; raised by up to kMaxDrapeBend where a point along it would come
      // nearer the ground than a third of its distance from the joint (its far end, or a
      // nearer point over the edge of a ledge the head reaches out over).
      const Mat2x3& up = model_fs[parent];
      const float level = rig.skull_rest_angle, length = sk.length(b);
      const glm::vec2 joint = up.apply(pose.locals[b].offset_ls);
      float rise = -1e30f;  // the largest (ground + lift − joint.y) / distance along it
      for (const float f : {0.25f, 0.5f, 0.75f, 1.0f}) {
        const float g = ground_at(joint.x + f * length * std::cos(level), 0.0f);
        if (g <= joint.y + f * length) rise = std::max(rise, (g - joint.y) / (f * length) + kHeadLiftOfSkull);
      }
      float dir = level;
      if (rise > -1e29f) {
        const float want = std::asin(std::clamp(rise, -1.0f, 1.0f));
        // Pitching up turns a skull facing +x counter-clockwise, one facing −x clockwise.
        const float forward = std::cos(level) >= 0.0f ? 1.0f : -1.0f;
        const float up = forward * wrap_angle((forward > 0.0f ? want : kPi - want) - level);
        dir = level + forward * std::clamp(up, 0.0f, kMaxDrapeBend);
      }
      dir += turn_clear_of_level(joint, length, dir, 0.0f);
      pose.locals[b].angle_ls = wrap_angle(dir - angle[parent]);
    }
    const Mat2x3 local = local_matrix(pose.locals[b]);
    model_fs[b] = parent < 0 ? local : model_fs[parent] * local;
    angle[b] = (parent < 0 ? 0.0f : angle[parent]) + pose.locals[b].angle_ls;
  }
  return bent;
}

void swing_arm(const AnimRig& rig, const SplinePrototypes& prototypes, const GaitState& gait, const FootSet& feet, const RigLimb& arm,
               float motion, Pose& pose) {
  float p = gait.phase;
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    if (rig.legs[i].side == arm.side) p = frac(gait.phase + gait.foot_offset[feet.foot_of_leg[i]]);
  }
  const float t = frac(p + 0.5f);
  for (int k = 0; k < 2; ++k) {
    const PrototypeId id = k == 0 ? PrototypeId::kArmSwing : PrototypeId::kArmBend;
    pose.locals[arm.bones[k]].angle_ls += motion * prototype_range(id).clamp(prototypes[id].value(t, gait.run_factor));
  }
}

void beat_fin(const AnimatorParams& params, const RigLimb& fin, float motion, float phase, Pose& pose) {
  pose.locals[fin.bones[0]].angle_ls += params.fin_beat * motion * std::sin(kTwoPi * phase);
}

}  // namespace ossa::anim
