#pragma once
// Headless simulation with the measurements ossa-sim reports and the animation tests check:
// a script of control segments ("walk:0.5:10,run:1:6,stop:2,walk:-0.5:5") drives one or more
// creatures over a level; a SimProbe watches every tick for stance slip, penetration of
// limbs into colliders, swing clearance, non-finite values and the pose hash.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/game/controls.h"
#include "ossa/io/result.h"

namespace ossa {

class Entity;

struct ScriptSegment {
  std::string mode;        // "walk", "run" or "stop"
  float stick = 0.0f;      // [-1, 1]
  float seconds = 0.0f;    // > 0
  Controls controls() const { return {mode == "stop" ? 0.0f : stick, mode == "run"}; }
};
// Parses "mode:stick:seconds" segments separated by commas ("stop:seconds" for stops).
Result<std::vector<ScriptSegment>> parse_script(std::string_view text);

struct SegmentMetrics {
  std::string command;        // the segment's text
  float commanded_speed = 0;  // m/s, signed
  float mean_speed = 0;       // m/s, signed, after the segment's first second
  float speed_error = 0;      // |mean - commanded| / |commanded| (0 for stops)
  float stride_length = 0;    // m, mean over the measured window
  float cycle_frequency = 0;  // Hz
  float duty_factor = 0;
  float froude = 0;
  std::string gait;           // most frequent gait in the window
  bool flight_phase = false;  // a tick with every foot in the air (moving segments)
};

// Watches an animator tick by tick.
class SimProbe {
 public:
  void observe(const Animator& animator, const Level& level);

  float max_stance_slip_m = 0.0f;
  float max_penetration_m = 0.0f;
  float min_swing_clearance_m = 1e9f;
  int nan_count = 0;
  uint64_t pose_hash = 1469598103934665603ull;

 private:
  std::vector<glm::vec2> stance_anchor_;
  std::vector<int> stance_since_;
  int last_facing_ = 0;
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
  float update_seconds = 0.0f;  // wall time spent in Entity::step
};

// Runs `script` on `entity` (already placed with Animator::reset) over `level` at `tick_hz`.
// `on_tick` (optional) is called after every tick with the tick index.
SimResult run_script(Entity& entity, const Level& level, const std::vector<ScriptSegment>& script,
                     int tick_hz, const std::function<void(long long)>& on_tick = {});

// Deepest a point lies inside any collider (0 when outside or on a surface), metres.
float penetration_depth(const Level& level, glm::vec2 p_ws);

}  // namespace ossa
