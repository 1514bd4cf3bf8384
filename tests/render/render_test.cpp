// Renderer tests under SDL's offscreen driver (no display): shaders, drawing an example, the
// far/near shading, constant draw calls for a crowd, texture fallback, PNG and GIF capture,
// creature images drawn into an offscreen framebuffer.

#include <catch2/catch.hpp>

#include <gif_lib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#pragma GCC diagnostic pop

#include "ossa/gen/skeleton_builder.h"
#include "ossa/level/level.h"
#include "ossa/platform/window.h"
#include "ossa/render/level_view.h"
#include "ossa/render/capture.h"
#include "ossa/render/character_mesh.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/creature_image.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/render/render_target.h"
#include "ossa/render/renderer.h"
#include "ossa/render/shader.h"
#include "ossa/render/texture.h"
#include "render/gl_fixture.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

using test::Gl;
using test::gl;
using test::kH;
using test::kW;

Creature example(const char* name) {
  auto g = scenes::generator().example(name, 1);
  REQUIRE(g.ok());
  auto c = build_creature(g.value());
  REQUIRE(c.ok());
  return std::move(c.value());
}

std::string temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "ossa_render_test";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

Box model_bounds(const Creature& c) {
  const auto model = model_matrices(c.skeleton, c.rest_pose.locals);
  Box b{{1e9f, 1e9f}, {-1e9f, -1e9f}};
  for (int i = 0; i < c.skeleton.bone_count(); ++i) {
    for (glm::vec2 p : {bone_start(model[i]), bone_end(model[i], c.skeleton.length(i))}) {
      b.min_ws = glm::min(b.min_ws, p);
      b.max_ws = glm::max(b.max_ws, p);
    }
  }
  return b;
}

bool is_background(const uint8_t* p, glm::vec3 bg) {
  return std::abs(p[0] - bg.r * 255.0f) < 3.0f && std::abs(p[1] - bg.g * 255.0f) < 3.0f &&
         std::abs(p[2] - bg.b * 255.0f) < 3.0f;
}

// A copy of `mesh` that keeps only the triangles of one layer.
SpriteMesh only_layer(const SpriteMesh& mesh, Layer layer) {
  SpriteMesh m = mesh;
  const int l = static_cast<int>(layer);
  m.indices.assign(mesh.indices.begin() + mesh.layer_begin[l],
                   mesh.indices.begin() + mesh.layer_begin[l + 1]);
  m.layer_begin = {0, 0, 0, 0};
  for (int k = l + 1; k < 4; ++k) m.layer_begin[k] = static_cast<uint32_t>(m.indices.size());
  return m;
}

// Renders `creature` (its mesh, or `mesh` when given) on a flat background, camera fitted.
Image render(const Creature& creature, const SpriteMesh& mesh, glm::vec3 bg, bool naive = false) {
  Gl& g = gl();
  CreatureBatch batch;
  const int id = batch.add(mesh, creature.skeleton);
  batch.set_pose(id, creature.skeleton, creature.rest_pose.locals, Mat2x3::identity());
  batch.upload_palettes();
  g.renderer->camera.fit(model_bounds(creature), float(kW) / kH, 0.1f);
  g.renderer->begin_frame(kW, kH, bg);
  if (naive) {
    g.renderer->draw_batch_naive(batch, g.atlas->texture);
  } else {
    g.renderer->draw_batch(batch, g.atlas->texture);
  }
  REQUIRE(check_gl("render test"));
  return read_framebuffer(kW, kH);
}

double mean_brightness(const Image& img, glm::vec3 bg, int* count) {
  double sum = 0.0;
  *count = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const uint8_t* p = img.pixel(x, y);
      if (is_background(p, bg)) continue;
      sum += (p[0] + p[1] + p[2]) / 3.0;
      ++*count;
    }
  }
  return *count ? sum / *count : 0.0;
}

}  // namespace

TEST_CASE("offscreen window gives a GL 3.3 core context", "[render]") {
  Gl& g = gl();
  CHECK(g.window.is_valid());
  CHECK(g.window.width() == kW);
  CHECK(g.window.height() == kH);
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  CHECK(major * 10 + minor >= 33);
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  CHECK((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
}

TEST_CASE("every shader compiles and links", "[render]") {
  Gl& g = gl();
  for (const ShaderProgram* p : {&g.renderer->debug, &g.renderer->textured, &g.renderer->skinned,
                                 &g.renderer->skinned_naive, &g.renderer->bone, &g.renderer->body}) {
    INFO(p->vertex_path());
    CHECK(p->is_valid());
    GLint linked = 0;
    glGetProgramiv(p->id(), GL_LINK_STATUS, &linked);
    CHECK(linked == GL_TRUE);
  }
  // The tile program (level_view.h).
  auto level_view = LevelView::create(Gl::shader_dir());
  INFO((level_view.ok() ? std::string() : level_view.message()));
  CHECK(level_view.ok());
  // Every shader file in shaders/ belongs to a program the renderer or the level view loads.
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(Gl::shader_dir())) {
    const auto ext = e.path().extension();
    if (ext == ".vert" || ext == ".frag") ++files;
  }
  CHECK(files == 13);
}

TEST_CASE("a shader with a syntax error reports file and line", "[render]") {
  gl();
  const std::string vert = temp_path("broken.vert"), frag = Gl::shader_dir() + "/debug.frag";
  write_text(vert,
             "#version 330 core\n"
             "layout(location = 0) in vec2 a_position;\n"
             "void main() {\n"
             "  vec2 p = a_position\n"          // line 4: missing semicolon
             "  gl_Position = vec4(p, 0.0, 1.0);\n"
             "}\n");
  auto p = ShaderProgram::load(vert, frag);
  REQUIRE_FALSE(p.ok());
  INFO(p.message());
  CHECK(p.message().find(vert + ":") != std::string::npos);
  // Mesa reports the error where the statement ends (line 4 or 5).
  const bool has_line = p.message().find(vert + ":4:") != std::string::npos ||
                        p.message().find(vert + ":5:") != std::string::npos;
  CHECK(has_line);

  auto missing = ShaderProgram::load(temp_path("does-not-exist.vert"), frag);
  REQUIRE_FALSE(missing.ok());
  CHECK(missing.message().find("does-not-exist.vert") != std::string::npos);
}

TEST_CASE("shader logs are rewritten to file:line for Mesa and NVIDIA forms", "[render]") {
  CHECK(format_shader_log("0:12(5): error: syntax error\n", "a.frag") ==
        "a.frag:12:5: error: syntax error");
  CHECK(format_shader_log("0(7) : error C0000: syntax error", "b.vert") ==
        "b.vert:7: error C0000: syntax error");
  CHECK(format_shader_log("no location here", "c.vert") == "no location here");
  CHECK(format_shader_log("0:3(1): warning: x\n0:4(2): error: y", "d.vert") ==
        "d.vert:3:1: warning: x\nd.vert:4:2: error: y");
}

TEST_CASE("a failed reload keeps the old program, a fixed file reloads", "[render]") {
  gl();
  const std::string vert = temp_path("reload.vert"), frag = Gl::shader_dir() + "/debug.frag";
  const std::string good = "#version 330 core\nlayout(location = 0) in vec2 a_position_ws;\n"
                           "layout(location = 1) in vec4 a_colour;\nout vec4 v_colour;\n"
                           "void main() { v_colour = a_colour; gl_Position = vec4(a_position_ws, 0.0, 1.0); }\n";
  write_text(vert, good);
  auto p = ShaderProgram::load(vert, frag);
  REQUIRE(p.ok());
  const unsigned old_id = p->id();
  CHECK_FALSE(p->reload_if_changed());  // nothing changed

  const auto bump = [&] {
    auto t = std::filesystem::last_write_time(vert);
    std::filesystem::last_write_time(vert, t + std::chrono::seconds(2));
  };
  write_text(vert, "#version 330 core\nvoid main() { nonsense }\n");
  bump();
  const int logs = render_log_count();
  CHECK_FALSE(p->reload_if_changed());
  CHECK(p->id() == old_id);
  CHECK(p->is_valid());
  CHECK(render_log_count() == logs + 1);
  CHECK(render_last_log().find("reload.vert:2") != std::string::npos);

  write_text(vert, good);
  bump();
  CHECK(p->reload_if_changed());
  CHECK(p->is_valid());
}

TEST_CASE("an example's sprites fill its projected bounding box and nothing outside", "[render]") {
  Gl& g = gl();
  const glm::vec3 bg{0.1f, 0.2f, 0.3f};
  for (const char* name : {"horse", "kangaroo", "giraffe"}) {
    INFO(name);
    const Creature c = example(name);
    const Image img = render(c, build_sprite_mesh(c, g.atlas->sprites), bg);
    // Sprites are as thick as the bone is wide: pad the joint box by the widest bone.
    float pad = 0.0f;
    for (int i = 0; i < c.skeleton.bone_count(); ++i) pad = std::max(pad, c.skeleton.width(i));
    const Box b = model_bounds(c);
    const glm::vec2 lo = g.renderer->camera.world_to_pixel(b.min_ws - glm::vec2(pad), kW, kH);
    const glm::vec2 hi = g.renderer->camera.world_to_pixel(b.max_ws + glm::vec2(pad), kW, kH);
    int inside = 0, outside = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        if (is_background(img.pixel(x, y), bg)) continue;
        const bool in = x >= lo.x - 1 && x <= hi.x + 1 && y >= hi.y - 1 && y <= lo.y + 1;
        (in ? inside : outside) += 1;
      }
    }
    CHECK(outside == 0);
    // A skeleton covers a good part of its box, not just a few pixels.
    const double box_px = double(hi.x - lo.x) * double(lo.y - hi.y);
    CHECK(inside > 0.03 * box_px);
    // The frame corners are background.
    CHECK(is_background(img.pixel(0, 0), bg));
    CHECK(is_background(img.pixel(kW - 1, kH - 1), bg));
  }
}

TEST_CASE("far-side bones are drawn darker than near-side bones", "[render]") {
  Gl& g = gl();
  const glm::vec3 bg{0.0f, 0.0f, 0.0f};
  for (const char* name : {"horse", "pig", "kangaroo"}) {
    INFO(name);
    const Creature c = example(name);
    const SpriteMesh mesh = build_sprite_mesh(c, g.atlas->sprites);
    REQUIRE(mesh.layer_begin[1] > mesh.layer_begin[0]);  // has far triangles
    REQUIRE(mesh.layer_begin[3] > mesh.layer_begin[2]);  // has near triangles
    int far_n = 0, near_n = 0;
    const double far_b = mean_brightness(render(c, only_layer(mesh, Layer::kFar), bg), bg, &far_n);
    const double near_b = mean_brightness(render(c, only_layer(mesh, Layer::kNear), bg), bg, &near_n);
    CHECK(far_n > 50);
    CHECK(near_n > 50);
    CHECK(far_b < 0.85 * near_b);
  }
}

TEST_CASE("200 creatures take as many draw calls as one", "[render]") {
  Gl& g = gl();
  const Creature c = example("horse");
  const SpriteMesh mesh = build_sprite_mesh(c, g.atlas->sprites);
  auto draw_calls = [&](int n) {
    CreatureBatch batch;
    for (int i = 0; i < n; ++i) {
      const int id = batch.add(mesh, c.skeleton);
      Transform2D place;
      place.translation = {2.5f * float(i % 20), 2.0f * float(i / 20)};
      batch.set_pose(id, c.skeleton, c.rest_pose.locals, place.to_mat2x3());
    }
    batch.upload_palettes();
    g.renderer->camera.fit({{-1.0f, -1.0f}, {50.0f, 20.0f}}, float(kW) / kH);
    g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
    g.renderer->draw_batch(batch, g.atlas->texture);
    CHECK(g.renderer->stats.creatures == n);
    CHECK(g.renderer->stats.bones == n * c.skeleton.bone_count());
    return g.renderer->stats.draw_calls;
  };
  const int one = draw_calls(1);
  CHECK(one >= 1);
  CHECK(one <= kLayerCount);
  CHECK(draw_calls(200) == one);
}

TEST_CASE("layer-major index buffer keeps every layer contiguous across creatures", "[render]") {
  Gl& g = gl();
  CreatureBatch batch;
  std::vector<SpriteMesh> meshes;
  for (const char* name : {"horse", "kangaroo", "magpie"}) {
    const Creature c = example(name);
    meshes.push_back(build_sprite_mesh(c, g.atlas->sprites));
    batch.add(meshes.back(), c.skeleton);
  }
  const auto ranges = batch.layer_ranges();
  uint32_t expected_first = 0;
  for (int l = 0; l < kLayerCount; ++l) {
    uint32_t count = 0;
    for (const SpriteMesh& m : meshes) count += m.layer_begin[l + 1] - m.layer_begin[l];
    CHECK(ranges[l].first == expected_first);
    CHECK(ranges[l].second == count);
    expected_first += count;
  }
}

TEST_CASE("the per-bone reference path draws the same picture as the batch", "[render]") {
  Gl& g = gl();
  const glm::vec3 bg{0.2f, 0.2f, 0.2f};
  const Creature c = example("horse");
  const SpriteMesh mesh = build_sprite_mesh(c, g.atlas->sprites);
  const Image a = render(c, mesh, bg, false);
  const Image b = render(c, mesh, bg, true);
  int differ = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    if (std::abs(a.rgba[i] - b.rgba[i]) > 8 || std::abs(a.rgba[i + 1] - b.rgba[i + 1]) > 8) ++differ;
  }
  CHECK(differ < kW * kH / 200);  // rounding at sprite edges only
}

TEST_CASE("a missing texture gives the checker and no crash", "[render]") {
  gl();
  const int logs = render_log_count();
  Texture t = Texture::load(temp_path("no-such-texture.png"));
  CHECK_FALSE(t.is_valid());
  CHECK(t.is_fallback());
  CHECK(t.id() != 0);
  CHECK(t.width() == 64);
  CHECK(render_log_count() == logs + 1);
  CHECK(render_last_log().find("no-such-texture.png") != std::string::npos);

  // A broken file (not an image) falls back the same way.
  const std::string broken = temp_path("broken.png");
  write_text(broken, "this is not a PNG");
  CHECK(Texture::load(broken).is_fallback());

  // An atlas whose sprite folder is missing packs checker tiles with valid UVs.
  Atlas atlas = Atlas::build(default_sprite_set(), temp_path("no-sprites"));
  CHECK(atlas.missing == static_cast<int>(SpriteId::kCount));
  CHECK(atlas.texture.id() != 0);
  for (const SpriteInfo& s : atlas.sprites.sprites) {
    CHECK(s.uv_min.x < s.uv_max.x);
    CHECK(s.uv_min.y < s.uv_max.y);
    CHECK(s.uv_min.x >= 0.0f);
    CHECK(s.uv_max.y <= 1.0f);
  }
}

TEST_CASE("the shipped sprite atlas packs every sprite without overlap", "[render]") {
  Gl& g = gl();
  CHECK(g.atlas->missing == 0);
  const auto& s = g.atlas->sprites.sprites;
  for (size_t i = 0; i < s.size(); ++i) {
    for (size_t j = i + 1; j < s.size(); ++j) {
      const bool apart = s[i].uv_max.x <= s[j].uv_min.x || s[j].uv_max.x <= s[i].uv_min.x ||
                         s[i].uv_max.y <= s[j].uv_min.y || s[j].uv_max.y <= s[i].uv_min.y;
      CHECK(apart);
    }
  }
}

TEST_CASE("joint reach: how far a sprite's ends reach across the bone, from its alpha", "[render]") {
  // 20 × 10 px, anchors at u 0.1 and 0.8, v 0.5. Opaque: the first 4 columns over rows 2…7
  // (v 0.2…0.8 from the bottom), a 2-row bar in the middle, the last 4 columns over rows 0…5.
  SpriteInfo info;
  info.parent_anchor = {0.1f, 0.5f};
  info.child_anchor = {0.8f, 0.5f};
  Image img{20, 10, std::vector<uint8_t>(20 * 10 * 4, 0)};
  const auto fill = [&](int x0, int x1, int y0, int y1) {
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) img.pixel(x, y)[3] = 255;
    }
  };
  fill(0, 3, 2, 7);
  fill(4, 15, 4, 5);
  fill(16, 19, 0, 5);
  CHECK(joint_reach(info, false) == glm::vec2(0.5f, 0.5f));  // not measured: the whole box
  measure_joint_reach(info, img);
  // Parent end u in [0, 0.2] (columns 0…3): rows 2…7 reach v 0.2 … 0.8.
  CHECK(joint_reach(info, false).x == Approx(0.3f));
  CHECK(joint_reach(info, false).y == Approx(0.3f));
  // Child end u in [0.6, 1] (columns 12…19): rows 0…5 reach v 0.4 … 1.
  CHECK(joint_reach(info, true).x == Approx(0.1f));
  CHECK(joint_reach(info, true).y == Approx(0.5f));
  // The shipped long bone: its distal knob reaches further down than its proximal one.
  const SpriteInfo& bone = gl().atlas->sprites[SpriteId::kLongBone];
  CHECK(joint_reach(bone, true).x > joint_reach(bone, false).x);
  CHECK(joint_reach(bone, true).x < 0.5f);
}

TEST_CASE("PNG capture round-trips", "[render]") {
  Gl& g = gl();
  DebugDraw debug;
  debug.add_box({{-1.0f, -1.0f}, {0.0f, 0.0f}}, {1.0f, 0.0f, 0.0f, 1.0f}, true);
  g.renderer->camera = Camera2D{};
  g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 1.0f});
  g.renderer->camera.center_ws = {0.0f, 0.0f};
  g.renderer->camera.half_height = 1.0f;
  g.renderer->draw_debug(debug);
  const Image frame = read_framebuffer(kW, kH);
  // The box (below-left of the centre) red, the top right blue: rows are top to bottom.
  const glm::vec2 red = g.renderer->camera.world_to_pixel({-0.5f, -0.5f}, kW, kH);
  CHECK(red.y > kH / 2);
  CHECK(frame.pixel(int(red.x), int(red.y))[0] == 255);
  CHECK(frame.pixel(int(red.x), int(red.y))[2] == 0);
  CHECK(frame.pixel(kW - 10, 10)[2] == 255);

  const std::string path = temp_path("capture.png");
  REQUIRE(write_png(path, frame).ok());
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  REQUIRE(data != nullptr);
  CHECK(w == kW);
  CHECK(h == kH);
  CHECK(std::equal(frame.rgba.begin(), frame.rgba.end(), data));
  stbi_image_free(data);

  CHECK_FALSE(write_png(temp_path("no/such/dir.png"), frame).ok());
}

TEST_CASE("GIF capture writes a valid looping GIF with every frame", "[render]") {
  Gl& g = gl();
  const std::string path = temp_path("capture.gif");
  auto gif = GifWriter::open(path, kW, kH, 5);
  REQUIRE(gif.ok());
  for (int f = 0; f < 4; ++f) {
    DebugDraw debug;
    debug.add_box({{-1.0f + 0.4f * f, -0.5f}, {-0.6f + 0.4f * f, 0.5f}}, {1.0f, 1.0f, 0.0f, 1.0f}, true);
    g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
    g.renderer->camera.center_ws = {0.0f, 0.0f};
    g.renderer->camera.half_height = 1.0f;
    g.renderer->draw_debug(debug);
    REQUIRE(gif->add_frame(read_framebuffer(kW, kH)).ok());
  }
  CHECK_FALSE(gif->add_frame(Image{}).ok());  // wrong size is an error, not a crash
  REQUIRE(gif->close().ok());

  std::ifstream in(path, std::ios::binary);
  char header[6] = {};
  in.read(header, 6);
  CHECK(std::string(header, 6) == "GIF89a");

  int err = 0;
  GifFileType* file = DGifOpenFileName(path.c_str(), &err);
  REQUIRE(file != nullptr);
  REQUIRE(DGifSlurp(file) == GIF_OK);
  CHECK(file->SWidth == kW);
  CHECK(file->SHeight == kH);
  CHECK(file->ImageCount == 4);
  // Yellow and black map to exact palette entries.
  const ColorMapObject* map = file->SColorMap;
  REQUIRE(map != nullptr);
  const GifByteType* raster = file->SavedImages[0].RasterBits;
  const GifColorType corner = map->Colors[raster[0]];
  CHECK((corner.Red == 0 && corner.Green == 0 && corner.Blue == 0));
  DGifCloseFile(file, &err);
}

TEST_CASE("GIF palette maps colours to their nearest entry", "[render]") {
  for (int r = 0; r < 256; r += 17) {
    for (int g = 0; g < 256; g += 17) {
      for (int b = 0; b < 256; b += 17) {
        const uint32_t c = gif_palette_colour(gif_palette_index(r, g, b));
        const int dr = int(c >> 16) - r, dg = int((c >> 8) & 255) - g, db = int(c & 255) - b;
        CHECK(dr * dr + dg * dg + db * db <= 3 * 26 * 26);
      }
    }
  }
  CHECK(gif_palette_colour(gif_palette_index(255, 255, 255)) == 0xffffffu);
}

TEST_CASE("the camera maps its visible box to the viewport corners", "[render]") {
  Camera2D cam;
  cam.fit({{2.0f, -1.0f}, {6.0f, 1.0f}}, 2.0f, 0.0f);
  const Box v = cam.visible_box();
  CHECK(v.min_ws.x == Approx(2.0f));
  CHECK(v.max_ws.x == Approx(6.0f));
  const glm::vec2 tl = cam.world_to_pixel({v.min_ws.x, v.max_ws.y}, 200, 100);
  const glm::vec2 br = cam.world_to_pixel({v.max_ws.x, v.min_ws.y}, 200, 100);
  CHECK(tl.x == Approx(0.0f).margin(1e-3));
  CHECK(tl.y == Approx(0.0f).margin(1e-3));
  CHECK(br.x == Approx(200.0f));
  CHECK(br.y == Approx(100.0f));
}

TEST_CASE("bone lines and debug shapes draw with the bone and debug programs", "[render]") {
  Gl& g = gl();
  const Creature c = example("horse");
  CreatureBatch batch;
  const int id = batch.add(build_sprite_mesh(c, g.atlas->sprites), c.skeleton);
  batch.set_pose(id, c.skeleton, c.rest_pose.locals, Mat2x3::identity());
  batch.upload_palettes();
  Level level({Box::from_corner(-5.0f, -1.0f, 10.0f, 1.0f)});
  DebugDraw debug;
  debug.add_level(level, {0.0f, 1.0f, 0.0f, 1.0f}, {0.0f, 0.5f, 0.0f, 1.0f});
  const glm::vec2 spline[3] = {{0.0f, 0.5f}, {0.5f, 0.8f}, {1.0f, 0.5f}};
  debug.add_polyline(spline, {1.0f, 1.0f, 1.0f, 1.0f});
  debug.add_cross({0.5f, 0.2f}, 0.05f, {1.0f, 0.0f, 1.0f, 1.0f});
  g.renderer->camera.fit(model_bounds(c), float(kW) / kH);
  g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
  g.renderer->draw_debug(debug);
  g.renderer->draw_bones(batch, {1.0f, 0.0f, 0.0f, 1.0f});
  CHECK(g.renderer->stats.draw_calls == 3);
  CHECK(check_gl("bone lines"));
  const Image img = read_framebuffer(kW, kH);
  int red = 0, green = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) {
    red += img.rgba[i] == 255 && img.rgba[i + 1] == 0 && img.rgba[i + 2] == 0;
    green += img.rgba[i] == 0 && img.rgba[i + 1] == 255 && img.rgba[i + 2] == 0;
  }
  CHECK(red > 100);    // skeleton lines
  CHECK(green > 100);  // the ground box below the feet
}

TEST_CASE("a creature image is the window's picture, framed on the sprites, GL state kept", "[render]") {
  Gl& g = gl();
  const Creature c = example("horse");
  const Box sprites = sprite_mesh_bounds(build_sprite_mesh(c, g.atlas->sprites));
  // The window shows something else; the game's camera looks elsewhere.
  Camera2D game_camera;
  game_camera.center_ws = {3.0f, 4.0f};
  g.renderer->camera = game_camera;
  g.renderer->begin_frame(kW, kH, {1.0f, 0.0f, 0.0f});
  g.renderer->stats.draw_calls = 7;

  for (const glm::vec4 bg : {glm::vec4(0.0f), glm::vec4(0.1f, 0.2f, 0.3f, 1.0f)}) {
    INFO("background alpha " << bg.a);
    CreatureImageOptions o;
    o.width = kW;
    o.height = kH;
    o.background = bg;
    o.margin = 0.05f;
    o.look = CreatureLook::kBones;  // compared below with the sprites drawn in the window
    auto img = render_creature_image(*g.renderer, *g.atlas, c, o);
    REQUIRE(img.ok());
    REQUIRE((img->width == kW && img->height == kH));

    // The caller's frame is untouched: window framebuffer bound, viewport, camera, stats, pixels.
    GLint draw_fb = -1, read_fb = -1, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_fb);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fb);
    glGetIntegerv(GL_VIEWPORT, viewport);
    CHECK((draw_fb == 0 && read_fb == 0));
    CHECK((viewport[2] == kW && viewport[3] == kH));
    CHECK(g.renderer->camera.center_ws == game_camera.center_ws);
    CHECK(g.renderer->stats.draw_calls == 7);
    const Image window = read_framebuffer(kW, kH);
    CHECK((window.pixel(kW / 2, kH / 2)[0] == 255 && window.pixel(kW / 2, kH / 2)[1] == 0));

    // Transparent corners (or the background), sprites inside, touching the margin box.
    CHECK(img->pixel(0, 0)[3] == (bg.a > 0.0f ? 255 : 0));
    int x0 = kW, x1 = -1, y0 = kH, y1 = -1;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const uint8_t* p = img->pixel(x, y);
        const bool creature = bg.a > 0.0f ? !is_background(p, glm::vec3(bg)) : p[3] > 0;
        if (!creature) continue;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    }
    REQUIRE(x1 >= 0);
    CHECK((x0 > 0 && y0 > 0 && x1 < kW - 1 && y1 < kH - 1));  // fully in frame
    const float fill_x = float(x1 - x0 + 1) / kW, fill_y = float(y1 - y0 + 1) / kH;
    CHECK(std::max(fill_x, fill_y) > 0.85f);                  // framed on the creature

    // The same picture as the window path with the same camera (so the right way up).
    g.renderer->camera.fit(sprites, float(kW) / kH, o.margin);
    CreatureBatch batch;
    const int id = batch.add(build_sprite_mesh(c, g.atlas->sprites), c.skeleton);
    batch.set_pose(id, c.skeleton, c.rest_pose.locals, Mat2x3::identity());
    batch.upload_palettes();
    g.renderer->begin_frame(kW, kH, glm::vec3(bg));
    g.renderer->draw_batch(batch, g.atlas->texture);
    const Image reference = read_framebuffer(kW, kH);
    int differ = 0;
    for (size_t i = 0; i < reference.rgba.size(); i += 4) {
      const float a = img->rgba[i + 3] / 255.0f;  // straight alpha: over the background again
      for (size_t k = 0; k < 3; ++k) {
        const float over = img->rgba[i + k] * a + bg[static_cast<int>(k)] * 255.0f * (1.0f - a);
        differ += std::abs(over - reference.rgba[i + k]) > 3.0f;
      }
    }
    CHECK(differ == 0);
    // Back to the game's frame for the next round.
    g.renderer->camera = game_camera;
    g.renderer->begin_frame(kW, kH, {1.0f, 0.0f, 0.0f});
    g.renderer->stats.draw_calls = 7;
  }
}

TEST_CASE("creature images refuse bad sizes, and the PNG writer names the file", "[render]") {
  Gl& g = gl();
  const Creature c = example("pig");
  CreatureImageOptions o;
  o.width = 0;
  auto img = render_creature_image(*g.renderer, *g.atlas, c, o);
  REQUIRE_FALSE(img.ok());
  CHECK(img.message().find("0x600") != std::string::npos);
  o.width = RenderTarget::kMaxSize + 1;
  CHECK_FALSE(render_creature_image(*g.renderer, *g.atlas, c, o).ok());
  o.width = 64;
  o.height = 48;
  const std::string path = temp_path("pig.png");
  REQUIRE(write_creature_png(path, c, o, Gl::shader_dir(), scenes::source_path("assets/sprites/bones")).ok());
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  REQUIRE(data != nullptr);
  CHECK((w == 64 && h == 48));
  stbi_image_free(data);
  const Status bad = write_creature_png(temp_path("no/such/dir/pig.png"), c, o, Gl::shader_dir());
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.message().find("no/such/dir/pig.png") != std::string::npos);
  const Status no_shaders = write_creature_png(path, c, o, temp_path("no-shaders"));
  REQUIRE_FALSE(no_shaders.ok());
  CHECK(no_shaders.message().find("pig.png") != std::string::npos);
}

TEST_CASE("creatures and rigged characters share one batch: one palette upload, a draw per layer and texture", "[render][character]") {
  Gl& g = gl();
  const Creature horse = example("horse");
  Result<LoadedCharacter> human = load_character(scenes::source_path("assets/characters/humanoid.rig.json"));
  REQUIRE(human.ok());
  const Character& ch = *human->character;
  CreatureBatch batch;
  const int h = batch.add(build_sprite_mesh(horse, g.atlas->sprites), horse.skeleton);
  const int c = batch.add(human->sprite_mesh, ch.skeleton, 1);
  CHECK(batch.texture_slots() == 2);
  batch.set_pose(h, horse.skeleton, horse.rest_pose.locals, Mat2x3::identity());
  Transform2D beside;
  beside.translation = {2.5f, 0.0f};
  batch.set_pose(c, ch.skeleton, ch.rest_pose.locals, beside.to_mat2x3());
  batch.upload_palettes();  // once, for both
  const Texture texture = Texture::from_image(Image{human->mesh.texture_width, human->mesh.texture_height, human->mesh.texture_rgba});
  const Texture* textures[] = {&g.atlas->texture, &texture};
  g.renderer->camera.fit({{-1.5f, -0.2f}, {3.5f, 2.0f}}, float(kW) / kH);
  g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
  g.renderer->draw_batch(batch, textures);
  CHECK(g.renderer->stats.draw_calls == 4);  // the horse's three layers, the character's body
  CHECK(check_gl("creatures and characters"));
  // The character's shirt shows (red), right of the horse.
  const Image img = read_framebuffer(kW, kH);
  int shirt = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = kW / 2; x < kW; ++x) {
      const uint8_t* p = img.pixel(x, y);
      shirt += p[0] > 180 && p[1] < 110 && p[2] < 100;
    }
  }
  CHECK(shirt > 50);
}
