// Level files: round trips, shipped levels, and bad input naming the file and field.

#include "ossa/level/level_io.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/math/rng.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace ossa;

namespace {

Level random_float_level(uint64_t seed, int n) {
  Rng rng(seed);
  std::vector<Box> boxes;
  for (int i = 0; i < n; ++i) {
    // Arbitrary floats, not short decimals: the writer must still round-trip them exactly.
    const float x = static_cast<float>(rng.uniform(-950.0, 950.0));  // within kMaxLevelCoordinate
    const float y = static_cast<float>(rng.uniform(-50.0, 50.0));
    const float w = static_cast<float>(rng.uniform(1e-3, 30.0));
    const float h = static_cast<float>(rng.uniform(1e-3, 5.0));
    boxes.push_back(Box::from_corner(x, y, w, h));
  }
  Level level(std::move(boxes), {static_cast<float>(rng.uniform(-3.0, 3.0)), 0.1f}, "random \"level\"");
  if (seed % 2 == 0) {
    level.background = Background{"backgrounds/hills.png", 0.3f, {0.1f, 0.2f, 0.3f}};
  }
  return level;
}

std::string message_of(std::string_view text) {
  Result<Level> r = parse_level(text, "levels/x.json");
  REQUIRE_FALSE(r.ok());
  return r.message();
}

}  // namespace

TEST_CASE("level files round-trip exactly", "[level][io]") {
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const Level level = random_float_level(seed, 200);
    Result<Level> back = parse_level(level_to_text(level), "mem");
    REQUIRE(back.ok());
    CHECK(*back == level);
    Result<Level> back2 = level_from_json(level_to_json(level), "mem");
    REQUIRE(back2.ok());
    CHECK(*back2 == level);
  }
  // Through a file.
  const std::string path = (std::filesystem::temp_directory_path() / "ossa_level_io_test.json").string();
  const Level level = scenes::stairs_level(5, 0.17f, 0.31f);
  REQUIRE(save_level(path, level).ok());
  Result<Level> loaded = load_level(path);
  REQUIRE(loaded.ok());
  CHECK(*loaded == level);
  // Short decimals stay short in the text.
  CHECK_THAT(level_to_text(level), Catch::Contains("\"h\":1.17") && !Catch::Contains("0000000"));
  std::filesystem::remove(path);
}

TEST_CASE("a hand-written level loads with defaults", "[level][io]") {
  Result<Level> r = parse_level(R"({"format":"ossa.level","version":1,"spawn":{"x":1,"y":0},
      "colliders":[{"x":0.1,"y":-1,"w":0.2,"h":1}], "future_field": 3})", "f.json");
  REQUIRE(r.ok());
  CHECK(r->name.empty());
  CHECK_FALSE(r->background);
  REQUIRE(r->size() == 1);
  CHECK(r->box(0).min_ws.x == 0.1f);
  CHECK(r->box(0).max_ws.x == 0.3f);  // float(0.1 + 0.2), one rounding
  CHECK(r->box(0).max_ws.y == 0.0f);
  Result<Level> bg = parse_level(R"({"format":"ossa.level","version":1,"spawn":{"x":1,"y":0},
      "background":{"parallax":0.25},"colliders":[]})", "f.json");
  REQUIRE(bg.ok());
  REQUIRE(bg->background);
  CHECK(bg->background->parallax == 0.25f);
  CHECK(bg->background->image.empty());
}

TEST_CASE("bad level files give errors naming the file and field", "[level][io]") {
  const std::string head = R"({"format":"ossa.level","version":1,"spawn":{"x":1,"y":0},)";
  CHECK(message_of(head + R"("colliders":[{"x":0,"y":0,"w":1,"h":1},{"x":0,"y":0,"w":1,"h":1},
      {"x":0,"y":0,"w":1,"h":1},{"x":0,"y":0,"w":-2,"h":1}]})") ==
        "levels/x.json: colliders[3].w: expected a number > 0, got -2");
  CHECK(message_of(head + R"("colliders":[{"x":0,"y":0,"w":1,"h":0}]})") ==
        "levels/x.json: colliders[0].h: expected a number > 0, got 0");
  CHECK(message_of(head + R"("colliders":[{"x":0,"y":0,"w":1}]})") ==
        "levels/x.json: colliders[0].h: missing (required field)");
  CHECK(message_of(head + R"("colliders":[{"x":"0","y":0,"w":1,"h":1}]})") ==
        "levels/x.json: colliders[0].x: expected a number in [-1000, 1000], got a string \"0\"");
  // JSON text cannot hold NaN or infinity (the parser rejects 1e999), but a document built in
  // code can.
  CHECK_THAT(message_of(head + R"("colliders":[{"x":1e999,"y":0,"w":1,"h":1}]})"),
             Catch::Contains("not valid JSON"));
  {
    Json doc = level_to_json(scenes::flat_level(3.0f));
    doc["colliders"][0]["w"] = std::numeric_limits<double>::quiet_NaN();
    // (describe_json prints NaN and infinity as null, as nlohmann's dump does.)
    CHECK_THAT(level_from_json(doc, "n.json").message(),
               Catch::StartsWith("n.json: colliders[0].w: expected a finite number, got "));
    doc["colliders"][0]["w"] = 1.0;
    doc["colliders"][0]["y"] = -std::numeric_limits<double>::infinity();
    CHECK_THAT(level_from_json(doc, "n.json").message(),
               Catch::StartsWith("n.json: colliders[0].y: expected a number in [-1000, 1000], got "));
  }
  CHECK(message_of(head + R"("colliders":[{"x":0,"y":0,"w":2e6,"h":1}]})") ==
        "levels/x.json: colliders[0].w: expected a number <= 2000, got 2000000.0");
  CHECK(message_of(head + R"("colliders":[{"x":999,"y":0,"w":1e-9,"h":1}]})") ==
        "levels/x.json: colliders[0].w: too small to be represented at x = 999.000000");
  // Coordinates stay where a float keeps 0.1 mm: far edges too (a level near x = 999 000
  // slipped feet by 8.7 mm from rounding alone).
  CHECK(message_of(head + R"("colliders":[{"x":990,"y":0,"w":20,"h":1}]})") ==
        "levels/x.json: colliders[0].w: puts the box's far edge at 1010.000000, expected at most 1000 m from "
        "the origin (beyond it a float cannot keep 0.1 mm)");
  CHECK(message_of(R"({"format":"ossa.level","version":1,"spawn":{"x":999000,"y":0},"colliders":[]})") ==
        "levels/x.json: spawn.x: expected a number in [-1000, 1000], got 999000");
  // A key given twice is an error, not "the last one wins" (which emptied the level).
  CHECK(message_of(head + R"("colliders":[{"x":0,"y":0,"w":1,"h":1}],"colliders":[]})") ==
        "levels/x.json: colliders: duplicate key (a key may appear only once in an object)");
  CHECK(message_of(head + R"("colliders":[3]})") ==
        "levels/x.json: colliders[0]: expected an object, got 3");
  CHECK(message_of(head + R"("colliders":{}})") ==
        "levels/x.json: colliders: expected an array, got an object");
  CHECK(message_of(head + "\"x\":1}") == "levels/x.json: colliders: missing (required field)");
  CHECK(message_of(R"({"format":"ossa.level","version":2,"spawn":{"x":1,"y":0},"colliders":[]})") ==
        "levels/x.json: version: expected an integer in [1, 1], got 2");
  CHECK(message_of(R"({"format":"ossa.lvl","version":1})") ==
        "levels/x.json: format: expected \"ossa.level\", got a string \"ossa.lvl\"");
  CHECK(message_of(R"({"version":1})") == "levels/x.json: format: missing (required field)");
  CHECK_THAT(message_of(R"({"orientation":"orthogonal","layers":[]})"), Catch::Contains("Tiled map"));
  CHECK(message_of(R"({"format":"ossa.level","version":1,"colliders":[]})") ==
        "levels/x.json: spawn: missing (required field)");
  CHECK(message_of(R"({"format":"ossa.level","version":1,"spawn":{"x":1,"y":true},"colliders":[]})") ==
        "levels/x.json: spawn.y: expected a number in [-1000, 1000], got true");
  CHECK(message_of(head + R"("background":{"colour":[1,0]},"colliders":[]})") ==
        "levels/x.json: background.colour: expected an array of 3 numbers (r, g, b), got 2 elements");
  CHECK(message_of(head + R"("background":{"colour":[1,0,2]},"colliders":[]})") ==
        "levels/x.json: background.colour[2]: expected a number in [0, 1], got 2");
  CHECK(message_of(head + R"("background":{"parallax":-1},"colliders":[]})") ==
        "levels/x.json: background.parallax: expected a number in [0, 1], got -1");
  CHECK(message_of(head + R"("name":7,"colliders":[]})") == "levels/x.json: name: expected a string, got 7");
  CHECK(message_of("[1,2]") == "levels/x.json: (document): expected an object, got an array");
  CHECK_THAT(message_of("{\"format\":"), Catch::StartsWith("levels/x.json: not valid JSON at line 1"));
  CHECK_THAT(load_level("/nonexistent/nope.json").message(), Catch::Contains("/nonexistent/nope.json"));
}

TEST_CASE("more than 1 000 000 colliders is an error", "[level][io]") {
  Json doc = level_to_json(scenes::flat_level(10.0f));
  Json box = doc["colliders"][0];
  doc["colliders"] = Json::array();
  for (int i = 0; i <= kMaxLevelColliders; ++i) doc["colliders"].push_back(box);
  Result<Level> r = level_from_json(doc, "big.json");
  REQUIRE_FALSE(r.ok());
  CHECK(r.message() == "big.json: colliders: expected at most 1000000 boxes, got 1000001");
}

TEST_CASE("shipped levels load and read as levels", "[level][io]") {
  for (const char* name : {"levels/default.json", "levels/stairs.json", "levels/rough.json"}) {
    INFO(name);
    Result<Level> r = load_level(scenes::source_path(name));
    REQUIRE(r.ok());
    const Level& level = *r;
    CHECK_FALSE(level.name.empty());
    CHECK(level.size() > 3);
    // The spawn stands on ground: a box top right below it, and nothing overlapping a
    // 1 m tall creature there.
    const auto g = level.ground_height_below(level.spawn_ws.x - 0.2f, level.spawn_ws.x + 0.2f,
                                             level.spawn_ws.y + 0.01f, 0.05f);
    REQUIRE(g);
    CHECK(g->height_ws == Approx(level.spawn_ws.y).margin(0.02));
    CHECK_FALSE(level.overlaps(Box::from_corner(level.spawn_ws.x - 0.3f, level.spawn_ws.y + 0.001f, 0.6f, 1.0f)));
    CHECK(level.bounds().width() > 20.0f);
    // Loading and saving gives the same text back (the files are in canonical form).
    Result<std::string> text = read_file(scenes::source_path(name));
    REQUIRE(text.ok());
    CHECK(level_to_text(level) == *text);
  }
}

namespace {
// Walks a level from the spawn to the right end wall in 5 cm steps, following the ground
// within a climbable step (0.25 m), and counts the gaps (no ground in reach) and walls (a
// box above a 0.25 m step in the way of a 1 m tall creature) met on the way.
struct Walk {
  int gaps = 0, walls = 0;
  float max_step = 0.0f;
};
Walk walk(const Level& level) {
  Walk w;
  float h = level.spawn_ws.y;
  bool in_gap = false, at_wall = false;
  const float end_x = level.bounds().max_ws.x - 0.5f;
  for (float x = level.spawn_ws.x; x < end_x; x += 0.05f) {
    const bool wall = level.overlaps(Box::from_corner(x - 0.05f, h + 0.26f, 0.1f, 0.74f));
    if (wall && !at_wall) ++w.walls;
    at_wall = wall;
    if (wall) continue;  // climb over it (tests only count it)
    const auto g = level.ground_height_below(x - 0.05f, x + 0.05f, h + 0.26f, 0.51f);
    if (!g && !in_gap) ++w.gaps;
    in_gap = !g;
    if (!g) continue;
    w.max_step = std::max(w.max_step, std::abs(g->height_ws - h));
    h = g->height_ws;
  }
  return w;
}
}  // namespace

TEST_CASE("shipped levels are walkable with steps of at most 0.25 m", "[level][io]") {
  const Walk d = walk(load_level(scenes::source_path("levels/default.json")).value());
  CHECK(d.gaps == 1);   // the gap
  CHECK(d.walls == 2);  // the 1.8 m wall and the end wall
  CHECK(d.max_step <= 0.2501f);
  for (const char* name : {"levels/stairs.json", "levels/rough.json"}) {
    INFO(name);
    const Walk w = walk(load_level(scenes::source_path(name)).value());
    CHECK(w.gaps == 0);
    CHECK(w.walls == 1);  // only the end wall
    CHECK(w.max_step <= 0.2501f);
    CHECK(w.max_step >= 0.05f);
  }
}

TEST_CASE("the kill height round-trips, defaults below the lowest box, and a bad one names the field", "[level][io]") {
  const std::string head = R"({"format":"ossa.level","version":1,"spawn":{"x":1,"y":0},"colliders":[{"x":0,"y":-1,"w":5,"h":1}])";
  const Result<Level> plain = parse_level(head + "}", "levels/x.json");
  REQUIRE(plain.ok());
  CHECK_FALSE(plain->kill_height_ws.has_value());
  CHECK(plain->kill_y() == Approx(-1.0f - Level::kKillMargin));  // kKillMargin below the lowest box
  const Result<Level> set = parse_level(head + R"(,"kill_height":-6.5})", "levels/x.json");
  REQUIRE(set.ok());
  CHECK(set->kill_y() == -6.5f);
  const Result<Level> again = parse_level(level_to_text(*set), "levels/y.json");
  REQUIRE(again.ok());
  CHECK(*again == *set);
  CHECK(message_of(head + R"(,"kill_height":"low"})") ==
        "levels/x.json: kill_height: expected a number in [-1000, 1000], got a string \"low\"");
  CHECK(message_of(head + R"(,"kill_height":5000})") == "levels/x.json: kill_height: expected a number in [-1000, 1000], got 5000");
}

TEST_CASE("level_warnings names a spawn with no ground below it", "[level][io]") {
  const Level over_gap({Box::from_corner(0.0f, -1.0f, 5.0f, 1.0f)}, {20.0f, 2.0f}, "gap");
  const std::vector<std::string> w = level_warnings(over_gap);
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::Contains("the spawn (20, 2) has no ground below it"));
  const Level fine({Box::from_corner(0.0f, -1.0f, 5.0f, 1.0f)}, {2.0f, 0.0f}, "fine");
  CHECK(level_warnings(fine).empty());
}
