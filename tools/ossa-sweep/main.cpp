// ossa-sweep — drives every example animal over every shipped level, in parallel, and sums up
// how they walked: the README's "Known limits" figures, and issue 14's slopes acceptance check.
//
//   ossa-sweep [--jobs 2] [--json out/sweep.json]     44 animals × levels/*.json × 3 scripts
//   ossa-sweep --slopes-check [--json out/slopes.json] every animal walks and runs both ways
//                                                      over levels/slopes.json; exit 1 on failure
//
// Each run is ossa-sim's (ossa::run_script and its SimProbe, spawn 1 m above the level's spawn,
// 120 Hz), so a line of the sweep can be reproduced with ossa-sim --example NAME --level F
// --script S --json. Every failure to start prints one line naming what was wrong, status 1.
//
// [SECTION] arguments · [SECTION] the sweep · [SECTION] the slopes check · [SECTION] main

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/game/player.h"
#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/io/parse_arg.h"
#include "ossa/level/level_io.h"
#include "sweep_run.h"

using namespace ossa;
using namespace ossa::sweep;
using OJson = nlohmann::ordered_json;

namespace {

// [SECTION] arguments ---------------------------------------------------------------------

const char* kUsage = R"(usage: ossa-sweep [--slopes-check] [--level F]... [--example NAME]... [--script S]...
                  [--size true|FRAME_M] [--jobs N] [--hz N] [--json OUT.json]
  (default)        the Known-limits sweep: every example × every level × every script, then
                   the summary table (runs over 1 mm, runs stopped at a step, tails in steps)
  --slopes-check   every example walks (stick 0.5) right across the level and back, and runs
                   (run, stick 1) the same way, each from the spawn, with durations from its
                   speeds (it turns in the middle of the flat ends); each moving segment must keep
                   its mean speed within 10% of the command, every segment stance slip and
                   limb penetration <= 1 mm and no NaN. Exit status 1 and a list of failures
  --level F        a level (repeatable; default: every levels/*.json, or levels/slopes.json
                   with --slopes-check)
  --known-failures F  with --slopes-check: the animals (one name per line) allowed to fail;
                   any other failing is a regression (exit 1)
  --example NAME   an example animal (repeatable; default: all 44)
  --size S         the examples' size: true (default: each animal's own size) or a fixed
                   frame in metres (2: the frame the shipped levels' steps were laid out for)
  --script S       an ossa-sim script (repeatable; default: "walk:0.6:30", "run:1:15",
                   "walk:0.5:6,stop:1,walk:-0.6:6")
  --jobs N         worker threads (default: one per hardware thread); --threads N is the
                   same flag, named as on ossa and ossa-sim (each run is one creature, so the
                   runs, not the creatures, are spread over the threads)
  --hz N           simulation rate, 30..480 (default 120)
  --json OUT.json  every run's figures
)";


[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "ossa-sweep: %s\n", message.c_str());
  std::exit(1);
}

struct Args {
  bool slopes_check = false;
  std::vector<std::string> levels, examples, scripts;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int hz = 120;
  std::optional<std::string> json;
  std::optional<std::string> known_failures;  // --known-failures FILE
  SizeChoice size;                             // --size
};

long long parse_int(const std::string& flag, const std::string& text, long long lo, long long hi) {
  Result<long long> v = parse_int_arg(flag, text, lo, hi);
  if (!v) fail(v.message());
  return *v;
}

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string f = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail(f + ": missing value");
      return argv[++i];
    };
    if (f == "--help" || f == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (f == "--slopes-check") a.slopes_check = true;
    else if (f == "--level") a.levels.push_back(value());
    else if (f == "--example") a.examples.push_back(value());
    else if (f == "--script") a.scripts.push_back(value());
    else if (f == "--jobs" || f == "--threads") a.jobs = static_cast<int>(parse_int(f, value(), 1, 1024));
    else if (f == "--hz") a.hz = static_cast<int>(parse_int(f, value(), 30, 480));
    else if (f == "--json") a.json = value();
    else if (f == "--known-failures") a.known_failures = value();
    else if (f == "--size") {
      Result<SizeChoice> s = parse_size_arg(f, value());
      if (!s) fail(s.message());
      a.size = *s;
    }
    else fail("unknown option " + f + " (see --help)");
  }
  if (a.slopes_check && !a.scripts.empty()) fail("--script: the slopes check makes its own scripts");
  if (a.slopes_check && a.levels.size() > 1) fail("--level: the slopes check takes one level");
  return a;
}

struct Setup {
  std::vector<std::shared_ptr<const Creature>> creatures;
  std::vector<std::string> level_names;  // file names, for the tables
  std::vector<Level> levels;
  SplinePrototypes prototypes = SplinePrototypes::defaults();
};

Setup load_setup(const Args& args) {
  Setup s;
  std::vector<std::string> paths = args.levels;
  if (paths.empty() && args.slopes_check) paths.push_back(data_path("levels/slopes.json"));
  if (paths.empty()) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(data_path("levels"), ec)) {
      if (entry.path().extension() == ".json") paths.push_back(entry.path().string());
    }
    if (ec) fail(data_path("levels") + ": " + ec.message());
    std::sort(paths.begin(), paths.end());
    if (paths.empty()) fail(data_path("levels") + ": no level files");
  }
  if (args.json) {  // no output may be one of the inputs (io/file.h)
    std::vector<std::string> inputs = paths;
    if (args.known_failures) inputs.push_back(*args.known_failures);
    if (Status st = check_output_path("--json", *args.json, inputs); !st) fail(st.message());
  }
  for (const std::string& path : paths) {
    Result<Level> level = load_level(path);
    if (!level) fail(level.message());
    for (const std::string& w : level_warnings(*level)) std::fprintf(stderr, "warning: %s: %s\n", path.c_str(), w.c_str());
    s.levels.push_back(std::move(*level));
    s.level_names.push_back(std::filesystem::path(path).filename().string());
  }
  const std::string proto_path = data_path("assets/animation/prototypes.json");
  std::error_code exists_error;
  if (std::filesystem::exists(proto_path, exists_error)) {
    Result<SplinePrototypes> p = load_prototypes(proto_path);
    if (!p) fail(p.message());
    s.prototypes = *p;
  }
  Result<Generator> gen = Generator::load(data_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  if (!gen) fail(gen.message());
  std::vector<std::string> names = args.examples;
  if (names.empty()) {
    for (const Animal& animal : gen->dataset().animals) names.push_back(animal.name);
  }
  GenerateOptions options;
  args.size.apply_to(options.genome);
  for (const std::string& name : names) {
    Result<Genome> g = gen->example(name, 1, options);
    if (!g) fail(g.message());
    Result<Creature> c = build_creature(*g);
    if (!c) fail(name + ": " + c.message());
    s.creatures.push_back(std::make_shared<const Creature>(std::move(*c)));
  }
  return s;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

OJson record_json(const RunRecord& r) {
  OJson segs = OJson::array();
  for (size_t i = 0; i < r.segments.size(); ++i) {
    const SegmentMetrics& m = r.sim.segments[i];
    const SegmentStats& s = r.segments[i];
    segs.push_back({{"command", m.command},
                    {"commanded_speed", json_float(m.commanded_speed)},
                    {"mean_speed", json_float(m.mean_speed)},
                    {"speed_ratio", json_float(m.commanded_speed != 0.0f ? m.mean_speed / m.commanded_speed : 0.0f)},
                    {"gait", m.gait},
                    {"max_stance_slip_m", json_float(s.max_slip_m)},
                    {"max_penetration_m", json_float(s.max_penetration_m)},
                    {"penetration_limb", s.penetration_limb},
                    {"nan_count", s.nan_count},
                    {"blocked_s", json_float(s.blocked_s)},
                    {"x_start", json_float(s.x_start)},
                    {"x_end", json_float(s.x_end)},
                    {"x_far", json_float(s.x_far)},
                    {"x_far_t", json_float(s.x_far_t)},
                    {"goal_t", json_float(s.goal_t)},
                    {"mean_speed_to_goal", json_float(s.mean_speed_to_goal)}});
  }
  return {{"animal", r.animal},
          {"level", r.level},
          {"script", r.script},
          {"max_stance_slip_m", json_float(r.sim.probe.max_stance_slip_m)},
          {"max_stance_gap_m", json_float(r.sim.probe.max_stance_gap_m)},
          // The worst over everything, the drawn body's outline too; the bones' alone next.
          {"max_penetration_m", json_float(std::max(r.sim.probe.max_penetration_m, r.outline_penetration_m))},
          {"max_bone_penetration_m", json_float(r.sim.probe.max_penetration_m)},
          {"max_limb_penetration_m", json_float(r.sim.probe.max_limb_penetration_m)},
          {"max_body_penetration_m", json_float(r.sim.probe.max_body_penetration_m)},
          {"deepest_bone", r.sim.probe.deepest_bone},
          {"deepest_at_s", json_float(r.sim.probe.deepest_at_s)},
          {"max_body_jolt_g", json_float(r.sim.probe.max_body_jolt_g)},
          {"max_limb_flick", json_float(r.sim.probe.max_limb_flick)},
          {"limb_flick_at_s", json_float(r.sim.probe.limb_flick_at_s)},
          {"limb_flicks", r.sim.probe.limb_flicks},
          {"max_outline_penetration_m", json_float(r.outline_penetration_m)},
          {"deepest_outline_part", r.outline_part},
          {"deepest_outline_at_s", json_float(r.outline_at_s)},
          {"worst_limb", r.worst_limb},
          {"worst_limb_m", json_float(r.worst_limb_m)},
          {"tail_penetration_m", r.has_tail ? OJson(json_float(r.tail_penetration_m)) : OJson(nullptr)},
          {"tail_joint_penetration_m", r.has_tail ? OJson(json_float(r.tail_joint_penetration_m)) : OJson(nullptr)},
          {"min_swing_clearance_m", json_float(r.sim.probe.min_swing_clearance_m > 1e8f ? 0.0f : r.sim.probe.min_swing_clearance_m)},
          {"nan_count", r.sim.probe.nan_count},
          {"blocked_s", json_float(r.blocked_s)},
          {"x_reached", json_float(r.sim.x_reached)},
          {"x_min", json_float(r.x_min)},
          {"x_max", json_float(r.x_max)},
          {"steps", r.sim.steps},
          {"pose_hash", [&] {
             char hash[32];
             std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(r.sim.probe.pose_hash));
             return std::string(hash);
           }()},
          {"segments", segs}};
}

void write_json(const std::string& path, const char* kind, const std::vector<RunRecord>& runs, OJson extra = {}) {
  OJson doc;
  doc["format"] = std::string("ossa.") + kind;
  doc["version"] = 1;
  for (auto& [key, value] : extra.items()) doc[key] = value;
  OJson list = OJson::array();
  for (const RunRecord& r : runs) list.push_back(record_json(r));
  doc["runs"] = std::move(list);
  if (Status s = write_file_atomic(path, doc.dump(1, ' ', false, OJson::error_handler_t::replace) + "\n"); !s) fail(s.message());
}

// [SECTION] the sweep -----------------------------------------------------------------------

constexpr float kLimit = 0.001f;  // metres: the README's 1 mm for slip, penetration and tails

// A run that went on: every moving segment kept at least 20% of its commanded speed.
bool kept_going(const RunRecord& r) {
  for (const SegmentMetrics& m : r.sim.segments) {
    if (m.commanded_speed != 0.0f && m.mean_speed / m.commanded_speed < 0.2f) return false;
  }
  return true;
}

bool over_limit(const RunRecord& r) {
  return r.sim.probe.max_stance_slip_m > kLimit || r.sim.probe.max_penetration_m > kLimit;
}

std::string mm(float metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, metres >= 0.01f ? "%.1f cm" : "%.1f mm", metres >= 0.01f ? metres * 100.0f : metres * 1000.0f);
  return buf;
}

int run_sweep(const Args& args, const Setup& setup) {
  const std::vector<std::string> texts =
      args.scripts.empty() ? std::vector<std::string>{"walk:0.6:30", "run:1:15", "walk:0.5:6,stop:1,walk:-0.6:6"} : args.scripts;
  std::vector<std::vector<ScriptSegment>> scripts;
  for (const std::string& t : texts) {
    Result<std::vector<ScriptSegment>> s = parse_script(t);
    if (!s) fail(s.message());
    scripts.push_back(*s);
  }
  const int na = static_cast<int>(setup.creatures.size()), nl = static_cast<int>(setup.levels.size());
  const int ns = static_cast<int>(scripts.size());
  const int count = na * nl * ns;
  std::vector<RunRecord> runs(count);
  const auto start = std::chrono::steady_clock::now();
  parallel_for(count, args.jobs, [&](int i) {
    const int a = i / (nl * ns), l = i / ns % nl, s = i % ns;
    const Level& level = setup.levels[l];
    runs[i] = run_one(setup.creatures[a], setup.prototypes, level, level.spawn_ws + glm::vec2(0.0f, 1.0f), texts[s], scripts[s],
                      args.hz);
    runs[i].level = setup.level_names[l];
  });
  const double wall = seconds_since(start);

  // The README's figures.
  std::vector<const RunRecord*> over, stopped, tails;
  const RunRecord *deepest = nullptr, *slid = nullptr, *worst_tail = nullptr;
  int walks = 0, tail_joints = 0;
  for (const RunRecord& r : runs) {
    if (over_limit(r)) {
      over.push_back(&r);
      if (!deepest || r.sim.probe.max_penetration_m > deepest->sim.probe.max_penetration_m) deepest = &r;
      if (!slid || r.sim.probe.max_stance_slip_m > slid->sim.probe.max_stance_slip_m) slid = &r;
    } else if (!kept_going(r)) {
      stopped.push_back(&r);
    }
    if (r.script == texts[0]) {
      ++walks;
      if (r.has_tail && r.tail_penetration_m > kLimit) tails.push_back(&r);
      if (r.has_tail && r.tail_joint_penetration_m > kLimit) ++tail_joints;
      if (r.has_tail && (!worst_tail || r.tail_penetration_m > worst_tail->tail_penetration_m)) worst_tail = &r;
    }
  }
  std::printf("ossa-sweep: %d animals x %d levels x %d scripts = %d runs in %.1f s (%d jobs)\n\n", na, nl, ns, count, wall,
              args.jobs);
  std::printf("| figure | value |\n| --- | --- |\n");
  int limbs_over = 0;
  for (const RunRecord& r : runs) limbs_over += r.sim.probe.max_stance_slip_m > kLimit || r.sim.probe.max_limb_penetration_m > kLimit;
  std::printf("| runs with a bone > 1 mm in a collider or a foot sliding > 1 mm | %zu of %d |\n", over.size(), count);
  std::printf("| the same, limbs only (the metric before every bone was measured) | %d of %d |\n", limbs_over, count);
  if (deepest) {
    std::printf("| of these, the deepest bone | %s (%s, %s, %s) |\n", mm(deepest->sim.probe.max_penetration_m).c_str(),
                deepest->animal.c_str(), deepest->level.c_str(), deepest->sim.probe.deepest_bone.c_str());
    std::printf("| of these, the worst slide | %s (%s, %s) |\n", mm(slid->sim.probe.max_stance_slip_m).c_str(),
                slid->animal.c_str(), slid->level.c_str());
  }
  int gaps = 0;
  const RunRecord* widest = nullptr;
  for (const RunRecord& r : runs) {
    gaps += r.sim.probe.max_stance_gap_m > kLimit;
    if (!widest || r.sim.probe.max_stance_gap_m > widest->sim.probe.max_stance_gap_m) widest = &r;
  }
  std::printf("| runs with a standing foot > 1 mm short of its foothold (a leg stretched past its length) | %d of %d", gaps, count);
  if (widest && gaps > 0) std::printf(" (widest %s, %s on %s)", mm(widest->sim.probe.max_stance_gap_m).c_str(), widest->animal.c_str(), widest->level.c_str());
  std::printf(" |\n");
  // The drawn body (outline_probe.h): flesh, horns, fins and flukes beyond the bones, as drawn.
  int outlines = 0;
  const RunRecord* deepest_outline = nullptr;
  for (const RunRecord& r : runs) {
    outlines += r.outline_penetration_m > kLimit;
    if (!deepest_outline || r.outline_penetration_m > deepest_outline->outline_penetration_m) deepest_outline = &r;
  }
  std::printf("| runs with the drawn body's outline > 1 mm in a collider (not in the bones' figure above) | %d of %d", outlines, count);
  if (deepest_outline && outlines > 0) {
    std::printf(" (deepest %s, %s's %s on %s)", mm(deepest_outline->outline_penetration_m).c_str(), deepest_outline->animal.c_str(),
                deepest_outline->outline_part.c_str(), deepest_outline->level.c_str());
  }
  std::printf(" |\n");
  // Limb flicks (SimProbe::limb_flicks): a leg or arm thrown somewhere else for a tick.
  int flicking = 0;
  long long flick_ticks = 0;
  const RunRecord* hardest = nullptr;
  for (const RunRecord& r : runs) {
    flicking += r.sim.probe.limb_flicks > 0;
    flick_ticks += r.sim.probe.limb_flicks;
    if (!hardest || r.sim.probe.max_limb_flick > hardest->sim.probe.max_limb_flick) hardest = &r;
  }
  std::printf("| runs with a limb flick (a joint thrown > %.0f times the gait's own acceleration in a tick) | %d of %d, %lld ticks",
              static_cast<double>(SimProbe::kLimbFlick), flicking, count, flick_ticks);
  if (hardest && flicking > 0) {
    std::printf(" (hardest %.0f times, %s on %s at %.2f s)", static_cast<double>(hardest->sim.probe.max_limb_flick), hardest->animal.c_str(),
                hardest->level.c_str(), static_cast<double>(hardest->sim.probe.limb_flick_at_s));
  }
  std::printf(" |\n");
  std::printf("| runs stopped at a step (< 20%% of the commanded speed, limbs clean) | %zu |\n", stopped.size());
  std::printf("| example walks (%s) with a tail > 1 mm in a step | %zu of %d", texts[0].c_str(), tails.size(), walks);
  if (worst_tail) std::printf(" (deepest %s, %s on %s)", mm(worst_tail->tail_penetration_m).c_str(), worst_tail->animal.c_str(), worst_tail->level.c_str());
  std::printf(" |\n| the same, sampling the tail's joints only | %d of %d |\n", tail_joints, walks);

  std::printf("\nruns over 1 mm (slide, deepest bone):\n");
  for (const RunRecord* r : over) {
    const bool named = r->sim.probe.max_penetration_m > 0.1f * kLimit;  // name the bone when it went in at all
    std::printf("  %-18s %-12s %-32s slide %-8s bone %s%s%s at %.1f s\n", r->animal.c_str(), r->level.c_str(), r->script.c_str(),
                mm(r->sim.probe.max_stance_slip_m).c_str(), mm(r->sim.probe.max_penetration_m).c_str(), named ? " " : "",
                named ? r->sim.probe.deepest_bone.c_str() : "", r->sim.probe.deepest_at_s);
  }
  std::printf("\nstopped at a step (furthest x):\n");
  for (const RunRecord* r : stopped) {
    std::printf("  %-18s %-12s %-32s x %.2f..%.2f, blocked %.1f s\n", r->animal.c_str(), r->level.c_str(), r->script.c_str(),
                r->x_min, r->x_max, r->blocked_s);
  }
  std::printf("\ntails over 1 mm:\n");
  for (const RunRecord* r : tails) {
    std::printf("  %-18s %-12s %s\n", r->animal.c_str(), r->level.c_str(), mm(r->tail_penetration_m).c_str());
  }
  if (args.json) write_json(*args.json, "sweep", runs, {{"seconds", wall}, {"jobs", args.jobs}});
  return 0;
}

// [SECTION] the slopes check -----------------------------------------------------------------

struct Ends {
  float left = 0.0f, right = 0.0f;  // middles of the flat run-ups at either end, world x
};

// The flat ground around the spawn and the flat ground before the right end of the level at
// the same height: the check starts in the first and turns round in the middle of each.
Ends find_ends(const Level& level) {
  const float x0 = level.spawn_ws.x;
  const auto g0 = level.ground_height_below(x0, level.spawn_ws.y + 1.0f, 100.0f);
  if (!g0) fail(level.name + ": no ground under the spawn");
  const float y0 = g0->height_ws;
  const Box bounds = level.bounds();
  auto flat = [&](float x) {
    const auto g = level.ground_height_below(x, y0 + 2.0f, 100.0f);
    return g && std::fabs(g->height_ws - y0) <= 0.001f;
  };
  const float step = 0.01f;
  float a = x0, b = x0;
  while (a - step > bounds.min_ws.x && flat(a - step)) a -= step;
  while (b + step < bounds.max_ws.x && flat(b + step)) b += step;
  float d = bounds.max_ws.x - step;
  while (d > b && !flat(d)) d -= step;
  float c = d;
  while (c - step > b && flat(c - step)) c -= step;
  if (d <= b + 1.0f || d - c < 2.0f) fail(level.name + ": expected flat ground at the spawn's height before the right end");
  return {0.5f * (a + b), 0.5f * (c + d)};
}

// "x 9.85, 0.30 m up, 10° down ahead" — where a creature got to, for people.
std::string describe_ground(const Level& level, float x, int dir) {
  char buf[128];
  const auto here = level.ground_height_below(x, 10.0f, 100.0f);
  const auto ahead = level.ground_height_below(x + 0.3f * static_cast<float>(dir), 10.0f, 100.0f);
  if (!here || !ahead) {
    std::snprintf(buf, sizeof buf, "x %.2f, at a gap", x);
    return buf;
  }
  const float rise = ahead->height_ws - here->height_ws;
  const float deg = std::atan2(std::fabs(rise), 0.3f) * 57.29578f;
  if (rise < -0.3f) {
    std::snprintf(buf, sizeof buf, "x %.2f, ground %.2f m, a gap or drop ahead", x, here->height_ws);
  } else if (deg < 2.0f) {
    std::snprintf(buf, sizeof buf, "x %.2f, ground %.2f m, flat ahead", x, here->height_ws);
  } else {
    std::snprintf(buf, sizeof buf, "x %.2f, ground %.2f m, %.0f° %s ahead", x, here->height_ws, deg, rise > 0 ? "up" : "down");
  }
  return buf;
}

// Why a run of the slopes check failed, a line per failure: segments whose mean speed is off
// the command by more than 10%, and segments with stance slip or penetration over 1 mm or NaNs.
std::vector<std::string> failure_lines(const RunRecord& r, const std::vector<ScriptSegment>& script, const Level& level) {
  std::vector<std::string> lines;
  char buf[320];
  for (size_t k = 0; k < r.segments.size(); ++k) {
    const SegmentMetrics& m = r.sim.segments[k];
    const SegmentStats& s = r.segments[k];
    const int dir = m.commanded_speed > 0.0f ? 1 : m.commanded_speed < 0.0f ? -1 : 0;
    const std::string what = dir == 0 ? "stop" : script[k].mode + (dir > 0 ? " right" : " left");
    char head[96];
    std::snprintf(head, sizeof head, "%-10s %-22s", what.c_str(), m.command.c_str());
    const float speed = s.mean_speed_to_goal;
    if (dir != 0 && !s.goal_before_window && std::fabs(speed - m.commanded_speed) > 0.10f * std::fabs(m.commanded_speed)) {
      std::snprintf(buf, sizeof buf, "%s mean speed %.2f of %.2f m/s (%+.0f%%); got to %s at %.1f s, blocked %.1f s", head,
                    speed, m.commanded_speed, 100.0f * (speed / m.commanded_speed - 1.0f),
                    describe_ground(level, s.x_far, dir).c_str(), s.x_far_t, s.blocked_s);
      lines.push_back(buf);
    }
    if (s.max_slip_m > kLimit) {
      std::snprintf(buf, sizeof buf, "%s stance slip %s at %s, %.1f s", head, mm(s.max_slip_m).c_str(),
                    describe_ground(level, s.slip_at_ws.x, dir ? dir : 1).c_str(), s.slip_t);
      lines.push_back(buf);
    }
    if (s.max_penetration_m > kLimit) {
      std::snprintf(buf, sizeof buf, "%s penetration %s (%s) at x %.2f y %.3f, %.1f s", head, mm(s.max_penetration_m).c_str(),
                    s.penetration_limb.c_str(), s.penetration_at_ws.x, s.penetration_at_ws.y, s.penetration_t);
      lines.push_back(buf);
    }
    if (s.nan_count > 0) {
      std::snprintf(buf, sizeof buf, "%s %d non-finite matrix values", head, s.nan_count);
      lines.push_back(buf);
    }
  }
  bool slip_listed = false;
  for (const SegmentStats& s : r.segments) slip_listed |= s.max_slip_m > kLimit;
  if (!slip_listed && r.sim.probe.max_stance_slip_m > kLimit) {
    std::snprintf(buf, sizeof buf, "%s: stance slip %s, spread over segments", r.script.c_str(),
                  mm(r.sim.probe.max_stance_slip_m).c_str());
    lines.push_back(buf);
  }
  return lines;
}

int slopes_check(const Args& args, const Setup& setup) {
  const Level& level = setup.levels[0];
  const std::string& level_name = setup.level_names[0];
  const Ends ends = find_ends(level);
  const glm::vec2 spawn = level.spawn_ws + glm::vec2(0.0f, 1.0f);
  const int n = static_cast<int>(setup.creatures.size());
  // Two runs per animal, each from the spawn: walking (stick 0.5, the walk speed) right to the
  // middle of the far run-up and back to the near one, then running (run, stick 1) the same
  // way. Durations from the animal's commanded speeds.
  struct Plan {
    std::string text;
    std::vector<ScriptSegment> script;
    std::vector<float> goals_x;  // the speed is measured until the root gets there
  };
  const float kNone = std::numeric_limits<float>::quiet_NaN();
  std::vector<Plan> plans;
  for (int i = 0; i < n; ++i) {
    const Entity e(setup.creatures[i], setup.prototypes);
    const float across = ends.right - ends.left, first = ends.right - level.spawn_ws.x;
    for (const bool run : {false, true}) {
      const float stick = run ? 1.0f : 0.5f, speed = e.desired_velocity({stick, run});
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s:%g:%.2f,stop:1,%s:%g:%.2f,stop:1", run ? "run" : "walk", stick, first / speed,
                    run ? "run" : "walk", -stick, across / speed);
      plans.push_back({buf, parse_script(buf).value(), {ends.right, kNone, ends.left, kNone}});
    }
  }
  std::vector<RunRecord> runs(plans.size());
  const auto start = std::chrono::steady_clock::now();
  parallel_for(static_cast<int>(plans.size()), args.jobs, [&](int i) {
    runs[i] = run_one(setup.creatures[i / 2], setup.prototypes, level, spawn, plans[i].text, plans[i].script, args.hz,
                      plans[i].goals_x);
    runs[i].level = level_name;
  });
  const double wall = seconds_since(start);

  int failures = 0;
  std::vector<std::string> failed_names;
  for (int i = 0; i < n; ++i) {
    std::vector<std::string> lines = failure_lines(runs[2 * i], plans[2 * i].script, level);
    const std::vector<std::string> running = failure_lines(runs[2 * i + 1], plans[2 * i + 1].script, level);
    lines.insert(lines.end(), running.begin(), running.end());
    if (lines.empty()) continue;
    failures += static_cast<int>(lines.size());
    failed_names.push_back(runs[2 * i].animal);
    std::printf("FAIL %s\n", runs[2 * i].animal.c_str());
    for (const std::string& line : lines) std::printf("  %s\n", line.c_str());
  }
  const int failed = static_cast<int>(failed_names.size());
  std::printf("slopes: %d of %d examples walk and run both ways on %s (run-ups at x %.2f and %.2f); %d failed (%d failures) in %.1f s\n",
              n - failed, n, level_name.c_str(), ends.left, ends.right, failed, failures, wall);
  if (args.json) {
    write_json(*args.json, "slopes_check", runs,
               {{"level", level_name}, {"left_x", json_float(ends.left)}, {"right_x", json_float(ends.right)},
                {"failed", failed_names}});
  }
  if (!args.known_failures) return failed == 0 ? 0 : 1;
  // A regression guard while some animals still fail: the listed ones may fail, no other may;
  // a listed one that now passes is named so the list can shrink.
  Result<std::string> list = read_file(*args.known_failures);  // the input rule (io/file.h)
  if (!list) fail("--known-failures: " + list.message());
  std::vector<std::string> known;
  std::istringstream in(*list);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') known.push_back(line);
  }
  int unexpected = 0;
  for (const std::string& name : failed_names) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::printf("REGRESSION %s fails on %s but is not in %s\n", name.c_str(), level_name.c_str(), args.known_failures->c_str());
      ++unexpected;
    }
  }
  for (const std::string& name : known) {
    if (std::find(failed_names.begin(), failed_names.end(), name) == failed_names.end()) {
      std::printf("now passes: %s (remove it from %s)\n", name.c_str(), args.known_failures->c_str());
    }
  }
  return unexpected == 0 ? 0 : 1;
}

}  // namespace

// [SECTION] main ------------------------------------------------------------------------------

int main(int argc, char** argv) {
  const Args args = parse_args(argc, argv);
  const Setup setup = load_setup(args);
  return args.slopes_check ? slopes_check(args, setup) : run_sweep(args, setup);
}
