// Creature draw data (draw/creature_draw.h): the world-space triangles any renderer draws are
// the meshes CreatureBatch draws, skinned as its shaders skin them, with texture coordinates
// inside the atlas, in layer order, for every look.

#include "ossa/draw/creature_draw.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "ossa/draw/sprite_atlas.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/math/rng.h"
#include "ossa/skeleton/pose.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

Creature example(const char* name) { return build_creature(scenes::generator().example(name).value()).value(); }

const SpriteAtlas& atlas() {
  static const SpriteAtlas a = load_sprite_atlas(scenes::source_path("assets/sprites/bones"));
  return a;
}

// The creature's rest pose with every joint turned by up to ±0.4 rad, placed at `at`, facing
// left when `mirror`.
std::vector<Mat2x3> posed(const Creature& c, Rng& rng, glm::vec2 at, bool mirror) {
  std::vector<BoneLocal> locals = c.rest_pose.locals;
  for (BoneLocal& l : locals) l.angle_ls += static_cast<float>(rng.uniform(-0.4, 0.4));
  Transform2D place;
  place.translation = at;
  place.mirror_x = mirror;
  const std::vector<Mat2x3> model = model_matrices(c.skeleton, locals);
  std::vector<Mat2x3> world(model.size());
  for (size_t b = 0; b < model.size(); ++b) world[b] = place.to_mat2x3() * model[b];
  return world;
}

}  // namespace

TEST_CASE("the sprite atlas packs every shipped sprite with its rectangle inside the image", "[draw]") {
  const SpriteAtlas& a = atlas();
  CHECK(a.missing == 0);
  CHECK(a.problems.empty());
  REQUIRE(!a.image.empty());
  CHECK(a.image.width == a.image.height);
  CHECK(a.image.rgba.size() == static_cast<size_t>(a.image.width) * a.image.height * 4);
  for (const SpriteInfo& s : a.sprites.sprites) {
    INFO(s.name);
    CHECK(s.uv_min.x > 0.0f);
    CHECK(s.uv_min.y > 0.0f);
    CHECK(s.uv_max.x < 1.0f);
    CHECK(s.uv_max.y < 1.0f);
    CHECK(s.uv_min.x < s.uv_max.x);
    CHECK(s.uv_min.y < s.uv_max.y);
    CHECK(s.parent_reach.x >= 0.0f);  // measured from the image
  }
  // A folder without sprites packs checker tiles and says why.
  const SpriteAtlas none = load_sprite_atlas(scenes::source_path("tests/no-such-folder"));
  CHECK(none.missing == static_cast<int>(SpriteId::kCount));
  CHECK(none.problems.size() == static_cast<size_t>(SpriteId::kCount) + 1);
}

TEST_CASE("decode_image_file reads PNGs and names the file when it cannot", "[draw]") {
  Result<Image> png = decode_image_file(scenes::source_path("assets/sprites/bones/hoof.png"));
  REQUIRE(png.ok());
  CHECK(png->width > 0);
  CHECK(png->rgba.size() == static_cast<size_t>(png->width) * png->height * 4);
  Result<Image> missing = decode_image_file("no-such.png");
  REQUIRE(!missing.ok());
  CHECK(missing.message().find("no-such.png") != std::string::npos);
  Result<Image> not_image = decode_image_file(scenes::source_path("assets/sprites/bones/sprites.json"));
  REQUIRE(!not_image.ok());
  CHECK(not_image.message().find("sprites.json") != std::string::npos);
}

TEST_CASE("draw lists hold the meshes CreatureBatch draws, skinned as its shaders skin them", "[draw]") {
  Rng rng(31);
  for (const char* name : {"horse", "kangaroo", "magpie", "crocodile"}) {
    const Creature c = example(name);
    for (const CreatureLook look : {CreatureLook::kBody, CreatureLook::kXray, CreatureLook::kBones}) {
      INFO(name << ", look " << creature_look_name(look));
      CreatureDrawOptions options;
      options.look = look;
      const CreatureDrawable d = make_creature_drawable(c, atlas().sprites, options).value();
      const SpriteMesh sprites = build_sprite_mesh(c, atlas().sprites);
      const BodyMesh body = build_body(c);
      CHECK(d.sprites.indices.size() == (look == CreatureLook::kBody ? 0 : sprites.indices.size()));
      CHECK(d.body.indices.size() == (look == CreatureLook::kBones ? 0 : body.indices.size()));

      const std::vector<Mat2x3> world = posed(c, rng, {3.0f, 1.0f}, look == CreatureLook::kXray);
      DrawList list;
      append_creature(list, d, world);
      CHECK(list.triangle_count() == d.triangle_count());
      CHECK(list.creature_count == 1);

      // The palettes as CreatureBatch::set_world builds them, every vertex as the shaders skin it.
      std::vector<glm::vec2> expected;
      if (look != CreatureLook::kBody) {
        std::vector<Mat2x3> palette(static_cast<size_t>(sprites.palette_size()));
        PaletteJob job;
        job.world = world;
        job.inverse_bind = sprites.inverse_bind;
        job.palette = std::span<Mat2x3>(palette).first(world.size());
        REQUIRE(job.run());
        mid_joint_palette(sprites.mid_joints, world, palette);
        for (const SpriteVertex& v : sprites.vertices) expected.push_back(skin_vertex(v, palette));
      }
      if (look != CreatureLook::kBones) {
        std::vector<Mat2x3> palette(static_cast<size_t>(body.palette_size()));
        body_palette(body, world, palette);
        for (const BodyVertex& v : body.vertices) expected.push_back(skin_body_vertex(v, palette));
      }
      REQUIRE(list.vertices.size() == expected.size());
      float worst = 0.0f;
      for (size_t i = 0; i < expected.size(); ++i) {
        worst = std::max(worst, glm::length(list.vertices[i].position_ws - expected[i]));
      }
      CHECK(worst < 1e-5f);

      // Texture coordinates inside the atlas, every index a vertex, every command's texture
      // the mesh it came from.
      for (const DrawVertex& v : list.vertices) {
        CHECK((v.uv.x >= 0.0f && v.uv.x <= 1.0f && v.uv.y >= 0.0f && v.uv.y <= 1.0f));
      }
      for (const uint32_t i : list.indices) REQUIRE(i < list.vertices.size());
      const auto textured = std::count_if(list.commands.begin(), list.commands.end(),
                                          [](const DrawCommand& k) { return k.texture == DrawTexture::kAtlas; });
      CHECK((textured > 0) == (look != CreatureLook::kBody));
      CHECK((textured < static_cast<long>(list.commands.size())) == (look != CreatureLook::kBones));

      // Draw order: layer by layer (far, body, near); the commands cover every index once, in order.
      uint32_t next = 0;
      for (size_t k = 0; k < list.commands.size(); ++k) {
        const DrawCommand& cmd = list.commands[k];
        CHECK(cmd.first_index == next);
        next += cmd.index_count;
        if (k > 0) CHECK(static_cast<int>(cmd.layer) >= static_cast<int>(list.commands[k - 1].layer));
        // X-ray: each layer's sprites, then its body over them.
        if (look == CreatureLook::kXray && k > 0 && cmd.layer == list.commands[k - 1].layer) {
          CHECK(list.commands[k - 1].texture == DrawTexture::kAtlas);
          CHECK(cmd.texture == DrawTexture::kNone);
        }
      }
      CHECK(next == list.indices.size());
    }
  }
}

TEST_CASE("draw lists: sprites tinted by their shade, atlas texels in image rows, bodies in their coat", "[draw]") {
  const Creature c = example("horse");
  CreatureDrawOptions options;
  options.look = CreatureLook::kXray;
  const CreatureDrawable d = make_creature_drawable(c, atlas().sprites, options).value();
  DrawList list;
  append_creature(list, d, model_matrices(c.skeleton, c.rest_pose.locals));
  // Far bones darker than near ones; texture v counts rows down the image (the atlas's t up).
  const SpriteMesh& m = d.sprites;
  int far = 0;
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const DrawVertex& v = list.vertices[i];
    CHECK(v.uv.x == Approx(m.vertices[i].uv.x));
    CHECK(v.uv.y == Approx(1.0f - m.vertices[i].uv.y));
    CHECK(v.colour[3] == 255);
    if (m.vertices[i].shade < 1.0f) {
      ++far;
      CHECK(v.colour[0] < 200);
    } else {
      CHECK(v.colour[0] == 255);
    }
  }
  CHECK(far > 0);
  // The body's vertices carry its coat colour, translucent in the x-ray look.
  for (size_t i = 0; i < d.body.vertices.size(); ++i) {
    const DrawVertex& v = list.vertices[m.vertices.size() + i];
    const BodyVertex& b = d.body.vertices[i];
    CHECK(v.colour[0] == b.colour[0]);
    CHECK(v.colour[3] == static_cast<uint8_t>(std::lround(kXrayBodyAlpha * b.colour[3])));
  }
}

TEST_CASE("draw lists: creatures one after another, whole, the floor under their flesh", "[draw]") {
  const Creature c = example("horse");
  const CreatureDrawable d = make_creature_drawable(c, atlas().sprites).value();
  const std::vector<Mat2x3> rest = model_matrices(c.skeleton, c.rest_pose.locals);
  DrawList list;
  for (int k = 0; k < 3; ++k) {
    Transform2D at;
    at.translation = {2.0f * k, -0.08f};  // sunk 8 cm into a ground at y = 0
    std::vector<Mat2x3> world(rest.size());
    for (size_t b = 0; b < rest.size(); ++b) world[b] = at.to_mat2x3() * rest[b];
    const BodyFloor floor = flat_floor(0.0f);
    append_creature(list, d, world, &floor);
  }
  CHECK(list.creature_count == 3);
  CHECK(list.triangle_count() == 3 * d.triangle_count());
  // Creature-major: each creature's commands together, in order (far, body, near: 3 each).
  CHECK(list.commands.size() == 9);
  for (size_t k = 0; k < list.commands.size(); ++k) CHECK(list.commands[k].creature == k / 3);
  float lowest = 1e9f;
  for (const DrawVertex& v : list.vertices) lowest = std::min(lowest, v.position_ws.y);
  CHECK(lowest >= 0.0f);  // no flesh below the ground's top
  const Box b0 = creature_draw_bounds(list, 0), b2 = creature_draw_bounds(list, 2);
  CHECK(b2.min_ws.x == Approx(b0.min_ws.x + 4.0f).margin(1e-4));
  CHECK(b0.width() > 1.0f);
  CHECK(creature_draw_bounds(list, 7).width() == 0.0f);
  list.clear();
  CHECK(list.vertices.empty());
  CHECK(list.creature_count == 0);
}
