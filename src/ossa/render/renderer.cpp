#include "ossa/render/renderer.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstddef>
#include <span>

#include "ossa/io/data_dir.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/render/render_target.h"
#include "ossa/render/texture.h"
#include "ossa/render/vertex_array.h"

namespace ossa {
std::span<const VertexAttrib> TexturedVertex::layout() {
  static const std::array<VertexAttrib, 2> kLayout{{
      {0, 2, GL_FLOAT, false, false, offsetof(TexturedVertex, position_ws)},
      {1, 2, GL_FLOAT, false, false, offsetof(TexturedVertex, uv)},
  }};
  return kLayout;
}

glm::mat3 Camera2D::view_proj() const {
  const float sx = 1.0f / (half_height * aspect), sy = 1.0f / half_height;
  // Column-major: columns are the images of x, y and the translation.
  return glm::mat3(sx, 0.0f, 0.0f, 0.0f, sy, 0.0f, -center_ws.x * sx, -center_ws.y * sy, 1.0f);
}

void Camera2D::fit(const Box& box, float new_aspect, float margin) {
  aspect = new_aspect > 0.0f ? new_aspect : 1.0f;
  center_ws = box.center();
  const float half_w = 0.5f * std::max(box.width(), 1e-3f) * (1.0f + 2.0f * margin);
  const float half_h = 0.5f * std::max(box.height(), 1e-3f) * (1.0f + 2.0f * margin);
  half_height = std::max(half_h, half_w / aspect);
}

glm::vec2 Camera2D::world_to_pixel(glm::vec2 p, int width, int height) const {
  const glm::vec3 c = view_proj() * glm::vec3(p, 1.0f);
  return {(c.x * 0.5f + 0.5f) * width, (0.5f - c.y * 0.5f) * height};
}

Box Camera2D::visible_box() const {
  const glm::vec2 h{half_height * aspect, half_height};
  return {center_ws - h, center_ws + h};
}

std::string default_shader_dir() { return data_path("shaders"); }

Result<Renderer> Renderer::create(const std::string& dir) {
  Renderer r;
  struct Entry { ShaderProgram* program; const char* vert; const char* frag; };
  const Entry entries[] = {
      {&r.debug, "debug.vert", "debug.frag"},
      {&r.textured, "textured.vert", "textured.frag"},
      {&r.skinned, "skinned.vert", "skinned.frag"},
      {&r.skinned_naive, "skinned_naive.vert", "skinned.frag"},
      {&r.body, "body.vert", "body.frag"},
      {&r.bone, "bone.vert", "bone.frag"},
  };
  for (const Entry& e : entries) {
    auto p = ShaderProgram::load(dir + "/" + e.vert, dir + "/" + e.frag);
    if (!p.ok()) return Error{p.message()};
    *e.program = std::move(p.value());
  }
  return r;
}

void Renderer::begin_frame(int width, int height, glm::vec3 clear_rgb) {
  setup_frame(0, width, height, glm::vec4(clear_rgb, 1.0f));
}

void Renderer::begin_frame(const RenderTarget& target, glm::vec4 clear_rgba) {
  setup_frame(target.framebuffer(), target.width(), target.height(), clear_rgba);
}

void Renderer::setup_frame(unsigned framebuffer, int width, int height, glm::vec4 clear_rgba) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glClearColor(clear_rgba.r, clear_rgba.g, clear_rgba.b, clear_rgba.a);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // mirrored creatures flip the winding
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (height > 0) camera.aspect = static_cast<float>(width) / static_cast<float>(height);
  stats = {};
}

int Renderer::reload_shaders_if_changed() {
  int n = 0;
  for (ShaderProgram* p : {&debug, &textured, &skinned, &skinned_naive, &bone, &body}) {
    n += p->reload_if_changed() ? 1 : 0;
  }
  return n;
}

void Renderer::draw_debug(DebugDraw& d) {
  debug.use();
  debug.set("u_view_proj", camera.view_proj());
  debug.set("u_colour", glm::vec4(1.0f));
  stats.vertices += static_cast<int>(d.lines().size() + d.triangles().size());
  stats.draw_calls += d.draw();
}

void Renderer::count_batch(const CreatureBatch& batch, int calls) {
  stats.draw_calls += calls;
  stats.creatures += batch.creature_count();
  stats.bones += batch.bone_count();
  stats.vertices += batch.vertex_count();
}

void Renderer::draw_batch(CreatureBatch& batch, const Texture& atlas) {
  skinned.use();
  skinned.set("u_view_proj", camera.view_proj());
  count_batch(batch, batch.draw(skinned, atlas.id()));
}

void Renderer::draw_batch(CreatureBatch& batch, std::span<const Texture* const> textures) {
  std::vector<unsigned> ids;
  for (const Texture* t : textures) ids.push_back(t ? t->id() : 0u);
  skinned.use();
  skinned.set("u_view_proj", camera.view_proj());
  count_batch(batch, batch.draw(skinned, ids));
}

void Renderer::draw_batch_naive(CreatureBatch& batch, const Texture& atlas) {
  skinned_naive.use();
  skinned_naive.set("u_view_proj", camera.view_proj());
  count_batch(batch, batch.draw_naive(skinned_naive, atlas.id()));
}

void Renderer::draw_bodies(CreatureBatch& batch, float alpha) {
  body.use();
  body.set("u_view_proj", camera.view_proj());
  stats.draw_calls += batch.draw_bodies(body, alpha);
  stats.creatures += batch.creature_count();
  stats.vertices += batch.body_vertex_count();
}

void Renderer::draw_creatures(CreatureBatch& batch, std::span<const Texture* const> textures, CreatureLook look) {
  std::vector<unsigned> ids;
  for (const Texture* t : textures) ids.push_back(t ? t->id() : 0u);
  if (look != CreatureLook::kXray) {
    if (batch.body_vertex_count() > 0) draw_bodies(batch, 1.0f);
    if (batch.vertex_count() > 0) {
      skinned.use();
      skinned.set("u_view_proj", camera.view_proj());
      stats.draw_calls += batch.draw(skinned, ids);
      stats.vertices += batch.vertex_count();
    }
    stats.creatures += batch.creature_count();
    stats.bones += batch.bone_count();
    return;
  }
  // X-ray: each layer's bones, then that layer's bodies translucent over them.
  for (int l = 0; l < kLayerCount; ++l) {
    skinned.use();
    skinned.set("u_view_proj", camera.view_proj());
    stats.draw_calls += batch.draw_layer(skinned, ids, l);
    body.use();
    body.set("u_view_proj", camera.view_proj());
    stats.draw_calls += batch.draw_body_layer(body, l, kXrayBodyAlpha);
  }
  stats.creatures += batch.creature_count();
  stats.bones += batch.bone_count();
  stats.vertices += batch.vertex_count() + batch.body_vertex_count();
}

void Renderer::draw_bones(CreatureBatch& batch, glm::vec4 colour) {
  bone.use();
  bone.set("u_view_proj", camera.view_proj());
  bone.set("u_colour", colour);
  stats.draw_calls += batch.draw_bones(bone);
  stats.vertices += 2 * batch.bone_count();
}

void Renderer::draw_textured_box(const Texture& texture, const Box& b, glm::vec4 tint, glm::vec2 uv_min, glm::vec2 uv_max) {
  if (!quad_) quad_ = std::make_unique<VertexArray<TexturedVertex>>();
  const glm::vec2 a = uv_min, c = uv_max;
  const TexturedVertex v[6] = {
      {{b.min_ws.x, b.min_ws.y}, {a.x, a.y}}, {{b.max_ws.x, b.min_ws.y}, {c.x, a.y}},
      {{b.max_ws.x, b.max_ws.y}, {c.x, c.y}}, {{b.min_ws.x, b.min_ws.y}, {a.x, a.y}},
      {{b.max_ws.x, b.max_ws.y}, {c.x, c.y}}, {{b.min_ws.x, b.max_ws.y}, {a.x, c.y}}};
  quad_->upload(v, {}, GL_STREAM_DRAW);
  textured.use();
  textured.set("u_view_proj", camera.view_proj());
  textured.set("u_tint", tint);
  textured.set("u_texture", 0);
  texture.bind(0);
  quad_->draw(GL_TRIANGLES);
  stats.draw_calls += 1;
  stats.vertices += 6;
}

}  // namespace ossa
