#include "ossa/render/tile_atlas.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb_rect_pack.h>  // the implementation is in texture.cpp
#pragma GCC diagnostic pop

namespace ossa {

namespace {

// Copies the w x h block of `src` at (sx, sy) into `dst` at (dx, dy), its edge pixels repeated
// kTileExtrude pixels outwards (the block's cell in dst is (w + 2e) x (h + 2e) from
// (dx - e, dy - e)).
void blit_extruded(const Image& src, int sx, int sy, int w, int h, Image& dst, int dx, int dy) {
  const int e = kTileExtrude;
  for (int y = -e; y < h + e; ++y) {
    const int yy = sy + std::clamp(y, 0, h - 1);
    for (int x = -e; x < w + e; ++x) {
      const int xx = sx + std::clamp(x, 0, w - 1);
      std::memcpy(dst.pixel(dx + x, dy + y), src.pixel(xx, yy), 4);
    }
  }
}

// GL texture coordinates of the pixel rectangle (x, y, w, h) (top-left origin) in an image of
// size (W, H).
void set_uv(TileAtlas& a, size_t i, double x, double y, double w, double h) {
  const double W = a.image.width, H = a.image.height;
  a.uv_tl[i] = {static_cast<float>(x / W), static_cast<float>(1.0 - y / H)};
  a.uv_br[i] = {static_cast<float>((x + w) / W), static_cast<float>(1.0 - (y + h) / H)};
}

}  // namespace

TileAtlas build_grid_atlas(const Image& image, const ArtTileset& set, int max_side) {
  TileAtlas a;
  const int tw = set.tile_w_px, th = set.tile_h_px;
  if (image.empty() || tw <= 0 || th <= 0) return a;
  const int step_x = tw + set.spacing_px, step_y = th + set.spacing_px;
  const int fit_cols = std::max(0, (image.width - 2 * set.margin_px + set.spacing_px) / step_x);
  const int cols = set.columns > 0 ? set.columns : fit_cols;
  const int rows = std::max(0, (image.height - 2 * set.margin_px + set.spacing_px) / step_y);
  const int n = cols * rows;
  if (n <= 0) return a;
  a.uv_tl.assign(static_cast<size_t>(n), glm::vec2(0.0f));
  a.uv_br.assign(static_cast<size_t>(n), glm::vec2(0.0f));
  const auto source_x = [&](int i) { return set.margin_px + (i % cols) * step_x; };
  const auto source_y = [&](int i) { return set.margin_px + (i / cols) * step_y; };
  const auto inside = [&](int i) { return source_x(i) + tw <= image.width && source_y(i) + th <= image.height; };

  const int cw = tw + 2 * kTileExtrude, ch = th + 2 * kTileExtrude;
  const int atlas_cols = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n) * ch / cw))));
  const int atlas_rows = (n + atlas_cols - 1) / atlas_cols;
  if (static_cast<long long>(atlas_cols) * cw > max_side || static_cast<long long>(atlas_rows) * ch > max_side) {
    // Too large to re-pack: the image as it is (tiles may pick up their neighbours' edge
    // pixels when filtered; the texture is then sampled without filtering).
    a.image = image;
    for (int i = 0; i < n; ++i) {
      if (inside(i)) set_uv(a, static_cast<size_t>(i), source_x(i), source_y(i), tw, th);
    }
    return a;
  }
  a.image.width = atlas_cols * cw;
  a.image.height = atlas_rows * ch;
  a.image.rgba.assign(static_cast<size_t>(a.image.width) * a.image.height * 4, 0);
  for (int i = 0; i < n; ++i) {
    if (!inside(i)) continue;
    const int dx = (i % atlas_cols) * cw + kTileExtrude, dy = (i / atlas_cols) * ch + kTileExtrude;
    blit_extruded(image, source_x(i), source_y(i), tw, th, a.image, dx, dy);
    set_uv(a, static_cast<size_t>(i), dx, dy, tw, th);
  }
  return a;
}

TileAtlas build_collection_atlas(const std::vector<const Image*>& images, int max_side) {
  TileAtlas a;
  const size_t n = images.size();
  if (n == 0) return a;
  std::vector<stbrp_rect> rects(n);
  for (size_t i = 0; i < n; ++i) {
    rects[i] = {};
    rects[i].id = static_cast<int>(i);
    const bool empty = !images[i] || images[i]->empty();
    rects[i].w = empty ? 1 : images[i]->width + 2 * kTileExtrude;
    rects[i].h = empty ? 1 : images[i]->height + 2 * kTileExtrude;
  }
  int side = 64;
  for (;; side *= 2) {
    if (side > max_side) return TileAtlas{};
    std::vector<stbrp_node> nodes(static_cast<size_t>(side));
    stbrp_context ctx;
    stbrp_init_target(&ctx, side, side, nodes.data(), static_cast<int>(nodes.size()));
    if (stbrp_pack_rects(&ctx, rects.data(), static_cast<int>(n)) == 1) break;
  }
  a.image.width = a.image.height = side;
  a.image.rgba.assign(static_cast<size_t>(side) * side * 4, 0);
  a.uv_tl.assign(n, glm::vec2(0.0f));
  a.uv_br.assign(n, glm::vec2(0.0f));
  for (size_t i = 0; i < n; ++i) {
    if (!images[i] || images[i]->empty()) continue;
    const Image& img = *images[i];
    const int dx = rects[i].x + kTileExtrude, dy = rects[i].y + kTileExtrude;
    blit_extruded(img, 0, 0, img.width, img.height, a.image, dx, dy);
    set_uv(a, i, dx, dy, img.width, img.height);
  }
  return a;
}

}  // namespace ossa
