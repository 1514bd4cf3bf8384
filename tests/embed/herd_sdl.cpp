// A walking herd drawn with SDL2's own 2D renderer (SDL_Renderer, SDL_RenderGeometry) through
// ossa::draw — no OpenGL in this program. It is what an embedder with any renderer copies:
//   1. once: the sprite atlas image (load_sprite_atlas) into a texture of your renderer, and a
//      CreatureDrawable per creature (make_creature_drawable);
//   2. every frame: append_creature() per entity with its animator's world matrices, then for
//      each DrawCommand one textured (the atlas) or untextured triangle draw of its indices.
//
//   herd_sdl [DATA_DIR] [--look body|xray|bones] [--frame OUT.bmp]
// DATA_DIR is an installed ossa's share/ossa (ossa_DATA_DIR, compiled in as the default).
// Without --frame it opens a window (Esc quits). With --frame it draws one frame after 1.5 s
// of walking into a software renderer (an SDL_Surface: no display, no GPU), writes it as BMP,
// and checks that every creature is drawn: within each creature's screen box at least one pixel
// in twenty differs from the same frame drawn without creatures (exit 1 otherwise; a long-legged
// skeleton in the bones look covers a tenth of its box, a creature not drawn none).
#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <ossa/body/body_mesh.h>
#include <ossa/draw.h>

#ifndef HERD_SDL_DATA_DIR
#define HERD_SDL_DATA_DIR "share/ossa"
#endif

namespace {

constexpr int kWidth = 1280, kHeight = 480;
constexpr float kDt = 1.0f / 120.0f;

// World metres → screen pixels: a window onto [x0, x0 + kWidth / scale] × [y0, ...], y up.
struct Camera {
  float x0 = 0.0f, y0 = 0.0f, scale = 100.0f;  // pixels per metre
  SDL_FPoint to_screen(glm::vec2 p) const {
    return {(p.x - x0) * scale, static_cast<float>(kHeight) - (p.y - y0) * scale};
  }
  // Frames `box` with a margin, whole, at the screen's aspect.
  static Camera fit(const ossa::Box& box) {
    const glm::vec2 lo = box.min_ws - glm::vec2(0.6f, 0.8f), hi = box.max_ws + glm::vec2(0.6f, 0.6f);
    Camera c;
    c.scale = std::min(kWidth / (hi.x - lo.x), kHeight / (hi.y - lo.y));
    c.x0 = 0.5f * (lo.x + hi.x) - 0.5f * kWidth / c.scale;
    c.y0 = lo.y;
    return c;
  }
};

struct Herd {
  ossa::Level level;
  std::vector<std::unique_ptr<ossa::Entity>> entities;
  std::vector<const ossa::CreatureDrawable*> drawables;  // per entity
  std::vector<std::unique_ptr<ossa::CreatureDrawable>> owned;
  std::vector<ossa::Controls> controls;

  void step() {
    std::vector<ossa::Entity*> all;
    for (auto& e : entities) all.push_back(e.get());
    ossa::step_all(all, controls, kDt, level);
  }
};

// The herd: four animals of the examples and two random walkers, spread along the ground.
bool make_herd(Herd& herd, const std::string& data, const ossa::SpriteSet& sprites, ossa::CreatureLook look) {
  ossa::Result<ossa::Level> level = ossa::load_level(data + "/levels/default.json");
  ossa::Result<ossa::Generator> gen = ossa::Generator::load(data + "/assets/creatures/examples.json", ossa::body_volume_m3);
  if (!level || !gen) {
    std::fprintf(stderr, "%s\n", (!level ? level.message() : gen.message()).c_str());
    return false;
  }
  herd.level = std::move(*level);
  std::vector<ossa::Genome> genomes;
  for (const char* name : {"horse", "red deer", "pig", "kangaroo"}) genomes.push_back(gen->example(name).value());
  for (uint64_t seed = 1; genomes.size() < 6; ++seed) {
    ossa::GenerateOptions options;
    options.leg_pairs = 2;  // walkers
    genomes.push_back(gen->random(seed, options));
  }
  const ossa::SplinePrototypes prototypes = ossa::SplinePrototypes::defaults();
  ossa::CreatureDrawOptions options;
  options.look = look;
  float x = herd.level.spawn_ws.x - 1.8f;  // default.json: a wall at x = 0, flat ground to x = 10, then stairs
  for (const ossa::Genome& genome : genomes) {
    ossa::Result<ossa::Creature> creature = ossa::build_creature(genome);
    if (!creature) continue;
    auto shared = std::make_shared<const ossa::Creature>(std::move(*creature));
    ossa::Result<ossa::CreatureDrawable> drawable = ossa::make_creature_drawable(*shared, sprites, options);
    if (!drawable) {
      std::fprintf(stderr, "%s\n", drawable.message().c_str());
      return false;
    }
    const float length = std::max(ossa::body_bounds(drawable->body).width(), ossa::sprite_mesh_bounds(drawable->sprites).width());
    auto entity = std::make_unique<ossa::Entity>(shared, prototypes);
    entity->animator().reset({x + 0.5f * length, herd.level.spawn_ws.y + 1.0f}, herd.level);
    x += length;
    herd.owned.push_back(std::make_unique<ossa::CreatureDrawable>(std::move(*drawable)));
    herd.drawables.push_back(herd.owned.back().get());
    herd.entities.push_back(std::move(entity));
    herd.controls.push_back({0.35f + 0.05f * static_cast<float>(herd.controls.size() % 3), false, false});
  }
  return !herd.entities.empty();
}

// Every entity's triangles, far creatures (appended first) behind near ones.
void build_draw_list(const Herd& herd, ossa::DrawList& list) {
  list.clear();
  for (size_t i = 0; i < herd.entities.size(); ++i) {
    const ossa::Entity& e = *herd.entities[i];
    const std::vector<ossa::Mat2x3>& world = e.animator().world_matrices();
    const ossa::BodyFloor floor = ossa::body_floor(herd.level, e.skeleton(), world, herd.drawables[i]->body.reach, herd.drawables[i]->body.feet);
    ossa::append_creature(list, *herd.drawables[i], world, &floor);
  }
}

void draw_level(SDL_Renderer* r, const ossa::Level& level, const Camera& cam) {
  SDL_SetRenderDrawColor(r, 196, 220, 236, 255);
  SDL_RenderClear(r);
  for (int i = 0; i < level.size(); ++i) {
    const ossa::Box& b = level.box(i);
    // Whole pixels, each edge rounded alone: neighbouring boxes share their edge, no seam.
    const SDL_FPoint top_left = cam.to_screen({b.min_ws.x, b.max_ws.y});
    const SDL_FPoint bottom_right = cam.to_screen({b.max_ws.x, b.min_ws.y});
    const int x0 = static_cast<int>(std::lround(top_left.x)), y0 = static_cast<int>(std::lround(top_left.y));
    const SDL_Rect rect{x0, y0, static_cast<int>(std::lround(bottom_right.x)) - x0,
                        static_cast<int>(std::lround(bottom_right.y)) - y0};
    SDL_SetRenderDrawColor(r, 122, 104, 84, 255);
    SDL_RenderFillRect(r, &rect);
    const SDL_Rect grass{rect.x, rect.y, rect.w, std::min(rect.h, 4)};
    SDL_SetRenderDrawColor(r, 92, 138, 70, 255);
    SDL_RenderFillRect(r, &grass);
  }
}

// The draw list through SDL_RenderGeometry: one call per command, the atlas or no texture.
void draw_creatures(SDL_Renderer* r, SDL_Texture* atlas, const ossa::DrawList& list, const Camera& cam,
                    std::vector<SDL_Vertex>& vertices, std::vector<int>& indices) {
  vertices.resize(list.vertices.size());
  for (size_t i = 0; i < list.vertices.size(); ++i) {
    const ossa::DrawVertex& v = list.vertices[i];
    vertices[i].position = cam.to_screen(v.position_ws);
    vertices[i].color = {v.colour[0], v.colour[1], v.colour[2], v.colour[3]};
    vertices[i].tex_coord = {v.uv.x, v.uv.y};
  }
  indices.assign(list.indices.begin(), list.indices.end());
  SDL_SetRenderDrawBlendMode(r, SDL_BLENDMODE_BLEND);
  for (const ossa::DrawCommand& c : list.commands) {
    SDL_RenderGeometry(r, c.texture == ossa::DrawTexture::kAtlas ? atlas : nullptr, vertices.data(),
                       static_cast<int>(vertices.size()), indices.data() + c.first_index,
                       static_cast<int>(c.index_count));
  }
}

SDL_Texture* atlas_texture(SDL_Renderer* r, const ossa::Image& image) {
  SDL_Texture* t = SDL_CreateTexture(r, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, image.width, image.height);
  if (!t) return nullptr;
  SDL_UpdateTexture(t, nullptr, image.rgba.data(), image.width * 4);
  SDL_SetTextureBlendMode(t, SDL_BLENDMODE_BLEND);
  SDL_SetTextureScaleMode(t, SDL_ScaleModeLinear);
  return t;
}

ossa::Box herd_bounds(const ossa::DrawList& list) {
  ossa::Box all = ossa::creature_draw_bounds(list, 0);
  for (uint32_t c = 1; c < list.creature_count; ++c) {
    const ossa::Box b = ossa::creature_draw_bounds(list, c);
    all = {glm::min(all.min_ws, b.min_ws), glm::max(all.max_ws, b.max_ws)};
  }
  return all;
}

// --frame: one frame offscreen, written and checked.
int render_frame(Herd& herd, const ossa::SpriteAtlas& atlas, const char* out) {
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, kWidth, kHeight, 32, SDL_PIXELFORMAT_RGBA32);
  SDL_Renderer* r = surface ? SDL_CreateSoftwareRenderer(surface) : nullptr;
  SDL_Texture* texture = r ? atlas_texture(r, atlas.image) : nullptr;
  if (!texture) {
    std::fprintf(stderr, "herd_sdl: %s\n", SDL_GetError());
    return 1;
  }
  for (int tick = 0; tick < 180; ++tick) herd.step();
  ossa::DrawList list;
  std::vector<SDL_Vertex> vertices;
  std::vector<int> indices;
  build_draw_list(herd, list);
  const Camera cam = Camera::fit(herd_bounds(list));

  // The frame without creatures, to tell their pixels from the level's.
  draw_level(r, herd.level, cam);
  SDL_RenderPresent(r);
  std::vector<uint8_t> level_only(static_cast<const uint8_t*>(surface->pixels),
                                  static_cast<const uint8_t*>(surface->pixels) + surface->pitch * surface->h);
  // The frame, timed over a few repeats: the draw list built, converted and drawn.
  constexpr int kRepeats = 10;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < kRepeats; ++k) {
    build_draw_list(herd, list);
    draw_level(r, herd.level, cam);
    draw_creatures(r, texture, list, cam, vertices, indices);
    SDL_RenderPresent(r);
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / kRepeats;
  if (SDL_SaveBMP(surface, out) != 0) {
    std::fprintf(stderr, "herd_sdl: cannot write %s: %s\n", out, SDL_GetError());
    return 1;
  }
  std::printf("herd_sdl: %u creatures, %d triangles, %zu draw calls, %.2f ms per frame (software renderer, %dx%d) -> %s\n",
              list.creature_count, list.triangle_count(), list.commands.size(), ms, kWidth, kHeight, out);

  bool ok = true;
  const auto* pixels = static_cast<const uint8_t*>(surface->pixels);
  for (uint32_t c = 0; c < list.creature_count; ++c) {
    const ossa::Box b = ossa::creature_draw_bounds(list, c);
    const SDL_FPoint a = cam.to_screen({b.min_ws.x, b.max_ws.y}), z = cam.to_screen({b.max_ws.x, b.min_ws.y});
    const int x0 = std::clamp(static_cast<int>(a.x), 0, kWidth), x1 = std::clamp(static_cast<int>(z.x) + 1, 0, kWidth);
    const int y0 = std::clamp(static_cast<int>(a.y), 0, kHeight), y1 = std::clamp(static_cast<int>(z.y) + 1, 0, kHeight);
    int drawn = 0, area = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        const size_t at = static_cast<size_t>(y) * surface->pitch + static_cast<size_t>(x) * 4;
        drawn += std::memcmp(pixels + at, level_only.data() + at, 3) != 0;
        ++area;
      }
    }
    const bool seen = area > 0 && drawn * 20 >= area;
    ok = ok && seen;
    std::printf("  %-12s %4dx%-4d px box, %5.1f %% drawn%s\n", herd.entities[c]->name().c_str(), x1 - x0, y1 - y0,
                area ? 100.0 * drawn / area : 0.0, seen ? "" : "  <- NOT DRAWN");
  }
  SDL_DestroyTexture(texture);
  SDL_DestroyRenderer(r);
  SDL_FreeSurface(surface);
  return ok ? 0 : 1;
}

// A window: the herd walks on (Esc or closing the window quits).
int run_window(Herd& herd, const ossa::SpriteAtlas& atlas) {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    std::fprintf(stderr, "herd_sdl: %s\n", SDL_GetError());
    return 1;
  }
  SDL_Window* window = SDL_CreateWindow("ossa herd — SDL_Renderer", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                        kWidth, kHeight, 0);
  SDL_Renderer* r = window ? SDL_CreateRenderer(window, -1, SDL_RENDERER_PRESENTVSYNC) : nullptr;
  SDL_Texture* texture = r ? atlas_texture(r, atlas.image) : nullptr;
  if (!texture) {
    std::fprintf(stderr, "herd_sdl: %s\n", SDL_GetError());
    SDL_Quit();
    return 1;
  }
  ossa::DrawList list;
  std::vector<SDL_Vertex> vertices;
  std::vector<int> indices;
  Uint64 last = SDL_GetPerformanceCounter();
  double lag = 0.0;
  for (bool running = true; running;) {
    for (SDL_Event e; SDL_PollEvent(&e);) {
      if (e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE)) running = false;
    }
    const Uint64 now = SDL_GetPerformanceCounter();
    lag = std::min(lag + static_cast<double>(now - last) / SDL_GetPerformanceFrequency(), 0.25);
    last = now;
    for (; lag >= kDt; lag -= kDt) herd.step();
    build_draw_list(herd, list);
    const Camera cam = Camera::fit(herd_bounds(list));
    draw_level(r, herd.level, cam);
    draw_creatures(r, texture, list, cam, vertices, indices);
    SDL_RenderPresent(r);
  }
  SDL_DestroyTexture(texture);
  SDL_DestroyRenderer(r);
  SDL_DestroyWindow(window);
  SDL_Quit();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string data = HERD_SDL_DATA_DIR;
  const char* frame = nullptr;
  ossa::CreatureLook look = ossa::CreatureLook::kBody;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--frame" && i + 1 < argc) {
      frame = argv[++i];
    } else if (arg == "--look" && i + 1 < argc) {
      const auto parsed = ossa::creature_look_from_name(argv[++i]);
      if (!parsed) {
        std::fprintf(stderr, "herd_sdl: --look takes body, xray or bones\n");
        return 2;
      }
      look = *parsed;
    } else if (!arg.empty() && arg[0] != '-') {
      data = arg;
    } else {
      std::fprintf(stderr, "usage: herd_sdl [DATA_DIR] [--look body|xray|bones] [--frame OUT.bmp]\n");
      return 2;
    }
  }
  const ossa::SpriteAtlas atlas = ossa::load_sprite_atlas(data + "/assets/sprites/bones");
  for (const std::string& problem : atlas.problems) std::fprintf(stderr, "herd_sdl: %s\n", problem.c_str());
  Herd herd;
  if (!make_herd(herd, data, atlas.sprites, look)) return 1;
  return frame ? render_frame(herd, atlas, frame) : run_window(herd, atlas);
}
