// LevelView: a Tiled map's and an LDtk level's art drawn from their tilesets (pixels), flips,
// one draw per tileset per layer, the fallback for a missing image; the CPU parts (tile atlas,
// box look) it draws from.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "gl_fixture.h"
#include "ossa/level/level_load.h"
#include "ossa/render/box_look.h"
#include "ossa/render/capture.h"
#include "ossa/render/gl.h"
#include "ossa/render/level_view.h"
#include "ossa/render/tile_atlas.h"

using namespace ossa;
using namespace ossa::test;

namespace {

LevelView& view() {
  static std::unique_ptr<LevelView> v;
  if (!v) {
    gl();
    auto made = LevelView::create(Gl::shader_dir());
    INFO((made.ok() ? std::string() : made.message()));
    REQUIRE(made.ok());
    v = std::make_unique<LevelView>(std::move(made.value()));
  }
  return *v;
}

Level load(const std::string& relative) {
  auto level = load_level(scenes::source_path(relative), LevelLoadOptions{});
  INFO((level.ok() ? std::string() : level.message()));
  REQUIRE(level.ok());
  return std::move(level.value());
}

Image draw(const Level& level, const std::string& file, const Box& view_ws) {
  Gl& g = gl();
  g.renderer->camera.fit(view_ws, float(kW) / kH, 0.0f);
  g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
  view().draw_back(*g.renderer, level, file);
  view().draw_front(*g.renderer, level);
  REQUIRE(check_gl("level view test"));
  return read_framebuffer(kW, kH);
}

glm::ivec3 rgb(const Image& im, int x, int y) {
  const uint8_t* p = im.pixel(x, y);
  return {p[0], p[1], p[2]};
}

bool near(glm::ivec3 a, glm::ivec3 b, int tolerance = 12) {
  return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

// Pixels of `im` whose colour (4 bits a channel) is one of `colours` (same quantisation).
double share_of_colours(const Image& im, const std::vector<bool>& colours) {
  size_t hits = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) {
      const uint8_t* p = im.pixel(x, y);
      hits += colours[static_cast<size_t>((p[0] >> 4) << 8 | (p[1] >> 4) << 4 | (p[2] >> 4))] ? 1 : 0;
    }
  }
  return static_cast<double>(hits) / (static_cast<double>(im.width) * im.height);
}

// The opaque colours of every tileset image of `art` (4 bits a channel), excluding those near
// `except` (the sky).
std::vector<bool> art_colours(const LevelArt& art, glm::ivec3 except) {
  std::vector<bool> colours(4096, false);
  for (const ArtImage& ai : art.images) {
    auto im = load_image(ai.path);
    REQUIRE(im.ok());
    for (int y = 0; y < im->height; ++y) {
      for (int x = 0; x < im->width; ++x) {
        const uint8_t* p = im->pixel(x, y);
        if (p[3] < 250 || near({p[0], p[1], p[2]}, except, 24)) continue;
        colours[static_cast<size_t>((p[0] >> 4) << 8 | (p[1] >> 4) << 4 | (p[2] >> 4))] = true;
      }
    }
  }
  return colours;
}

// A 16 x 8 tileset of two 8 px tiles: tile 0 in four quadrants (top-left red, top-right green,
// bottom-left blue, bottom-right white), tile 1 yellow.
std::string write_quadrant_tileset() {
  Image im{16, 8, std::vector<uint8_t>(16 * 8 * 4, 255)};
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) {
      uint8_t* p = im.pixel(x, y);
      glm::ivec3 c{255, 255, 0};
      if (x < 8) c = y < 4 ? (x < 4 ? glm::ivec3(255, 0, 0) : glm::ivec3(0, 255, 0))
                           : (x < 4 ? glm::ivec3(0, 0, 255) : glm::ivec3(255, 255, 255));
      p[0] = static_cast<uint8_t>(c.x), p[1] = static_cast<uint8_t>(c.y), p[2] = static_cast<uint8_t>(c.z);
    }
  }
  const std::string path = (std::filesystem::temp_directory_path() / "ossa_level_view_quadrants.png").string();
  REQUIRE(write_png(path, im).ok());
  return path;
}

}  // namespace

TEST_CASE("a tile layer draws its tiles' pixels with their flips, one draw per tileset", "[render][level_view]") {
  const std::string png = write_quadrant_tileset();
  auto art = std::make_shared<LevelArt>();
  art->file = "quadrants.tmx";
  art->add_image(png, "quadrants.png", 16, 8);
  ArtTileset set;
  set.name = "quadrants";
  set.images = {0};
  set.tile_w_px = set.tile_h_px = 8;
  art->tilesets.push_back(set);
  ArtLayer layer;
  layer.name = "tiles";
  ArtBatch batch;
  // Four 1 m tiles side by side from x = 0: plain, flipped in x, in y, diagonally.
  const uint8_t flags[4] = {0, kArtFlipX, kArtFlipY, kArtFlipDiagonal};
  for (int i = 0; i < 4; ++i) batch.tiles.push_back(ArtTile{{static_cast<float>(i), 0.0f}, {1.0f, 1.0f}, 0, flags[i], 255});
  layer.batches.push_back(batch);
  art->layers.push_back(layer);
  art->background = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Level level;
  level.add_box(Box{{0.0f, -1.0f}, {4.0f, 0.0f}});
  level.art = art;

  const Image im = draw(level, "quadrants.tmx", Box{{0.0f, -0.5f}, {4.0f, 1.5f}});
  CHECK(view().take_warnings().empty());
  CHECK_FALSE(view().drawing_boxes());
  CHECK(view().stats().tiles_drawn == 4);
  CHECK(view().stats().draw_calls == 2);  // the background colour and the one batch
  // The picture is 4 m wide (80 px a metre) and shows y -1..2 m: the tiles' row, y 0..1 m, is
  // pixel rows 80..160.
  const auto quadrant = [&](int tile, int qx, int qy) { return rgb(im, tile * 80 + 20 + qx * 40, 100 + qy * 40); };
  const glm::ivec3 red{255, 0, 0}, green{0, 255, 0}, blue{0, 0, 255}, white{255, 255, 255};
  // Plain.
  CHECK(near(quadrant(0, 0, 0), red));
  CHECK(near(quadrant(0, 1, 0), green));
  CHECK(near(quadrant(0, 0, 1), blue));
  CHECK(near(quadrant(0, 1, 1), white));
  // Flipped in x: left and right swap.
  CHECK(near(quadrant(1, 0, 0), green));
  CHECK(near(quadrant(1, 1, 1), blue));
  // Flipped in y: top and bottom swap.
  CHECK(near(quadrant(2, 0, 0), blue));
  CHECK(near(quadrant(2, 1, 0), white));
  // Diagonal: mirrored across the top-left to bottom-right diagonal.
  CHECK(near(quadrant(3, 1, 0), blue));
  CHECK(near(quadrant(3, 0, 1), green));
  CHECK(near(quadrant(3, 0, 0), red));

  SECTION("opacity and tint multiply the texels") {
    auto faded = std::make_shared<LevelArt>(*art);
    faded->layers[0].opacity = 0.5f;
    faded->layers[0].tint = glm::vec4(1.0f, 0.0f, 1.0f, 1.0f);
    Level l2 = level;
    l2.art = faded;
    const Image im2 = draw(l2, "quadrants.tmx", Box{{0.0f, -0.5f}, {4.0f, 1.5f}});
    // White at half opacity over black, without its green: (128, 0, 128).
    CHECK(near(rgb(im2, 60, 140), {128, 0, 128}, 16));
    CHECK(near(rgb(im2, 20, 100), {128, 0, 0}, 16));
  }
  SECTION("parallax shifts a layer by (1 - p) times the view's offset from the origin") {
    auto far = std::make_shared<LevelArt>(*art);
    far->layers[0].parallax = glm::vec2(0.5f, 1.0f);
    Level l2 = level;
    l2.art = far;
    // The view's centre at x = 4 m: the layer is shifted 2 m, tile 0 drawn at 2..3 m (without
    // the shift that is tile 2's place, flipped in y: blue at its top-left).
    const Image im2 = draw(l2, "quadrants.tmx", Box{{2.0f, -0.5f}, {6.0f, 1.5f}});
    CHECK(near(rgb(im2, 20, 100), {255, 0, 0}));
    CHECK(near(rgb(im2, 20 + 40, 100), {0, 255, 0}));
  }
}

TEST_CASE("the Tiled fixture and the LDtk fixture draw their tiles, a missing image warns and falls back",
          "[render][level_view]") {
  for (const std::string file : {"tests/level/data/art/meadow.tmx", "tests/level/data/art/canyon.ldtk"}) {
    INFO(file);
    const Level level = load(file);
    REQUIRE(level.art);
    REQUIRE(level.art->tile_count() > 100);
    // A view of 12 x 9 m around the spawn.
    const Box around{level.spawn_ws - glm::vec2(6.0f, 3.0f), level.spawn_ws + glm::vec2(6.0f, 6.0f)};
    const Image im = draw(level, scenes::source_path(file), around);
    if (const char* dump = std::getenv("OSSA_LEVEL_VIEW_DUMP")) {
      REQUIRE(write_png(std::string(dump) + "/" + std::filesystem::path(file).filename().string() + ".png", im).ok());
    }
    CHECK(view().take_warnings().empty());
    CHECK_FALSE(view().drawing_boxes());
    CHECK(view().stats().tiles_drawn == level.art->tile_count());
    CHECK(view().stats().textures >= 2);
    // One draw per tileset per layer (or fewer), plus the sky.
    int batches = 0;
    for (const ArtLayer& l : level.art->layers) batches += l.kind == ArtLayer::Kind::kTiles ? static_cast<int>(l.batches.size()) : 1;
    CHECK(view().stats().draw_calls <= batches + 1);
    const glm::vec4 sky = level.art->background.value_or(glm::vec4(0.0f));
    const glm::ivec3 sky_rgb{static_cast<int>(sky.r * 255.0f), static_cast<int>(sky.g * 255.0f), static_cast<int>(sky.b * 255.0f)};
    const std::vector<bool> colours = art_colours(*level.art, sky_rgb);
    const double drawn = share_of_colours(im, colours);
    INFO("share of the art's colours: " << drawn);
    CHECK(drawn > 0.1);  // the art's colours cover a good part of the picture

    // The same level with its images gone: warnings naming the map and the path, boxes drawn.
    auto broken = std::make_shared<LevelArt>(*level.art);
    for (ArtImage& ai : broken->images) ai.path = ai.path + ".missing.png";
    Level without = level;
    without.art = broken;
    const Image fallback = draw(without, scenes::source_path(file), around);
    const std::vector<std::string> warnings = view().take_warnings();
    REQUIRE(warnings.size() == broken->images.size());
    CHECK(warnings[0].find(broken->file) != std::string::npos);
    CHECK(warnings[0].find(broken->images[0].path) != std::string::npos);
    CHECK(view().drawing_boxes());
    int changed = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) changed += near(rgb(im, x, y), rgb(fallback, x, y), 24) ? 0 : 1;
    }
    CHECK(changed > kW * kH / 10);  // the art is gone: a different picture
    // The boxes' earth colour (background.h) shows where the ground is: under the spawn.
    gl().renderer->camera.fit(around, float(kW) / kH, 0.0f);
    const glm::vec2 px = gl().renderer->camera.world_to_pixel(level.spawn_ws - glm::vec2(0.0f, 0.5f), kW, kH);
    const glm::ivec3 ground = rgb(fallback, static_cast<int>(px.x), static_cast<int>(px.y));
    CHECK_FALSE(near(ground, sky_rgb, 24));
  }
}

TEST_CASE("an ossa level's look draws its tiles on the boxes, a missing tileset falls back", "[render][level_view]") {
  const std::string file = "levels/drops.json";
  const Level level = load(file);
  REQUIRE(level.look);
  const Box around{level.spawn_ws - glm::vec2(6.0f, 3.0f), level.spawn_ws + glm::vec2(6.0f, 6.0f)};
  draw(level, scenes::source_path(file), around);
  CHECK(view().take_warnings().empty());
  CHECK_FALSE(view().drawing_boxes());
  CHECK(view().stats().tiles_drawn > 0);

  Level broken = level;
  broken.look->tileset = "no/such/tiles.png";
  draw(broken, scenes::source_path(file), around);
  const std::vector<std::string> warnings = view().take_warnings();
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("drops.json") != std::string::npos);
  CHECK(warnings[0].find("tiles.png") != std::string::npos);
  CHECK(view().drawing_boxes());
}

TEST_CASE("a grid tileset's atlas keeps each tile's pixels with a repeated edge", "[render][level_view]") {
  Image src{8, 4, std::vector<uint8_t>(8 * 4 * 4, 0)};
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      uint8_t* p = src.pixel(x, y);
      p[0] = static_cast<uint8_t>(x * 30), p[1] = static_cast<uint8_t>(y * 60), p[2] = 7, p[3] = 255;
    }
  }
  ArtTileset set;
  set.tile_w_px = set.tile_h_px = 4;
  const TileAtlas a = build_grid_atlas(src, set, 256);
  REQUIRE(a.tile_count() == 2);
  for (uint32_t t = 0; t < 2; ++t) {
    // The tile's top-left pixel, and the pixel kTileExtrude to its left and above: the same.
    const int x = static_cast<int>(std::lround(a.uv_tl[t].x * a.image.width));
    const int y = static_cast<int>(std::lround((1.0f - a.uv_tl[t].y) * a.image.height));
    CHECK(a.image.pixel(x, y)[0] == src.pixel(static_cast<int>(t) * 4, 0)[0]);
    CHECK(a.image.pixel(x - kTileExtrude, y - kTileExtrude)[0] == src.pixel(static_cast<int>(t) * 4, 0)[0]);
    CHECK(a.image.pixel(x + 3, y + 3)[1] == src.pixel(static_cast<int>(t) * 4 + 3, 3)[1]);
  }
  CHECK_FALSE(a.has(2));
}

TEST_CASE("a look's top row runs along the uncovered tops only", "[render][level_view]") {
  CHECK(uncovered(0.0f, 10.0f, {{2.0f, 3.0f}, {5.0f, 12.0f}}) == std::vector<glm::vec2>{{0.0f, 2.0f}, {3.0f, 5.0f}});
  Level level;
  level.add_box(Box{{0.0f, 0.0f}, {4.0f, 1.0f}});
  level.add_box(Box{{1.0f, 1.0f}, {2.0f, 2.0f}});  // covers part of the first box's top
  LevelLook look;
  look.tile_m = 0.5f;
  const BoxLookGeometry g = build_box_look(level, look);
  const auto& tops = g.parts[static_cast<size_t>(LookPart::kTop)];
  // The first box's top in two stretches (0..1, 2..4), the second's whole.
  REQUIRE(tops.size() == 3);
  CHECK(tops[0].rect_ws.max_ws.x == Approx(1.0f));
  CHECK(tops[1].rect_ws.min_ws.x == Approx(2.0f));
  CHECK(tops[1].rect_ws.max_ws.y == Approx(1.0f));
  CHECK(tops[1].rect_ws.min_ws.y == Approx(0.5f));
  CHECK(g.parts[static_cast<size_t>(LookPart::kFill)].size() == 2);
}

TEST_CASE("a 200 x 50 tile map is one draw per tileset per layer", "[render][level_view]") {
  const std::string png = write_quadrant_tileset();
  auto art = std::make_shared<LevelArt>();
  art->file = "big.tmx";
  art->add_image(png, "quadrants.png", 16, 8);
  ArtTileset set;
  set.images = {0};
  set.tile_w_px = set.tile_h_px = 8;
  art->tilesets.push_back(set);
  for (int layer = 0; layer < 2; ++layer) {
    ArtLayer l;
    ArtBatch batch;
    for (int y = 0; y < 50; ++y) {
      for (int x = 0; x < 200; ++x) {
        batch.tiles.push_back(ArtTile{{0.5f * static_cast<float>(x), 0.5f * static_cast<float>(y)}, {0.5f, 0.5f},
                                      static_cast<uint32_t>((x + y + layer) % 2), 0, 255});
      }
    }
    l.batches.push_back(std::move(batch));
    art->layers.push_back(std::move(l));
  }
  Level level;
  level.add_box(Box{{0.0f, -1.0f}, {100.0f, 0.0f}});
  level.art = art;
  draw(level, "big.tmx", Box{{0.0f, 0.0f}, {100.0f, 25.0f}});
  CHECK(view().stats().tiles_drawn == 20000);
  CHECK(view().stats().draw_calls == 3);  // the sky and one per layer
  CHECK(view().stats().textures == 1);
}
