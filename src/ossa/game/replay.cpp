#include "ossa/game/replay.h"

#include <cmath>

#include "ossa/io/file.h"
#include "ossa/level/level_io.h"

namespace ossa {

namespace {
constexpr const char* kFormat = "ossa.replay";
constexpr int kVersion = 2;
}  // namespace

void Replay::push(const Controls& c) {
  if (!runs.empty() && runs.back().controls == c) {
    ++runs.back().count;
  } else {
    runs.push_back({1, c});
  }
}

long long Replay::tick_count() const {
  long long n = 0;
  for (const ReplayRun& r : runs) n += r.count;
  return n;
}

bool ReplayCursor::done() const {
  if (!replay_) return true;
  size_t run = run_;
  long long used = used_;
  while (run < replay_->runs.size() && used >= replay_->runs[run].count) {
    ++run;
    used = 0;
  }
  return run >= replay_->runs.size();
}

Controls ReplayCursor::next() {
  OSSA_ASSERT(!done(), "ReplayCursor::next after the last tick");
  while (used_ >= replay_->runs[run_].count) {
    ++run_;
    used_ = 0;
  }
  ++used_;
  ++played_;
  return replay_->runs[run_].controls;
}

Json replay_to_json(const Replay& r) {
  Json runs = Json::array();
  for (const ReplayRun& run : r.runs) {
    if (run.count <= 0) continue;
    runs.push_back({run.count, run.controls.move_x, run.controls.run ? 1 : 0, run.controls.jump ? 1 : 0});
  }
  Json doc{{"format", kFormat}, {"version", kVersion}, {"tick_hz", r.tick_hz}, {"level", r.level},
           {"spawn", {r.spawn_ws.x, r.spawn_ws.y}}, {"facing", r.facing}, {"ticks", runs}};
  if (!r.character.empty()) {
    doc["character"] = r.character;
  } else {
    doc["creature"] = r.creature;
  }
  return doc;
}

Result<Replay> replay_from_json(const Json& doc, std::string_view file) {
  JsonReader r{std::string(file)};
  if (!r.expect_object(doc, "")) return r.error();
  const std::string format = r.string(doc, "", "format");
  if (!r.failed() && format != kFormat) r.fail("format", std::string("expected \"") + kFormat + "\", got \"" + format + "\"");
  const long long version = r.integer(doc, "", "version", 1, 1000000);
  if (!r.failed() && (version < 1 || version > kVersion)) {
    r.fail("version", "expected 1 to " + std::to_string(kVersion) + ", got " + std::to_string(version));
  }
  // Version 1 recorded no jump button: [count, move_x, run]; version 2 adds it.
  const size_t columns = version >= 2 ? 4 : 3;
  Replay out;
  out.tick_hz = static_cast<int>(r.integer(doc, "", "tick_hz", 30, 480));
  out.level = r.string_or(doc, "", "level", "");
  if (r.has(doc, "character")) {
    out.character = r.string(doc, "", "character");
    if (!r.failed() && out.character.empty()) r.fail("character", "expected a rig file (.rig.json), got an empty string");
    if (!r.failed() && r.has(doc, "creature")) r.fail("creature", "expected either a creature or a character, got both");
  } else if (const Json* c = r.object(doc, "", "creature")) {
    out.creature = *c;
  }
  if (const Json* spawn = r.array(doc, "", "spawn")) {
    if (spawn->size() != 2) {
      r.fail("spawn", "expected [x, y], got " + std::to_string(spawn->size()) + " numbers");
    } else {
      // Where a level's spawn may be (level_io.h): a spawn far out would walk where a float
      // cannot keep a planted foot still.
      out.spawn_ws = {static_cast<float>(r.as_number((*spawn)[0], "spawn[0]", -kMaxLevelCoordinate, kMaxLevelCoordinate)),
                      static_cast<float>(r.as_number((*spawn)[1], "spawn[1]", -kMaxLevelCoordinate, kMaxLevelCoordinate))};
    }
  }
  out.facing = r.integer_or(doc, "", "facing", 1, -1, 1) < 0 ? -1 : 1;
  if (const Json* runs = r.array(doc, "", "ticks")) {
    long long total = 0;
    for (size_t i = 0; i < runs->size() && !r.failed(); ++i) {
      const std::string path = json_path("ticks", i);
      const Json& run = (*runs)[i];
      if (!run.is_array() || run.size() != columns) {
        r.fail(path, std::string(columns == 4 ? "expected [count, move_x, run, jump]" : "expected [count, move_x, run]") +
                         ", got " + describe_json(run));
        break;
      }
      const double count = r.as_number(run[0], json_path(path, 0), 1, static_cast<double>(kMaxReplayTicks));
      const double move = r.as_number(run[1], json_path(path, 1), -1.0, 1.0);
      const double run_flag = r.as_number(run[2], json_path(path, 2), 0.0, 1.0);
      const double jump_flag = columns == 4 ? r.as_number(run[3], json_path(path, 3), 0.0, 1.0) : 0.0;
      if (r.failed()) break;
      if (count != std::floor(count)) {
        r.fail(json_path(path, 0), "expected a whole number of ticks, got " + describe_json(run[0]));
        break;
      }
      total += static_cast<long long>(count);
      if (total > kMaxReplayTicks) {
        r.fail(path, "expected at most " + std::to_string(kMaxReplayTicks) + " ticks in all");
        break;
      }
      out.runs.push_back({static_cast<long long>(count), Controls{static_cast<float>(move), run_flag >= 0.5, jump_flag >= 0.5}});
    }
  }
  if (r.failed()) return r.error();
  return out;
}

Result<Replay> load_replay(const std::string& path) {
  Result<Json> doc = read_json_file(path);
  if (!doc) return doc.error();
  return replay_from_json(*doc, path);
}

Status save_replay(const std::string& path, const Replay& replay) {
  return write_json_atomic(path, replay_to_json(replay));
}

}  // namespace ossa
