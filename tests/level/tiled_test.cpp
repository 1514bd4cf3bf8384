// Tiled JSON import/export: round trips, hand-written maps from Tiled 1.8 (`type`) and 1.9
// (`class`), and the documented rules for shapes that cannot be colliders.

#include "ossa/level/tiled.h"
#include "ossa/io/json.h"
#include "ossa/level/level_io.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

#include <catch2/catch.hpp>

using namespace ossa;

namespace {

// A 10 x 5 map of 32 px tiles (160 px high): a ground strip along the bottom, a 64 x 32 px
// block on it, a spawn point, and a decoration of another class. `kind_key` is "type"
// (Tiled < 1.9) or "class" (Tiled 1.9).
std::string hand_map(const std::string& kind_key) {
  return R"({"compressionlevel":-1,"height":5,"width":10,"infinite":false,
    "layers":[
      {"data":[0,0],"height":1,"id":1,"name":"tiles","type":"tilelayer","width":2,"x":0,"y":0},
      {"draworder":"topdown","id":2,"name":"Objects","type":"objectgroup","opacity":1,"visible":true,"x":0,"y":0,
       "objects":[
        {"id":1,"name":"ground","rotation":0,")" + kind_key + R"(":"collider","visible":true,
         "x":0,"y":128,"width":320,"height":32},
        {"id":2,"name":"","rotation":0,")" + kind_key + R"(":"","visible":true,
         "x":64,"y":96,"width":64,"height":32},
        {"id":3,"name":"start","point":true,"rotation":0,")" + kind_key + R"(":"spawn","visible":true,
         "x":16,"y":128,"width":0,"height":0},
        {"id":4,"name":"tree","rotation":30,")" + kind_key + R"(":"decoration","ellipse":true,
         "x":200,"y":50,"width":20,"height":40}
       ]}],
    "nextlayerid":3,"nextobjectid":5,"orientation":"orthogonal","renderorder":"right-down",
    "tiledversion":"1.8.2","tileheight":32,"tilewidth":32,"tilesets":[],"type":"map","version":"1.8",
    "properties":[{"name":"name","type":"string","value":"hand made"}]})";
}

std::string import_error(const std::string& objects, const std::string& extra = "") {
  const std::string text = R"({"height":5,"tileheight":32,"tilewidth":32,"width":10,"orientation":"orthogonal",)" +
                           extra + R"("layers":[{"type":"objectgroup","objects":[)" + objects + "]}]}";
  Result<Level> r = import_tiled(text, "maps/m.json");
  REQUIRE_FALSE(r.ok());
  return r.message();
}

}  // namespace

TEST_CASE("hand-written Tiled maps with `type` and with `class` import the same", "[level][tiled]") {
  for (const char* key : {"type", "class"}) {
    INFO(key);
    Result<Level> r = import_tiled(hand_map(key), "maps/hand.json");
    REQUIRE(r.ok());
    const Level& level = *r;
    CHECK(level.name == "hand made");
    REQUIRE(level.size() == 2);
    // Map bottom (160 px) is y = 0; 32 px = 1 m.
    CHECK(level.box(0) == Box::from_corner(0.0f, 0.0f, 10.0f, 1.0f));
    CHECK(level.box(1) == Box::from_corner(2.0f, 1.0f, 2.0f, 1.0f));
    CHECK(level.spawn_ws == glm::vec2(0.5f, 1.0f));
    CHECK_FALSE(level.background);
  }
}

TEST_CASE("Tiled export then import gives the same level", "[level][tiled]") {
  for (const char* name : {"levels/default.json", "levels/stairs.json", "levels/rough.json"}) {
    INFO(name);
    const Level level = load_level(scenes::source_path(name)).value();
    const Json map = export_tiled(level);
    CHECK(map["type"] == "map");
    CHECK(map["orientation"] == "orthogonal");
    CHECK(map["tilewidth"] == 32);
    CHECK(map["height"].get<int>() >= 1);
    CHECK(map["nextobjectid"] == level.size() + 2);
    Result<Level> back = import_tiled(map.dump(), "x.json");
    REQUIRE(back.ok());
    CHECK(back->colliders() == level.colliders());
    CHECK(back->spawn_ws == level.spawn_ws);
    CHECK(back->name == level.name);
    REQUIRE(back->background.has_value() == level.background.has_value());
    if (level.background) {
      CHECK(back->background->parallax == level.background->parallax);
      for (int c = 0; c < 3; ++c) CHECK(back->background->colour[c] == Approx(level.background->colour[c]).margin(0.51 / 255));
    }
  }
  // Random levels with boxes below the map's bottom edge, an image background, and a
  // non-power-of-two scale (equal up to rounding then).
  Level level = scenes::random_level(9, 450);  // 900 m: within kMaxLevelCoordinate
  level.add_box(Box::from_corner(-5.0f, -7.5f, 3.0f, 2.0f));
  level.background = Background{"backgrounds/sky.png", 0.25f, {1.0f, 0.5f, 0.0f}};
  level.name = "random";
  for (float ppm : {32.0f, 16.0f, 50.0f}) {
    INFO("ppm " << ppm);
    TiledOptions o;
    o.pixels_per_metre = ppm;
    o.tile_width_px = o.tile_height_px = 50;
    Result<Level> back = import_tiled_json(export_tiled(level, o), "x.json", o);
    INFO((back.ok() ? std::string() : back.message()));
    REQUIRE(back.ok());
    REQUIRE(back->size() == level.size());
    REQUIRE(back->background);
    CHECK(back->background->image == "backgrounds/sky.png");
    CHECK(back->background->parallax == 0.25f);
    for (int i = 0; i < level.size(); ++i) {
      if (ppm != 50.0f) {
        REQUIRE(back->box(i) == level.box(i));
      } else {
        REQUIRE(back->box(i).min_ws.x == Approx(level.box(i).min_ws.x).margin(1e-4));
        REQUIRE(back->box(i).max_ws.y == Approx(level.box(i).max_ws.y).margin(1e-4));
      }
    }
  }
}

TEST_CASE("Tiled import: group layers, offsets, and the default spawn", "[level][tiled]") {
  Result<Level> r = import_tiled(R"({"height":2,"tileheight":32,"orientation":"orthogonal",
    "layers":[{"type":"group","offsetx":32,"layers":[
      {"type":"objectgroup","offsety":-32,"objects":[{"id":1,"x":0,"y":32,"width":64,"height":32}]}]}]})",
                                 "maps/group.json");
  REQUIRE(r.ok());
  REQUIRE(r->size() == 1);
  CHECK(r->box(0) == Box::from_corner(1.0f, 1.0f, 2.0f, 1.0f));
  CHECK(r->name == "group");
  CHECK(r->spawn_ws == glm::vec2(2.0f, 2.0f));  // 1 m in from the left edge, on top
}

TEST_CASE("Tiled import rejects shapes that cannot be colliders, naming the object", "[level][tiled]") {
  CHECK(import_error(R"({"id":7,"x":0,"y":0,"width":32,"height":32,"rotation":45})") ==
        "maps/m.json: layers[0].objects[0].rotation: collider (id 7) is rotated by 45 degrees; "
        "colliders must be axis-aligned (rotation 0)");
  CHECK(import_error(R"({"id":1,"x":0,"y":0,"width":32,"height":32},{"id":8,"x":0,"y":0,"width":32,"height":32,"ellipse":true,"type":"collider"})") ==
        "maps/m.json: layers[0].objects[1]: collider (id 8) is an ellipse; colliders must be rectangles "
        "(give it another class to skip it)");
  CHECK_THAT(import_error(R"({"id":2,"x":0,"y":0,"polygon":[{"x":0,"y":0}]})"), Catch::Contains("is a polygon"));
  CHECK_THAT(import_error(R"({"id":2,"x":0,"y":0,"width":0,"height":32})"), Catch::Contains("objects[0]: collider (id 2) has an empty size"));
  CHECK_THAT(import_error(R"({"id":2,"x":0,"y":0,"point":true,"class":"spawn"},{"id":3,"x":0,"y":0,"name":"Spawn"})"),
             Catch::Contains("objects[1]: a second spawn object (id 3); the first is layers[0].objects[0]"));
  CHECK_THAT(import_error(R"({"id":2,"x":"a","y":0})"), Catch::Contains("objects[0].x: expected a finite number"));
  CHECK_THAT(import_error(R"({"id":2,"x":1e300,"y":0,"width":1,"height":1})"), Catch::Contains("objects[0]: lies more than") && Catch::Contains("m from the origin"));
  CHECK_THAT(import_error("", R"("backgroundcolor":"red",)"), Catch::Contains("backgroundcolor: expected \"#RRGGBB\""));
  {
    Result<Level> r = import_tiled(R"({"height":5,"tileheight":32,"orientation":"isometric","layers":[]})", "i.json");
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains("orientation: expected \"orthogonal\""));
  }
  {
    Result<Level> r = import_tiled(R"({"tileheight":32,"layers":[]})", "i.json");
    REQUIRE_FALSE(r.ok());
    CHECK(r.message() == "i.json: height: missing (required field)");
  }
  // Objects of other classes are skipped whatever their shape.
  Result<Level> ok = import_tiled(R"({"height":5,"tileheight":32,"layers":[{"type":"objectgroup","objects":[
      {"id":1,"x":0,"y":0,"polygon":[],"type":"decoration"},{"id":2,"x":0,"y":0,"width":3,"height":3,"rotation":9,"class":"enemy"}]}]})",
                                  "ok.json");
  REQUIRE(ok.ok());
  CHECK(ok->empty());
}
