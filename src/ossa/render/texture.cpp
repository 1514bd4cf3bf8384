#include "ossa/render/texture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "ossa/render/gl.h"

namespace ossa {

Texture Texture::load(const std::string& path, Wrap wrap) {
  auto image = load_image(path);
  if (!image.ok()) {
    render_log(image.message() + " (using the checker texture)");
    return checker();
  }
  return from_image(image.value(), true, wrap);
}

Texture Texture::checker() {
  Texture t = from_image(checker_image(), false);
  t.fallback_ = true;
  return t;
}

Texture Texture::from_image(const Image& image, bool linear_filter, Wrap wrap) {
  if (image.empty() || image.rgba.size() < static_cast<size_t>(image.width) * image.height * 4) {
    render_log("texture: empty image (using the checker texture)");
    return checker();
  }
  // Flip rows so that texture coordinate (0, 0) is the bottom-left of the image.
  std::vector<uint8_t> flipped(image.rgba.size());
  const size_t row = static_cast<size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&flipped[(image.height - 1 - y) * row], &image.rgba[y * row], row);
  }
  Texture t;
  t.width_ = image.width;
  t.height_ = image.height;
  glGenTextures(1, &t.id_);
  glBindTexture(GL_TEXTURE_2D, t.id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, flipped.data());
  const GLint filter = linear_filter ? GL_LINEAR : GL_NEAREST;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  const GLint wrap_mode = wrap == Wrap::kRepeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_mode);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap_mode);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

Texture::~Texture() {
  if (id_) glDeleteTextures(1, &id_);
}

Texture::Texture(Texture&& o) noexcept { *this = std::move(o); }

Texture& Texture::operator=(Texture&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteTextures(1, &id_);
    id_ = std::exchange(o.id_, 0u);
    width_ = o.width_;
    height_ = o.height_;
    fallback_ = o.fallback_;
  }
  return *this;
}

void Texture::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, id_);
}

Atlas Atlas::from_sprite_atlas(SpriteAtlas packed) {
  for (const std::string& problem : packed.problems) render_log(problem);
  Atlas atlas;
  atlas.sprites = std::move(packed.sprites);
  atlas.image = std::move(packed.image);
  atlas.missing = packed.missing;
  atlas.texture = Texture::from_image(atlas.image);
  return atlas;
}

Atlas Atlas::load(const std::string& sprite_dir) { return from_sprite_atlas(load_sprite_atlas(sprite_dir)); }

Atlas Atlas::build(const SpriteSet& sprites, const std::string& sprite_dir) {
  return from_sprite_atlas(pack_sprite_atlas(sprites, sprite_dir));
}

}  // namespace ossa
