#include "ossa/game/replay.h"

#include "ossa/io/file.h"

namespace ossa {

namespace {
constexpr const char* kFormat = "ossa.replay";
constexpr int kVersion = 2;
constexpr long long kMaxTicks = 480LL * 3600 * 24;  // a day at the highest tick rate
}  // namespace

Json replay_to_json(const Replay& r) {
  Json runs = Json::array();
  for (size_t i = 0; i < r.ticks.size();) {
    size_t j = i + 1;
    while (j < r.ticks.size() && r.ticks[j] == r.ticks[i]) ++j;
    runs.push_back({j - i, r.ticks[i].move_x, r.ticks[i].run ? 1 : 0, r.ticks[i].jump ? 1 : 0});
    i = j;
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
      out.spawn_ws = {static_cast<float>(r.as_number((*spawn)[0], "spawn[0]", -1e6, 1e6)),
                      static_cast<float>(r.as_number((*spawn)[1], "spawn[1]", -1e6, 1e6))};
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
      const double count = r.as_number(run[0], json_path(path, 0), 1, static_cast<double>(kMaxTicks));
      const double move = r.as_number(run[1], json_path(path, 1), -1.0, 1.0);
      const double run_flag = r.as_number(run[2], json_path(path, 2), 0.0, 1.0);
      const double jump_flag = columns == 4 ? r.as_number(run[3], json_path(path, 3), 0.0, 1.0) : 0.0;
      if (r.failed()) break;
      total += static_cast<long long>(count);
      if (total > kMaxTicks) {
        r.fail(path, "expected at most " + std::to_string(kMaxTicks) + " ticks in all");
        break;
      }
      out.ticks.insert(out.ticks.end(), static_cast<size_t>(count),
                       Controls{static_cast<float>(move), run_flag >= 0.5, jump_flag >= 0.5});
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
