#pragma once
// Texture — a GL RGBA8 texture from an image file (SDL2_image) — and Atlas, every bone sprite
// packed into one texture (stb_rect_pack) so that all creatures draw with one texture bind.
//
// Resource failures never crash (DESIGN.md §11): a missing or broken file is logged and the
// texture shows a magenta checkerboard; is_valid() tells the caller it is a fallback.
// Texture coordinates follow GL: (0, 0) is the bottom-left of the image (rows are flipped on
// upload), so a sprite's unit box (v up) maps to its atlas rectangle without a flip.

#include <string>

#include "ossa/draw/sprite_atlas.h"
#include "ossa/platform/image.h"

namespace ossa {

class Texture {
 public:
  // How texture coordinates outside [0, 1] sample: the edge pixels, or the image repeated.
  enum class Wrap { kClamp, kRepeat };
  // Loads `path` (load_image: the input rule and the size check before decoding); on failure
  // logs and returns the checker fallback (is_valid() == false).
  static Texture load(const std::string& path, Wrap wrap = Wrap::kClamp);
  // Uploads an image (rows top to bottom). An empty image gives the checker fallback.
  static Texture from_image(const Image& image, bool linear_filter = true, Wrap wrap = Wrap::kClamp);
  static Texture checker();

  Texture() = default;
  ~Texture();
  Texture(Texture&& o) noexcept;
  Texture& operator=(Texture&& o) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  // False for the checker fallback (or a default-constructed texture).
  bool is_valid() const { return id_ != 0 && !fallback_; }
  bool is_fallback() const { return fallback_; }
  unsigned id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  void bind(int unit = 0) const;

 private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0;
  bool fallback_ = false;
};

// All sprites of a SpriteSet packed into one texture: draw/sprite_atlas.h's SpriteAtlas (the
// same packing for every renderer) uploaded. Each sprite's PNG is `<sprite_dir>/<name>.png`;
// a missing one is logged and packed as a checker tile.
struct Atlas {
  Texture texture;
  SpriteSet sprites;        // the input set with uv_min / uv_max and the joint reaches
                            // (measure_joint_reach) filled in
  Image image;              // the packed pixels (rows top to bottom), kept for export/tests
  int missing = 0;          // sprites that fell back to the checker

  // Packs with 2 px padding into the smallest square power of two (≤ 4096) that fits.
  static Atlas build(const SpriteSet& sprites, const std::string& sprite_dir);
  // The bone sprites of `sprite_dir`: its sprites.json (when that fails to load, the message is
  // logged and the built-in anchors are used) packed by build().
  static Atlas load(const std::string& sprite_dir);
  // Uploads a packed atlas (its problems logged).
  static Atlas from_sprite_atlas(SpriteAtlas packed);
};

}  // namespace ossa
