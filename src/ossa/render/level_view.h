#pragma once
// LevelView — a level drawn as designed (DESIGN.md §6, §9): the game, ossa-render and the
// tests draw levels through it.
//
//   auto view = LevelView::create(default_shader_dir());
//   view->draw_back(renderer, level, level_file);   // sky, art behind the creatures, boxes
//   renderer.draw_batch(...);                        // the creatures
//   view->draw_front(renderer, level);               // art layers marked as foreground
//
// What is drawn:
//   * a Tiled map or an LDtk level (Level::art): its background colour, then every layer in
//     its order — image layers (placed, cropped, repeated), tile layers from their tilesets
//     (tile_atlas.h: one texture per tileset, one draw per tileset per layer), with flips,
//     opacity, tint, parallax and offsets — the foreground layers after the creatures. The
//     colliders are not drawn: the art is the level's look.
//   * an ossa level: the sky and hills (background.h) and its background image, then its boxes:
//     with the tiles of its look (box_look.h) when it has one, else as earth-coloured boxes.
//   * a fallback: an image that cannot be read is a warning naming the level file and the
//     image's path; the level then draws its boxes too (earth-coloured), so it still plays and
//     shows what collides.
// Images are read through SDL_image (load_image) once per level: the GPU data is rebuilt when
// the Level's art object changes (a new level loaded), the look's geometry when the colliders
// change (Level::revision(), the level editor) or the look does. Per frame there is only one
// draw per tileset per layer (every tile of the batch: a 200 x 50 map is 10 000 quads, cheap for
// any GPU) and one per image layer and per part of the look.

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ossa/io/result.h"
#include "ossa/level/level.h"
#include "ossa/render/box_look.h"
#include "ossa/render/renderer.h"
#include "ossa/render/shader.h"
#include "ossa/render/texture.h"
#include "ossa/render/vertex_array.h"

namespace ossa {

// The tile program's vertex (world space): texture coordinates and a colour that multiplies
// the texel (white, or a tile's own alpha).
struct TileVertex {
  glm::vec2 position_ws{0.0f};
  glm::vec2 uv{0.0f};
  uint32_t rgba = 0xffffffffu;  // R in the lowest byte
  static std::span<const VertexAttrib> layout();
};

struct LevelViewStats {
  int draw_calls = 0;       // of the last draw_back + draw_front
  int tiles_drawn = 0;      // tiles sent to the GPU (after culling)
  int textures = 0;         // textures the current level's art and look hold
};

class LevelView {
 public:
  // Loads the tile program (tile.vert, tile.frag) from `shader_dir`.
  static Result<LevelView> create(const std::string& shader_dir);

  LevelView();
  ~LevelView();
  LevelView(LevelView&&) noexcept;
  LevelView& operator=(LevelView&&) noexcept;

  // Everything behind the creatures, with the renderer's camera. `level_file` is the file the
  // level was loaded from (images of an ossa level are found relative to it, and warnings
  // name it); it may end in "#Level" for LDtk.
  void draw_back(Renderer& renderer, const Level& level, const std::string& level_file);
  // The art layers drawn in front of the creatures (Tiled "foreground", LDtk "Foreground").
  void draw_front(Renderer& renderer, const Level& level);

  // Warnings since the last call (each missing image once per level), e.g.
  // "levels/x.tmx: tileset image levels/tiles/a.png: cannot open ...; drawing the level's boxes".
  std::vector<std::string> take_warnings();
  // True when the boxes are drawn (an ossa level without a look, or a fallback).
  bool drawing_boxes() const { return boxes_; }
  const LevelViewStats& stats() const { return stats_; }
  // Recompiles the tile program when its files changed (hot reload).
  void reload_shaders_if_changed();

 private:
  struct ArtGpu;
  struct LookGpu;
  void prepare_art(const Level& level);
  void prepare_look(const Level& level, const std::string& level_file);
  void draw_sky(Renderer& r, const Level& level, const std::string& level_file);
  void draw_layers(Renderer& r, bool front);
  void draw_look(Renderer& r);
  void draw_quads(Renderer& r, const VertexArray<TileVertex>& va, int first, int count, const Texture& texture,
                  glm::vec2 shift_ws, glm::vec4 tint);
  void warn(const std::string& message);

  ShaderProgram program_;
  std::unique_ptr<ArtGpu> art_;
  std::unique_ptr<LookGpu> look_;
  std::unique_ptr<VertexArray<TileVertex>> quad_;     // image layers, streamed per frame
  std::map<std::string, Texture> background_images_;  // an ossa level's background.image
  std::vector<std::string> warnings_;
  std::vector<std::string> warned_;                   // said once
  bool boxes_ = true;
  LevelViewStats stats_;
  int max_texture_ = 4096;
};

}  // namespace ossa
