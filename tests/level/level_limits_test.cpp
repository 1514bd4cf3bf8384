// Levels under issue 33's rules: saves that load back at the ±1000 m edges, the kill height
// (cached, relative to the creature, below the spawn), maps whose cost is bounded per map,
// tile gids that do not wrap, UTF-16 files named as such, the files a load read, and
// level-relative resources that stay in the level's folder.

#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/level/level_io.h"
#include "ossa/level/level_load.h"
#include "ossa/level/tiled.h"
#include "ossa/math/rng.h"
#include "shared/scenes.h"

#include <catch2/catch.hpp>
#include <zlib.h>

#include <cmath>
#include <filesystem>

#include "shared/scratch_files.h"

using namespace ossa;
using namespace ossa::test;
namespace fs = std::filesystem;

namespace {

// A float within `spread` metres inside the ±1000 m bound, rounded nowhere in particular.
float near_edge(Rng& rng, float spread, bool high) {
  const float limit = static_cast<float>(kMaxLevelCoordinate);
  return high ? limit - static_cast<float>(rng.uniform(0.0, spread)) : -limit + static_cast<float>(rng.uniform(0.0, spread));
}

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out.push_back(k[(v >> s) & 63]);
  }
  if (i < bytes.size()) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    out.push_back(k[(v >> 18) & 63]);
    out.push_back(k[(v >> 12) & 63]);
    out.push_back(i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=');
    out.push_back('=');
  }
  return out;
}

std::string zlib(const std::string& raw) {
  uLongf n = compressBound(static_cast<uLong>(raw.size()));
  std::string out(n, '\0');
  REQUIRE(compress2(reinterpret_cast<Bytef*>(out.data()), &n, reinterpret_cast<const Bytef*>(raw.data()),
                    static_cast<uLong>(raw.size()), 9) == Z_OK);
  out.resize(n);
  return out;
}

}  // namespace

TEST_CASE("levels with boxes at the ±1000 m edges save and load back equal", "[level]") {
  // A box ending at x = +1000 m was written with a width whose decimal sum lay a rounding step
  // past 1000 (1000.00003), and the loader refused what the writer had written.
  Rng rng(33);
  const fs::path dir = fresh_dir("ossa_level_edges_test");
  for (int round = 0; round < 200; ++round) {
    std::vector<Box> boxes;
    for (int i = 0; i < 50; ++i) {
      const bool high = rng.uniform(0.0, 1.0) < 0.5;
      Box b;
      if (high) {
        b.max_ws = {near_edge(rng, 1.0f, true), near_edge(rng, 1.0f, true)};
        b.min_ws = b.max_ws - glm::vec2(static_cast<float>(rng.uniform(1e-3, 20.0)), static_cast<float>(rng.uniform(1e-3, 20.0)));
      } else {
        b.min_ws = {near_edge(rng, 1.0f, false), near_edge(rng, 1.0f, false)};
        b.max_ws = b.min_ws + glm::vec2(static_cast<float>(rng.uniform(1e-3, 20.0)), static_cast<float>(rng.uniform(1e-3, 20.0)));
      }
      if (i == 0) b = Box{{-1000.0f, -1000.0f}, {1000.0f, 1000.0f}};  // the whole square
      if (i == 1) b = Box{{999.99994f, 0.0f}, {1000.0f, 3.0f}};       // one float step wide
      REQUIRE(b.is_valid());
      boxes.push_back(b);
    }
    Level level(std::move(boxes), {near_edge(rng, 5.0f, true), near_edge(rng, 5.0f, true)});
    if (round % 3 == 0) level.kill_height_ws = near_edge(rng, 5.0f, false);
    const std::string path = (dir / "edges.json").string();
    REQUIRE(save_level(path, level).ok());
    Result<Level> back = load_level(path);
    INFO("round " << round << ": " << (back ? "" : back.message()));
    REQUIRE(back.ok());
    CHECK(*back == level);
  }
  fs::remove_all(dir);
}

TEST_CASE("a level the loader would refuse is not saved", "[level]") {
  const fs::path dir = fresh_dir("ossa_level_refuse_save_test");
  const std::string path = (dir / "l.json").string();
  Level level({Box::from_corner(0.0f, -1.0f, 10.0f, 1.0f)}, {1.0f, 0.0f});
  REQUIRE(save_level(path, level).ok());
  Level far = level;
  far.spawn_ws.x = 1500.0f;  // the editor can drag a spawn anywhere
  Status s = save_level(path, far);
  REQUIRE_FALSE(s.ok());
  CHECK(s.message() == path + ": spawn: (1500, 0) lies more than 1000 m from the origin (not saved)");
  CHECK(load_level(path).value() == level);  // the old file stays
  fs::remove_all(dir);
}

TEST_CASE("a kill height at or above the spawn is refused, naming both", "[level]") {
  // It used to load with a warning about missing ground and respawn the creature every tick.
  const std::string head = R"({"format":"ossa.level","version":1,"spawn":{"x":1,"y":0.5},"colliders":[{"x":0,"y":-1,"w":5,"h":1}])";
  Result<Level> above = parse_level(head + R"(,"kill_height":3})", "k.json");
  REQUIRE_FALSE(above.ok());
  CHECK(above.message() == "k.json: kill_height: expected below the spawn (y 0.5), got 3: a creature would start below "
                           "the kill height and start again every tick");
  CHECK_FALSE(parse_level(head + R"(,"kill_height":0.5})", "k.json").ok());
  CHECK(parse_level(head + R"(,"kill_height":0.4})", "k.json").ok());
}

TEST_CASE("the default kill height scales with the creature and costs no scan", "[level]") {
  Level level({Box::from_corner(0.0f, -1.0f, 10.0f, 1.0f), Box::from_corner(20.0f, -7.0f, 5.0f, 1.0f)}, {1.0f, 0.0f});
  CHECK(level.kill_y() == -7.0f - Level::kKillMargin);
  CHECK(level.kill_y(0.9f) == -7.0f - Level::kKillMargin);  // a human: the fixed margin
  CHECK(level.kill_y(90.0f) == -7.0f - 90.0f);               // a hundred times one: its own size
  // The lowest box follows every edit (the index's root bound, refitted exactly).
  level.set_box(1, Box::from_corner(20.0f, -3.0f, 5.0f, 1.0f));
  CHECK(level.kill_y() == -3.0f - Level::kKillMargin);
  level.set_box(0, Box::from_corner(0.0f, -12.0f, 10.0f, 1.0f));
  CHECK(level.kill_y() == -12.0f - Level::kKillMargin);
  level.remove_box(0);
  CHECK(level.kill_y() == -3.0f - Level::kKillMargin);
  level.kill_height_ws = -50.0f;
  CHECK(level.kill_y(500.0f) == -50.0f);  // a designer's kill height is kept as it is
  const Level empty({}, {0.0f, 4.0f});
  CHECK(empty.kill_y() == 4.0f - Level::kKillMargin);
  // bounds() from the index too, the spawn included.
  CHECK(level.bounds().min_ws.y == -3.0f);
  CHECK(level.bounds().max_ws.x == 25.0f);
}

TEST_CASE("Tiled: a gid beyond 32 bits is an error, not another tile", "[level][tiled]") {
  // <tile gid="4294967297"/> used to wrap to gid 1.
  const std::string tmx = R"(<map orientation="orthogonal" width="2" height="1" tilewidth="32" tileheight="32">
<layer name="Collision" width="2" height="1"><data><tile gid="1"/><tile gid="4294967297"/></data></layer></map>)";
  Result<Level> r = parse_level_any(tmx, "g.tmx", LevelLoadOptions{});
  REQUIRE_FALSE(r.ok());
  CHECK(r.message() == "g.tmx: layers[0].data[1]: expected a tile gid (an integer in [0, 4294967295]), got \"4294967297\"");
  const std::string ok = R"(<map orientation="orthogonal" width="2" height="1" tilewidth="32" tileheight="32">
<layer name="Collision" width="2" height="1"><data><tile gid="1"/><tile gid="4294967295"/></data></layer></map>)";
  CHECK(parse_level_any(ok, "g.tmx", LevelLoadOptions{}).ok());
}

TEST_CASE("a UTF-16 map is named UTF-16, not invalid JSON", "[level][tiled]") {
  const std::string ascii = R"(<map orientation="orthogonal" width="1" height="1" tilewidth="32" tileheight="32"></map>)";
  std::string utf16 = "\xFF\xFE";
  for (char c : ascii) {
    utf16.push_back(c);
    utf16.push_back('\0');
  }
  Result<Level> r = parse_level_any(utf16, "u.tmx", LevelLoadOptions{});
  REQUIRE_FALSE(r.ok());
  CHECK(r.message() == "u.tmx: is UTF-16 (little-endian) text; level files must be UTF-8 (save it as UTF-8)");
  CHECK(tsx_to_json(utf16, "t.tsx").message() == "t.tsx: is UTF-16 (little-endian) text; Tiled files must be UTF-8 (save it as UTF-8)");
}

TEST_CASE("Tiled: the cell limit holds for the whole map, not each layer", "[level][tiled]") {
  // 40 zlib layers of 1 M cells each: 3.4 MB of file, 49 s of work before. Now the map stops
  // at kMaxMapCells cells in all, whatever the number of layers.
  const int side = 1024;
  const std::string layer_data = base64(zlib(std::string(static_cast<size_t>(side) * side * 4, '\0')));
  std::string layers;
  const int n = static_cast<int>(kMaxMapCells / (side * side)) + 1;  // 17 layers
  for (int i = 0; i < n; ++i) {
    layers += std::string(i ? "," : "") + R"({"type":"tilelayer","name":"L)" + std::to_string(i) + R"(","width":1024,"height":1024,)" +
              R"("encoding":"base64","compression":"zlib","data":")" + layer_data + "\"}";
  }
  const std::string map = R"({"type":"map","orientation":"orthogonal","width":1024,"height":1024,"tilewidth":32,"tileheight":32,"layers":[)" +
                          layers + "]}";
  Result<Level> r = parse_level_any(map, "many.tmj", LevelLoadOptions{});
  REQUIRE_FALSE(r.ok());
  CHECK(r.message() == "many.tmj: layers[16]: tile layer \"L16\": has 1048576 cells, 17825792 with the layers before; at most "
                       "16777216 in all the layers of a map");
  // Up to the limit, the layers load.
  const size_t cut = map.find(",{\"type\":\"tilelayer\",\"name\":\"L16\"");
  REQUIRE(cut != std::string::npos);
  CHECK(parse_level_any(map.substr(0, cut) + "]}", "many.tmj", LevelLoadOptions{}).ok());
}

TEST_CASE("an LDtk field nested 300 000 deep is an error, not a crash", "[level][ldtk]") {
  const std::string deep = std::string(300000, '[') + "64" + std::string(300000, ']');
  const std::string project = R"({"jsonVersion":"1.5.3","defaultGridSize":16,"levels":[{"identifier":"L","worldX":0,"worldY":0,)"
                              R"("fieldInstances":[{"__identifier":"pixels_per_metre","__value":)" + deep + R"(}],"layerInstances":[]}]})";
  const fs::path dir = fresh_dir("ossa_ldtk_deep_test");
  const std::string path = (dir / "deep.ldtk").string();
  REQUIRE(write_file_atomic(path, project).ok());
  Result<Level> r = load_level(path);
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::StartsWith(path + ": levels[0].fieldInstances[0].__value"));
  CHECK_THAT(r.message(), Catch::Contains("nested more than 256 arrays or objects deep"));
  fs::remove_all(dir);
}

TEST_CASE("load_level reports every file it read", "[level][tiled]") {
  LevelLoadReport report;
  const std::string map = scenes::source_path("tests/level/data/tiles_tsj.tmj");
  REQUIRE(load_level(map, LevelLoadOptions{}, &report).ok());
  REQUIRE(report.files.size() == 2);
  CHECK(report.files[0] == map);
  CHECK(fs::path(report.files[1]).filename() == "terrain.tsj");
  REQUIRE(load_level(scenes::source_path("tests/level/data/external.ldtk"), LevelLoadOptions{}, &report).ok());
  REQUIRE(report.files.size() == 2);
  CHECK(fs::path(report.files[1]).filename() == "Level_1.ldtkl");
}

TEST_CASE("a level's background image resolves in the level's folder and may not leave it", "[level]") {
  const fs::path dir = fresh_dir("ossa_level_resource_test");
  fs::create_directories(dir / "maps" / "art");
  fs::create_directories(dir / "assets" / "bg");
  REQUIRE(write_file_atomic((dir / "maps" / "art" / "sky.png").string(), "x").ok());
  REQUIRE(write_file_atomic((dir / "assets" / "bg" / "old.png").string(), "x").ok());
  const std::string level = (dir / "maps" / "cave.json").string();
  CHECK(resolve_level_resource(level, "background.image", "art/sky.png").value() == (dir / "maps" / "art" / "sky.png").string());
  CHECK(resolve_level_resource(level + "#Level_1", "background.image", "art/./sky.png").value() ==
        (dir / "maps" / "art" / "sky.png").string());
  // Not beside the level: the old place, assets/, is tried.
  CHECK(resolve_level_resource(level, "background.image", "bg/old.png", (dir / "assets").string()).value() ==
        (dir / "assets" / "bg" / "old.png").string());
  // Leaving the folder is refused, wherever it points.
  Result<std::string> up = resolve_level_resource(level, "background.image", "../../../etc/passwd");
  REQUIRE_FALSE(up.ok());
  CHECK(up.message() == level + ": background.image: \"../../../etc/passwd\" leaves the level's folder; name a file in it or below it");
  CHECK_FALSE(resolve_level_resource(level, "background.image", "/etc/passwd").ok());
  CHECK_FALSE(resolve_level_resource(level, "background.image", "art/../../x.png").ok());
  CHECK(resolve_level_resource(level, "background.image", "art/../sky.png").ok());  // stays inside
  fs::remove_all(dir);
}
