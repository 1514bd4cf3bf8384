// Replays and long scripts under issue 33's rules: memory in proportion to the file, 64-bit
// tick counts, spawns within the level bound, deep documents and non-UTF-8 paths that never
// crash.

#include "ossa/game/replay.h"
#include "ossa/game/sim.h"
#include "ossa/io/file.h"

#include <catch2/catch.hpp>

#include <climits>
#include <filesystem>

using namespace ossa;
namespace fs = std::filesystem;

namespace {

std::string replay_text(const std::string& ticks, const std::string& spawn = "[1, 2]",
                        const std::string& creature = R"({"format":"ossa.creature"})") {
  return R"({"format":"ossa.replay","version":2,"tick_hz":120,"level":"l.json","spawn":)" + spawn +
         R"(,"facing":1,"creature":)" + creature + R"(,"ticks":)" + ticks + "}";
}

Result<Replay> parse_replay(const std::string& text) {
  Result<Json> doc = parse_json(text, "r.replay.json");
  if (!doc) return doc.error();
  return replay_from_json(*doc, "r.replay.json");
}

}  // namespace

TEST_CASE("a replay keeps its runs: a day of ticks in one run takes one run of memory", "[game][replay]") {
  // It used to expand every run tick by tick: 41 472 000 Controls from a 200-byte file.
  Result<Replay> r = parse_replay(replay_text("[[41472000, 0.5, 0, 0]]"));
  REQUIRE(r.ok());
  CHECK(r->runs.size() == 1);
  CHECK(r->tick_count() == kMaxReplayTicks);
  CHECK_THAT(parse_replay(replay_text("[[41472000, 0.5, 0, 0], [1, 0, 0, 0]]")).message(),
             Catch::Contains("ticks[1]: expected at most 41472000 ticks in all"));
  CHECK_THAT(parse_replay(replay_text("[[2.5, 0.5, 0, 0]]")).message(), Catch::Contains("ticks[0][0]: expected a whole number of ticks"));
}

TEST_CASE("recording and playing a replay give the same ticks", "[game][replay]") {
  Replay rec;
  const Controls a{0.5f, false, false}, b{1.0f, true, false}, c{1.0f, true, true};
  for (const Controls& t : {a, a, a, b, c, c, a}) rec.push(t);
  CHECK(rec.runs.size() == 4);
  CHECK(rec.tick_count() == 7);
  rec.creature = Json::object();
  Result<Replay> back = replay_from_json(replay_to_json(rec), "x");
  REQUIRE(back.ok());
  ReplayCursor cursor(&*back);
  std::vector<Controls> played;
  while (!cursor.done()) played.push_back(cursor.next());
  CHECK(played == std::vector<Controls>{a, a, a, b, c, c, a});
  CHECK(cursor.ticks_played() == 7);
  CHECK(ReplayCursor().done());
}

TEST_CASE("a replay's spawn lies within the level bound", "[game][replay]") {
  Result<Replay> far = parse_replay(replay_text("[[1, 0, 0, 0]]", "[1000000, 0]"));
  REQUIRE_FALSE(far.ok());
  CHECK(far.message() == "r.replay.json: spawn[0]: expected a number in [-1000, 1000], got 1000000");
  CHECK(parse_replay(replay_text("[[1, 0, 0, 0]]", "[-1000, 1000]")).ok());
}

TEST_CASE("a replay whose creature is nested 300 000 deep is refused, not a crash", "[game][replay]") {
  const fs::path dir = fs::temp_directory_path() / "ossa_replay_deep_test";
  fs::create_directories(dir);
  const std::string path = (dir / "deep.replay.json").string();
  REQUIRE(write_file_atomic(path, replay_text("[[1, 0, 0, 0]]", "[0, 0]", "{\"a\":" + std::string(300000, '[') +
                                                                            std::string(300000, ']') + "}")).ok());
  Result<Replay> r = load_replay(path);
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::StartsWith(path + ": creature.a"));
  CHECK_THAT(r.message(), Catch::Contains("nested more than 256"));
  fs::remove_all(dir);
}

TEST_CASE("a replay recorded on a level whose name is not UTF-8 is still saved", "[game][replay]") {
  // Stopping a recording threw json type_error 316 out of the game loop.
  const fs::path dir = fs::temp_directory_path() / "ossa_replay_bytes_test";
  fs::create_directories(dir);
  Replay rec;
  rec.level = (dir / "caf\xe9.json").string();  // Latin-1, as an old file system wrote it
  rec.creature = Json::object();
  rec.push({0.5f, false, false});
  const std::string path = (dir / "r\xe9.replay.json").string();
  REQUIRE(save_replay(path, rec).ok());
  Result<Replay> back = load_replay(path);
  REQUIRE(back.ok());
  CHECK(back->level == (dir / "caf\xEF\xBF\xBD.json").string());
  fs::remove_all(dir);
}

TEST_CASE("long scripts count ticks in 64 bits and stream their controls", "[game][sim]") {
  // Thirteen walk:0.5:86400 at 480 Hz built 539 M controls up front (and sixty overflow an int).
  std::string text;
  for (int i = 0; i < 60; ++i) text += std::string(i ? "," : "") + (i % 2 ? "run:1:86400" : "walk:0.5:86400");
  Result<std::vector<ScriptSegment>> script = parse_script(text);
  REQUIRE(script.ok());
  CHECK(script_ticks(*script, 480) == 60LL * 86400 * 480);
  CHECK(script_ticks(*script, 480) > INT_MAX);
  // The cursor gives what run_script applies, tick by tick, across segment ends.
  Result<std::vector<ScriptSegment>> small = parse_script("walk:0.5:0.02,jump,stop:0.01,run:-1:0.02");
  REQUIRE(small.ok());
  ScriptCursor cursor(*small, 100);
  std::vector<Controls> got;
  for (int i = 0; i < 7; ++i) got.push_back(cursor.next());
  const Controls walk{0.5f, false, false}, jump{0.5f, false, true}, stop{0.0f, false, false}, run{-1.0f, true, false};
  CHECK(got == std::vector<Controls>{walk, walk, jump, stop, run, run, run});
}
