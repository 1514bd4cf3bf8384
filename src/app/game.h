#pragma once
// Game — the playable runtime (DESIGN.md §8, [T 4.3]): a window, a World stepped at a fixed
// rate with interpolated rendering, gamepad and keyboard input, a following camera, the
// parallax background and the level, the player and NPC walkers, the HUD, screenshots, GIFs
// and replays.
//
//   GameOptions options;              // or parse_game_args(argc, argv) (options.h)
//   Game game;
//   if (auto s = game.init(options); !s.ok()) { report(s.message()); return 1; }
//   return game.run();                // until Escape, the window closes or --frames ran out
//
// Timing: the simulation advances in fixed ticks of 1/tick_hz; each frame adds its wall time
// (a fixed 1/60 s when headless, so headless runs are deterministic) to an accumulator, runs
// whole ticks (at most max_steps_per_frame — the guard against the spiral of death: a slow
// frame drops time instead of demanding ever more ticks) and renders every creature blended
// between its last two poses by the accumulator's remainder.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/game/controls.h"
#include "ossa/game/replay.h"
#include "ossa/gen/genome.h"
#include "ossa/game/world.h"
#include "ossa/editor/hud.h"
#include "ossa/io/result.h"
#include "ossa/platform/input.h"

namespace ossa {

class DebugDraw;
class Gamepad;
class MouseKeyboardInput;
struct Camera2D;

struct GameOptions {
  std::string level = "levels/default.json";  // level file (relative paths: cwd, then the source tree)
  // Scale of Tiled/LDtk maps with neither a pixels_per_metre property nor a tile size
  // (LevelLoadOptions::pixels_per_metre), pixels per metre, > 0.
  float pixels_per_metre = 32.0f;
  // Player creature: a genome file, an example name or a random seed (at most one set;
  // none → kDefaultExample).
  std::string creature_file;
  std::string example;
  std::optional<uint64_t> seed;
  // ... or a rigged character: its rig mapping (.rig.json); exclusive with the three above.
  std::string character;
  // The size of every creature the game makes (the player, the NPCs, the next example and
  // random creatures) and of a --creature genome: unset, examples and random creatures at their
  // true size and genome files as saved (GenomeOptions::true_size, frame_m).
  std::optional<SizeChoice> size;
  int npcs = 3;                 // NPC walkers, [0, 64]
  bool npc_characters = false;  // every other NPC is one of the shipped rigged characters
  std::string replay;           // play this replay file back
  std::string record;           // record the session's controls to this replay file
  bool headless = false;        // offscreen driver, fixed 1/60 s frames
  int frames = 0;               // stop after this many frames (0: run until quit / replay end)
  std::string png;              // screenshot of the last frame
  std::string gif;              // GIF of the whole run (headless) or the first gif_seconds
  std::string state;            // JSON state written on exit
  int tick_hz = 120;            // [30, 480]
  int threads = 0;              // threads stepping the world (World::set_threads): 0 = every core
  bool vsync = true;
  int fps_cap = 0;              // frames per second when vsync is off (0 = uncapped); [0, 1000]
  int width = 1280, height = 720;
  float gif_seconds = 5.0f;     // length of a G-key GIF, seconds
  std::string out_dir = "out";  // where key-triggered screenshots, GIFs and replays go
  // Drive the player with the built-in demo script (walk right, run, stop, walk). Set by
  // main for headless runs without a replay.
  bool demo = false;
  bool hud = true;              // the HUD starts visible
  // How generated creatures are drawn: their bodies (default), bodies over bones (x-ray) or
  // bone sprites; key B cycles (body/body_mesh.h). Rigged characters are drawn as made.
  CreatureLook look = CreatureLook::kBody;
  int max_steps_per_frame = 8;  // the spiral-of-death guard, >= 1
};

inline constexpr const char* kDefaultExample = "horse";
// The demo script (sim.h's segment syntax), 10 seconds long.
// The headless demo (tools/play without a display runs it on levels/drops.json): walking
// off a ledge, running off the next, a jump down the third.
inline constexpr const char* kDemoScript = "walk:0.5:2.5,run:1:2.5,stop:1,walk:0.5:1.5,jump,walk:0.5:2.5";

class Game {
 public:
  Game();
  ~Game();
  Game(const Game&) = delete;
  Game& operator=(const Game&) = delete;

  // Loads everything and opens the window. Every bad file or option gives an Error naming it.
  Status init(const GameOptions& options);
  // The main loop; returns the process exit code (0, or 1 when writing an output failed).
  int run();

  // ---- One frame (run() calls these; tests drive them directly) ---------------------------
  // Polls SDL events, then advances the simulation by `dt_seconds` of wall time and renders.
  // Returns false once the game should quit.
  bool frame(double dt_seconds);
  // Writes --png / --gif / --record / --state outputs; run() calls it at the end.
  Status finish();

  // ---- Introspection ----------------------------------------------------------------------
  World& world() { return *world_; }
  const World& world() const { return *world_; }
  Gamepad& gamepad() { return *gamepad_; }
  MouseKeyboardInput& keyboard() { return *keyboard_; }
  const GameOptions& options() const { return options_; }
  long long frames() const { return frames_; }
  // The controls used in the last tick.
  const Controls& last_controls() const { return last_controls_; }
  // Name of the player's creature or character.
  std::string creature_name() const;
  // Switches the player's creature: the next example (cycling the 44) / a new random one.
  void next_example();
  void random_creature();
  // Switches the player to the next shipped rigged character (assets/characters/*.rig.json).
  void next_character();
  // Makes the player the rigged character of this rig file, read anew (the rig window may have
  // saved it since); on an error the player stays as it was and the error names the file.
  Status set_player_character(const std::string& rig_path);
  bool replay_finished() const;
  // What the HUD shows (H cycles it: player, developer, off).
  HudMode hud_mode() const;
  // Whether the HUD is drawn: its mode is not off and hide_hud (the editors) does not hide it.
  bool hud_shown() const { return hud_mode() != HudMode::kOff && !(hide_hud && hide_hud()); }
  // The camera of the last rendered frame (world metres; for mouse picking).
  const Camera2D& camera() const;
  // The keys pressed during this frame's events, in order (a press and its release within one
  // frame included): the editors' shortcuts read them in on_ui.
  std::span<const KeyChord> key_presses() const { return key_presses_; }

  // ---- Hooks for the editors (DESIGN.md §10) -----------------------------------------------
  // Called every frame inside the ImGui frame, after the HUD (dt = the frame's seconds).
  std::function<void(float dt)> on_ui;
  // Called every frame after the creatures are drawn: world-space overlays (selection,
  // handles, grid), drawn on top of the scene.
  std::function<void(DebugDraw& draw)> on_viewport;
  // Called when the player asks to quit (Escape, closing the window). Return false to keep
  // running — e.g. unsaved editor work, for which a prompt asks first.
  std::function<bool()> on_quit;
  // Polled every frame: true ends the game (e.g. the editors' "discard" was confirmed).
  std::function<bool()> should_quit;
  // Polled every frame: true hides the HUD (the editors are shown: their windows and menu bar
  // take the screen's edges).
  std::function<bool()> hide_hud;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  GameOptions options_;
  std::unique_ptr<World> world_;
  std::vector<KeyChord> key_presses_;
  std::unique_ptr<Gamepad> gamepad_;
  std::unique_ptr<MouseKeyboardInput> keyboard_;
  Controls last_controls_;
  long long frames_ = 0;
};

// Path resolution shared with main: `path` as given when it exists, else relative to the
// data folder (data_path(), ossa/io/data_dir.h: $OSSA_SOURCE_DIR or the compiled-in source tree).
std::string resolve_data_path(const std::string& path);

}  // namespace ossa
