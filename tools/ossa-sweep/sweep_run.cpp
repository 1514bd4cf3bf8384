#include "sweep_run.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "ossa/game/outline_probe.h"
#include "ossa/game/player.h"

namespace ossa::sweep {

std::string limb_label(const Limb& limb) {
  const char* where = limb.girdle == GirdleKind::kHip ? "hind" : limb.girdle == GirdleKind::kShoulder ? "front" : "neck";
  char label[64];
  std::snprintf(label, sizeof label, limb.slot > 0 ? "%s %s %s %d" : "%s %s %s", limb.side == Side::kNear ? "near" : "far",
                where, limb_kind_name(limb.kind), limb.slot + 1);
  return label;
}

namespace {

// Deepest of five samples along each of `bones` (the probe's sampling), or of the bones' two
// ends only (`every` = 4).
float deepest(const Creature& c, const std::vector<Mat2x3>& world, const int* bones, size_t count, const Level& level,
              glm::vec2* at_ws, int every = 1) {
  float depth = 0.0f;
  for (size_t i = 0; i < count; ++i) {
    const int b = bones[i];
    const glm::vec2 p = bone_start(world[b]), q = bone_end(world[b], c.skeleton.length(b));
    for (int k = 0; k <= 4; k += every) {
      const glm::vec2 s = p + (q - p) * (k / 4.0f);
      const float d = penetration_depth(level, s);
      if (d > depth) {
        depth = d;
        if (at_ws) *at_ws = s;
      }
    }
  }
  return depth;
}

// Stance slip as SimProbe::observe measures it: a foot's distance from where it was planted,
// re-anchored when the foot lands again or the creature turns round.
class SlipTracker {
 public:
  // Returns the largest slip this tick and the foot it belongs to.
  float observe(const Animator& a, glm::vec2* foot_ws) {
    const int legs = a.leg_count();
    if (static_cast<int>(anchor_.size()) != legs) {
      anchor_.assign(legs, glm::vec2(0.0f));
      planted_.assign(legs, false);
    }
    const bool turned = last_facing_ != 0 && a.facing() != last_facing_;
    float worst = 0.0f;
    for (int i = 0; i < legs; ++i) {
      const glm::vec2 foot = a.foot_ws(i);
      if (a.leg_state(i) != LegState::kStance) {
        planted_[i] = false;
      } else if (!planted_[i] || turned) {
        anchor_[i] = foot;
        planted_[i] = true;
      } else {
        const float slip = glm::length(foot - anchor_[i]);
        if (slip > worst) {
          worst = slip;
          *foot_ws = foot;
        }
      }
    }
    last_facing_ = a.facing();
    return worst;
  }

  // Planted feet count from where they stand now: a segment's slip is what slid in it.
  void reanchor(const Animator& a) {
    for (int i = 0; i < static_cast<int>(anchor_.size()); ++i) anchor_[i] = a.foot_ws(i);
  }

 private:
  std::vector<glm::vec2> anchor_;
  std::vector<bool> planted_;
  int last_facing_ = 0;
};

}  // namespace

RunRecord run_one(std::shared_ptr<const Creature> creature, const SplinePrototypes& prototypes, const Level& level,
                  glm::vec2 spawn_ws, const std::string& script_text, const std::vector<ScriptSegment>& script,
                  int tick_hz, const std::vector<float>& goals_x) {
  const auto start = std::chrono::steady_clock::now();
  const Creature& c = *creature;
  Player player(creature, prototypes);
  player.animator().reset(spawn_ws, level);
  const Animator& a = player.animator();

  RunRecord r;
  r.animal = c.name;
  r.script = script_text;
  r.has_tail = !c.tail.empty();
  r.segments.resize(script.size());
  std::vector<long long> segment_end;  // first tick after each segment (run_script's rounding)
  long long ticks = 0;
  for (const ScriptSegment& s : script) segment_end.push_back(ticks += s.ticks(tick_hz));
  std::vector<int> dirs;  // the sign of each segment's command (0 for stops)
  for (const ScriptSegment& s : script) dirs.push_back(s.mode == "stop" || s.stick == 0.0f ? 0 : s.stick > 0.0f ? 1 : -1);

  const float dt = 1.0f / static_cast<float>(tick_hz);
  SlipTracker slip;
  size_t seg = 0;
  long long seg_first = 0;
  r.x_min = r.x_max = a.x();
  r.segments[0].x_start = r.segments[0].x_far = a.x();
  std::vector<float> x_mark(script.size(), a.x());
  std::vector<float> x_warm(script.size(), a.x());  // x after run_script's warm-up tick
  OutlineProbe outline(c);
  r.sim = run_script(player, level, script, tick_hz, [&](long long tick) {
    outline.observe(a, level, static_cast<float>(tick + 1) * dt);
    while (seg + 1 < segment_end.size() && tick >= segment_end[seg]) {
      seg_first = segment_end[seg];
      ++seg;
      r.segments[seg].x_start = r.segments[seg].x_far = x_mark[seg] = r.segments[seg - 1].x_end;
    }
    SegmentStats& s = r.segments[seg];
    const float t = static_cast<float>(tick - seg_first + 1) * dt;
    const std::vector<Mat2x3>& world = a.world_matrices();
    for (const Mat2x3& m : world) {
      for (float v : m.m) s.nan_count += std::isfinite(v) ? 0 : 1;
    }
    glm::vec2 foot(0.0f);
    if (const float d = slip.observe(a, &foot); d > s.max_slip_m) {
      s.max_slip_m = d;
      s.slip_at_ws = foot;
      s.slip_t = t;
    }
    for (const Limb& limb : c.limbs) {
      glm::vec2 at(0.0f);
      const float d = deepest(c, world, limb.bones.data(), limb.bones.size(), level, &at);
      if (d > s.max_penetration_m) {
        s.max_penetration_m = d;
        s.penetration_limb = limb_label(limb);
        s.penetration_at_ws = at;
        s.penetration_t = t;
      }
      if (d > r.worst_limb_m) {
        r.worst_limb_m = d;
        r.worst_limb = limb_label(limb);
      }
    }
    if (r.has_tail) {
      r.tail_penetration_m = std::max(r.tail_penetration_m, deepest(c, world, c.tail.data(), c.tail.size(), level, nullptr));
      r.tail_joint_penetration_m =
          std::max(r.tail_joint_penetration_m, deepest(c, world, c.tail.data(), c.tail.size(), level, nullptr, 4));
    }
    if (a.blocked()) {
      s.blocked_s += dt;
      r.blocked_s += dt;
    }
    const float x = a.x();
    s.x_end = x;
    r.x_min = std::min(r.x_min, x);
    r.x_max = std::max(r.x_max, x);
    const int dir = dirs[seg];
    const long long local = tick - seg_first;  // run_script's t
    const long long warmup = std::min((segment_end[seg] - seg_first) / 2, static_cast<long long>(tick_hz));
    if (local == warmup) x_warm[seg] = x;
    if (dir != 0 && seg < goals_x.size() && std::isfinite(goals_x[seg]) && s.goal_t < 0.0f &&
        (x - goals_x[seg]) * static_cast<float>(dir) >= 0.0f) {
      s.goal_t = t;
      s.goal_before_window = local <= warmup;
      if (!s.goal_before_window) s.mean_speed_to_goal = (x - x_warm[seg]) / (static_cast<float>(local - warmup) * dt);
    }
    if (dir != 0 && (x - s.x_far) * static_cast<float>(dir) > 0.0f) s.x_far = x;
    if (dir != 0 && (x - x_mark[seg]) * static_cast<float>(dir) > 0.05f) {
      x_mark[seg] = x;  // the last 5 cm of progress ended at x_far_t
      s.x_far_t = t;
    }
    if (tick + 1 == segment_end[seg]) slip.reanchor(a);  // the next segment's slip starts here
  });
  for (size_t i = 0; i < script.size(); ++i) {
    if (dirs[i] == 0) r.segments[i].x_far = r.segments[i].x_end;
    if (r.segments[i].goal_t < 0.0f) r.segments[i].mean_speed_to_goal = r.sim.segments[i].mean_speed;
  }
  r.outline_penetration_m = outline.max_outline_penetration_m;
  r.outline_part = outline.deepest_outline_part;
  r.outline_at_s = outline.deepest_outline_at_s;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void parallel_for(int count, int threads, const std::function<void(int)>& job) {
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  const int n = std::max(1, std::min(threads, count));
  for (int t = 0; t < n; ++t) {
    pool.emplace_back([&] {
      for (int i = next++; i < count; i = next++) job(i);
    });
  }
  for (std::thread& th : pool) th.join();
}

}  // namespace ossa::sweep
