// ossa-sim — runs creatures headless over a level with a script of control segments and
// reports how they walked (speed, stride, gait, stance slip, penetration, clearance...).
//
//   ossa-sim --example horse --level levels/default.json
//            --script "walk:0.5:10,run:1:6,stop:2,walk:-0.5:5" --json --svg out/horse.svg
//
// Every failure prints one line naming what was wrong and exits with status 1.

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/anim/spline_prototypes.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/game/herd.h"
#include "ossa/game/outline_probe.h"
#include "ossa/game/sim.h"
#include "ossa/game/player.h"
#include "ossa/game/world.h"
#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/io/parse_arg.h"
#include "ossa/level/level_io.h"
#if OSSA_SIM_CHARACTERS
#include "ossa/render/character_mesh.h"
#endif

using namespace ossa;

namespace {

const char* kUsage = R"(usage: ossa-sim (--example NAME | --creature F.creature.json | --character F.rig.json | --random --seed N)
                [--size true|FRAME_M] [--level F] --script "mode:stick:seconds,..." [--hz 120] [--count N [--threads N]]
                [--prototypes F] [--json] [--trace F.csv] [--trace-joints F.csv]
                [--svg F.svg [--svg-window FROM:TO[:EVERY]]]
  --example NAME   one of the 44 example animals (English or German name)
  --creature F     a saved genome (.creature.json)
  --character F    a rigged character: its rig mapping (.rig.json) and the mesh it names
  --random         a random creature (with --seed N, default 1)
  --size S         the creature's size: true (the animal's true size from its weight and
                   body plan, the default for --example and --random) or a fixed frame of S
                   metres (0.05 to 50); a --creature genome is resized (default: as saved)
  --level F        level file (default: levels/default.json): an ossa level, a Tiled map
                   (.tmj, .tmx) or an LDtk project (.ldtk, F#LevelName picks a level)
  --pixels-per-metre P  scale of Tiled/LDtk maps with neither a pixels_per_metre property
                   nor a tile size (default 32)
  --script S       segments: walk:STICK:SECONDS, run:STICK:SECONDS, stop:SECONDS, jump (the
                   jump button for one tick) and jump:SECONDS (held), keeping the stick
  --hz N           simulation rate, 30..480 (default 120)
  --count N        N creatures at once, sharing one rig (reports update_us_per_creature,
                   and herd_pose_hash over the extra creatures' final poses)
  --threads N      threads stepping the extra creatures of --count (step_all): 0 = every
                   core (default), 1 = one; the poses do not depend on it
  --prototypes F   spline prototypes (default: assets/animation/prototypes.json)
  --json           print the metrics as JSON
  --trace F.csv    per-tick foot and girdle positions
  --trace-joints F.csv  per tick the world position of every joint of the skeleton: t, then
                   x and y of each bone's joint (BONE_x, BONE_y) and of each bone's far end
                   that no other bone starts at (BONE.end_x, BONE.end_y), metres; to check a
                   pose against the level with no trust in ossa's own metrics
  --svg F.svg      a strobe of the creature over the level (a pose every 0.4 s): its bones
                   and, for a generated creature, its drawn body's outlines
  --svg-window FROM:TO[:EVERY]  the strobe's poses from FROM to TO seconds, one every EVERY
                   seconds (default 0.4): a close look at a moment (a pose's time is the
                   metrics': a window from deepest_at_s starts with that pose)
)";

// Output bounds (see main): at most this many trace rows (ticks) and SVG poses.
constexpr long long kMaxTraceTicks = 1000000;
constexpr long long kMaxJointTraceTicks = 100000;
constexpr long long kMaxSvgPoses = 2000;

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "ossa-sim: %s\n", message.c_str());
  std::exit(1);
}

struct Args {
  std::optional<std::string> example, creature, character, level, script, prototypes, trace, trace_joints, svg;
  bool random = false, json = false;
  uint64_t seed = 1;
  int hz = 120, count = 1, threads = 0;
  std::optional<SizeChoice> size;  // --size: the genome's size choice
  float pixels_per_metre = 32.0f;  // LevelLoadOptions::pixels_per_metre
  float svg_from = 0.0f, svg_to = 1e30f, svg_every = 0.4f;  // seconds (--svg-window)
};

long long parse_int(const std::string& flag, const std::string& text, long long lo, long long hi) {
  Result<long long> v = parse_int_arg(flag, text, lo, hi);
  if (!v) fail(v.message());
  return *v;
}

float parse_scale(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (errno || text.empty() || *end || !(v > 0.0 && v <= 1e6)) {
    fail(flag + ": expected a number in (0, 1000000], got \"" + text + "\"");
  }
  return static_cast<float>(v);
}

// --svg-window FROM:TO[:EVERY], seconds: 0 <= FROM < TO, 1/hz <= EVERY.
void parse_svg_window(const std::string& flag, const std::string& text, Args& a) {
  float v[3] = {0.0f, 0.0f, a.svg_every};
  int n = 0;
  const char* p = text.c_str();
  while (n < 3) {
    char* end = nullptr;
    errno = 0;
    const double d = std::strtod(p, &end);
    if (errno || end == p || !std::isfinite(d) || d < 0.0 || d > 1e6) break;
    v[n++] = static_cast<float>(d);
    if (*end == '\0') {
      p = end;
      break;
    }
    if (*end != ':') {
      n = 0;
      break;
    }
    p = end + 1;
  }
  if (n < 2 || *p != '\0' || !(v[0] < v[1]) || !(v[2] > 0.0f)) {
    fail(flag + ": expected FROM:TO[:EVERY] in seconds (0 <= FROM < TO, EVERY > 0), got \"" + text + "\"");
  }
  a.svg_from = v[0];
  a.svg_to = v[1];
  a.svg_every = v[2];
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
    } else if (f == "--example") a.example = value();
    else if (f == "--creature") a.creature = value();
    else if (f == "--character") a.character = value();
    else if (f == "--random") a.random = true;
    else if (f == "--seed") a.seed = static_cast<uint64_t>(parse_int(f, value(), 0, 1LL << 62));
    else if (f == "--size") {
      Result<SizeChoice> size = parse_size_arg(f, value());
      if (!size) fail(size.message());
      a.size = *size;
    }
    else if (f == "--level") a.level = value();
    else if (f == "--pixels-per-metre") a.pixels_per_metre = parse_scale(f, value());
    else if (f == "--script") a.script = value();
    else if (f == "--hz") a.hz = static_cast<int>(parse_int(f, value(), 30, 480));
    else if (f == "--count") a.count = static_cast<int>(parse_int(f, value(), 1, 100000));
    else if (f == "--threads") a.threads = static_cast<int>(parse_int(f, value(), 0, 1024));
    else if (f == "--prototypes") a.prototypes = value();
    else if (f == "--json") a.json = true;
    else if (f == "--trace") a.trace = value();
    else if (f == "--trace-joints") a.trace_joints = value();
    else if (f == "--svg") a.svg = value();
    else if (f == "--svg-window") parse_svg_window(f, value(), a);
    else fail("unknown option " + f + " (see --help)");
  }
  if (static_cast<int>(a.example.has_value()) + a.creature.has_value() + a.character.has_value() + a.random != 1) {
    fail("give exactly one of --example NAME, --creature F, --character F or --random");
  }
  if (a.size && a.character) fail("--size: a rigged character has the size its mesh gives; drop --size");
  if (!a.script) fail("--script: missing (e.g. --script \"walk:0.5:10,stop:2\")");
  return a;
}

struct Snapshot {
  std::vector<Mat2x3> world;
  std::vector<std::vector<glm::vec2>> outlines;  // the drawn body's parts (generated creatures)
};

std::string strobe_svg(const Skeleton& sk, const Level& level, const std::vector<Snapshot>& shots) {
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const Snapshot& s : shots) {
    for (int b = 0; b < sk.bone_count(); ++b) {
      const glm::vec2 p = bone_start(s.world[b]), q = bone_end(s.world[b], sk.length(b));
      lo = glm::min(lo, glm::min(p, q));
      hi = glm::max(hi, glm::max(p, q));
    }
    for (const std::vector<glm::vec2>& o : s.outlines) {
      for (const glm::vec2 p : o) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
  }
  lo -= glm::vec2(0.5f, 0.6f);
  hi += glm::vec2(0.5f, 0.4f);
  const float scale = 200.0f;  // px per metre
  const float w = (hi.x - lo.x) * scale, h = (hi.y - lo.y) * scale;
  std::string out;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.1f %.1f\">\n"
                "<rect width=\"100%%\" height=\"100%%\" fill=\"#eef3f7\"/>\n<g transform=\"translate(%.2f %.2f) scale(%.2f %.2f)\">\n",
                w, h, w, h, -lo.x * scale, hi.y * scale, scale, -scale);
  out += buf;
  for (const Box& b : level.colliders()) {
    if (b.max_ws.x < lo.x || b.min_ws.x > hi.x || b.max_ws.y < lo.y || b.min_ws.y > hi.y) continue;
    const Box v{glm::max(b.min_ws, lo), glm::min(b.max_ws, hi)};
    std::snprintf(buf, sizeof buf, "<rect x=\"%.4f\" y=\"%.4f\" width=\"%.4f\" height=\"%.4f\" fill=\"#8a7f6e\" stroke=\"#5b5346\" stroke-width=\"0.01\"/>\n",
                  v.min_ws.x, v.min_ws.y, v.width(), v.height());
    out += buf;
  }
  for (size_t i = 0; i < shots.size(); ++i) {
    const float opacity = 0.25f + 0.75f * static_cast<float>(i + 1) / static_cast<float>(shots.size());
    std::snprintf(buf, sizeof buf, "<g opacity=\"%.2f\" stroke-linecap=\"round\">\n", opacity);
    out += buf;
    for (const std::vector<glm::vec2>& o : shots[i].outlines) {
      out += "<polygon fill=\"#d9a066\" fill-opacity=\"0.25\" stroke=\"#6b3d12\" stroke-width=\"0.006\" points=\"";
      for (const glm::vec2 p : o) {
        std::snprintf(buf, sizeof buf, "%.4f,%.4f ", p.x, p.y);
        out += buf;
      }
      out += "\"/>\n";
    }
    for (int layer = 0; layer < kLayerCount; ++layer) {
      for (int b = 0; b < sk.bone_count(); ++b) {
        if (static_cast<int>(sk.layer(b)) != layer || sk.length(b) <= 0.0f) continue;
        const glm::vec2 p = bone_start(shots[i].world[b]), q = bone_end(shots[i].world[b], sk.length(b));
        const char* colour = layer == 0 ? "#7d7565" : layer == 1 ? "#c9b98f" : "#e9dcb8";
        std::snprintf(buf, sizeof buf, "<line x1=\"%.4f\" y1=\"%.4f\" x2=\"%.4f\" y2=\"%.4f\" stroke=\"%s\" stroke-width=\"%.4f\"/>\n",
                      p.x, p.y, q.x, q.y, colour, std::max(0.35f * sk.width(b), 0.008f));
        out += buf;
      }
    }
    out += "</g>\n";
  }
  out += "</g>\n</svg>\n";
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse_args(argc, argv);
  Result<std::vector<ScriptSegment>> script = parse_script(*args.script);
  if (!script) fail(script.message());

  const std::string level_path = args.level ? *args.level : data_path("levels/default.json");
  LevelLoadOptions level_options;
  level_options.pixels_per_metre = args.pixels_per_metre;
  LevelLoadReport level_report;
  Result<Level> level = load_level(level_path, level_options, &level_report);
  if (!level) fail(level.message());
  // No output may be one of the inputs (io/file.h).
  {
    std::vector<std::string> inputs = level_report.files;
    for (const auto* in : {&args.creature, &args.character, &args.prototypes}) {
      if (*in) inputs.push_back(**in);
    }
    if (args.trace) {
      if (Status st = check_output_path("--trace", *args.trace, inputs); !st) fail(st.message());
    }
    if (args.trace_joints) {
      if (Status st = check_output_path("--trace-joints", *args.trace_joints, inputs); !st) fail(st.message());
    }
    if (args.svg) {
      if (Status st = check_output_path("--svg", *args.svg, inputs); !st) fail(st.message());
    }
  }
  for (const std::string& w : level_warnings(*level)) std::fprintf(stderr, "warning: %s: %s\n", level_path.c_str(), w.c_str());

  SplinePrototypes prototypes = SplinePrototypes::defaults();
  const std::string proto_path = args.prototypes ? *args.prototypes : data_path("assets/animation/prototypes.json");
  std::error_code exists_error;
  if (args.prototypes || std::filesystem::exists(proto_path, exists_error)) {
    Result<SplinePrototypes> p = load_prototypes(proto_path);
    if (!p) fail(p.message());
    prototypes = *p;
  }

  std::shared_ptr<const Creature> creature;
  std::shared_ptr<const Character> character;
  if (args.character) {
#if OSSA_SIM_CHARACTERS
    Result<LoadedCharacter> loaded = load_character(*args.character);
    if (!loaded) fail(loaded.message());
    character = loaded->character;
#else
    fail("--character: this ossa-sim was built without Assimp (ossa::render), which reads the mesh");
#endif
  } else {
    Genome genome;
    std::optional<Generator> gen;
    if (!args.creature || args.size) {
      Result<Generator> g = Generator::load(data_path("assets/creatures/examples.json"), ossa::body_volume_m3);
      if (!g) fail(g.message());
      gen.emplace(std::move(*g));
    }
    GenerateOptions options;
    if (args.size) args.size->apply_to(options.genome);
    if (args.creature) {
      Result<Genome> g = load_genome(*args.creature);
      if (!g) fail(g.message());
      genome = *g;
      if (args.size) {  // resized: its scale made again for the size asked for
        args.size->apply_to(genome.options);
        gen->apply_size(genome);
      }
    } else if (args.example) {
      Result<Genome> g = gen->example(*args.example, 1, options);
      if (!g) fail(g.message());
      genome = *g;
    } else {
      genome = gen->random(args.seed, options);
    }
    Result<Creature> built = build_creature(genome);
    if (!built) fail((args.creature ? *args.creature + ": " : std::string()) + built.message());
    creature = std::make_shared<const Creature>(std::move(*built));
  }
  // Every creature of --count shares one rig (a character's rig is shared already).
  RigCache rigs;
  auto make_entity = [&]() -> std::unique_ptr<Entity> {
    if (character) return std::make_unique<Player>(character, prototypes);
    return std::make_unique<Player>(creature, rigs.rig(creature), prototypes);
  };

  std::unique_ptr<Entity> player_ptr = make_entity();
  Entity& player = *player_ptr;
  const glm::vec2 spawn = level->spawn_ws + glm::vec2(0.0f, 1.0f);
  player.animator().reset(spawn, *level);
  // Extra creatures for --count walk the same script in lock-step beside the first.
  std::vector<std::unique_ptr<Entity>> extra;
  std::vector<Entity*> extra_list;
  for (int i = 1; i < args.count; ++i) {
    extra.push_back(make_entity());
    extra.back()->animator().reset(spawn, *level);
    extra_list.push_back(extra.back().get());
  }
  std::vector<Controls> extra_step_controls(extra.size());

  // Outputs stay bounded: a trace row per tick and an SVG pose per strobe step are counted
  // before the run, and a run that would write more is refused with what to change.
  {
    const long long ticks = script_ticks(*script, args.hz);
    if (args.trace && ticks > kMaxTraceTicks) {
      fail("--trace: the script runs " + std::to_string(ticks) + " ticks at " + std::to_string(args.hz) +
           " Hz; a trace holds at most " + std::to_string(kMaxTraceTicks) + " (one row per tick, about 100 bytes per leg); "
           "shorten the script or lower --hz");
    }
    if (args.trace_joints && ticks > kMaxJointTraceTicks) {
      fail("--trace-joints: the script runs " + std::to_string(ticks) + " ticks at " + std::to_string(args.hz) +
           " Hz; a joint trace holds at most " + std::to_string(kMaxJointTraceTicks) +
           " (one row per tick, about 20 bytes per joint); shorten the script or lower --hz");
    }
    if (args.svg) {
      const double seconds = static_cast<double>(ticks) / args.hz;
      const double window = std::max(0.0, std::min<double>(args.svg_to, seconds) - args.svg_from);
      const double every = static_cast<double>(std::max(1LL, std::llround(static_cast<double>(args.svg_every) * args.hz))) / args.hz;
      const long long poses = static_cast<long long>(window / every) + 1;
      if (poses > kMaxSvgPoses) {
        char what[256];
        std::snprintf(what, sizeof what,
                      "--svg: %lld poses (%g s, one every %g s); an SVG holds at most %lld: narrow --svg-window FROM:TO "
                      "or draw fewer with :EVERY",
                      poses, window, every, kMaxSvgPoses);
        fail(what);
      }
    }
  }
  std::ofstream trace;
  if (args.trace) {
    trace.open(*args.trace);
    if (!trace) fail(*args.trace + ": cannot open for writing");
    trace << "t,x,root_y,gait,mode";
    for (int i = 0; i < player.animator().leg_count(); ++i) {
      trace << ",foot" << i << "_x,foot" << i << "_y,foot" << i << "_stance,target" << i << "_x,target" << i << "_y";
    }
    trace << "\n";
  }
  // The joint trace: every bone's joint, and the far end of every bone no other bone starts at
  // (a leaf: the skull's tip, the tail's, a toe's), in world space.
  std::ofstream joints;
  std::vector<uint8_t> leaf;
  if (args.trace_joints) {
    joints.open(*args.trace_joints);
    if (!joints) fail(*args.trace_joints + ": cannot open for writing");
    const Skeleton& sk = player.animator().rig().skeleton;
    leaf.assign(static_cast<size_t>(sk.bone_count()), 1);
    for (int b = 0; b < sk.bone_count(); ++b) {
      if (sk.parent(b) >= 0) leaf[static_cast<size_t>(sk.parent(b))] = 0;
    }
    joints << "t";
    for (int b = 0; b < sk.bone_count(); ++b) joints << "," << sk.name(b) << "_x," << sk.name(b) << "_y";
    for (int b = 0; b < sk.bone_count(); ++b) {
      if (leaf[static_cast<size_t>(b)]) joints << "," << sk.name(b) << ".end_x," << sk.name(b) << ".end_y";
    }
    joints << "\n";
  }
  const long long total_ticks = script_ticks(*script, args.hz);
  const long long shot_every = std::max(1LL, std::llround(static_cast<double>(args.svg_every) * args.hz));
  // The pose after tick k is the creature at (k + 1) / hz seconds, the time the metrics stamp
  // (deepest_at_s, deepest_outline_at_s): a window from such a time draws that pose. The
  // strobe's poses count from the window's first one (a window between two multiples of EVERY
  // still has its poses).
  const long long shot_from =
      std::max(0LL, static_cast<long long>(std::ceil(static_cast<double>(args.svg_from) * args.hz - 1e-6)) - 1);
  std::vector<Snapshot> shots;
  double extra_seconds = 0.0;
  const float dt = 1.0f / static_cast<float>(args.hz);
  // Controls of the extra creatures follow the player's script tick by tick, computed as they
  // go (a long script is not stored tick by tick).
  ScriptCursor extra_controls(*script, args.hz);
  // The drawn body's outline against the level, for --json (a generated creature's; a rigged
  // character has no generated body).
  std::optional<OutlineProbe> outline;
  if (creature && (args.json || args.svg)) outline.emplace(*creature);
  const SimResult result = run_script(player, *level, *script, args.hz, [&](long long tick) {
    const Animator& a = player.animator();
    if (outline) outline->observe(a, *level, static_cast<float>(tick + 1) * dt);
    if (!extra.empty()) {
      const Controls c = extra_controls.next();
      const auto start = std::chrono::steady_clock::now();
      std::fill(extra_step_controls.begin(), extra_step_controls.end(), c);
      step_all(extra_list, extra_step_controls, dt, *level, args.threads);
      extra_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    if (trace.is_open()) {
      trace << tick * dt << "," << a.x() << "," << bone_start(a.world_matrices()[a.rig().root]).y << ","
            << gait_name(a.gait()) << "," << locomotion_name(a.locomotion());
      for (int i = 0; i < a.leg_count(); ++i) {
        const glm::vec2 f = a.foot_ws(i);
        trace << "," << f.x << "," << f.y << "," << (a.leg_state(i) == LegState::kStance ? 1 : 0) << "," << a.foot_target_ws(i).x << "," << a.foot_target_ws(i).y;
      }
      trace << "\n";
    }
    if (joints.is_open()) {
      const std::vector<Mat2x3>& w = a.world_matrices();
      const Skeleton& sk = a.rig().skeleton;
      joints << (tick + 1) * dt;
      for (int b = 0; b < sk.bone_count(); ++b) joints << "," << w[b].m[4] << "," << w[b].m[5];
      for (int b = 0; b < sk.bone_count(); ++b) {
        if (!leaf[static_cast<size_t>(b)]) continue;
        const glm::vec2 e = bone_end(w[b], sk.length(b));
        joints << "," << e.x << "," << e.y;
      }
      joints << "\n";
    }
    const float t = static_cast<float>(tick + 1) * dt;
    if (args.svg && tick >= shot_from && t <= args.svg_to && (tick - shot_from) % shot_every == 0) shots.push_back({a.world_matrices(), outline ? outline->drawn_outlines() : std::vector<std::vector<glm::vec2>>{}});
  });
  const SimProbe& probe = result.probe;
  const std::vector<SegmentMetrics>& segments = result.segments;
  const Animator& a = player.animator();
  const double update_seconds = result.update_seconds + extra_seconds;
  const long long updates = total_ticks * args.count;
  if (args.svg) {
    if (shots.empty()) {
      char msg[160];
      std::snprintf(msg, sizeof msg, "--svg-window: no pose between %g and %g s (the script runs %g s)", args.svg_from, args.svg_to,
                    static_cast<double>(total_ticks) / args.hz);
      fail(msg);
    }
    if (Status s = write_file_atomic(*args.svg, strobe_svg(player.skeleton(), *level, shots)); !s) fail(s.message());
  }
  if (args.json) {
    Json out;
    out["creature"] = player.name();
    if (character) out["character"] = *args.character;
    out["level"] = level_path;
    out["hz"] = args.hz;
    Json segs = Json::array();
    for (const SegmentMetrics& m : segments) {
      segs.push_back({{"command", m.command},       {"commanded_speed", m.commanded_speed},
                      {"mean_speed", m.mean_speed}, {"speed_error", m.speed_error},
                      {"stride_length", m.stride_length}, {"cycle_frequency", m.cycle_frequency},
                      {"duty_factor", m.duty_factor}, {"froude", m.froude},
                      {"gait", m.gait},             {"flight_phase", m.flight_phase},
                      {"airborne_s", m.airborne_s}, {"max_body_jolt_g", m.max_body_jolt_g},
                      {"blocked", m.blocked},  // why it stood blocked at the segment's end, or ""
                      {"gait_family", m.gait_family},  // "" until the gait families land (gait_family_label)
                      // Measured from the feet and the root as simulated (GaitMeasure); null: not applicable
                      {"footfall_sequence", m.measured.footfall_sequence}, {"limb_phase", m.measured.limb_phase},
                      {"hind_pair_phase", m.measured.hind_pair_phase}, {"fore_pair_phase", m.measured.fore_pair_phase},
                      {"measured_duty_factor", m.measured.duty_factor}, {"strides", m.measured.strides},
                      {"suspensions_per_stride", m.measured.suspensions_per_stride},
                      {"suspension_fraction", m.measured.suspension_fraction},
                      {"vertical_excursion", m.measured.vertical_excursion}, {"bobs_per_stride", m.measured.bobs_per_stride}});
    }
    out["segments"] = segs;
    // Per leg: the hip, knee and ankle angles (degrees, 180 in line; least, largest, mean) in stance and swing, and
    // the contact the foot stands on (SimProbe::joint_angles).
    Json legs = Json::array();
    for (size_t i = 0; i < probe.joint_angles.size() && i < a.rig().legs.size(); ++i) {
      const SimProbe::LegJointAngles& j = probe.joint_angles[i];
      auto phase = [](const std::array<SimProbe::AngleStats, 3>& s) {
        Json o;
        const char* names[3] = {"hip", "knee", "ankle"};
        for (size_t k = 0; k < 3; ++k) {
          o[names[k]] = s[k].count > 0 ? Json{{"min", s[k].min}, {"max", s[k].max}, {"mean", s[k].mean()}} : Json();
        }
        return o;
      };
      legs.push_back({{"leg", a.rig().skeleton.name(a.rig().legs[i].bones[0])},
                      {"contact", a.rig().flat_contact ? "flat" : "tip"},
                      {"stance", phase(j.stance)},
                      {"swing", phase(j.swing)}});
    }
    out["joint_angles"] = legs;
    out["max_stance_slip_m"] = probe.max_stance_slip_m;
    out["max_stance_gap_m"] = probe.max_stance_gap_m;  // a standing foot short of its foothold
    // The worst over everything (issue 27): every bone, and the drawn body's outline where the
    // creature has one; the bones' alone in max_bone_penetration_m.
    out["max_penetration_m"] = outline ? std::max(probe.max_penetration_m, outline->max_outline_penetration_m) : probe.max_penetration_m;
    out["max_bone_penetration_m"] = probe.max_penetration_m;
    out["max_limb_penetration_m"] = probe.max_limb_penetration_m;
    out["max_body_penetration_m"] = probe.max_body_penetration_m;
    out["deepest_bone"] = probe.deepest_bone;
    out["deepest_at_s"] = probe.deepest_at_s;
    // The drawn body's outline (outline_probe.h; null for a rigged character).
    out["max_outline_penetration_m"] = outline ? Json(outline->max_outline_penetration_m) : Json();
    out["deepest_outline_part"] = outline ? Json(outline->deepest_outline_part) : Json();
    out["deepest_outline_at_s"] = outline ? Json(outline->deepest_outline_at_s) : Json();
    out["max_body_jolt_g"] = probe.max_body_jolt_g;
    out["max_limb_flick"] = probe.max_limb_flick;  // SimProbe: limb flicks
    out["limb_flick_at_s"] = probe.limb_flick_at_s;
    out["limb_flicks"] = probe.limb_flicks;
    out["min_swing_clearance_m"] = probe.min_swing_clearance_m > 1e8f ? 0.0f : probe.min_swing_clearance_m;
    out["steps"] = a.steps();
    out["x_reached"] = result.x_reached;  // the final x (SimResult::x_reached)
    out["x_max_m"] = result.x_max_m;
    out["blocked_s"] = result.blocked_s;
    const anim::LocomotionStats& loco = result.locomotion;
    out["falls"] = loco.falls;
    out["jumps"] = loco.jumps;
    out["max_fall_m"] = loco.max_fall_m;
    out["max_jump_height_m"] = loco.max_jump_height_m;
    out["airborne_s"] = loco.airborne_s;
    out["hard_landings"] = loco.hard_landings;
    out["respawns"] = loco.respawns;
    out["hip_height_m"] = a.hip_height();
    out["nan_count"] = probe.nan_count;
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(probe.pose_hash));
    out["pose_hash"] = hash;
    if (args.count > 1) {
      out["count"] = args.count;
      out["threads"] = resolve_threads(args.threads);
      uint64_t herd = pose_hash({});
      for (const auto& e : extra) herd = pose_hash(e->animator().world_matrices(), herd);
      std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(herd));
      out["herd_pose_hash"] = hash;
      out["update_us_per_creature"] = 1e6 * update_seconds / static_cast<double>(updates);
    }
    std::printf("%s\n", json_text(out, 2).c_str());
  } else {
    // A creature that ends a segment blocked says why (a step too high for a small one).
    for (const SegmentMetrics& m : segments) {
      if (!m.blocked.empty()) std::printf("%s: %s\n", m.command.c_str(), m.blocked.c_str());
    }
  }
  return 0;
}
