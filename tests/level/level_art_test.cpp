// Level art (level_art.h): the tile and image layers of a Tiled map and an LDtk level as the
// loaders read them, over the fixtures in tests/level/data/art (make_fixtures.py; meadow.tmj
// is Tiled 1.8.2's own export of meadow.tmx): layer order, tilesets (embedded, .tsx, .tsj,
// image collections), flips, opacity, tint, parallax, offsets, hidden layers, the background,
// LDtk's auto-layer and IntGrid tiles; and an ossa level's look, saved and loaded.

#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/level/level_io.h"
#include "ossa/level/level_load.h"
#include "shared/scenes.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace ossa;

namespace {

std::string art_fixture(const std::string& name) { return scenes::source_path("tests/level/data/art/" + name); }

const ArtLayer* layer_named(const LevelArt& art, const std::string& name) {
  for (const ArtLayer& l : art.layers) {
    if (l.name == name) return &l;
  }
  return nullptr;
}

std::vector<std::string> layer_names(const LevelArt& art) {
  std::vector<std::string> out;
  for (const ArtLayer& l : art.layers) out.push_back(l.name);
  return out;
}

// The tile of `layer` whose rectangle starts at `min_ws` (within 1 mm), or null.
const ArtTile* tile_at(const ArtLayer& layer, glm::vec2 min_ws, int* tileset = nullptr) {
  for (const ArtBatch& b : layer.batches) {
    for (const ArtTile& t : b.tiles) {
      if (std::abs(t.min_ws.x - min_ws.x) < 1e-3f && std::abs(t.min_ws.y - min_ws.y) < 1e-3f) {
        if (tileset) *tileset = b.tileset;
        return &t;
      }
    }
  }
  return nullptr;
}

Level load(const std::string& path, LevelLoadReport* report = nullptr) {
  auto level = load_level(path, LevelLoadOptions{}, report);
  INFO((level.ok() ? std::string() : level.message()));
  REQUIRE(level.ok());
  return std::move(level.value());
}

}  // namespace

TEST_CASE("a Tiled map's art: layers in order, hidden ones left out, group style passed down", "[level][art]") {
  for (const char* file : {"meadow.tmx", "meadow.tmj"}) {
    INFO(file);
    const Level level = load(art_fixture(file));
    REQUIRE(level.art);
    const LevelArt& art = *level.art;
    CHECK(layer_names(art) == std::vector<std::string>{"Far hills", "Back", "Ground", "Crystals", "Props", "Front grass"});
    REQUIRE(art.background);
    CHECK(art.background->r == Approx(0xa6 / 255.0f));
    CHECK(art.background->b == Approx(0xe8 / 255.0f));

    const ArtLayer& hills = *layer_named(art, "Far hills");
    CHECK(hills.kind == ArtLayer::Kind::kImage);
    CHECK(hills.repeat_x);
    CHECK_FALSE(hills.repeat_y);
    CHECK(hills.parallax.x == Approx(0.4f));
    CHECK(hills.parallax.y == Approx(0.8f));
    CHECK(hills.metres_per_px == Approx(1.0f / 64.0f));
    // Its top-left at offset y 192 px of the 448 px map: (448 - 192) / 64 = 4 m.
    CHECK(hills.origin_ws.y == Approx(4.0f));
    CHECK(art.images[static_cast<size_t>(hills.image)].path == std::filesystem::path(art_fixture("hills.png")).lexically_normal().string());

    CHECK(layer_named(art, "Back")->parallax.x == Approx(0.9f));
    CHECK(layer_named(art, "Back")->parallax.y == Approx(1.0f));
    // The group "Terrain" has opacity 0.95: both its layers inherit it.
    CHECK(layer_named(art, "Ground")->opacity == Approx(0.95f));
    CHECK(layer_named(art, "Crystals")->opacity == Approx(0.95f));
    const ArtLayer& front = *layer_named(art, "Front grass");
    CHECK(front.front);
    CHECK_FALSE(layer_named(art, "Ground")->front);
    CHECK(front.opacity == Approx(0.85f));
    CHECK(front.tint.r == Approx(0xc8 / 255.0f));
    CHECK(front.tint.g == Approx(0xe6 / 255.0f));
    CHECK(front.tint.b == Approx(0xa0 / 255.0f));
  }
}

TEST_CASE("a Tiled map's tiles: placed on their cells, flipped, from embedded, .tsx and .tsj tilesets", "[level][art]") {
  const Level level = load(art_fixture("meadow.tmx"));
  const LevelArt& art = *level.art;
  // Tilesets: meadow (external .tsx), cave (embedded, 16 px tiles), props (external .tsj, a
  // collection of four images).
  REQUIRE(art.tilesets.size() == 3);
  CHECK(art.tilesets[0].name == "meadow");
  CHECK(art.tilesets[0].tile_w_px == 32);
  CHECK(art.images[static_cast<size_t>(art.tilesets[0].images[0])].path ==
        std::filesystem::path(art_fixture("meadow.png")).lexically_normal().string());
  CHECK(art.tilesets[1].tile_w_px == 16);
  CHECK(art.tilesets[2].collection);
  REQUIRE(art.tilesets[2].images.size() == 4);
  CHECK(art.images[static_cast<size_t>(art.tilesets[2].images[0])].source == "props/tree.png");
  CHECK(art.images[static_cast<size_t>(art.tilesets[2].images[0])].width_px == 64);

  // Ground: column 38's grass (the left end after the pit, tile 1) sits on the ground's top at
  // y = 1.5 m.
  const ArtLayer& ground = *layer_named(art, "Ground");
  REQUIRE(ground.batches.size() == 1);
  const ArtTile* grass = tile_at(ground, {19.0f, 1.0f});
  REQUIRE(grass);
  CHECK(grass->tile == 1);
  CHECK(grass->flags == 0);
  CHECK(grass->size_ws.x == Approx(0.5f));
  const auto top = level.ground_height_below(19.25f, 3.0f, 10.0f);
  REQUIRE(top);
  CHECK(top->height_ws == Approx(grass->min_ws.y + grass->size_ws.y));
  // Column 33 ends the middle stretch before the pit: the left end mirrored.
  const ArtTile* right_end = tile_at(ground, {16.5f, 1.0f});
  REQUIRE(right_end);
  CHECK(right_end->tile == 1);
  CHECK(right_end->flags == kArtFlipX);

  // Back: the ladder turned a quarter (diagonal + horizontal flip) and the hanging mushroom.
  const ArtLayer& back = *layer_named(art, "Back");
  const ArtTile* ladder = tile_at(back, {25.0f, 1.5f});
  REQUIRE(ladder);
  CHECK(ladder->tile == 11);
  CHECK(ladder->flags == (kArtFlipDiagonal | kArtFlipX));
  const ArtTile* mushroom = tile_at(back, {23.0f, 2.5f});
  REQUIRE(mushroom);
  CHECK(mushroom->flags == kArtFlipY);

  // Crystals: 16 px cave tiles on the 32 px grid, bottom-left in their cell: 0.25 m wide.
  int tileset = -1;
  const ArtTile* crystal = tile_at(*layer_named(art, "Crystals"), {11.0f, 2.0f}, &tileset);
  REQUIRE(crystal);
  CHECK(tileset == 1);
  CHECK(crystal->size_ws.x == Approx(0.25f));
  CHECK(crystal->tile == 10);

  // Props: the tree (64 x 96 px) at column 8, bottom on the ground, moved 4 px down by the
  // layer's offset: y = (448 - 356) / 64.
  const ArtTile* tree = tile_at(*layer_named(art, "Props"), {4.0f, (448.0f - 356.0f) / 64.0f}, &tileset);
  REQUIRE(tree);
  CHECK(tileset == 2);
  CHECK(tree->tile == 0);
  CHECK(tree->size_ws.x == Approx(1.0f));
  CHECK(tree->size_ws.y == Approx(1.5f));

  // The same art from Tiled's JSON export (which declares no image layer size).
  const Level json = load(art_fixture("meadow.tmj"));
  REQUIRE(json.art);
  CHECK(json.art->layers == art.layers);
  CHECK(json.art->tilesets == art.tilesets);
  CHECK(json.art->tile_count() == art.tile_count());
  // And the art changes nothing the creatures stand on: the colliders come from the Ground
  // layer's collider tiles alone.
  CHECK(json.colliders() == level.colliders());
}

TEST_CASE("an LDtk level's art: auto-layer, IntGrid and tile layers back to front, background", "[level][art]") {
  const Level level = load(art_fixture("canyon.ldtk"));
  REQUIRE(level.art);
  const LevelArt& art = *level.art;
  // LDtk lists layers front to back; drawn back to front, the background image first.
  CHECK(layer_names(art) == std::vector<std::string>{"background", "Wall", "Collisions", "Decor", "Foreground"});
  REQUIRE(level.background);
  CHECK(level.background->colour.r == Approx(0x2b / 255.0f));
  REQUIRE(art.background);

  const ArtLayer& bg = art.layers[0];
  CHECK(bg.kind == ArtLayer::Kind::kImage);
  CHECK(bg.crop_px == glm::vec4(0.0f, 0.0f, 512.0f, 160.0f));
  CHECK(bg.origin_ws.y == Approx(-48.0f / 32.0f));
  CHECK(art.images[static_cast<size_t>(bg.image)].source == "hills.png");

  const ArtLayer& wall = *layer_named(art, "Wall");
  CHECK(wall.opacity == Approx(0.6f));
  CHECK(wall.parallax.x == Approx(0.8f));  // LDtk factor 0.2

  // One auto-layer tile per solid IntGrid cell (value 1; the ladder, value 2, has none).
  const ArtLayer& ground = *layer_named(art, "Collisions");
  REQUIRE(ground.batches.size() == 1);
  int64_t solid_cells = 0;
  LevelLoadReport report;
  (void)load(art_fixture("canyon.ldtk"), &report);
  solid_cells = report.solid_cells;
  CHECK(static_cast<int64_t>(ground.batches[0].tiles.size()) == solid_cells);
  // The floor's first top, cell (2, 12) beside the left wall: tile 0 (moss) at px (32, 192):
  // x = 1 m, bottom y = -(192 + 16) / 32.
  const ArtTile* moss = tile_at(ground, {1.0f, -208.0f / 32.0f});
  REQUIRE(moss);
  CHECK(moss->tile == 0);
  CHECK(moss->size_ws == glm::vec2(0.5f));
  // The right side of the step is the left side mirrored (f = 1).
  bool mirrored_side = false;
  for (const ArtTile& t : ground.batches[0].tiles) mirrored_side = mirrored_side || (t.tile == 4 && t.flags == kArtFlipX);
  CHECK(mirrored_side);

  const ArtLayer& front = *layer_named(art, "Foreground");
  CHECK(front.front);
  bool upside_down = false;
  for (const ArtTile& t : front.batches[0].tiles) upside_down = upside_down || t.flags == kArtFlipY;
  CHECK(upside_down);
  CHECK_FALSE(layer_named(art, "Decor")->front);
}

TEST_CASE("art errors name the file and the field", "[level][art]") {
  const std::string dir = art_fixture("");
  SECTION("a tint that is no colour") {
    Result<std::string> text = read_file(art_fixture("meadow.tmj"));
    REQUIRE(text);
    std::string t = *text;
    const size_t at = t.find("\"#c8e6a0\"");
    REQUIRE(at != std::string::npos);
    t.replace(at, 9, "\"green\"");
    auto level = parse_level_any(t, art_fixture("bad.tmj"), LevelLoadOptions{}, nullptr, [](const std::string& p) { return read_file(p); });
    REQUIRE_FALSE(level.ok());
    CHECK_THAT(level.message(), Catch::Contains("bad.tmj") && Catch::Contains("tintcolor") && Catch::Contains("#RRGGBB"));
  }
  SECTION("an LDtk layer naming a tileset that is not defined") {
    Result<std::string> text = read_file(art_fixture("canyon.ldtk"));
    REQUIRE(text);
    Result<Json> doc = parse_json(*text, "canyon.ldtk");
    REQUIRE(doc);
    (*doc)["levels"][0]["layerInstances"][2]["__tilesetDefUid"] = 99;
    auto level = parse_level_any(doc->dump(), art_fixture("bad.ldtk"), LevelLoadOptions{});
    REQUIRE_FALSE(level.ok());
    CHECK_THAT(level.message(), Catch::Contains("bad.ldtk") && Catch::Contains("__tilesetDefUid") && Catch::Contains("uid 99"));
  }
}

TEST_CASE("an ossa level's look is saved and loaded with the level, and checked", "[level][art]") {
  Level level(std::vector<Box>{Box::from_corner(0.0f, -1.0f, 10.0f, 1.0f)}, {1.0f, 0.0f}, "looks");
  LevelLook look;
  look.tileset = "tiles/meadow.png";
  look.tile_px = 32;
  look.tile_m = 0.6f;
  look.top = 0;
  look.top_left = 1;
  look.top_right = 2;
  look.left = 4;
  look.right = 5;
  look.fill = 3;
  level.look = look;
  const std::string text = level_to_text(level);
  CHECK_THAT(text, Catch::Contains("\"look\": {\"tileset\":\"tiles/meadow.png\""));
  auto back = parse_level(text, "looks.json");
  REQUIRE(back.ok());
  CHECK(back->look == level.look);
  CHECK(*back == level);

  Level plain = level;
  plain.look.reset();
  CHECK_FALSE(plain == level);
  CHECK(level_to_text(plain).find("\"look\"") == std::string::npos);

  for (const auto& [field, value, expect] :
       {std::tuple{"tile_px", "0", "look.tile_px"}, std::tuple{"tile_m", "-1", "look.tile_m"},
        std::tuple{"fill", "-2", "look.fill"}, std::tuple{"tileset", "\"\"", "look.tileset"}}) {
    std::string bad = text;
    const std::string key = std::string("\"") + field + "\":";
    const size_t at = bad.find(key);
    REQUIRE(at != std::string::npos);
    const size_t end = bad.find_first_of(",}", at + key.size());
    bad.replace(at + key.size(), end - at - key.size(), value);
    auto r = parse_level(bad, "bad_look.json");
    INFO(bad);
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains("bad_look.json") && Catch::Contains(expect));
  }

  // Every shipped level has a look, and its tileset is there.
  for (const char* name : {"default", "drops", "stairs", "rough", "slopes"}) {
    INFO(name);
    const std::string path = scenes::source_path(std::string("levels/") + name + ".json");
    const Level shipped = load(path);
    REQUIRE(shipped.look);
    auto file = resolve_level_resource(path, "look.tileset", shipped.look->tileset, scenes::source_path("assets"));
    REQUIRE(file.ok());
    CHECK(std::filesystem::exists(*file));
  }
}

TEST_CASE("a map with more art tiles than the limit keeps its colliders and warns", "[level][art]") {
  // 1500 x 1500 = 2 250 000 tiles (over kMaxArtTiles) of one collider tile, as a CSV-free
  // Tiled JSON map: every cell is tile 1 of a tileset with an image.
  const int n = 1500;
  Json map = {{"type", "map"}, {"orientation", "orthogonal"}, {"width", n}, {"height", n}, {"tilewidth", 32},
              {"tileheight", 32}, {"infinite", false}};
  map["tilesets"] = Json::array({{{"firstgid", 1}, {"name", "t"}, {"tilewidth", 32}, {"tileheight", 32}, {"columns", 1},
                                  {"image", "t.png"}, {"imagewidth", 32}, {"imageheight", 32},
                                  {"tiles", Json::array({{{"id", 0}, {"type", "collider"}}})}}});
  Json data = Json::array();
  for (int i = 0; i < n * n; ++i) data.push_back(1);
  map["layers"] = Json::array({{{"type", "tilelayer"}, {"name", "all"}, {"width", n}, {"height", n}, {"data", std::move(data)}}});
  LevelLoadReport report;
  auto level = parse_level_any(map.dump(), "big.tmj", LevelLoadOptions{}, &report);
  REQUIRE(level.ok());
  CHECK(level->size() == 1);  // the colliders all count (merged into one box)
  REQUIRE(level->art);
  CHECK(level->art->tile_count() == kMaxArtTiles);
  REQUIRE_FALSE(report.warnings.empty());
  CHECK_THAT(report.warnings.front(), Catch::Contains("not drawn"));
}
