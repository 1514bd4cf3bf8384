#pragma once
// The render tests' GL: one offscreen window (SDL's offscreen driver, no display), renderer
// and sprite atlas per process (contexts are expensive on llvmpipe), made on first use.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/platform/window.h"
#include "ossa/render/renderer.h"
#include "ossa/render/texture.h"
#include "shared/scenes.h"

namespace ossa::test {

inline constexpr int kW = 320, kH = 240;

// The CPU's picture of triangles the GPU draws: the pixels (kW x kH, 1: covered) whose centres
// the triangles `indices` over vertices at `px` (pixels, top row first) cover.
inline std::vector<uint8_t> covered_pixels(std::span<const glm::vec2> px, std::span<const uint32_t> indices) {
  auto cross2 = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
  std::vector<uint8_t> out(static_cast<size_t>(kW * kH), 0);
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec2 a = px[indices[t]], b = px[indices[t + 1]], c = px[indices[t + 2]];
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(kW - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(kH - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const glm::vec2 p{x + 0.5f, y + 0.5f};
        const float d1 = cross2(b - a, p - a), d2 = cross2(c - b, p - b), d3 = cross2(a - c, p - c);
        if (!((d1 < 0.0f || d2 < 0.0f || d3 < 0.0f) && (d1 > 0.0f || d2 > 0.0f || d3 > 0.0f))) out[static_cast<size_t>(y * kW + x)] = 1;
      }
    }
  }
  return out;
}

struct Gl {
  Window window;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Atlas> atlas;
  std::string error;

  Gl() {
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    WindowDesc desc;
    desc.width = kW;
    desc.height = kH;
    desc.offscreen = true;
    auto w = Window::create(desc);
    if (!w.ok()) {
      error = w.message();
      return;
    }
    window = std::move(w.value());
    auto r = Renderer::create(shader_dir());
    if (!r.ok()) {
      error = r.message();
      return;
    }
    renderer = std::make_unique<Renderer>(std::move(r.value()));
    const std::string dir = scenes::source_path("assets/sprites/bones");
    auto set = load_sprite_set(dir + "/sprites.json");
    atlas = std::make_unique<Atlas>(
        Atlas::build(set.ok() ? set.value() : default_sprite_set(), dir));
  }
  static std::string shader_dir() { return scenes::source_path("shaders"); }
};

inline Gl& gl() {
  static Gl g;
  INFO(g.error);
  REQUIRE(g.renderer);
  return g;
}

}  // namespace ossa::test
