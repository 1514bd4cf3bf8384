#include "ossa/anim/secondary_motion.h"

#include <algorithm>
#include <cmath>

#include "ossa/anim/anim_math.h"

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

void crawl_wave(const AnimRig& rig, const AnimatorParams& params, float crawl_phase, float speed, Pose& pose) {
  if (!rig.legs.empty() || !(params.crawl_amplitude > 0.0f)) return;
  const std::vector<int>& chain = rig.crawl_chain;
  const float n = static_cast<float>(chain.size());
  const float amp = params.crawl_amplitude * std::min(speed / std::max(walk_speed(rig, params), 1e-3f), 1.0f);
  for (size_t i = 0; i < chain.size(); ++i) {
    pose.locals[chain[i]].angle_ls += amp * std::sin(kTwoPi * (crawl_phase - params.crawl_waves * static_cast<float>(i) / n));
  }
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
