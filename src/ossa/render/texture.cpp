#include "ossa/render/texture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define STB_RECT_PACK_IMPLEMENTATION
#include <stb_rect_pack.h>
#pragma GCC diagnostic pop

#include "ossa/io/data_dir.h"
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

Atlas Atlas::load(const std::string& sprite_dir) {
  SpriteSet sprites = default_sprite_set();
  if (auto s = load_sprite_set(sprite_dir + "/sprites.json"); s.ok()) {
    sprites = std::move(s.value());
  } else {
    render_log(s.message() + " (using the built-in sprite anchors)");
  }
  return build(sprites, sprite_dir);
}

std::string default_sprite_dir() { return data_path("assets/sprites/bones"); }

void measure_joint_reach(SpriteInfo& info, const Image& image) {
  if (image.empty()) return;
  const auto reach = [&](float u0, float u1, float anchor_v) {
    const int x0 = std::clamp(static_cast<int>(std::floor(u0 * image.width)), 0, image.width - 1);
    const int x1 = std::clamp(static_cast<int>(std::ceil(u1 * image.width)), x0 + 1, image.width);
    glm::vec2 r(0.0f);  // below, above
    const float h = static_cast<float>(image.height);
    for (int y = 0; y < image.height; ++y) {
      for (int x = x0; x < x1; ++x) {
        if (image.pixel(x, y)[3] < 128) continue;
        r.x = std::max(r.x, anchor_v - (1.0f - static_cast<float>(y + 1) / h));  // pixel's bottom edge
        r.y = std::max(r.y, (1.0f - static_cast<float>(y) / h) - anchor_v);      // its top edge
      }
    }
    return r;
  };
  const float pu = info.parent_anchor.x, cu = info.child_anchor.x;
  info.parent_reach = reach(0.0f, std::min(2.0f * pu, cu), info.parent_anchor.y);
  info.child_reach = reach(std::max(2.0f * cu - 1.0f, pu), 1.0f, info.child_anchor.y);
}

Atlas Atlas::build(const SpriteSet& sprites, const std::string& sprite_dir) {
  constexpr int kPadding = 2;  // pixels between sprites, so linear filtering does not bleed
  constexpr size_t n = static_cast<size_t>(SpriteId::kCount);
  Atlas atlas;
  atlas.sprites = sprites;
  std::vector<Image> images(n);
  for (size_t i = 0; i < n; ++i) {
    const std::string path = sprite_dir + "/" + sprites.sprites[i].name + ".png";
    auto image = load_image(path);
    if (image.ok()) {
      images[i] = std::move(image.value());
      measure_joint_reach(atlas.sprites.sprites[i], images[i]);
    } else {
      render_log(image.message() + " (sprite packed as a checker tile)");
      images[i] = checker_image(64, 32, 8);
      ++atlas.missing;
    }
  }

  std::vector<stbrp_rect> rects(n);
  int size = 256;
  for (;; size *= 2) {
    for (size_t i = 0; i < n; ++i) {
      rects[i] = {};
      rects[i].id = static_cast<int>(i);
      rects[i].w = images[i].width + 2 * kPadding;
      rects[i].h = images[i].height + 2 * kPadding;
    }
    std::vector<stbrp_node> nodes(static_cast<size_t>(size));
    stbrp_context ctx;
    stbrp_init_target(&ctx, size, size, nodes.data(), static_cast<int>(nodes.size()));
    if (stbrp_pack_rects(&ctx, rects.data(), static_cast<int>(n)) == 1) break;
    if (size >= 4096) {
      // Too big to pack: shrink nothing, fall back to checker tiles (never crash).
      render_log("atlas: bone sprites do not fit in 4096x4096 (using checker tiles)");
      for (auto& img : images) img = checker_image(64, 32, 8);
      atlas.missing = static_cast<int>(n);
      size = 128;
    }
  }

  atlas.image.width = size;
  atlas.image.height = size;
  atlas.image.rgba.assign(static_cast<size_t>(size) * size * 4, 0);
  for (size_t i = 0; i < n; ++i) {
    const Image& img = images[i];
    const int x0 = rects[i].x + kPadding, y0 = rects[i].y + kPadding;
    for (int y = 0; y < img.height; ++y) {
      std::memcpy(atlas.image.pixel(x0, y0 + y), img.pixel(0, y), static_cast<size_t>(img.width) * 4);
    }
    // Image rows run top to bottom; texture t runs bottom to top (flipped on upload).
    // Half a texel inset keeps linear filtering inside the sprite.
    const float s = static_cast<float>(size);
    SpriteInfo& info = atlas.sprites.sprites[i];
    info.uv_min = {(x0 + 0.5f) / s, 1.0f - (y0 + img.height - 0.5f) / s};
    info.uv_max = {(x0 + img.width - 0.5f) / s, 1.0f - (y0 + 0.5f) / s};
  }
  atlas.texture = Texture::from_image(atlas.image);
  return atlas;
}

}  // namespace ossa
