// load_level(path, options) over files written by the real editors: Tiled 1.8.2 (Debian's
// `tiled --export-map json`) exported the .tmj fixtures from the .tmx sources next to them;
// the LDtk fixtures follow LDtk's published JSON format. Every fixture is compared with the
// boxes it must give, the merge figures are checked, the horse walks over each converted
// map, and malformed maps fail with a message naming the file, the layer and the expectation.

#include "ossa/anim/spline_prototypes.h"
#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/level/ldtk.h"
#include "ossa/level/level_io.h"
#include "ossa/level/level_load.h"
#include "ossa/level/tiled.h"
#include "shared/scenes.h"

#include <catch2/catch.hpp>

#include <memory>

using namespace ossa;

namespace {

std::string fixture(const std::string& name) { return scenes::source_path("tests/level/data/" + name); }

Box box(float x0, float y0, float x1, float y1) { return Box{{x0, y0}, {x1, y1}}; }

struct Expected {
  std::vector<Box> boxes;
  glm::vec2 spawn;
  int64_t cells;
  int64_t boxes_from_cells;
  float ppm;
  const char* scale_from;
};

// tiles_*.tmx: 60 x 16 tiles of 32 px at the map's pixels_per_metre = 128 (0.25 m a tile):
// walls at both ends, a floor two tiles thick, two steps; grass and ladder tiles do not
// collide, flipped tiles do.
const Expected kTiles{{box(0.0f, 0.5f, 0.25f, 2.0f), box(14.75f, 0.5f, 15.0f, 2.0f), box(6.0f, 0.75f, 7.0f, 1.0f),
                       box(5.0f, 0.5f, 7.5f, 0.75f), box(0.0f, 0.0f, 15.0f, 0.5f)},
                      {2.5f, 0.5f}, 146, 5, 128.0f, "map property"};
// objects.tmx: rectangles only, one tile (32 px) = 0.5 m by default.
const Expected kObjects{{box(0.0f, 0.0f, 30.0f, 1.0f), box(10.0f, 1.0f, 15.0f, 1.25f), box(12.0f, 1.25f, 14.0f, 1.5f),
                         box(0.0f, 1.0f, 0.5f, 4.0f), box(29.5f, 1.0f, 30.0f, 4.0f)},
                        {1.5f, 1.0f}, 0, 0, 64.0f, "tile size"};
// infinite.tmx: chunks from x = -16 tiles on, external .tsx tileset, default scale.
const Expected kInfinite{{box(-8.0f, 1.0f, -7.5f, 4.0f), box(21.5f, 1.0f, 22.0f, 4.0f), box(-8.0f, 0.0f, 22.0f, 1.0f)},
                         {-5.0f, 1.0f}, 132, 3, 64.0f, "tile size"};
// group_offsets.tmx: a "Collision" tile layer (every tile solid) in a group offset by
// (64, -32) px, a nested group at (-32, 0), an object layer offset by (16, 8); 128 px/m.
const Expected kGroups{{box(5.5f, 0.5f, 8.0f, 0.75f), box(0.5f, 0.25f, 15.5f, 0.5f), box(0.25f, 0.5f, 0.5f, 1.75f),
                        box(15.0f, 0.5f, 15.25f, 1.75f), box(9.5f, 0.5625f, 10.5f, 0.8125f)},
                       {1.5f, 0.5f}, 80, 4, 128.0f, "map property"};
// world.ldtk Level_0 at world (0, 0): 16 px cells = 0.5 m by default; ladder and water cells
// do not collide.
const Expected kLdtk0{{box(0.0f, -5.0f, 0.5f, -2.5f), box(19.5f, -5.0f, 20.0f, -2.5f), box(0.0f, -6.0f, 20.0f, -5.0f)},
                      {2.25f, -5.0f}, 90, 3, 32.0f, "tile size"};
// world.ldtk Level_1 at world (640, 64) px with the level field pixels_per_metre = 64.
const Expected kLdtk1{{box(10.0f, -3.5f, 10.25f, -2.25f), box(19.75f, -3.5f, 20.0f, -2.25f),
                       box(13.75f, -3.25f, 14.5f, -3.0f), box(13.0f, -3.5f, 15.0f, -3.25f), box(10.0f, -4.0f, 20.0f, -3.5f)},
                      {11.125f, -3.5f}, 101, 5, 64.0f, "map property"};

struct Fixture {
  std::string path;
  const Expected* expected;
  LevelFormat format;
};

std::vector<Fixture> fixtures() {
  std::vector<Fixture> out;
  for (const char* stem : {"tiles_csv", "tiles_base64", "tiles_zlib", "tiles_gzip", "tiles_tsj"}) {
    out.push_back({fixture(std::string(stem) + ".tmx"), &kTiles, LevelFormat::kTiledXml});
    out.push_back({fixture(std::string(stem) + ".tmj"), &kTiles, LevelFormat::kTiledJson});
  }
  for (const auto& [stem, e] : {std::pair{"objects", &kObjects}, std::pair{"infinite", &kInfinite}, std::pair{"group_offsets", &kGroups}}) {
    out.push_back({fixture(std::string(stem) + ".tmx"), e, LevelFormat::kTiledXml});
    out.push_back({fixture(std::string(stem) + ".tmj"), e, LevelFormat::kTiledJson});
  }
  out.push_back({fixture("world.ldtk"), &kLdtk0, LevelFormat::kLdtk});
  out.push_back({fixture("world.ldtk#Level_0"), &kLdtk0, LevelFormat::kLdtk});
  out.push_back({fixture("world.ldtk#Level_1"), &kLdtk1, LevelFormat::kLdtk});
  out.push_back({fixture("external.ldtk"), &kLdtk1, LevelFormat::kLdtk});
  return out;
}

std::string load_error(std::string_view text, const std::string& file, const LevelLoadOptions& o = {}) {
  Result<Level> r = parse_level_any(text, file, o);
  REQUIRE_FALSE(r.ok());
  return r.message();
}

}  // namespace

TEST_CASE("every Tiled and LDtk fixture loads as the expected boxes", "[level][tiled][ldtk]") {
  for (const Fixture& f : fixtures()) {
    INFO(f.path);
    LevelLoadReport report;
    Result<Level> r = load_level(f.path, LevelLoadOptions{}, &report);
    REQUIRE(r.ok());
    CHECK(r->colliders() == f.expected->boxes);
    CHECK(r->spawn_ws == f.expected->spawn);
    CHECK(report.format == f.format);
    CHECK(report.solid_cells == f.expected->cells);
    CHECK(report.boxes_from_cells == f.expected->boxes_from_cells);
    CHECK(report.pixels_per_metre == f.expected->ppm);
    CHECK(report.scale_from == f.expected->scale_from);
    // The one-argument entry point (ossa --level, the editor, tests/embed) reads the same.
    Result<Level> plain = load_level(f.path);
    REQUIRE(plain.ok());
    CHECK(*plain == *r);
  }
}

TEST_CASE("the .tmj fixtures were written by Tiled itself", "[level][tiled]") {
  for (const char* stem : {"tiles_csv", "tiles_zlib", "infinite", "group_offsets", "objects"}) {
    INFO(stem);
    Result<Json> doc = read_json_file(fixture(std::string(stem) + ".tmj"));
    REQUIRE(doc.ok());
    CHECK((*doc)["tiledversion"] == "1.8.2");
  }
  Result<Json> inf = read_json_file(fixture("infinite.tmj"));
  REQUIRE(inf.ok());
  CHECK((*inf)["infinite"] == true);
  CHECK((*inf)["layers"][0]["chunks"].size() == 4);
  Result<Json> zl = read_json_file(fixture("tiles_zlib.tmj"));
  CHECK((*zl)["layers"][0]["compression"] == "zlib");
}

TEST_CASE("the horse walks over every converted fixture within 1 mm", "[level][tiled][ldtk][walk]") {
  auto creature = std::make_shared<const Creature>(scenes::quadruped());
  const SplinePrototypes prototypes =
      load_prototypes(scenes::source_path("assets/animation/prototypes.json")).value();
  const std::vector<ScriptSegment> script = parse_script("walk:0.5:7,run:1:3,stop:1,walk:-0.5:5").value();
  for (const Fixture& f : fixtures()) {
    if (f.path.find("tiles_") != std::string::npos && f.path.find("tiles_csv") == std::string::npos) continue;  // same map
    INFO(f.path);
    const Level level = load_level(f.path).value();
    Player player(creature, prototypes);
    player.animator().reset(level.spawn_ws + glm::vec2(0.0f, 1.0f), level);
    float max_x = level.spawn_ws.x;
    const SimResult result = run_script(player, level, script, 120, [&](long long) {
      max_x = std::max(max_x, player.animator().x());
    });
    CHECK(result.probe.max_stance_slip_m <= 0.001f);
    CHECK(result.probe.max_limb_penetration_m <= 0.001f);
    CHECK(result.probe.nan_count == 0);
    CHECK(max_x > level.spawn_ws.x + 6.0f);  // it got somewhere, over the steps where there are any
  }
}

TEST_CASE("load_level recognises the format by content first, extension second", "[level][tiled][ldtk]") {
  CHECK(detect_level_format("  <?xml version=\"1.0\"?><map/>", "a.json") == LevelFormat::kTiledXml);
  CHECK(detect_level_format(R"({"format":"ossa.level"})", "a.tmj") == LevelFormat::kOssa);
  CHECK(detect_level_format(R"({"orientation":"orthogonal"})", "a.ldtk") == LevelFormat::kTiledJson);
  CHECK(detect_level_format(R"({"jsonVersion":"1.3.4","levels":[]})", "a.json") == LevelFormat::kLdtk);
  CHECK(detect_level_format("{}", "a.ldtk") == LevelFormat::kLdtk);
  CHECK(detect_level_format("{}", "a.TMJ") == LevelFormat::kTiledJson);
  CHECK(detect_level_format("{}", "a.json") == LevelFormat::kOssa);
  // A Tiled map saved as .json loads like the .tmj.
  const std::string text = read_file(fixture("tiles_zlib.tmj")).value();
  Result<Level> r = parse_level_any(text, fixture("renamed.json"), LevelLoadOptions{}, nullptr,
                                    [](const std::string& p) { return read_file(p); });
  REQUIRE(r.ok());
  CHECK(r->colliders() == kTiles.boxes);
  // Ossa levels still load, and their errors are the ossa loader's.
  CHECK(load_level(scenes::source_path("levels/default.json")).ok());
  CHECK(load_error(R"({"format":"ossa.level","version":1})", "x.json") == "x.json: spawn: missing (required field)");
  CHECK_THAT(load_level(fixture("no_such.tmx")).message(), Catch::Contains("no_such.tmx"));
}

TEST_CASE("pixels per metre: the map property, else one tile = 0.5 m, else the option", "[level][tiled][ldtk]") {
  LevelLoadOptions o;
  o.pixels_per_metre = 10.0f;
  LevelLoadReport rep;
  // No property, tiles of 40 px: 80 px/m whatever the option says.
  const std::string base = R"({"type":"map","orientation":"orthogonal","width":4,"height":2,"tileheight":40,"layers":[
      {"type":"tilelayer","name":"collision","width":4,"height":2,"data":[0,0,0,0,1,1,1,1]}]})";
  Result<Level> a = parse_level_any(R"({"tilewidth":40,)" + base.substr(1) , "a.tmj", o, &rep);
  REQUIRE(a.ok());
  CHECK(rep.scale_from == "tile size");
  CHECK(a->colliders() == std::vector<Box>{box(0.0f, 0.0f, 2.0f, 0.5f)});
  // No tile width: the option (tile height alone does not set the scale).
  Result<Level> b = parse_level_any(base, "b.tmj", o, &rep);
  REQUIRE_FALSE(b.ok());  // a tile layer needs the tile width
  CHECK_THAT(b.message(), Catch::Contains("b.tmj: layers[0]: tile layer \"collision\": needs the map's tilewidth"));
  Result<Level> c = parse_level_any(R"({"type":"map","height":2,"tileheight":40,"layers":[{"type":"objectgroup","objects":[
      {"x":0,"y":40,"width":20,"height":40}]}]})", "c.tmj", o, &rep);
  REQUIRE(c.ok());
  CHECK(rep.scale_from == "option");
  CHECK(c->colliders() == std::vector<Box>{box(0.0f, 0.0f, 2.0f, 4.0f)});
  // The property wins over both.
  Result<Level> d = parse_level_any(R"({"tilewidth":40,"properties":[{"name":"pixels_per_metre","type":"int","value":20}],)" + base.substr(1),
                                    "d.tmj", o, &rep);
  REQUIRE(d.ok());
  CHECK(rep.scale_from == "map property");
  CHECK(d->colliders() == std::vector<Box>{box(0.0f, 0.0f, 8.0f, 2.0f)});
  CHECK_THAT(load_error(R"({"tilewidth":40,"properties":[{"name":"pixels_per_metre","type":"int","value":-2}],)" + base.substr(1), "e.tmj"),
             Catch::Contains("e.tmj: properties.pixels_per_metre: expected a number in (0, 1000000], got -2"));
  // LDtk: without defaultGridSize and without the field, the option.
  Json project = read_json_file(fixture("world.ldtk")).value();
  project.erase("defaultGridSize");
  Result<Level> l = import_ldtk_json(project, "w.ldtk", "", LdtkOptions{10.0f, {"ladder", "water"}, {}}, &rep);
  REQUIRE(l.ok());
  CHECK(rep.scale_from == "option");
  CHECK(l->box(2) == box(0.0f, -19.2f, 64.0f, -16.0f));
}

TEST_CASE("LDtk: passable IntGrid values and level choice", "[level][ldtk]") {
  LevelLoadOptions solid_all;
  solid_all.ldtk_passable.clear();
  LevelLoadReport rep;
  Result<Level> r = load_level(fixture("world.ldtk"), solid_all, &rep);
  REQUIRE(r.ok());
  CHECK(rep.solid_cells == 90 + 4 + 4);  // the ladder and the water collide now
  CHECK(rep.level_name == "Level_0");
  CHECK_THAT(load_level(fixture("world.ldtk#Level_9")).message(),
             Catch::Contains("world.ldtk: levels: no level named \"Level_9\" (the levels are Level_0, Level_1)"));
  CHECK_THAT(load_level(fixture("tiles_zlib.tmj#Level_1")).message(), Catch::Contains("picks a level of an LDtk project"));
}

TEST_CASE("malformed Tiled maps fail naming the file, the layer and the expectation", "[level][tiled]") {
  const auto map = [](const std::string& layer) {
    return R"({"type":"map","orientation":"orthogonal","width":2,"height":2,"tilewidth":32,"tileheight":32,"layers":[)" + layer + "]}";
  };
  CHECK(load_error(map(R"({"type":"tilelayer","name":"g","width":2,"height":2,"encoding":"base64","compression":"zstd","data":"AAAA"})"), "m.tmj") ==
        "m.tmj: layers[0].compression: tile layer \"g\": zstd is not supported; save the map with zlib, gzip or no compression "
        "(Map Properties > Tile Layer Format)");
  CHECK_THAT(load_error(map(R"({"type":"tilelayer","width":2,"height":2,"encoding":"base64","compression":"lz4","data":"AAAA"})"), "m.tmj"),
             Catch::Contains("layers[0].compression: tile layer \"\": expected \"zlib\", \"gzip\" or none"));
  CHECK_THAT(load_error(map(R"({"type":"tilelayer","width":2,"height":2,"data":[1,2,3]})"), "m.tmj"),
             Catch::Contains("m.tmj: layers[0].data: tile layer \"\": expected 4 tiles (width x height), got 3"));
  CHECK_THAT(load_error(map(R"({"type":"tilelayer","width":2,"height":2,"data":[1,2,-3,4]})"), "m.tmj"),
             Catch::Contains("layers[0].data[2]: tile layer \"\": expected a tile gid"));
  CHECK_THAT(load_error(map(R"({"type":"tilelayer","width":2,"height":2,"encoding":"base64","data":"AA!A"})"), "m.tmj"),
             Catch::Contains("layers[0].data: tile layer \"\": expected base64 text"));
  CHECK_THAT(load_error(map(R"({"type":"tilelayer","width":2,"height":2,"encoding":"base64","data":"AAAA"})"), "m.tmj"),
             Catch::Contains("layers[0].data: tile layer \"\": expected 16 bytes (4 per tile), got 3"));
  CHECK_THAT(load_error(map(R"({"type":"tilelayer","width":2,"height":2,"encoding":"base64","compression":"zlib","data":"AAAAAAAA"})"), "m.tmj"),
             Catch::Contains("layers[0].data: tile layer \"\": zlib data is not a valid zlib/gzip stream"));
  CHECK_THAT(load_error(map(R"({"type":"tilelayer","width":100000,"height":100000,"data":[]})"), "m.tmj"),
             Catch::Contains("layers[0]: tile layer \"\": has 10000000000 cells"));
  CHECK_THAT(load_error(map(R"({"type":"group","layers":[{"type":"tilelayer","width":1,"height":1,"chunks":[{"x":0,"y":0,"width":1,"height":1}]}]})"), "m.tmj"),
             Catch::Contains("layers[0].layers[0].chunks[0].data: tile layer \"\": missing"));
  // External tilesets: read relative to the map, errors name both files.
  const std::string ext = R"({"type":"map","orientation":"orthogonal","width":1,"height":1,"tilewidth":32,"tileheight":32,
      "tilesets":[{"firstgid":1,"source":"missing.tsx"}],"layers":[]})";
  CHECK(load_error(ext, "maps/m.tmj") ==
        "maps/m.tmj: tilesets[0].source: external tileset \"missing.tsx\" cannot be read here (no file access); embed the tileset");
  Result<Level> r = parse_level_any(ext, fixture("m.tmj"), LevelLoadOptions{}, nullptr, [](const std::string& p) { return read_file(p); });
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::Contains("m.tmj: tilesets[0].source: external tileset: ") && Catch::Contains("missing.tsx"));
  // XML: not XML, not a map, a bad number.
  CHECK_THAT(load_error("<map><layer", "x.tmx"), Catch::Contains("x.tmx: not valid XML at byte"));
  // A name with bytes that are not UTF-8 (found by the fuzzer: saving it threw).
  CHECK(load_error("<map orientation=\"orthogonal\">\n<properties><property name=\"name\" value=\"o\x9d\xfets\"/></properties></map>",
                   "x.tmx") == "x.tmx: not valid UTF-8 at byte 73 (line 2); save the map as UTF-8");
  CHECK(first_invalid_utf8("plain \xc3\xa9t\xc3\xa9 \xf0\x9f\x90\x8e") == std::string_view::npos);
  CHECK(first_invalid_utf8("ab\xc0\xaf") == 2);      // overlong '/'
  CHECK(first_invalid_utf8("a\xed\xa0\x80") == 1);  // a UTF-16 surrogate
  CHECK(first_invalid_utf8("ab\xe2\x82") == 2);      // cut short
  CHECK_THAT(load_error("<tileset/>", "x.tmx"), Catch::Contains("expected a Tiled map (root element <map>), got <tileset>"));
  CHECK_THAT(load_error(R"(<map orientation="orthogonal" width="2" height="2" tilewidth="32" tileheight="32"><layer name="g" width="two" height="2"><data encoding="csv">1,1,1,1</data></layer></map>)", "x.tmx"),
             Catch::Contains("x.tmx: layers[0].width: expected a number, got \"two\""));
  CHECK_THAT(load_error(R"(<map orientation="orthogonal" width="2" height="2" tilewidth="32" tileheight="32"><layer name="g" width="2" height="2"><data encoding="csv">1,x,1,1</data></layer></map>)", "x.tmx"),
             Catch::Contains("x.tmx: layers[0].data: expected comma-separated tile gids"));
}

TEST_CASE("malformed LDtk projects fail naming the file, the level and the layer", "[level][ldtk]") {
  Json project = read_json_file(fixture("world.ldtk")).value();
  Json bad = project;
  bad["levels"][0]["layerInstances"][1]["intGridCsv"].erase(0);
  CHECK_THAT(import_ldtk_json(bad, "w.ldtk").message(),
             Catch::Contains("w.ldtk: levels[0].layerInstances[1].intGridCsv: level \"Level_0\" layer \"Collisions\": "
                             "expected 480 values (__cWid x __cHei), got 479"));
  bad = project;
  bad["levels"][0]["layerInstances"][0]["entityInstances"].push_back(bad["levels"][0]["layerInstances"][0]["entityInstances"][0]);
  CHECK_THAT(import_ldtk_json(bad, "w.ldtk").message(),
             Catch::Contains("levels[0].layerInstances[0].entityInstances[1]: level \"Level_0\" layer \"Entities\": a second Player/Spawn entity"));
  bad = project;
  bad["levels"] = Json::array();
  CHECK(import_ldtk_json(bad, "w.ldtk").message() == "w.ldtk: levels: expected at least one level, got none");
  Json ext = read_json_file(fixture("external.ldtk")).value();
  CHECK_THAT(import_ldtk_json(ext, "e.ldtk").message(), Catch::Contains("is in an external file \"external/Level_1.ldtkl\""));
}

TEST_CASE("a 200 x 50 Tiled map becomes 1 box when solid, 5000 as a checkerboard", "[level][tiled][tiles]") {
  for (const bool checker : {false, true}) {
    Json data = Json::array();
    for (int y = 0; y < 50; ++y)
      for (int x = 0; x < 200; ++x) data.push_back(!checker || (x + y) % 2 == 0 ? 1 : 0);
    const Json map = {{"type", "map"}, {"orientation", "orthogonal"}, {"width", 200}, {"height", 50},
                      {"tilewidth", 16}, {"tileheight", 16},
                      {"layers", {{{"type", "tilelayer"}, {"name", "Colliders"}, {"width", 200}, {"height", 50}, {"data", data}}}}};
    LevelLoadReport rep;
    Result<Level> r = parse_level_any(map.dump(), "big.tmj", LevelLoadOptions{}, &rep);
    REQUIRE(r.ok());
    CHECK(rep.solid_cells == (checker ? 5000 : 10000));
    CHECK(rep.boxes_from_cells == (checker ? 5000 : 1));
    CHECK(r->size() == (checker ? 5000 : 1));
    if (!checker) CHECK(r->box(0) == box(0.0f, 0.0f, 100.0f, 25.0f));  // 16 px tiles = 0.5 m
  }
}
