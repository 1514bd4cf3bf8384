#pragma once
// One run of ossa-sweep: an example animal driven by a script over a level with
// ossa::run_script (the same SimProbe, so the run's figures are ossa-sim's), plus what the
// sweep and the slopes check need beyond the probe, measured from the animator after every
// tick:
//   - per segment: stance slip (the probe's definition, with planted feet re-anchored where
//     they stand at the segment's start, so it is what slid within the segment), limb
//     penetration and NaNs (the probe's), seconds blocked, the furthest x reached and when;
//   - per run: the limb that went deepest into a collider, the tail's deepest point (sampled
//     like the probe samples limbs: five points along each bone), seconds blocked, x range.
// Spaces: world (_ws), metres, seconds.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/anim/spline_prototypes.h"
#include "ossa/game/sim.h"
#include "ossa/gen/creature.h"
#include "ossa/level/level.h"

namespace ossa::sweep {

struct SegmentStats {
  float max_slip_m = 0.0f;         // a stance foot from where it was planted
  glm::vec2 slip_at_ws{0.0f};      // that foot, when the slip was largest
  float slip_t = 0.0f;             // seconds into the segment
  float max_penetration_m = 0.0f;  // deepest limb sample inside a collider
  std::string penetration_limb;    // which limb ("" when none)
  glm::vec2 penetration_at_ws{0.0f};
  float penetration_t = 0.0f;
  int nan_count = 0;
  float blocked_s = 0.0f;          // seconds with Animator::blocked()
  float x_start = 0.0f, x_end = 0.0f;
  float x_far = 0.0f;              // furthest x in the commanded direction (x_end for stops)
  float x_far_t = 0.0f;            // seconds into the segment when it last made 5 cm of progress
  // With a goal (run_one's `goals_x`): the mean speed over run_script's window (after the
  // segment's first second) cut short where the root first reaches the goal, and when.
  float goal_t = -1.0f;            // seconds into the segment; < 0: not reached
  float mean_speed_to_goal = 0.0f; // m/s, signed; SegmentMetrics::mean_speed when not reached
  bool goal_before_window = false; // reached within the first second: no speed to measure
};

struct RunRecord {
  std::string animal, level, script;
  SimResult sim;                      // run_script's result: segments and the whole-run probe
  std::vector<SegmentStats> segments; // one per script segment
  std::string worst_limb;             // the limb of the run's deepest penetration ("" if none)
  float worst_limb_m = 0.0f;
  bool has_tail = false;
  float tail_penetration_m = 0.0f;    // deepest tail sample inside a collider
  float tail_joint_penetration_m = 0.0f;  // the same at the tail bones' ends only (the README's
                                          // first count of tails in steps sampled joints)
  float blocked_s = 0.0f;
  float x_min = 0.0f, x_max = 0.0f;
  // The drawn body's outline (outline_probe.h): how deep it went into a collider, the part and
  // when (not part of sim.probe.max_penetration_m, which is the bones').
  float outline_penetration_m = 0.0f;
  std::string outline_part;
  float outline_at_s = 0.0f;
  double wall_s = 0.0;                // wall time of the run
};

// A limb named for people: "near hind leg", "far front leg", "near wing", "far neck fin 2".
std::string limb_label(const Limb& limb);

// Drives `creature` from `spawn_ws` (a height to search down from, as ossa-sim does: the level
// spawn + 1 m) over `level` with `script` at `tick_hz`. `goals_x` (empty, or one world x per
// segment, NaN for none) is where each moving segment is meant to end.
RunRecord run_one(std::shared_ptr<const Creature> creature, const SplinePrototypes& prototypes, const Level& level,
                  glm::vec2 spawn_ws, const std::string& script_text, const std::vector<ScriptSegment>& script,
                  int tick_hz, const std::vector<float>& goals_x = {});

// Calls job(i) for i in [0, count) on `threads` std::threads (each takes the next index).
void parallel_for(int count, int threads, const std::function<void(int)>& job);

}  // namespace ossa::sweep
