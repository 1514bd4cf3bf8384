#pragma once
// Game's private state, shared by game.cpp (loop, input, outputs) and game_render.cpp
// (camera, background, creatures, HUD, captures). Not part of the public interface.

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <SDL.h>

#include "app/game.h"
#include "ossa/editor/hud.h"
#include "ossa/game/sim.h"
#include "ossa/gen/generator.h"
#include "ossa/math/transform2d.h"
#include "ossa/platform/window.h"
#include "ossa/render/capture.h"
#include "ossa/render/character_mesh.h"
#include "ossa/render/creature_batch.h"
#include "app/camera_follow.h"
#include "ossa/render/level_view.h"
#include "ossa/render/renderer.h"
#include "ossa/render/texture.h"

namespace ossa {

struct Game::Impl {
  // Loading.
  std::unique_ptr<Generator> generator;
  GenerateOptions generate;      // of every creature made: the size choice (GameOptions::size)
  Genome genome;                 // the player's
  int example_index = 0;         // into the dataset, for cycling
  uint64_t random_seed = 1000;
  std::string level_path;
  std::string out_dir = "out";
  glm::vec2 spawn{0.0f};         // where the player was placed (the replay's spawn)

  // Platform and GL.
  Window window;
  std::optional<Renderer> renderer;
  std::optional<Atlas> atlas;
  std::unique_ptr<CreatureBatch> batch;
  bool imgui = false;
  bool batch_dirty = true;
  std::unordered_map<const Creature*, SpriteMesh> meshes;  // built once per creature
  std::unordered_map<const Creature*, BodyMesh> bodies;    // built once per creature
  CreatureLook look = CreatureLook::kBody;                 // key B cycles
  // Per entity (0 = player, 1.. NPCs) its batch instances (sprites and/or body).
  std::vector<std::vector<int>> instances;
  std::optional<LevelView> level_view;                     // the level as designed (art, look, sky)
  std::vector<const void*> batch_creatures;                // what the batch was built from (Creature or Character)

  // Rigged characters loaded so far, by rig path, each with its texture once GL is up.
  struct CharacterEntry {
    std::string path;             // as given (what replays record)
    LoadedCharacter loaded;
    std::optional<Texture> texture;
  };
  std::vector<std::unique_ptr<CharacterEntry>> characters;
  std::string character_path;    // the player's character's rig file ("" for a creature)
  int character_index = -1;      // into shipped_characters(), for cycling

  // Interpolation: per creature (0 = player, 1.. = NPCs) the world matrices of the last two ticks.
  std::vector<std::vector<Mat2x3>> prev, curr;
  std::vector<Mat2x3> blended;
  double accumulator = 0.0;      // seconds not yet simulated

  // Camera.
  CameraFollow follow;           // camera_follow.h
  glm::vec2 camera_ws{0.0f};     // follow's centre, drawn with
  float zoom = 1.0f;             // wheel factor on the base view height
  float base_half_height = 2.5f; // metres, from the player's size

  // Input sources.
  std::optional<Replay> playback;
  ReplayCursor playback_cursor;  // over *playback
  std::vector<ScriptSegment> demo;
  std::string input_name = "keyboard";

  // Outputs.
  Hud hud;
  std::string status;
  float status_timer = 0.0f;
  std::optional<GifWriter> gif;
  std::string gif_path;
  float gif_remaining = 0.0f;    // seconds
  float gif_clock = 0.0f;        // seconds since the last GIF frame
  std::optional<Image> gif_frame;  // the next GIF frame, read before the HUD was drawn
  bool capture_all_frames = false;
  bool recording = false;
  bool last_record_failed = false;
  Replay record;

  // game_render.cpp
  Status open_window(const GameOptions& o);
  void release_gl();
  void shutdown_imgui();
  void process_imgui_event(const SDL_Event& e);
  CameraSubject camera_subject(const World& world, float alpha) const;
  float window_aspect() const;
  void reset_camera(const World& world);
  void update_camera(const World& world, float alpha, float dt);
  void render(Game& game, float alpha);
  Status start_gif(const std::string& path, float seconds);
  void capture_gif_frame(float dt);
  Status finish_gif();
  bool ui_wants_keyboard() const;
  bool ui_wants_mouse() const;
  float frame_dt = 0.0f;         // seconds, the current frame's

  // game.cpp / game_render.cpp
  void snapshot_all(const World& world, bool both);  // prev = curr (both: also curr = now)
  void after_step(const World& world);               // curr = now
  bool switch_creature(World& world, const Genome& g);
  // Loaded once, then cached (the newest load of a path wins; older ones stay for whoever
  // still walks as them); `reload` loads the file again (the rig window saved it anew).
  Result<const CharacterEntry*> character(const std::string& path, bool reload = false);
  const CharacterEntry* entry_of(const Character* c) const;
  Status switch_character(World& world, const std::string& path, bool reload = false);
  void start_recording(World& world, const std::string& level, bool respawn);
  std::string stop_recording(const std::string& path);
  std::string next_free_replay_path();
  Controls demo_controls(uint64_t tick, int tick_hz) const;
  void say(const std::string& message) {
    status = message;
    status_timer = 4.0f;
  }
  glm::vec2 player_root(float alpha) const;
};

}  // namespace ossa
