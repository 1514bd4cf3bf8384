// Bodies drawn by the GPU (issue 30): the body program draws what the CPU skins (body_mesh.h's
// skin_body_vertex and the floor, body_floor.h), one draw per layer however many creatures,
// and one palette upload per frame for sprites and bodies together.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "gl_fixture.h"
#include "ossa/body/body_floor.h"
#include "ossa/body/body_mesh.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/render/capture.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/gl.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/skeleton/pose.h"

using namespace ossa;
using namespace ossa::test;

namespace {

Creature example(const char* name) { return build_creature(scenes::generator().example(name).value()).value(); }

bool background(const uint8_t* p, glm::vec3 bg) {
  return std::abs(p[0] - bg.r * 255.0f) < 3.0f && std::abs(p[1] - bg.g * 255.0f) < 3.0f && std::abs(p[2] - bg.b * 255.0f) < 3.0f;
}

}  // namespace

TEST_CASE("bodies: the GPU draws what the CPU skins, flesh resting on the floor", "[render][body]") {
  // A horse in its rest pose sunk to its belly into a ground whose top is y = 0 under its hind
  // half and 15 cm higher under its fore half: the shader lifts the flesh below a top onto it,
  // and the trunk's flesh within its overhang of the higher top's end too, as floor_point()
  // does. The pixels the GPU covers are the pixels the CPU's skinned, floored triangles cover
  // (up to the edges' antialiasing).
  Gl& g = gl();
  const glm::vec3 bg{0.1f, 0.2f, 0.3f};
  const Creature c = example("horse");
  const BodyMesh body = build_body(c);
  const Box rest = body_bounds(body);
  const float mid = 0.5f * (rest.min_ws.x + rest.max_ws.x);
  Level level;
  level.add_box(Box::from_corner(-10.0f, -2.0f, 10.0f + mid, 2.0f));
  level.add_box(Box::from_corner(mid, -2.0f, 10.0f, 2.15f));
  Transform2D sunk;
  sunk.translation = {0.0f, -0.85f};
  const std::vector<Mat2x3> model = model_matrices(c.skeleton, c.rest_pose.locals);
  std::vector<Mat2x3> world(model.size());
  for (size_t b = 0; b < model.size(); ++b) world[b] = sunk.to_mat2x3() * model[b];
  const BodyFloor floor = body_floor(level, c.skeleton, world, body.reach, body.feet);
  REQUIRE(floor.count == 2);

  CreatureBatch batch;
  const int id = batch.add_body(body, c.skeleton);
  batch.set_world(id, world);
  batch.set_floor(id, floor);
  batch.upload_palettes();
  const Box b = body_bounds(body);
  g.renderer->camera.fit({b.min_ws - glm::vec2(0.1f), b.max_ws + glm::vec2(0.1f)}, float(kW) / kH);
  g.renderer->begin_frame(kW, kH, bg);
  g.renderer->draw_creatures(batch, {}, CreatureLook::kBody);
  CHECK(check_gl("bodies"));
  CHECK(g.renderer->stats.draw_calls == 1);  // every body at once, creature by creature
  CHECK(batch.palette_uploads() == 1);
  const Image img = read_framebuffer(kW, kH);

  // The CPU's picture: every vertex skinned and floored, the triangles' pixel centres.
  std::vector<Mat2x3> palette(static_cast<size_t>(body.palette_size()));
  body_palette(body, world, palette, floor);
  std::vector<glm::vec2> px(body.vertices.size());
  float lowest = 1e9f;
  int overhung = 0;  // held up on the higher top short of its end
  for (size_t i = 0; i < px.size(); ++i) {
    const glm::vec2 p = drawn_body_vertex(body.vertices[i], palette, floor);
    lowest = std::min(lowest, p.y);
    overhung += p.x < mid && p.y == floor.segments[1].z;
    px[i] = g.renderer->camera.world_to_pixel(p, kW, kH);
  }
  CHECK(lowest >= 0.0f);  // nothing below the ground's top
  CHECK(overhung > 0);
  const std::vector<uint8_t> cpu = covered_pixels(px, body.indices);
  // read_framebuffer's rows: top row first (as world_to_pixel's y).
  int both = 0, either = 0, below_ground = 0;
  const float ground_px = g.renderer->camera.world_to_pixel({0.0f, 0.0f}, kW, kH).y;
  // Where only the overhang holds the flesh up: just short of the higher top's end, below it.
  float overhang = 0.0f;
  for (const BodyVertex& v : body.vertices) overhang = v.foot == kNoFoot ? std::max(overhang, v.overhang) : overhang;
  const glm::vec2 held_lo = g.renderer->camera.world_to_pixel({mid - overhang, floor.segments[1].z}, kW, kH);
  const glm::vec2 held_hi = g.renderer->camera.world_to_pixel({mid, 0.0f}, kW, kH);
  int held_cpu = 0, held_differ = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool gpu = !background(img.pixel(x, y), bg);
      const bool mine = cpu[static_cast<size_t>(y * kW + x)] != 0;
      both += gpu && mine;
      either += gpu || mine;
      below_ground += gpu && y > ground_px + 1.0f;
      if (x >= held_lo.x && x < held_hi.x && y >= held_lo.y && y < held_hi.y) held_cpu += mine, held_differ += gpu != mine;
    }
  }
  INFO("both " << both << ", either " << either << "; short of the higher top: " << held_cpu << " drawn, " << held_differ << " differ");
  REQUIRE(either > 2000);
  CHECK(static_cast<double>(both) / either > 0.95);
  CHECK(below_ground == 0);
  CHECK(held_cpu > 0);
  CHECK(held_differ < held_cpu / 4);
}

TEST_CASE("bodies: a leg's flesh rests level past the edge of the top its foot stands on, in the shader too", "[render][body]") {
  // A horse in its rest pose, its foremost hoof's tip 2 mm short of the end of the ground's
  // top, the ground 0.3 m lower beyond: the hoof's flesh out over the edge is held level with
  // the top (body_floor.h, floor_point with the vertex's foot), by the GPU as by the CPU.
  Gl& g = gl();
  const glm::vec3 bg{0.1f, 0.2f, 0.3f};
  const Creature c = example("horse");
  const BodyMesh body = build_body(c);
  REQUIRE(body.feet.size() == 4);
  const std::vector<Mat2x3> world = model_matrices(c.skeleton, c.rest_pose.locals);
  glm::vec2 toe(-1e9f);
  for (const BodyFoot& f : body.feet) {
    const glm::vec2 t = bone_end(world[static_cast<size_t>(f.toe_bone)], c.skeleton.length(f.toe_bone));
    if (t.x > toe.x) toe = t;
  }
  const float edge = toe.x + 0.002f;
  Level level;
  level.add_box(Box::from_corner(-10.0f, toe.y - 2.0f, 10.0f + edge, 2.0f));
  level.add_box(Box::from_corner(edge, toe.y - 2.0f, 10.0f, 1.7f));
  const BodyFloor floor = body_floor(level, c.skeleton, world, body.reach, body.feet);
  BodyFloor no_feet = floor;
  no_feet.feet.fill(glm::vec3(1.0f, 0.0f, 0.0f));

  CreatureBatch batch;
  const int id = batch.add_body(body, c.skeleton);
  batch.set_world(id, world);
  batch.set_floor(id, floor);
  batch.upload_palettes();
  const glm::vec2 lo = toe - glm::vec2(0.15f), hi = toe + glm::vec2(0.15f);
  g.renderer->camera.fit({lo, hi}, float(kW) / kH);
  g.renderer->begin_frame(kW, kH, bg);
  g.renderer->draw_creatures(batch, {}, CreatureLook::kBody);
  CHECK(check_gl("bodies at an edge"));
  const Image img = read_framebuffer(kW, kH);

  std::vector<Mat2x3> palette(static_cast<size_t>(body.palette_size()));
  body_palette(body, world, palette, floor);
  std::vector<glm::vec2> px(body.vertices.size());
  int held = 0;  // held level past the edge by its own foot's top
  float below = 0.0f;
  for (size_t i = 0; i < px.size(); ++i) {
    const BodyVertex& v = body.vertices[i];
    const glm::vec2 p = drawn_body_vertex(v, palette, floor);
    const glm::vec2 unheld = floor_point(skin_body_vertex(v, palette), no_feet, v.overhang, v.foot);
    if (p.y != unheld.y) {
      ++held;
      CHECK(p.x > edge);
      CHECK(p.y == Approx(toe.y).margin(1e-5));
      below = std::max(below, p.y - unheld.y);
    }
    px[i] = g.renderer->camera.world_to_pixel(p, kW, kH);
  }
  INFO("held " << held << " vertices, up to " << below << " m");
  CHECK(held > 0);
  CHECK(below < 0.05f);
  // The pixels past the edge below the top's height: the GPU's are the CPU's.
  const glm::vec2 corner = g.renderer->camera.world_to_pixel({edge, toe.y}, kW, kH);
  const glm::vec2 low = g.renderer->camera.world_to_pixel({edge, toe.y - 0.1f}, kW, kH);
  const std::vector<uint8_t> cpu = covered_pixels(px, body.indices);
  int both = 0, either = 0, gpu_below = 0, cpu_below = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool gpu = !background(img.pixel(x, y), bg);
      const bool mine = cpu[static_cast<size_t>(y * kW + x)] != 0;
      both += gpu && mine;
      either += gpu || mine;
      if (x > corner.x + 1.0f && y > corner.y + 1.0f && y < low.y) gpu_below += gpu, cpu_below += mine;
    }
  }
  INFO("both " << both << ", either " << either << "; below the top past the edge: GPU " << gpu_below << ", CPU " << cpu_below);
  REQUIRE(either > 2000);
  CHECK(static_cast<double>(both) / either > 0.95);
  CHECK(cpu_below == 0);
  CHECK(gpu_below <= 2 * kW / 100);  // antialiased edge pixels at most
}

TEST_CASE("bodies: the body look is one draw, the x-ray look a draw per layer each, from one palette upload", "[render][body]") {
  Gl& g = gl();
  const Creature c = example("pig");
  const BodyMesh body = build_body(c);
  const SpriteMesh sprites = build_sprite_mesh(c, g.atlas->sprites);
  auto draw = [&](int n, CreatureLook look) {
    CreatureBatch batch;
    for (int i = 0; i < n; ++i) {
      Transform2D place;
      place.translation = {2.5f * static_cast<float>(i % 20), 2.0f * static_cast<float>(i / 20)};
      if (look != CreatureLook::kBody) batch.set_pose(batch.add(sprites, c.skeleton), c.skeleton, c.rest_pose.locals, place.to_mat2x3());
      if (look != CreatureLook::kBones) batch.set_pose(batch.add_body(body, c.skeleton), c.skeleton, c.rest_pose.locals, place.to_mat2x3());
    }
    batch.upload_palettes();
    g.renderer->camera.fit({{-1.0f, -1.0f}, {50.0f, 20.0f}}, float(kW) / kH);
    g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
    const Texture* textures[] = {&g.atlas->texture};
    g.renderer->draw_creatures(batch, textures, look);
    CHECK(batch.palette_uploads() == 1);
    CHECK(check_gl("x-ray"));
    return g.renderer->stats.draw_calls;
  };
  CHECK(draw(1, CreatureLook::kBody) == 1);
  CHECK(draw(1, CreatureLook::kXray) == 2 * kLayerCount);
  // However many creatures.
  CHECK(draw(300, CreatureLook::kBody) == 1);
  CHECK(draw(300, CreatureLook::kXray) == 2 * kLayerCount);
}

TEST_CASE("bodies: overlapping creatures do not interleave (the later one is wholly in front)", "[render][body]") {
  // Two pigs on the same spot, a blue one added first and a red one after: wherever the red
  // one covers the picture it is drawn exactly as if alone — the blue one's near legs (drawn
  // after the bodies' trunks by a layer-major order) never show through it.
  Gl& g = gl();
  const glm::vec3 bg{0.1f, 0.2f, 0.3f};
  Creature blue = example("pig"), red = example("pig");
  blue.look.base = blue.look.belly = {0.1f, 0.2f, 0.9f};
  red.look.base = red.look.belly = {0.9f, 0.1f, 0.1f};
  blue.look.pattern = red.look.pattern = CoatPattern::kNone;
  const BodyMesh blue_body = build_body(blue), red_body = build_body(red);
  Transform2D shifted;
  shifted.translation = {0.15f, 0.0f};  // a little ahead: the blue legs under the red trunk
  const auto picture = [&](bool both) {
    CreatureBatch batch;
    if (both) batch.set_pose(batch.add_body(blue_body, blue.skeleton), blue.skeleton, blue.rest_pose.locals, shifted.to_mat2x3());
    batch.set_pose(batch.add_body(red_body, red.skeleton), red.skeleton, red.rest_pose.locals, Mat2x3::identity());
    batch.upload_palettes();
    const Box b = body_bounds(red_body);
    g.renderer->camera.fit({b.min_ws - glm::vec2(0.3f), b.max_ws + glm::vec2(0.3f)}, float(kW) / kH);
    g.renderer->begin_frame(kW, kH, bg);
    g.renderer->draw_creatures(batch, {}, CreatureLook::kBody);
    return read_framebuffer(kW, kH);
  };
  const Image alone = picture(false), both = picture(true);
  int covered = 0, differ = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      if (background(alone.pixel(x, y), bg)) continue;
      ++covered;
      const uint8_t* a = alone.pixel(x, y);
      const uint8_t* b = both.pixel(x, y);
      differ += std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 6;
    }
  }
  REQUIRE(covered > 2000);
  CHECK(differ < covered / 200);  // antialiased edges only
}
