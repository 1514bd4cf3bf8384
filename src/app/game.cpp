// Game — init, the fixed-step loop with interpolation, input routing and the outputs.
// Drawing (camera, background, creatures, HUD) is in game_render.cpp.
//
// [SECTION] paths and loading
// [SECTION] init
// [SECTION] the frame: events, actions, fixed steps
// [SECTION] replays, captures and the state file

#include "app/game.h"

#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "app/game_impl.h"
#include "ossa/body/body_mesh.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/gen/true_size.h"
#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/level/level_io.h"
#include "ossa/platform/input.h"

namespace ossa {

// ---- [SECTION] paths and loading ------------------------------------------------------------

std::string resolve_data_path(const std::string& path) {
  std::error_code ec;
  if (path.empty() || std::filesystem::exists(path, ec) || std::filesystem::path(path).is_absolute()) return path;
  // "project.ldtk#Level": resolve the file, keep the level name.
  if (const size_t hash = path.rfind('#'); hash != std::string::npos && hash > 0) {
    return resolve_data_path(path.substr(0, hash)) + path.substr(hash);
  }
  const std::string in_tree = data_path(path);
  return std::filesystem::exists(in_tree, ec) ? in_tree : path;
}

namespace {

// An NPC cast that walks well on box levels, first the smallest and one of the biggest beside
// the default horse (sizes at a glance); they cycle when there are more NPCs.
constexpr const char* kNpcExamples[] = {"rabbit", "african elephant", "red deer", "ostrich", "pig", "dromedary", "wildebeest", "triceratops"};

Result<std::shared_ptr<const Creature>> make_creature(const Genome& genome) {
  auto c = build_creature(genome);
  if (!c.ok()) return c.error();
  return std::shared_ptr<const Creature>(std::make_shared<Creature>(std::move(c.value())));
}

std::string next_free(const std::string& dir, const std::string& stem, const std::string& ext) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (int i = 1;; ++i) {
    char name[64];
    std::snprintf(name, sizeof(name), "%s-%04d%s", stem.c_str(), i, ext.c_str());
    const std::string p = dir + "/" + name;
    if (!std::filesystem::exists(p, ec)) return p;
  }
}

}  // namespace

Game::Game() : impl_(std::make_unique<Impl>()) {}

Game::~Game() {
  if (impl_) impl_->shutdown_imgui();
  // GL objects go before the window that owns the context.
  if (impl_) impl_->release_gl();
}

std::string Game::creature_name() const {
  const Player* p = world_ ? world_->player() : nullptr;
  return p ? p->name() : "";
}

bool Game::replay_finished() const {
  return impl_->playback && impl_->playback_cursor.done();
}

// ---- [SECTION] init -------------------------------------------------------------------------

Status Game::init(const GameOptions& o) {
  options_ = o;
  Impl& m = *impl_;
  if (o.tick_hz < 30 || o.tick_hz > 480) return Error{"--hz: expected an integer in [30, 480], got " + std::to_string(o.tick_hz)};
  if (o.npcs < 0 || o.npcs > 64) return Error{"--npcs: expected an integer in [0, 64], got " + std::to_string(o.npcs)};
  if (o.frames < 0) return Error{"--frames: expected an integer >= 0"};
  if (o.width < 16 || o.height < 16) return Error{"window size must be at least 16 x 16"};
  if (o.max_steps_per_frame < 1) return Error{"max_steps_per_frame must be >= 1"};
  const int sources = (o.creature_file.empty() ? 0 : 1) + (o.example.empty() ? 0 : 1) + (o.seed ? 1 : 0) +
                      (o.character.empty() ? 0 : 1);
  if (sources > 1) return Error{"give only one of --creature, --example, --seed, --character"};
  // No output may be one of the inputs (io/file.h).
  {
    std::vector<std::string> inputs;
    for (const std::string* in : {&o.level, &o.replay, &o.creature_file, &o.character}) {
      if (!in->empty()) inputs.push_back(resolve_data_path(*in));
    }
    for (const auto& [flag, path] : {std::pair{"--record", &o.record}, std::pair{"--state", &o.state},
                                     std::pair{"--png", &o.png}, std::pair{"--gif", &o.gif}}) {
      if (path->empty()) continue;
      if (Status st = check_output_path(flag, *path, inputs); !st) return st;
    }
  }

  // Replay first: it fixes the creature, the spawn and the tick rate.
  int tick_hz = o.tick_hz;
  std::string level_path = o.level;
  if (!o.replay.empty()) {
    if (sources > 0) return Error{"--replay brings its own creature: drop --creature/--example/--seed/--character"};
    if (o.size) return Error{"--replay brings its own creature: drop --size true|FRAME_M"};
    auto r = load_replay(o.replay);
    if (!r.ok()) return r.error();
    m.playback = std::move(r.value());
    m.playback_cursor = ReplayCursor(&*m.playback);
    tick_hz = m.playback->tick_hz;
    if (level_path.empty() && !m.playback->level.empty()) level_path = m.playback->level;
  }
  if (level_path.empty()) level_path = "levels/default.json";
  m.level_path = level_path;
  m.out_dir = o.out_dir;
  LevelLoadOptions level_options;
  level_options.pixels_per_metre = o.pixels_per_metre;
  auto level = load_level(resolve_data_path(level_path), level_options);
  if (!level.ok()) return level.error();
  for (const std::string& w : level_warnings(*level)) std::fprintf(stderr, "warning: %s: %s\n", level_path.c_str(), w.c_str());

  auto prototypes = load_prototypes(resolve_data_path("assets/animation/prototypes.json"));
  if (!prototypes.ok()) return prototypes.error();
  auto generator = Generator::load(resolve_data_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  if (!generator.ok()) return generator.error();
  m.generator = std::make_unique<Generator>(std::move(generator.value()));
  if (o.size) o.size->apply_to(m.generate.genome);

  // A rigged character: from --character or the replay.
  std::string character_path = o.character;
  if (m.playback && !m.playback->character.empty()) character_path = m.playback->character;
  const Impl::CharacterEntry* character = nullptr;
  if (!character_path.empty()) {
    auto c = m.character(character_path);
    if (!c.ok()) return m.playback ? Error{o.replay + ": character: " + c.message()} : c.error();
    character = c.value();
  }

  Genome genome;
  if (character) {
    auto g = m.generator->example(kDefaultExample, 1, m.generate);  // kept for N (next example) and the window title
    if (!g.ok()) return g.error();
    genome = std::move(g.value());
  } else if (m.playback) {
    auto g = genome_from_json(m.playback->creature, o.replay + ": creature");
    if (!g.ok()) return g.error();
    genome = std::move(g.value());
  } else if (!o.creature_file.empty()) {
    auto g = load_genome(o.creature_file);
    if (!g.ok()) return g.error();
    genome = std::move(g.value());
    if (o.size) {  // resized: its scale made again for the size asked for
      o.size->apply_to(genome.options);
      m.generator->apply_size(genome);
    }
  } else if (o.seed) {
    genome = m.generator->random(*o.seed, m.generate);
  } else {
    const std::string name = o.example.empty() ? kDefaultExample : o.example;
    auto g = m.generator->example(name, 1, m.generate);
    if (!g.ok()) return g.error();
    genome = std::move(g.value());
  }
  auto creature = make_creature(genome);
  if (!creature.ok()) return creature.error();
  m.genome = genome;
  const auto& animals = m.generator->dataset().animals;
  for (size_t i = 0; i < animals.size(); ++i) {
    if (animals[i].name == genome.name) m.example_index = static_cast<int>(i);
  }
  m.random_seed = o.seed ? *o.seed + 1 : 1000;

  world_ = std::make_unique<World>(std::move(level.value()), std::move(prototypes.value()), AnimatorParams{}, tick_hz);
  world_->set_threads(o.threads);
  glm::vec2 spawn = world_->level().spawn_ws + glm::vec2(0.0f, 0.5f);
  int facing = 1;
  if (m.playback) {
    spawn = m.playback->spawn_ws;
    facing = m.playback->facing >= 0 ? 1 : -1;
  }
  if (character) {
    world_->spawn_player(character->loaded.character, spawn, facing);
    m.character_path = character->path;
  } else {
    world_->spawn_player(creature.value(), spawn, facing);
  }
  m.spawn = spawn;
  const std::vector<std::string> shipped = shipped_characters();
  for (size_t i = 0; i < shipped.size(); ++i) {
    if (character && std::filesystem::path(shipped[i]).filename() == std::filesystem::path(character->path).filename()) {
      m.character_index = static_cast<int>(i);
    }
  }
  // NPCs stand ahead of the player in a row, each a metre (or a body length, for the small
  // ones: a rabbit beside a horse) clear of the one before, by their sizes at true size (a
  // triceratops is 9.5 m long, a rabbit 28 cm), inside the level.
  const Box npc_bounds = world_->level().bounds();
  const auto inside = [&](float x) {
    return std::clamp(x, npc_bounds.min_ws.x + 2.0f, std::max(npc_bounds.min_ws.x + 2.0f, npc_bounds.max_ws.x - 2.0f));
  };
  const float player_length = world_->player()->animator().rig().scale.length;
  float row_x = world_->level().spawn_ws.x + 0.5f * player_length;  // the row's front so far
  for (int i = 0; i < o.npcs; ++i) {
    if (o.npc_characters && i % 2 == 1 && !shipped.empty()) {
      const float npc_x = inside(row_x + 2.0f);
      row_x += 3.5f;
      auto c = m.character(shipped[static_cast<size_t>(i / 2) % shipped.size()]);
      if (!c.ok()) return c.error();
      world_->spawn_npc(c.value()->loaded.character, {npc_x, world_->level().spawn_ws.y + 2.0f},
                        0x9e3779b97f4a7c15ull * static_cast<uint64_t>(i + 1));
      continue;
    }
    auto g = m.generator->example(kNpcExamples[i % std::size(kNpcExamples)], 7 + i, m.generate);
    if (!g.ok()) return g.error();
    auto c = make_creature(g.value());
    if (!c.ok()) return c.error();
    const float length = size_measure(*c.value(), SizeMeasure::kLength);
    const float gap = std::min(1.0f, std::max(length, 0.1f));
    const float npc_x = inside(row_x + gap + 0.5f * length);
    row_x += gap + length;
    const glm::vec2 at{npc_x, world_->level().spawn_ws.y + 0.5f};  // (within the reset's snap: standing)
    world_->spawn_npc(c.value(), at, 0x9e3779b97f4a7c15ull * static_cast<uint64_t>(i + 1));
  }
  if (o.demo) {
    auto script = parse_script(kDemoScript);
    if (!script.ok()) return script.error();
    m.demo = std::move(script.value());
  }

  // Window, renderer, input.
  if (auto s = m.open_window(o); !s.ok()) return s;
  gamepad_ = std::make_unique<Gamepad>(resolve_data_path("assets/gamecontrollerdb.txt"));
  keyboard_ = std::make_unique<MouseKeyboardInput>();
  m.hud.mode = o.hud ? HudMode::kPlayer : HudMode::kOff;
  m.look = o.look;
  m.capture_all_frames = false;
  if (!o.gif.empty()) {
    if (auto s = m.start_gif(o.gif, o.headless ? 1e9f : o.gif_seconds); !s.ok()) return s;
  }
  m.snapshot_all(*world_, true);
  m.reset_camera(*world_);
  if (!o.record.empty()) m.start_recording(*world_, level_path, false);
  return {};
}

// ---- [SECTION] the frame --------------------------------------------------------------------

void Game::next_example() {
  Impl& m = *impl_;
  const int n = static_cast<int>(m.generator->dataset().animals.size());
  // Skip animals that cannot stand (no legs build a crawler; still fine) — every example
  // builds; an example that fails to build is skipped.
  for (int tries = 0; tries < n; ++tries) {
    m.example_index = (m.example_index + 1) % n;
    auto g = m.generator->example(m.generator->dataset().animals[m.example_index].name, 1, m.generate);
    if (!g.ok()) continue;
    if (m.switch_creature(*world_, g.value())) return;
  }
}

void Game::random_creature() {
  Impl& m = *impl_;
  for (int tries = 0; tries < 8; ++tries) {
    if (m.switch_creature(*world_, m.generator->random(m.random_seed++, m.generate))) return;
  }
}

void Game::next_character() {
  Impl& m = *impl_;
  const std::vector<std::string> shipped = shipped_characters();
  if (shipped.empty()) {
    m.say("no characters in " + data_path("assets/characters"));
    return;
  }
  for (size_t tries = 0; tries < shipped.size(); ++tries) {
    m.character_index = (m.character_index + 1) % static_cast<int>(shipped.size());
    const Status s = m.switch_character(*world_, shipped[static_cast<size_t>(m.character_index)]);
    if (s.ok()) return;
    m.say(s.message());
  }
}

HudMode Game::hud_mode() const { return impl_->hud.mode; }

Status Game::set_player_character(const std::string& rig_path) { return impl_->switch_character(*world_, rig_path, true); }

bool Game::frame(double dt_seconds) {
  Impl& m = *impl_;
  ActionPresses presses;
  SDL_Event e;
  key_presses_.clear();
  while (SDL_PollEvent(&e)) {
    if (auto chord = key_chord(e)) key_presses_.push_back(*chord);
    m.process_imgui_event(e);
    keyboard_->handle_event(e, presses);
    gamepad_->handle_event(e, presses);
  }
  if (keyboard_->quit_requested()) {
    keyboard_->clear_quit();
    if (!on_quit || on_quit()) return false;
  }
  if (should_quit && should_quit()) return false;
  m.frame_dt = static_cast<float>(dt_seconds);
  // A text field or an editor window has the keyboard / mouse: game keys and the wheel wait.
  if (m.ui_wants_keyboard()) presses = ActionPresses{};
  const float wheel = keyboard_->take_wheel();
  if (wheel != 0.0f && !m.ui_wants_mouse()) m.zoom = std::clamp(m.zoom * std::pow(0.88f, wheel), 0.2f, 10.0f);

  if (presses[Action::kNextCreature]) next_example();
  if (presses[Action::kRandomCreature]) random_creature();
  if (presses[Action::kNextCharacter]) next_character();
  if (presses[Action::kToggleHud]) {
    m.hud.cycle();
    if (m.hud.mode != HudMode::kOff) m.say(std::string("HUD: ") + hud_mode_name(m.hud.mode));
  }
  if (presses[Action::kNextLook]) {
    m.look = static_cast<CreatureLook>((static_cast<int>(m.look) + 1) % kCreatureLookCount);
    m.batch_dirty = true;
    m.say(std::string("look: ") + creature_look_name(m.look) + " (B for the next)");
  }
  if (presses[Action::kGif] && !m.gif) {
    const std::string path = next_free(options_.out_dir, "gif", ".gif");
    if (auto s = m.start_gif(path, options_.gif_seconds); !s.ok()) m.say(s.message());
    else m.say("GIF " + path);
  }
  if (presses[Action::kRecord]) {
    if (m.recording) {
      const std::string path = options_.record.empty() ? next_free(options_.out_dir, "replay", ".replay.json") : options_.record;
      m.say(m.stop_recording(path));
    } else {
      m.start_recording(*world_, m.level_path, true);
      m.say("recording a replay (R to stop)");
    }
  }

  // Fixed steps; at most max_steps_per_frame of them (spiral-of-death guard).
  const double tick = 1.0 / world_->tick_hz();
  m.accumulator += std::clamp(dt_seconds, 0.0, 0.25);
  int steps = 0;
  while (m.accumulator >= tick && steps < options_.max_steps_per_frame) {
    Controls c;
    if (m.playback && !m.playback_cursor.done()) {
      c = m.playback_cursor.next();
      m.input_name = "replay";
    } else if (m.playback && options_.headless && options_.frames == 0) {
      break;  // a headless playback ends with its replay
    } else if (!m.demo.empty() && !keyboard_->active() && !gamepad_->active()) {
      c = m.demo_controls(world_->tick(), world_->tick_hz());
      m.input_name = "demo";
    } else {
      // While an ImGui text field has the keyboard, A/D type letters instead of walking.
      c = !m.ui_wants_keyboard() ? combine_controls(*keyboard_, *gamepad_)
          : gamepad_->connected() ? gamepad_->controls() : Controls{};
      m.input_name = keyboard_->active() || !gamepad_->connected() ? "keyboard" : gamepad_->name();
    }
    m.snapshot_all(*world_, false);
    // A replay's controls already had the player's meetings applied when they were recorded.
    world_->player_meets_creatures = m.input_name != "replay";
    world_->step(c);
    m.after_step(*world_);
    // The controls the world applied (a move into a creature dropped): the replay then plays
    // back the same, whatever creatures are around.
    if (m.recording) m.record.push(world_->applied_player_controls());
    last_controls_ = c;
    m.accumulator -= tick;
    ++steps;
  }
  if (steps == options_.max_steps_per_frame && m.accumulator >= tick) m.accumulator = std::fmod(m.accumulator, tick);
  const float alpha = static_cast<float>(std::clamp(m.accumulator / tick, 0.0, 1.0));

  m.update_camera(*world_, alpha, static_cast<float>(dt_seconds));
  m.hud.add_frame_time(static_cast<float>(dt_seconds));
  m.render(*this, alpha);
  if (presses[Action::kScreenshot]) {
    const std::string path = next_free(options_.out_dir, "shot", ".png");
    const Status s = write_png(path, read_framebuffer(m.window.width(), m.window.height()));
    m.say(s.ok() ? "screenshot " + path : s.message());
    std::fprintf(stderr, "ossa: %s\n", m.status.c_str());
  }
  m.capture_gif_frame(static_cast<float>(dt_seconds));
  m.window.swap();
  ++frames_;
  m.status_timer -= static_cast<float>(dt_seconds);
  if (m.status_timer <= 0.0f) m.status.clear();

  if (options_.frames > 0 && frames_ >= options_.frames) return false;
  if (m.playback && options_.headless && options_.frames == 0 && replay_finished()) return false;
  return true;
}

int Game::run() {
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  const bool cap = options_.fps_cap > 0 && (!options_.vsync || options_.headless);
  while (true) {
    const auto start = Clock::now();
    double dt = options_.headless ? 1.0 / 60.0 : std::chrono::duration<double>(start - last).count();
    last = start;
    if (!frame(dt)) break;
    if (cap && !options_.headless) {
      const auto target = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options_.fps_cap));
      std::this_thread::sleep_until(target);
    }
  }
  const Status s = finish();
  if (!s.ok()) {
    std::fprintf(stderr, "ossa: %s\n", s.message().c_str());
    return 1;
  }
  return 0;
}

// ---- [SECTION] outputs ----------------------------------------------------------------------

Status Game::finish() {
  Impl& m = *impl_;
  Status result;
  if (m.gif) {
    const Status s = m.finish_gif();
    if (!s.ok() && result.ok()) result = s;
  }
  if (m.recording) {
    const std::string path = options_.record.empty() ? next_free(options_.out_dir, "replay", ".replay.json") : options_.record;
    const std::string msg = m.stop_recording(path);
    if (m.last_record_failed && result.ok()) result = Error{msg};
  }
  if (!options_.png.empty()) {
    m.render(*this, static_cast<float>(std::clamp(m.accumulator * world_->tick_hz(), 0.0, 1.0)));
    const Status s = write_png(options_.png, read_framebuffer(m.window.width(), m.window.height()));
    if (!s.ok() && result.ok()) result = s;
  }
  if (!options_.state.empty()) {
    const Player& p = *world_->player();
    Json doc;
    doc["format"] = "ossa.state";  // every file ossa writes starts with format and version
    doc["version"] = 1;
    doc["frames"] = frames_;
    doc["ticks"] = world_->tick();
    const glm::vec2 root = p.animator().world_matrices().empty() ? glm::vec2(p.animator().x(), 0.0f)
                               : glm::vec2(p.animator().world_matrices()[0].m[4], p.animator().world_matrices()[0].m[5]);
    char hash[32];
    std::snprintf(hash, sizeof(hash), "%016llx", static_cast<unsigned long long>(pose_hash(p.animator().world_matrices())));
    doc["player"] = {{"x", p.animator().x()}, {"y", root.y}, {"speed", p.animator().velocity()},
                     {"creature", p.name()}, {"gait", gait_name(p.animator().gait())},
                     {"pose_hash", hash}};
    doc["spawn"] = {{"x", world_->level().spawn_ws.x}, {"y", world_->level().spawn_ws.y}};
    doc["tick_hz"] = world_->tick_hz();
    const Status s = write_json_atomic(options_.state, doc);
    if (!s.ok() && result.ok()) result = s;
  }
  return result;
}

}  // namespace ossa
