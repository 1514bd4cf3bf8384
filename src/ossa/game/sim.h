#pragma once
// Headless simulation with the measurements ossa-sim reports and the animation tests check:
// a script of control segments ("walk:0.5:10,run:1:6,stop:2,walk:-0.5:5") drives one or more
// creatures over a level; a SimProbe watches every tick for stance slip, penetration of
// limbs into colliders, swing clearance, non-finite values and the pose hash, and each
// segment's gait is measured from the feet and the trunk (measure_gait, gait_metrics.h).

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/game/controls.h"
#include "ossa/game/gait_metrics.h"
#include "ossa/io/result.h"

namespace ossa {

class Entity;

struct ScriptSegment {
  std::string mode;        // "walk", "run", "stop" or "jump"
  float stick = 0.0f;      // [-1, 1]
  float seconds = 0.0f;    // > 0 (a one-tick "jump": 0)
  // The controls of this segment after a segment with `previous` controls: a jump holds the
  // jump button and keeps the stick and the run button as they were.
  Controls controls(const Controls& previous = {}) const {
    if (mode == "jump") return {previous.move_x, previous.run, true};
    return {mode == "stop" ? 0.0f : stick, mode == "run", false};
  }
  // How many ticks it lasts at tick_hz (a one-tick "jump": 1).
  int ticks(int tick_hz) const {
    return mode == "jump" && seconds <= 0.0f ? 1 : static_cast<int>(std::lround(seconds * static_cast<float>(tick_hz)));
  }
};
// Parses "mode:stick:seconds" segments separated by commas ("stop:seconds" for stops;
// "jump" presses the jump button for one tick, "jump:seconds" holds it, both keeping the stick
// and the run button of the segment before). Seconds are in (0, 86400] per segment.
Result<std::vector<ScriptSegment>> parse_script(std::string_view text);

// The ticks a whole script lasts at tick_hz: 64-bit, as a long script passes 2^31 ticks
// (86 400 s at 480 Hz is 41 472 000 ticks per segment).
long long script_ticks(const std::vector<ScriptSegment>& script, int tick_hz);

// The controls of a script tick by tick, computed as it goes: memory does not grow with the
// script's length (a day of ticks is not stored up front).
class ScriptCursor {
 public:
  ScriptCursor(const std::vector<ScriptSegment>& script, int tick_hz) : script_(&script), tick_hz_(tick_hz) {}
  // The controls of the next tick; after the last tick, the last controls again.
  Controls next();

 private:
  const std::vector<ScriptSegment>* script_;
  int tick_hz_;
  size_t segment_ = 0;
  long long left_ = -1;  // ticks left in the current segment; -1: not started
  Controls current_;
};

struct SegmentMetrics {
  std::string command;        // the segment's text
  float commanded_speed = 0;  // m/s, signed
  float mean_speed = 0;       // m/s, signed, after the segment's first second
  float speed_error = 0;      // |mean - commanded| / |commanded| (0 for stops)
  float stride_length = 0;    // m, mean over the measured window
  float cycle_frequency = 0;  // Hz
  float duty_factor = 0;      // the animator's target (Animator::duty_factor()), mean over the window;
                              // measured.duty_factor is what the feet did
  float froude = 0;
  float max_body_jolt_g = 0;  // the largest SimProbe::jolt_g in the segment
  std::string gait;           // most frequent gait in the window
  std::string gait_family;    // most frequent gait_family_label() in the window
  bool flight_phase = false;  // a tick with every foot in the air (moving segments)
  float airborne_s = 0;       // s in the air (Animator::airborne(): jumps and falls)
  std::string blocked;        // why it stood blocked at the segment's end (describe_block), or ""
  // The gait measured from the feet (LegState::kStance per leg) and the root's height as
  // simulated, not from the animator's intended offsets (measure_gait, gait_metrics.h): footfall
  // sequence, limb phase, pair phases, duty factor, suspensions per stride, vertical excursion
  // and bobs per stride, over the window after the segment's first second, its first
  // kGaitWindowS at most (a day-long segment keeps a bounded timeline). When the creature turns
  // in the window, from its last turn on (a turn hands feet between legs).
  GaitMeasure measured;
  static constexpr int kGaitWindowS = 120;  // s
};

// The gait family of the animator's current gait, for SegmentMetrics::gait_family: "" until the
// gait families of issue #28 give the Animator an accessor (that change fills this in).
std::string gait_family_label(const Animator& animator);

// Watches an animator tick by tick: every bone against the level, the feet, the trunk's
// vertical acceleration, non-finite values and the pose hash.
class SimProbe {
 public:
  // `dt`: seconds per tick (for times and accelerations; run_script sets it).
  void observe(const Animator& animator, const Level& level);
  float dt = 1.0f / 120.0f;

  float max_stance_slip_m = 0.0f;
  // How far a standing foot's drawn contact point lies from the foothold it stands on, metres:
  // a leg that does not reach its foothold (stretched past its length) draws the foot hanging
  // short of it, which the slip does not see (the hanging foot may keep still).
  float max_stance_gap_m = 0.0f;
  // Penetration: how deep any point of a bone (the segment from its joint to its end, the
  // whole of it, exactly: segment_penetration) lies inside a collider, metres. Every bone of
  // the skeleton: the worst (max_penetration_m), the legs, arms, fins and wings
  // (max_limb_penetration_m), every other bone (max_body_penetration_m: spine, neck, skull,
  // tail, ribs, girdles), and the bone that went deepest with when (seconds since the start).
  float max_penetration_m = 0.0f;
  float max_limb_penetration_m = 0.0f;
  float max_body_penetration_m = 0.0f;
  std::string deepest_bone;
  float deepest_at_s = 0.0f;
  float min_swing_clearance_m = 1e9f;
  // The trunk's vertical jolt: the root's vertical acceleration over 50 ms windows (the second
  // difference of its height at 25 ms spacing), in g, outside the air, landings and the crouch
  // before a jump (those are meant to jolt): the largest so far and on the last tick.
  float max_body_jolt_g = 0.0f;
  float jolt_g = 0.0f;
  // Limb flicks: how hard any leg's, arm's, fin's or wing's joint (its middle joint, its last
  // bone's start and end: knee, ankle and toe; elbow, wrist and the hand's end) is thrown about relative to its girdle joint: its acceleration there over three
  // ticks (the second difference of its place), in units of the gait's own, (2π f)² h (f the
  // gait's cycle frequency, h the hip height; at least g, a leg swinging as a pendulum), not
  // across a turn (which mirrors the limbs) nor a start again at the spawn. The largest, when
  // (the middle tick), and the ticks over kLimbFlick: a limb drawn somewhere else for a tick, or
  // snapped to a new place, by a clearance that changed its mind. On flat ground the examples'
  // gaits reach 7.5 at the median and 25 at most (the stegosaurus running), the seals' and the
  // kangaroo's arms and the giraffe's and the dromedary's gallops aside.
  static constexpr float kLimbFlick = 30.0f;
  float max_limb_flick = 0.0f;
  float limb_flick_at_s = 0.0f;
  int limb_flicks = 0;
  int nan_count = 0;
  uint64_t pose_hash = 1469598103934665603ull;
  // Per leg (AnimRig::legs): the angle at its hip (girdle bone to thigh), knee (thigh to shin)
  // and ankle (shin to foot) between the two bones' directions, degrees (180: in line; over
  // 180: bent past straight, the other way from the rest pose, or for the ankle from the way
  // the animator folds it, RigLeg::fold_sign), over the ticks its foot stood and those it
  // swung: the least, the largest and the mean.
  struct AngleStats {
    float min = 360.0f;
    float max = 0.0f;
    double sum = 0.0;
    long long count = 0;
    float mean() const { return count > 0 ? static_cast<float>(sum / static_cast<double>(count)) : 0.0f; }
  };
  struct LegJointAngles {
    std::array<AngleStats, 3> stance, swing;  // hip, knee, ankle
  };
  std::vector<LegJointAngles> joint_angles;

 private:
  std::vector<glm::vec2> stance_anchor_;
  std::vector<int> stance_since_;
  std::vector<std::uint32_t> plantings_;  // per leg: Animator::plantings when its stance began
  std::vector<uint8_t> limb_bone_;    // per bone: a leg's, arm's, fin's or wing's
  const AnimRig* limb_rig_ = nullptr;
  std::vector<float> root_y_;         // the root's height, the last window's ticks
  std::vector<uint8_t> steady_;       // per tick there: not in the air, landing or crouching
  std::vector<int> hits_;
  std::vector<glm::vec2> limb_joints_;  // last tick's limb joints relative to their girdle joints
  int last_facing_ = 0;
  int last_respawns_ = 0;
  uint64_t ticks_ = 0;
};

struct SimResult {
  std::vector<SegmentMetrics> segments;
  SimProbe probe;
  float x_reached = 0.0f;   // m, world x of the root (Animator::x()) after the last tick: the
                            // final x, not the furthest (a run that turns back ends short of it)
  float x_max_m = 0.0f;     // m, the largest Animator::x() at the start or after any tick: how
                            // far right (+x) the creature got. For a script that walks right
                            // first (as ossa-sim's and the tests' do) this is the furthest point
                            // from the spawn in its direction of travel, however far it came
                            // back afterwards; a script that only goes left gives the start x
  float blocked_s = 0.0f;   // s, simulated time with Animator::blocked() set after the tick
                            // (ticks × 1 / tick_hz): stopped at a wall, a step or a gap
  int steps = 0;
  // Falls, jumps, hard landings, starts again below the kill height, the highest fall and
  // jump, seconds in the air (Animator::locomotion_stats() after the last tick).
  anim::LocomotionStats locomotion;
  float update_seconds = 0.0f;  // wall time spent in Entity::step
};

// Runs `script` on `entity` (already placed with Animator::reset) over `level` at `tick_hz`.
// `on_tick` (optional) is called after every tick with the tick index.
SimResult run_script(Entity& entity, const Level& level, const std::vector<ScriptSegment>& script,
                     int tick_hz, const std::function<void(long long)>& on_tick = {});

}  // namespace ossa
