#pragma once
// Renderer — owns the four programs of [T 4.3.1] (Debug, Textured, Rigged = "skinned",
// Bone, plus the per-bone reference "skinned_naive"), the 2D camera and the draw statistics.
//
//   auto renderer = Renderer::create(default_shader_dir());
//   renderer->camera.fit(bounds_ws, aspect);
//   renderer->begin_frame(width, height, background);
//   renderer->draw_debug(debug);            // ground, colliders, splines, targets
//   renderer->draw_batch(batch, atlas.texture);
//   renderer->stats.draw_calls              // for --stats

#include <memory>
#include <span>
#include <string>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "ossa/body/body_mesh.h"
#include "ossa/io/result.h"
#include "ossa/level/box.h"
#include "ossa/render/shader.h"
#include "ossa/render/vertex_array.h"

namespace ossa {

class CreatureBatch;
class DebugDraw;
class RenderTarget;
class Texture;

// The textured program's vertex (world space).
struct TexturedVertex {
  glm::vec2 position_ws{0.0f};
  glm::vec2 uv{0.0f};
  static std::span<const VertexAttrib> layout();
};

// 2D orthographic camera: world metres → clip space. Square pixels: the visible world box is
// 2·half_height·aspect wide and 2·half_height high, centred on center_ws.
struct Camera2D {
  glm::vec2 center_ws{0.0f};
  float half_height = 2.0f;     // metres, > 0
  float aspect = 16.0f / 9.0f;  // viewport width / height

  glm::mat3 view_proj() const;
  // Centres `box` and zooms so it fills the view with `margin` (a fraction of its size)
  // around it on the tighter axis.
  void fit(const Box& box, float aspect, float margin = 0.1f);
  // World point → pixel (x right, y down, origin top-left) of a width × height viewport.
  glm::vec2 world_to_pixel(glm::vec2 p_ws, int width, int height) const;
  Box visible_box() const;
};

// What the last frame cost (reset by begin_frame).
struct DrawStats {
  int draw_calls = 0;
  int vertices = 0;   // vertices submitted (indices for indexed draws)
  int creatures = 0;
  int bones = 0;
};

// The shader folder: data_path("shaders") (ossa/io/data_dir.h).
std::string default_shader_dir();

class Renderer {
 public:
  // Loads every program from `shader_dir`; the error names the file and line.
  static Result<Renderer> create(const std::string& shader_dir);

  ShaderProgram debug, textured, skinned, skinned_naive, bone, body;
  Camera2D camera;
  DrawStats stats;

  // Binds the window's framebuffer, sets the viewport, clears to `clear_rgb`, enables alpha
  // blending, resets stats and sets camera.aspect from the size.
  void begin_frame(int width, int height, glm::vec3 clear_rgb);
  // The same into an offscreen target (its size), cleared to `clear_rgba` — alpha 0 gives a
  // transparent background, and the colours drawn over it come out premultiplied by alpha.
  void begin_frame(const RenderTarget& target, glm::vec4 clear_rgba);
  // Recompiles changed shader files (keeps the old program when the new one fails).
  int reload_shaders_if_changed();

  void draw_debug(DebugDraw& debug_draw);
  void draw_batch(CreatureBatch& batch, const Texture& atlas);
  // One texture per texture slot of the batch (CreatureBatch::add): the atlas first, then
  // the rigged characters' own.
  void draw_batch(CreatureBatch& batch, std::span<const Texture* const> textures);
  void draw_batch_naive(CreatureBatch& batch, const Texture& atlas);
  // Bodies only (the body look): one draw for every body, creature by creature.
  void draw_bodies(CreatureBatch& batch, float alpha = 1.0f);
  // The creatures of `batch` as `look` asks (body/body_mesh.h): bodies; bodies translucent
  // over the sprites, layer by layer (far sprites, far bodies, body sprites, …); or sprites.
  // A batch holds the instances the look needs (bodies, sprites or both).
  void draw_creatures(CreatureBatch& batch, std::span<const Texture* const> textures, CreatureLook look);
  void draw_bones(CreatureBatch& batch, glm::vec4 colour);
  // A textured rectangle in world space (background image), tinted. `uv_min`/`uv_max` are the
  // texture coordinates of its bottom-left and top-right corners: beyond [0, 1] a texture made
  // with Texture::Wrap::kRepeat tiles, so a strip repeated across the screen is one draw.
  void draw_textured_box(const Texture& texture, const Box& box_ws, glm::vec4 tint = glm::vec4(1.0f),
                         glm::vec2 uv_min = glm::vec2(0.0f), glm::vec2 uv_max = glm::vec2(1.0f));

 private:
  std::unique_ptr<VertexArray<TexturedVertex>> quad_;
  void setup_frame(unsigned framebuffer, int width, int height, glm::vec4 clear_rgba);
  void count_batch(const CreatureBatch& batch, int calls);
};

}  // namespace ossa
