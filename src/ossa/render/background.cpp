#include "ossa/render/background.h"

#include <algorithm>
#include <cmath>

#include <glm/vec4.hpp>

#include "ossa/level/level.h"
#include "ossa/render/debug_draw.h"

namespace ossa {
namespace {

constexpr int kSkyBands = 24;
constexpr int kHillSamples = 96;

glm::vec4 rgba(glm::vec3 c, float a = 1.0f) { return {c, a}; }

// Rolling hills: a few incommensurate sines of the layer coordinate u (metres), scaled in
// width by `freq`, metres above the horizon.
float hill_height(float u, float scale, float freq, float seed) {
  u *= freq;
  return scale * (0.55f + 0.30f * std::sin(u * 0.35f + seed) + 0.18f * std::sin(u * 0.83f + 2.1f * seed) +
                  0.08f * std::sin(u * 1.9f + 0.7f * seed));
}

void add_hills(DebugDraw& draw, const Camera2D& camera, float parallax, float base_ws, float scale,
               float freq, float seed, glm::vec3 colour) {
  const Box view = camera.visible_box();
  // A layer at parallax p moves p times as fast as the level: layer coordinate u = x − (1−p)·cx,
  // and its base rises with the camera by the same factor.
  const float shift_x = (1.0f - parallax) * camera.center_ws.x;
  const float base = base_ws + (1.0f - parallax) * (camera.center_ws.y - base_ws);
  const float step = view.width() / static_cast<float>(kHillSamples);
  const float bottom = std::min(view.min_ws.y, base) - 1.0f;
  for (int i = 0; i < kHillSamples; ++i) {
    const float x0 = view.min_ws.x + step * static_cast<float>(i);
    const float x1 = x0 + step;
    const float y0 = base + hill_height(x0 - shift_x, scale, freq, seed);
    const float y1 = base + hill_height(x1 - shift_x, scale, freq, seed);
    const glm::vec4 c = rgba(colour);
    draw.add_triangle({x0, bottom}, {x1, bottom}, {x1, y1}, c);
    draw.add_triangle({x0, bottom}, {x1, y1}, {x0, y0}, c);
  }
}

}  // namespace

void add_background(DebugDraw& draw, const Camera2D& camera, const BackgroundStyle& style) {
  const Box view = camera.visible_box();
  // Sky: bands fixed to the screen (parallax 0), top colour to bottom colour.
  for (int i = 0; i < kSkyBands; ++i) {
    const float t0 = static_cast<float>(i) / kSkyBands, t1 = static_cast<float>(i + 1) / kSkyBands;
    const glm::vec3 c = glm::mix(style.sky_bottom, style.sky_top, 0.5f * (t0 + t1));
    const float y0 = view.min_ws.y + t0 * view.height(), y1 = view.min_ws.y + t1 * view.height();
    draw.add_box({{view.min_ws.x, y0}, {view.max_ws.x, y1 + 0.001f * view.height()}}, rgba(c), true);
  }
  const float p = std::clamp(style.parallax, 0.05f, 1.0f);
  const glm::vec3 haze = style.sky_bottom;
  add_hills(draw, camera, p / 3.0f, style.horizon_ws + 0.6f, 1.8f, 0.5f, 0.3f,
            glm::mix(glm::vec3(0.45f, 0.58f, 0.62f), haze, 0.45f));
  add_hills(draw, camera, p, style.horizon_ws - 0.6f, 1.3f, 1.0f, 1.7f,
            glm::mix(glm::vec3(0.36f, 0.52f, 0.38f), haze, 0.25f));
}

void draw_background_image(Renderer& r, const Texture& texture, float parallax) {
  if (!texture.is_valid()) return;
  // A tile's world x is camera.x·(1 − parallax) + k·tile width. One quad over the view whose
  // texture coordinates run over as many tiles as it shows; u at the view's left edge is
  // reduced to [0, 1) in double, so float texture coordinates keep their precision.
  const Box view = r.camera.visible_box();
  const double tile_w = static_cast<double>(view.height()) * texture.width() / std::max(1, texture.height());
  const double origin = static_cast<double>(r.camera.center_ws.x) * (1.0 - static_cast<double>(parallax));
  const double u_left = (static_cast<double>(view.min_ws.x) - origin) / tile_w;
  const double u0 = u_left - std::floor(u_left);
  const double u1 = u0 + static_cast<double>(view.width()) / tile_w;
  if (!std::isfinite(u0) || !std::isfinite(u1)) return;
  r.draw_textured_box(texture, view, glm::vec4(1.0f), {static_cast<float>(u0), 0.0f}, {static_cast<float>(u1), 1.0f});
}

void add_level_scenery(DebugDraw& draw, const Level& level, const Box& visible) {
  const glm::vec4 earth{0.47f, 0.35f, 0.24f, 1.0f};
  const glm::vec4 earth_dark{0.30f, 0.22f, 0.15f, 1.0f};
  const glm::vec4 grass{0.42f, 0.62f, 0.28f, 1.0f};
  const glm::vec4 grass_light{0.60f, 0.78f, 0.40f, 1.0f};
  const float band = std::clamp(0.012f * visible.height(), 0.03f, 0.25f);
  for (const Box& b : level.colliders()) {
    if (b.max_ws.x < visible.min_ws.x || b.min_ws.x > visible.max_ws.x || b.max_ws.y < visible.min_ws.y ||
        b.min_ws.y > visible.max_ws.y) {
      continue;
    }
    draw.add_box(b, earth, true);
    draw.add_box(b, earth_dark, false);
    const float top_band = std::min(band, 0.5f * b.height());
    draw.add_box({{b.min_ws.x, b.max_ws.y - top_band}, b.max_ws}, grass, true);
    draw.add_line({b.min_ws.x, b.max_ws.y}, {b.max_ws.x, b.max_ws.y}, grass_light);
  }
}

}  // namespace ossa
