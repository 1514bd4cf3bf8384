#include "ossa/draw/sprite_atlas.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define STB_RECT_PACK_IMPLEMENTATION  // also serves ossa::render's tile atlas
#include <stb_rect_pack.h>
#pragma GCC diagnostic pop

#include "ossa/io/data_dir.h"

namespace ossa {

SpriteAtlas load_sprite_atlas(const std::string& sprite_dir) {
  SpriteSet sprites = default_sprite_set();
  std::string problem;
  if (auto s = load_sprite_set(sprite_dir + "/sprites.json"); s.ok()) {
    sprites = std::move(s.value());
  } else {
    problem = s.message() + " (using the built-in sprite anchors)";
  }
  SpriteAtlas atlas = pack_sprite_atlas(sprites, sprite_dir);
  if (!problem.empty()) atlas.problems.insert(atlas.problems.begin(), problem);
  return atlas;
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

SpriteAtlas pack_sprite_atlas(const SpriteSet& sprites, const std::string& sprite_dir) {
  constexpr int kPadding = 2;  // pixels between sprites, so linear filtering does not bleed
  constexpr size_t n = static_cast<size_t>(SpriteId::kCount);
  SpriteAtlas atlas;
  atlas.sprites = sprites;
  std::vector<Image> images(n);
  for (size_t i = 0; i < n; ++i) {
    const std::string path = sprite_dir + "/" + sprites.sprites[i].name + ".png";
    auto image = decode_image_file(path);
    if (image.ok()) {
      images[i] = std::move(image.value());
      measure_joint_reach(atlas.sprites.sprites[i], images[i]);
    } else {
      atlas.problems.push_back(image.message() + " (sprite packed as a checker tile)");
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
      atlas.problems.push_back("atlas: bone sprites do not fit in 4096x4096 (using checker tiles)");
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
  return atlas;
}

}  // namespace ossa
