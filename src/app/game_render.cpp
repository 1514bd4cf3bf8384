// Game — window and ImGui set-up, interpolation, camera, drawing and GIF captures (replays and
// the demo script: game_replay.cpp).

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/game_impl.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/data_dir.h"
#include "ossa/level/level_load.h"
#include "ossa/render/background.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/draw/sprite_mesh.h"

namespace ossa {
namespace {

// Per-component blend of two bone matrices. Between two ticks a bone turns by a small angle,
// so the linear blend is visually indistinguishable from a proper one; a mirror flip (the
// creature turned around this tick) has no in-between, so the newer matrix is used.
Mat2x3 blend(const Mat2x3& a, const Mat2x3& b, float t) {
  const float det_a = a.m[0] * a.m[3] - a.m[1] * a.m[2];
  const float det_b = b.m[0] * b.m[3] - b.m[1] * b.m[2];
  if ((det_a < 0.0f) != (det_b < 0.0f)) return b;
  Mat2x3 r;
  for (int i = 0; i < 6; ++i) r.m[i] = a.m[i] + (b.m[i] - a.m[i]) * t;
  return r;
}

const Entity& entity_at(const World& w, int i) {
  return i == 0 ? static_cast<const Entity&>(*w.player()) : w.npc(i - 1);
}

// Halves an image (2×2 box filter) for GIFs: a quarter of the pixels to quantise and store.
Image half_size(const Image& src) {
  Image out;
  out.width = std::max(1, src.width / 2);
  out.height = std::max(1, src.height / 2);
  out.rgba.resize(static_cast<size_t>(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        const int sx = std::min(2 * x, src.width - 1), sy = std::min(2 * y, src.height - 1);
        const int sx1 = std::min(sx + 1, src.width - 1), sy1 = std::min(sy + 1, src.height - 1);
        const int sum = src.pixel(sx, sy)[c] + src.pixel(sx1, sy)[c] + src.pixel(sx, sy1)[c] + src.pixel(sx1, sy1)[c];
        out.pixel(x, y)[c] = static_cast<uint8_t>((sum + 2) / 4);
      }
    }
  }
  return out;
}

}  // namespace

// ---- Window and ImGui -----------------------------------------------------------------------

Status Game::Impl::open_window(const GameOptions& o) {
  WindowDesc desc;
  desc.title = "ossa — " + (genome.name.empty() ? std::string("creature") : genome.name);
  desc.width = o.width;
  desc.height = o.height;
  desc.vsync = o.vsync;
  desc.offscreen = o.headless;
  auto w = Window::create(desc);
  if (!w.ok()) return w.error();
  window = std::move(w.value());
  auto r = Renderer::create(default_shader_dir());
  if (!r.ok()) return r.error();
  renderer.emplace(std::move(r.value()));
  auto view = LevelView::create(default_shader_dir());
  if (!view.ok()) return view.error();
  level_view.emplace(std::move(view.value()));
  const std::string sprite_dir = resolve_data_path("assets/sprites/bones");
  SpriteSet sprites = default_sprite_set();
  if (auto s = load_sprite_set(sprite_dir + "/sprites.json"); s.ok()) {
    sprites = std::move(s.value());
  } else {
    std::fprintf(stderr, "ossa: %s (using the built-in sprite anchors)\n", s.message().c_str());
  }
  atlas.emplace(Atlas::build(sprites, sprite_dir));
  batch = std::make_unique<CreatureBatch>();

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the player's files
  ImGui::StyleColorsDark();
  SDL_Window* sdl_window = SDL_GL_GetCurrentWindow();
  if (!sdl_window || !ImGui_ImplSDL2_InitForOpenGL(sdl_window, SDL_GL_GetCurrentContext())) {
    ImGui::DestroyContext();
    return Error{"ImGui: SDL2 backend failed to start"};
  }
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    return Error{"ImGui: OpenGL 3 backend failed to start"};
  }
  imgui = true;
  return {};
}

void Game::Impl::shutdown_imgui() {
  if (!imgui) return;
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
  imgui = false;
}

void Game::Impl::release_gl() {
  gif.reset();
  level_view.reset();
  batch.reset();
  atlas.reset();
  renderer.reset();
}

bool Game::Impl::ui_wants_keyboard() const { return imgui && ImGui::GetIO().WantCaptureKeyboard; }
bool Game::Impl::ui_wants_mouse() const { return imgui && ImGui::GetIO().WantCaptureMouse; }

const Camera2D& Game::camera() const { return impl_->renderer->camera; }

void Game::Impl::process_imgui_event(const SDL_Event& e) {
  if (imgui) ImGui_ImplSDL2_ProcessEvent(&e);
}

// ---- Interpolation and creatures ------------------------------------------------------------

void Game::Impl::snapshot_all(const World& world, bool both) {
  const int n = 1 + world.npc_count();
  if (static_cast<int>(curr.size()) != n || both) {
    curr.assign(n, {});
    for (int i = 0; i < n; ++i) curr[i] = entity_at(world, i).animator().world_matrices();
    prev = curr;
    return;
  }
  prev.swap(curr);
}

void Game::Impl::after_step(const World& world) {
  const int n = 1 + world.npc_count();
  curr.resize(n);
  prev.resize(n);
  for (int i = 0; i < n; ++i) {
    curr[i] = entity_at(world, i).animator().world_matrices();
    if (prev[i].size() != curr[i].size()) prev[i] = curr[i];
  }
}

glm::vec2 Game::Impl::player_root(float alpha) const {
  if (curr.empty() || curr[0].empty()) return glm::vec2(0.0f);
  const Mat2x3 m = prev[0].empty() ? curr[0][0] : blend(prev[0][0], curr[0][0], alpha);
  return {m.m[4], m.m[5]};
}

bool Game::Impl::switch_creature(World& world, const Genome& g) {
  auto c = build_creature(g);
  if (!c.ok()) {
    say(c.message());
    return false;
  }
  if (recording) say(stop_recording(next_free_replay_path()));
  genome = g;
  character_path.clear();
  world.set_player_creature(std::make_shared<Creature>(std::move(c.value())));
  batch_dirty = true;
  snapshot_all(world, true);
  base_half_height = framing_half_height(world.player()->animator().hip_height(), world.player()->animator().rig().scale.length, window_aspect());
  say(world.player()->creature().name);
  return true;
}

Result<const Game::Impl::CharacterEntry*> Game::Impl::character(const std::string& path, bool reload) {
  for (auto it = characters.rbegin(); it != characters.rend() && !reload; ++it) {
    if ((*it)->path == path) return it->get();
  }
  auto loaded = load_character(resolve_data_path(path));
  if (!loaded.ok()) return loaded.error();
  auto entry = std::make_unique<CharacterEntry>();
  entry->path = path;
  entry->loaded = std::move(loaded.value());
  characters.push_back(std::move(entry));
  return characters.back().get();
}

const Game::Impl::CharacterEntry* Game::Impl::entry_of(const Character* c) const {
  for (const auto& e : characters) {
    if (e->loaded.character.get() == c) return e.get();
  }
  return nullptr;
}

Status Game::Impl::switch_character(World& world, const std::string& path, bool reload) {
  auto c = character(path, reload);
  if (!c.ok()) return c.error();
  if (recording) say(stop_recording(next_free_replay_path()));
  character_path = c.value()->path;
  world.set_player_character(c.value()->loaded.character);
  batch_dirty = true;
  snapshot_all(world, true);
  base_half_height = framing_half_height(world.player()->animator().hip_height(), world.player()->animator().rig().scale.length, window_aspect());
  say(world.player()->name());
  return {};
}

// ---- Camera ---------------------------------------------------------------------------------

CameraSubject Game::Impl::camera_subject(const World& world, float alpha) const {
  const Animator& a = world.player()->animator();
  CameraSubject s;
  s.root_ws = player_root(alpha);
  s.hip_height = a.hip_height();
  s.velocity_x = a.velocity();
  s.airborne = a.airborne();
  return s;
}

float Game::Impl::window_aspect() const {
  return static_cast<float>(window.width()) / static_cast<float>(std::max(1, window.height()));
}

void Game::Impl::reset_camera(const World& world) {
  base_half_height = framing_half_height(world.player()->animator().hip_height(), world.player()->animator().rig().scale.length, window_aspect());
  follow.reset(world.level(), camera_subject(world, 1.0f), base_half_height * zoom, window_aspect());
  camera_ws = follow.center_ws();
}

void Game::Impl::update_camera(const World& world, float alpha, float dt) {
  camera_ws = follow.update(world.level(), camera_subject(world, alpha), base_half_height * zoom, window_aspect(), dt);
}

// ---- Drawing --------------------------------------------------------------------------------

void Game::Impl::render(Game& game, float alpha) {
  World& world = game.world();
  Renderer& r = *renderer;
  r.reload_shaders_if_changed();  // edited shader files take effect while the game runs
  r.camera.center_ws = camera_ws;
  r.camera.half_height = follow.half_height(base_half_height * zoom);

  const Level& level = world.level();
  level_view->reload_shaders_if_changed();
  // The sky, the art behind the creatures and the ground (level_view.h); the clear colour is
  // covered by the sky.
  r.begin_frame(window.width(), window.height(), level.background ? level.background->colour : glm::vec3(0.55f, 0.70f, 0.85f));
  level_view->draw_back(r, level, resolve_data_path(level_path));

  // Creatures: rebuild the batch when the cast changed, then one palette upload per frame.
  // Someone else (the editors' creature panel) may have replaced a creature: compare.
  const int n = 1 + world.npc_count();
  auto identity = [](const Entity& e) -> const void* {
    return e.is_character() ? static_cast<const void*>(e.character()) : static_cast<const void*>(&e.creature());
  };
  bool changed = batch_dirty || static_cast<int>(batch_creatures.size()) != n;
  for (int i = 0; i < n && !changed; ++i) changed = batch_creatures[i] != identity(entity_at(world, i));
  // Texture slot 0 is the bone-sprite atlas; each rigged character in view brings its own.
  std::vector<const Texture*> textures = {&atlas->texture};
  for (const auto& e : characters) {
    if (!e->texture) {
      const RiggedMesh& mesh = e->loaded.mesh;
      e->texture = mesh.texture_rgba.empty() ? Texture::checker()
                                             : Texture::from_image(Image{mesh.texture_width, mesh.texture_height, mesh.texture_rgba});
    }
    textures.push_back(&*e->texture);
  }
  if (changed) {
    batch_creatures.resize(n);
    for (int i = 0; i < n; ++i) batch_creatures[i] = identity(entity_at(world, i));
    snapshot_all(world, true);
    batch->clear();
    meshes.clear();  // creatures may have been replaced (an address can be reused)
    // NPCs first, the player last: within each layer instances draw in order, so the
    // player's creature stays in front of the walkers it passes. A creature brings its
    // sprites and/or its body, as the look shows it.
    bodies.clear();
    instances.assign(static_cast<size_t>(n), {});
    for (int k = 0; k < n; ++k) {
      const int index = k == n - 1 ? 0 : k + 1;
      const Entity& e = entity_at(world, index);
      std::vector<int>& ids = instances[static_cast<size_t>(index)];
      if (e.is_character()) {
        int slot = 0;
        for (size_t j = 0; j < characters.size(); ++j) {
          if (characters[j]->loaded.character.get() == e.character()) slot = static_cast<int>(j) + 1;
        }
        const CharacterEntry* entry = entry_of(e.character());
        // A character the game did not load (an embedder's) is drawn with nothing.
        if (entry) ids.push_back(batch->add(entry->loaded.sprite_mesh, e.skeleton(), slot));
        else {
          SpriteMesh empty;
          empty.inverse_bind.assign(e.skeleton().bone_count(), Mat2x3{});
          ids.push_back(batch->add(empty, e.skeleton()));
        }
        continue;
      }
      const Creature& c = e.creature();
      if (look != CreatureLook::kBody) {
        auto it = meshes.find(&c);
        if (it == meshes.end()) it = meshes.emplace(&c, build_sprite_mesh(c, atlas->sprites)).first;
        ids.push_back(batch->add(it->second, c.skeleton));
      }
      if (look != CreatureLook::kBones) {
        auto it = bodies.find(&c);
        if (it == bodies.end()) it = bodies.emplace(&c, build_body(c)).first;
        ids.push_back(batch->add_body(it->second, c.skeleton));
      }
    }
    batch_dirty = false;
  }
  for (int i = 0; i < n && i < static_cast<int>(curr.size()) && i < static_cast<int>(instances.size()); ++i) {
    const auto& b = curr[i];
    const auto& a = prev[i].size() == b.size() ? prev[i] : b;
    blended.resize(b.size());
    for (size_t k = 0; k < b.size(); ++k) blended[k] = blend(a[k], b[k], alpha);
    for (const int instance : instances[static_cast<size_t>(i)]) {
      if (blended.empty() || static_cast<int>(blended.size()) != batch->bone_count(instance)) continue;
      batch->set_world(instance, blended);
      // A body rests on the ground under it (body_floor.h): flesh flattens, never enters it.
      const Entity& e = entity_at(world, i);
      if (const auto it = e.is_character() ? bodies.end() : bodies.find(&e.creature()); it != bodies.end()) {
        batch->set_floor(instance, body_floor(level, e.skeleton(), blended, it->second.reach, it->second.feet));
      }
    }
  }
  batch->upload_palettes();
  r.draw_creatures(*batch, textures, look);
  level_view->draw_front(r, level);
  if (game.on_viewport) {
    DebugDraw overlay;
    game.on_viewport(overlay);
    r.draw_debug(overlay);
  }

  // A GIF frame due this frame is the scene without the HUD and the editors' windows (at the
  // GIF's half size their text would be unreadable).
  if (gif && gif_clock + frame_dt >= 0.04f - 1e-4f) gif_frame = half_size(read_framebuffer(window.width(), window.height()));

  // HUD.
  if (imgui) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();
    const Animator& an = world.player()->animator();
    HudInfo info;
    info.creature = world.player()->name();
    info.hip_height = an.hip_height();
    info.blocked = describe_block(an.block_report());
    info.speed = an.velocity();
    info.walk_speed = an.walk_speed();
    info.run_speed = an.run_speed();
    info.gait = gait_name(an.gait());
    info.locomotion = locomotion_name(an.locomotion());
    const anim::GaitBands bands = an.gait_bands();
    info.family = gait_family_name(bands.family);
    for (int k = 0; k < 3; ++k) info.gaits[k] = gait_name(bands.gaits[k]);
    info.mid_speed = bands.mid;
    info.fast_speed = bands.fast;
    info.froude = an.froude();
    info.tick_hz = world.tick_hz();
    info.input = input_name;
    info.status = status;
    info.recording = recording;
    info.gif = gif.has_value();
    if (!(game.hide_hud && game.hide_hud())) hud.draw(info);
    if (game.on_ui) game.on_ui(frame_dt);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }
  check_gl("ossa frame");
}

// ---- GIF ------------------------------------------------------------------------------------

Status Game::Impl::start_gif(const std::string& path, float seconds) {
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  auto g = GifWriter::open(path, std::max(1, window.width() / 2), std::max(1, window.height() / 2), 4);
  if (!g.ok()) return g.error();
  gif.emplace(std::move(g.value()));
  gif_path = path;
  gif_remaining = seconds;
  gif_clock = 1.0f;  // the first frame right away
  return {};
}

void Game::Impl::capture_gif_frame(float dt) {
  if (!gif) return;
  gif_clock += dt;
  if (gif_clock >= 0.04f - 1e-4f) {  // 25 frames per second, the GIF's 4 cs delay
    gif_clock = std::fmod(gif_clock, 0.04f);
    const Status s = gif->add_frame(gif_frame ? *gif_frame : half_size(read_framebuffer(window.width(), window.height())));
    gif_frame.reset();
    if (!s.ok()) {
      say(s.message());
      gif.reset();
      return;
    }
  }
  gif_remaining -= dt;
  if (gif_remaining <= 0.0f) {
    const Status s = finish_gif();
    say(s.ok() ? "GIF written: " + gif_path : s.message());
  }
}

Status Game::Impl::finish_gif() {
  if (!gif) return {};
  Status s = gif->close();
  gif.reset();
  if (s.ok()) std::fprintf(stderr, "ossa: GIF written: %s\n", gif_path.c_str());
  return s;
}

}  // namespace ossa
