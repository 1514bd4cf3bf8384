#pragma once
// The render tests' GL: one offscreen window (SDL's offscreen driver, no display), renderer
// and sprite atlas per process (contexts are expensive on llvmpipe), made on first use.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <memory>
#include <string>

#include "ossa/platform/window.h"
#include "ossa/render/renderer.h"
#include "ossa/render/texture.h"
#include "shared/scenes.h"

namespace ossa::test {

inline constexpr int kW = 320, kH = 240;

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
