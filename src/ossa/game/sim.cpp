#include "ossa/game/sim.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "ossa/game/player.h"
#include "ossa/game/world.h"

namespace ossa {

Result<std::vector<ScriptSegment>> parse_script(std::string_view text) {
  std::vector<ScriptSegment> out;
  std::string item;
  std::stringstream ss{std::string(text)};
  int index = 0;
  while (std::getline(ss, item, ',')) {
    const std::string where = "segment " + std::to_string(index) + " \"" + item + "\"";
    std::vector<std::string> parts;
    std::string part;
    std::stringstream ps(item);
    while (std::getline(ps, part, ':')) parts.push_back(part);
    ScriptSegment seg;
    if (parts.empty()) return Error::at("--script", where, "expected mode:stick:seconds");
    seg.mode = parts[0];
    auto number = [&](const std::string& s, float* v) {
      try {
        size_t used = 0;
        *v = std::stof(s, &used);
        return used == s.size() && std::isfinite(*v);
      } catch (...) {
        return false;
      }
    };
    if (seg.mode == "stop") {
      if (parts.size() != 2 || !number(parts[1], &seg.seconds)) {
        return Error::at("--script", where, "expected stop:seconds");
      }
    } else if (seg.mode == "jump") {
      if (parts.size() > 2 || (parts.size() == 2 && !number(parts[1], &seg.seconds))) {
        return Error::at("--script", where, "expected jump or jump:seconds");
      }
      if (parts.size() == 1) {  // one tick
        out.push_back(seg);
        ++index;
        continue;
      }
    } else if (seg.mode == "walk" || seg.mode == "run") {
      if (parts.size() != 3 || !number(parts[1], &seg.stick) || !number(parts[2], &seg.seconds)) {
        return Error::at("--script", where, "expected " + seg.mode + ":stick:seconds with numbers");
      }
      if (seg.stick < -1.0f || seg.stick > 1.0f) return Error::at("--script", where, "expected a stick in [-1, 1]");
    } else {
      return Error::at("--script", where, "expected the mode walk, run, stop or jump");
    }
    if (!(seg.seconds > 0.0f) || seg.seconds > 86400.0f) {
      return Error::at("--script", where, "expected seconds in (0, 86400]");
    }
    out.push_back(seg);
    ++index;
  }
  if (out.empty()) return Error::at("--script", "", "expected at least one segment");
  return out;
}

long long script_ticks(const std::vector<ScriptSegment>& script, int tick_hz) {
  long long n = 0;
  for (const ScriptSegment& s : script) n += s.ticks(tick_hz);
  return n;
}

Controls ScriptCursor::next() {
  while (left_ <= 0 && segment_ < script_->size()) {
    if (left_ == 0) ++segment_;
    if (segment_ >= script_->size()) break;
    const ScriptSegment& s = (*script_)[segment_];
    current_ = s.controls(current_);
    left_ = s.ticks(tick_hz_);
  }
  if (left_ > 0) --left_;
  return current_;
}

std::string gait_family_label(const Animator& animator) { return gait_family_name(animator.gait_family()); }

namespace {

std::string most_frequent(const std::map<std::string, int>& counts) {
  std::string best;
  int most = -1;
  for (const auto& [name, n] : counts) {
    if (n > most) {
      most = n;
      best = name;
    }
  }
  return best;
}

}  // namespace

SimResult run_script(Entity& entity, const Level& level, const std::vector<ScriptSegment>& script, int tick_hz,
                     const std::function<void(long long)>& on_tick) {
  SimResult result;
  const float dt = 1.0f / static_cast<float>(tick_hz);
  long long tick = 0;
  result.x_max_m = entity.animator().x();
  int blocked_ticks = 0;
  result.probe.dt = dt;
  Controls previous;
  for (const ScriptSegment& seg : script) {
    const Controls controls = seg.controls(previous);
    previous = controls;
    SegmentMetrics m;
    char text[96];
    if (seg.mode == "stop") {
      std::snprintf(text, sizeof text, "stop:%g", seg.seconds);
    } else if (seg.mode == "jump") {
      if (seg.seconds > 0.0f) std::snprintf(text, sizeof text, "jump:%g", seg.seconds);
      else std::snprintf(text, sizeof text, "jump");
    } else {
      std::snprintf(text, sizeof text, "%s:%g:%g", seg.mode.c_str(), seg.stick, seg.seconds);
    }
    m.command = text;
    m.commanded_speed = entity.desired_velocity(controls);
    const int ticks = seg.ticks(tick_hz);
    const int warmup = std::min(ticks / 2, tick_hz);  // measure after the first second
    float x_start = entity.animator().x();
    double stride = 0, freq = 0, duty = 0, froude = 0;
    int measured = 0;
    std::map<std::string, int> gaits, families;
    std::vector<GaitLeg> legs;
    for (const RigLeg& leg : entity.animator().rig().legs) legs.push_back({leg.girdle, leg.side});
    std::vector<GaitSample> timeline;  // the window's ticks since its last turn, at most gait_ticks
    const long long gait_ticks = static_cast<long long>(SegmentMetrics::kGaitWindowS) * tick_hz;
    int timeline_facing = 0;
    for (int t = 0; t < ticks; ++t) {
      const auto start = std::chrono::steady_clock::now();
      entity.step(dt, controls, level);
      result.update_seconds += std::chrono::duration<float>(std::chrono::steady_clock::now() - start).count();
      const Animator& a = entity.animator();
      result.probe.observe(a, level);
      m.max_body_jolt_g = std::max(m.max_body_jolt_g, result.probe.jolt_g);
      result.x_max_m = std::max(result.x_max_m, a.x());
      blocked_ticks += a.blocked() ? 1 : 0;
      m.airborne_s += a.airborne() ? dt : 0.0f;
      if (t == warmup) x_start = a.x();
      if (t > warmup) {
        stride += a.stride_length();
        freq += a.cycle_frequency();
        duty += a.duty_factor();
        froude += a.froude();
        ++gaits[gait_name(a.gait())];
        ++families[gait_family_label(a)];
        ++measured;
        bool any_down = false;
        for (int i = 0; i < a.leg_count(); ++i) any_down |= a.leg_state(i) == LegState::kStance;
        m.flight_phase |= a.leg_count() > 0 && !any_down;
        if (a.facing() != timeline_facing) timeline.clear();
        timeline_facing = a.facing();
        if (static_cast<long long>(timeline.size()) < gait_ticks) {
          GaitSample sample{0, a.root_y()};
          for (int i = 0; i < std::min(a.leg_count(), 64); ++i) {
            sample.stance |= a.leg_state(i) == LegState::kStance ? uint64_t{1} << i : uint64_t{0};
          }
          timeline.push_back(sample);
        }
      }
      if (on_tick) on_tick(tick);
      ++tick;
    }
    const float window = static_cast<float>(ticks - 1 - warmup) * dt;
    m.mean_speed = window > 0.0f ? (entity.animator().x() - x_start) / window : 0.0f;
    m.speed_error = m.commanded_speed != 0.0f ? std::fabs(m.mean_speed - m.commanded_speed) / std::fabs(m.commanded_speed)
                                              : std::fabs(m.mean_speed);
    if (measured > 0) {
      m.stride_length = static_cast<float>(stride / measured);
      m.cycle_frequency = static_cast<float>(freq / measured);
      m.duty_factor = static_cast<float>(duty / measured);
      m.froude = static_cast<float>(froude / measured);
      m.gait = most_frequent(gaits);
      m.gait_family = most_frequent(families);
      m.measured = measure_gait(timeline, legs, dt, entity.animator().hip_height());
    }
    m.blocked = describe_block(entity.animator().block_report());
    result.segments.push_back(m);
  }
  result.x_reached = entity.animator().x();
  result.blocked_s = static_cast<float>(blocked_ticks) * dt;
  result.steps = entity.animator().steps();
  result.locomotion = entity.animator().locomotion_stats();
  return result;
}

void SimProbe::observe(const Animator& a, const Level& level) {
  const AnimRig& rig = a.rig();
  const Skeleton& sk = rig.skeleton;
  const std::vector<Mat2x3>& world = a.world_matrices();
  pose_hash = ossa::pose_hash(world, pose_hash);
  // The legs' joint angles: 180° less the turn from one bone to the next, the turn counted
  // positive the way the joint bends at rest (past straight the other way: over 180°). A
  // creature facing −x is mirrored, which turns every joint the other way.
  joint_angles.resize(rig.legs.size());
  auto turn_of = [](const Mat2x3& p, const Mat2x3& q) {
    return std::atan2(p.m[0] * q.m[1] - p.m[1] * q.m[0], p.m[0] * q.m[0] + p.m[1] * q.m[1]);
  };
  for (size_t i = 0; i < rig.legs.size(); ++i) {
    const RigLeg& leg = rig.legs[i];
    const int chain[4] = {leg.girdle_bone, leg.bones[0], leg.bones[1], leg.bones[2]};
    auto& stats = a.leg_state(static_cast<int>(i)) == LegState::kStance ? joint_angles[i].stance : joint_angles[i].swing;
    for (size_t j = 0; j < 3; ++j) {
      const Mat2x3& p = world[static_cast<size_t>(chain[j])];
      const Mat2x3& q = world[static_cast<size_t>(chain[j + 1])];
      // (The ankle: the way the animator folds it, which for one straight at rest is the knee's.)
      const float rest = turn_of(rig.model_rest[static_cast<size_t>(chain[j])], rig.model_rest[static_cast<size_t>(chain[j + 1])]);
      const float way = (j == 2 ? leg.fold_sign : rest < 0.0f ? -1.0f : 1.0f) * static_cast<float>(a.facing());
      const float angle = 180.0f - way * turn_of(p, q) * (180.0f / 3.14159265f);
      if (!std::isfinite(angle)) continue;
      stats[j].min = std::min(stats[j].min, angle);
      stats[j].max = std::max(stats[j].max, angle);
      stats[j].sum += angle;
      ++stats[j].count;
    }
  }
  for (const Mat2x3& m : world) {
    for (float v : m.m) nan_count += std::isfinite(v) ? 0 : 1;
  }
  // Every bone stays out of the colliders, the whole segment from its joint to its end. A
  // rigged character's foot bone ends at its own contact point (character.h), so its feet are
  // measured there.
  if (limb_rig_ != &rig) {
    limb_rig_ = &rig;
    limb_bone_.assign(static_cast<size_t>(sk.bone_count()), 0);
    for (const RigLeg& leg : rig.legs) {
      for (int b : leg.bones) limb_bone_[static_cast<size_t>(b)] = 1;
    }
    for (const std::vector<RigLimb>* limbs : {&rig.arms, &rig.fins, &rig.wings}) {
      for (const RigLimb& limb : *limbs) {
        for (int b : limb.bones) limb_bone_[static_cast<size_t>(b)] = 1;
      }
    }
  }
  Box all{glm::vec2(1e30f), glm::vec2(-1e30f)};
  for (int b = 0; b < sk.bone_count(); ++b) {
    all = all.united(Box{glm::min(bone_start(world[b]), bone_end(world[b], sk.length(b))),
                         glm::max(bone_start(world[b]), bone_end(world[b], sk.length(b)))});
  }
  hits_.clear();
  if (std::isfinite(all.min_ws.x) && std::isfinite(all.max_ws.y)) level.overlapping(all, hits_);
  if (!hits_.empty()) {
    for (int b = 0; b < sk.bone_count(); ++b) {
      const float d = segment_penetration(level, bone_start(world[b]), bone_end(world[b], sk.length(b)), hits_);
      float& worst = limb_bone_[static_cast<size_t>(b)] ? max_limb_penetration_m : max_body_penetration_m;
      worst = std::max(worst, d);
      if (d > max_penetration_m) {
        max_penetration_m = d;
        deepest_bone = sk.name(b);
        deepest_at_s = static_cast<float>(ticks_ + 1) * dt;
      }
    }
  }
  // The trunk's jolt: (y(t) - 2 y(t - w) + y(t - 2w)) / w² over a 50 ms window (w = 25 ms),
  // over ticks that are all grounded (not in the air, landing or crouching), in g. (A step of
  // the body within a tick or two shows; the bob of a gait, tenths of a g, does not dominate.)
  const int w = std::max(1, static_cast<int>(std::lround(0.025f / dt)));
  const Locomotion mode = a.locomotion();
  const bool steady = mode == Locomotion::kGrounded;
  if (a.locomotion_stats().respawns != last_respawns_) {  // a start again at the spawn is no jolt
    root_y_.clear();
    steady_.clear();
  }
  root_y_.push_back(a.root_y());
  steady_.push_back(steady ? 1 : 0);
  if (static_cast<int>(root_y_.size()) > 2 * w + 1) {
    root_y_.erase(root_y_.begin());
    steady_.erase(steady_.begin());
  }
  jolt_g = 0.0f;
  if (static_cast<int>(root_y_.size()) == 2 * w + 1 && std::all_of(steady_.begin(), steady_.end(), [](uint8_t v) { return v != 0; })) {
    const float sw = static_cast<float>(w) * dt;
    const float accel = (root_y_[2 * w] - 2.0f * root_y_[w] + root_y_[0]) / (sw * sw);
    jolt_g = std::fabs(accel) / a.params().gravity;
    max_body_jolt_g = std::max(max_body_jolt_g, jolt_g);
  }
  const int legs = a.leg_count();
  if (static_cast<int>(stance_anchor_.size()) != legs) {
    stance_anchor_.assign(legs, glm::vec2(0.0f));
    stance_since_.assign(legs, -1);
    plantings_.assign(legs, 0);
  }
  // A turn, or a start again at the spawn, plants every foot anew.
  const bool turned = (last_facing_ != 0 && a.facing() != last_facing_) || a.locomotion_stats().respawns != last_respawns_;
  last_respawns_ = a.locomotion_stats().respawns;
  // The limbs' joints relative to their girdle joints, against the last two ticks'.
  size_t j = 0;
  const bool had = !limb_joints_.empty() && !turned;
  float flick = 0.0f;
  auto limb_joint = [&](glm::vec2 girdle, glm::vec2 p) {
    const glm::vec2 rel = p - girdle;
    if (2 * j + 1 >= limb_joints_.size()) limb_joints_.resize(2 * j + 2, glm::vec2(NAN));
    glm::vec2& last = limb_joints_[2 * j];
    glm::vec2& before = limb_joints_[2 * j + 1];
    if (had && std::isfinite(before.x)) flick = std::max(flick, glm::length(rel - 2.0f * last + before));
    before = had ? last : glm::vec2(NAN);
    last = rel;
    ++j;
  };
  auto chain = [&](const std::array<int, 3>& bones) {
    const glm::vec2 girdle = bone_start(world[static_cast<size_t>(bones[0])]);
    limb_joint(girdle, bone_start(world[static_cast<size_t>(bones[1])]));
    limb_joint(girdle, bone_start(world[static_cast<size_t>(bones[2])]));
    limb_joint(girdle, bone_end(world[static_cast<size_t>(bones[2])], sk.length(bones[2])));
  };
  for (const RigLeg& leg : rig.legs) chain(leg.bones);
  for (const std::vector<RigLimb>* limbs : {&rig.arms, &rig.fins, &rig.wings}) {
    for (const RigLimb& limb : *limbs) chain(limb.bones);
  }
  const float omega = 2.0f * 3.14159265f * a.cycle_frequency();
  const float scale = std::max(omega * omega * a.hip_height(), a.params().gravity) * dt * dt;
  if (const float times = flick / scale; std::isfinite(times)) {
    if (times > max_limb_flick) max_limb_flick = times, limb_flick_at_s = static_cast<float>(ticks_) * dt;
    limb_flicks += times > kLimbFlick;
  }
  for (int i = 0; i < legs; ++i) {
    const glm::vec2 foot = a.foot_ws(i);
    if (a.leg_state(i) == LegState::kStance) {
      max_stance_gap_m = std::max(max_stance_gap_m, glm::length(foot - a.foot_target_ws(i)));
      if (stance_since_[i] < 0 || turned || a.plantings(i) != plantings_[i]) {
        stance_anchor_[i] = foot;
        stance_since_[i] = static_cast<int>(ticks_);
        plantings_[i] = a.plantings(i);
      } else {
        max_stance_slip_m = std::max(max_stance_slip_m, glm::length(foot - stance_anchor_[i]));
      }
    } else {
      stance_since_[i] = -1;
      const float s = a.swing_progress(i);
      if (!a.easing(i) && s > 0.25f && s < 0.75f) {
        auto ground = level.ground_height_below(foot.x, foot.y + 1e-4f, 100.0f);
        if (ground) min_swing_clearance_m = std::min(min_swing_clearance_m, foot.y - ground->height_ws);
      }
    }
  }
  last_facing_ = a.facing();
  ++ticks_;
}

}  // namespace ossa
