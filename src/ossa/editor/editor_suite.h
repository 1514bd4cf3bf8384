#pragma once
// EditorSuite — the single entry point the game calls for all editors (DESIGN.md §10,
// [T 4.3, 4.4.2], [Z 8.3]): spline prototypes, level, creature panel, tuning panel and the
// rig window (a skinned character's bone roles, rig_editor_model.h), one
// shared UndoStack (Ctrl+Z / Ctrl+Y), unsaved-change markers in the window titles, a
// confirmation before unsaved work is discarded, and hot reload of the level and prototype
// files. The models (level_editor_model.h, spline_editor_model.h, creature_panel_model.h,
// tuning_model.h) hold all logic and are usable without ImGui; this class draws them.
//
// Integration, once per frame of the game loop (ImGui context and backends are the game's):
//
//   EditorSuite editors(world, &generator, paths);      // after the World has its player
//   ...
//   editors.update(frame_dt);                           // footfall sampling, hot reload
//   ImGui_ImplOpenGL3_NewFrame(); ImGui_ImplSDL2_NewFrame(); ImGui::NewFrame();
//   editors.handle_keys(key_presses);                   // F2, Ctrl+Z/Y/S, Delete (SDL events)
//   bool used = editors.handle_mouse(mouse_px, left_down, wheel, camera, viewport_px);
//   if (!used && !ImGui::GetIO().WantCaptureMouse) { /* game mouse: pan, zoom */ }
//   if (!editors.wants_keyboard()) { /* game keys */ }
//   editors.draw_ui();                                  // all editor windows and popups
//   ImGui::Render();
//   debug.clear(); editors.draw_viewport(debug);        // selection, handles, grid, spawn
//   renderer.draw_debug(debug); ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
//   if (user_closed_window && editors.request_quit()) break;   // else a popup asks first
//   if (editors.quit_confirmed()) break;
//
// Space: handle_mouse takes the mouse in viewport pixels (x right, y down, origin top-left)
// and the Camera2D the game drew with; picking happens in world metres.
// Live: level edits change World::level() in place; spline and tuning edits reach the World
// at once (set_prototypes / set_params); the creature panel applies to the player or spawns
// NPCs on request. The world keeps stepping while you edit.
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/editor/creature_panel_model.h"
#include "ossa/editor/editor_layout.h"
#include "ossa/editor/level_editor_model.h"
#include "ossa/editor/rig_editor_model.h"
#include "ossa/editor/spline_editor_model.h"
#include "ossa/editor/tuning_model.h"
#include "ossa/editor/undo_stack.h"
#include "ossa/platform/input.h"
#include "ossa/render/renderer.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/render/texture.h"

namespace ossa {

class DebugDraw;
class World;

struct EditorPaths {
  std::string levels_dir = "levels";               // listed in the level editor (*.json)
  std::string level_file;                          // the file World::level() came from ("" = none)
  std::string prototypes_file;                     // the file the prototypes came from ("" = none)
  std::string genome_file = "creature.json";       // default path of genome save / load
  std::string tuning_file = "tuning.json";         // default path of tuning save / load
  std::string export_dir = ".";                    // creature (glTF, SVG, PNG) and Tiled exports go here
  std::string rig_file;                            // the mapping the rig window opens ("" = none)
  std::vector<std::string> characters;             // rig files the creature panel offers (shipped_characters())
};

class EditorSuite {
 public:
  // `world` and `generator` must outlive the suite. `generator` may be null: the creature
  // panel then says so and stays empty. Nothing is loaded: the World's current level and
  // prototypes are what is edited, with paths.level_file / paths.prototypes_file as their files.
  EditorSuite(World& world, const Generator* generator, EditorPaths paths);
  ~EditorSuite();

  // Master switch (the game binds a key to it): while off, draw_ui draws nothing and handles
  // no shortcuts, handle_mouse returns false and draw_viewport adds nothing; update() still
  // samples footfalls and polls files.
  bool enabled = true;
  // Which windows draw_ui shows (the game may bind keys to these).
  // The creature and tuning windows start closed so the viewport stays visible; the Windows
  // menu opens them.
  bool show_level = true, show_splines = true, show_creature = false, show_tuning = false, show_rig = false;
  // Makes the player the character of a rig file (the game passes Game::set_player_character,
  // which also loads its mesh for drawing). Unset: the suite loads it and replaces the World's
  // player itself.
  std::function<Status(const std::string& rig_path)> apply_character;
  // Level editing in the viewport (handle_mouse picks boxes only while this is on).
  bool level_edit_mode = true;

  // Per frame: samples the player's legs for the footfall diagram and polls the level and
  // prototype files about twice a second (hot reload; a file that fails to parse keeps the
  // current state and shows the error). dt in seconds.
  void update(float dt);

  // The keyboard shortcuts, from the frame's key presses (Game::key_presses(): SDL events, so a
  // tap shorter than a frame is never lost): F2 shows / hides the editors (`enabled`); while
  // shown and no text field has the keyboard, Ctrl+Z undoes (Ctrl+Shift+Z redoes), Ctrl+Y
  // redoes, Ctrl+S saves the level (the Level window's Save) and Delete removes the selected
  // box (viewport editing on, no window has the keyboard). Call once per frame, inside the
  // ImGui frame, before draw_ui().
  void handle_keys(std::span<const KeyChord> keys);

  // Draws every editor window and the popups. Call between ImGui::NewFrame() and
  // ImGui::Render().
  void draw_ui();

  // Adds the level editor's overlay in world space: grid around the view, the selected box
  // with its eight resize handles, the hovered box, and the spawn marker.
  void draw_viewport(DebugDraw& debug) const;

  // Level editing in the game viewport. Call once per frame with the current mouse state:
  // mouse_px in viewport pixels, `down` = left button held, wheel = scroll this frame
  // (unused by the editor: returned false so the game can zoom), the camera the scene was
  // drawn with and the viewport size in pixels. A press starts a drag (handle, spawn or box;
  // empty space deselects), moves drag, a release ends it as one undo step. Returns true
  // when the editor used the mouse (the game should not also use it). Ignored while ImGui
  // has the mouse (io.WantCaptureMouse, so call this after ImGui::NewFrame()) or
  // level_edit_mode is off.
  bool handle_mouse(glm::vec2 mouse_px, bool down, float wheel, const Camera2D& camera,
                    glm::vec2 viewport_px);

  // True while an ImGui text field or window wants the keyboard (the game should then
  // ignore its keys).
  bool wants_keyboard() const;

  // Any document (level, prototypes, genome, tuning) changed since its last save or load.
  bool has_unsaved_changes() const;
  // The user wants to quit: true when nothing is unsaved (quit now); otherwise opens the
  // "discard unsaved changes?" popup and returns false — quit_confirmed() turns true once
  // the user chose to discard.
  bool request_quit();
  bool quit_confirmed() const { return quit_confirmed_; }

  // ---- Models (for the game and tests) ---------------------------------------------------
  UndoStack& undo() { return undo_; }
  LevelEditorModel& level_editor() { return *level_; }
  SplineEditorModel& spline_editor() { return *spline_; }
  CreaturePanelModel* creature_panel() { return creature_.get(); }   // null without generator
  TuningModel& tuning() { return *tuning_; }
  RigEditorModel& rig() { return *rig_; }
  // What the creature panel's "Apply character to player" does (apply_character, or the
  // suite's own loading without it).
  Status apply_character_to_player_for_tests(const std::string& rig_path) { return apply_character_to_player(rig_path); }

  // The GL texture the Rig window's preview draws the character's mesh with (0: none yet, or
  // the mesh has no texture and is drawn grey). For tests.
  unsigned rig_preview_texture() const { return rig_preview_texture_ ? rig_preview_texture_->id() : 0u; }

  // Screen position (ImGui pixels) of a key of the spline canvas as drawn in the last frame
  // (nullopt before the first frame or when the window is hidden). For tests and tooling.
  std::optional<glm::vec2> spline_key_screen_px(SplineVersion version, int key) const;

  // Runs `action` at once, or — when `document` has unsaved changes — after the user
  // confirmed discarding them in a popup.
  void confirm_discard(EditorDocument document, std::function<void()> action);

 private:
  struct Canvas;       // a spline canvas's screen rectangle and value range
  void draw_level_window();
  void draw_spline_window();
  void draw_creature_window();
  void draw_creature_body(CreaturePanelModel& m);  // the look, appendages, skull (creature_body_window.cpp)
  void draw_tuning_window();
  void draw_rig_window();
  void draw_rig_preview(float width, float height);
  Status apply_character_to_player(const std::string& rig_path);
  void draw_popups();
  void save_level();
  // Sets the next window's position and size from editor_layout() (first use, or always in
  // the frame after Windows > Reset layout).
  void place_next_window(EditorWindow window);
  void draw_spline_canvas(int slot, SplineVersion version, float width, float height);
  void draw_preview_canvas(float width, float height);
  void refresh_level_files();

  World* world_;
  const Generator* generator_;
  EditorPaths paths_;
  UndoStack undo_;
  std::unique_ptr<LevelEditorModel> level_;
  std::unique_ptr<SplineEditorModel> spline_;
  std::unique_ptr<CreaturePanelModel> creature_;
  std::unique_ptr<TuningModel> tuning_;
  std::unique_ptr<RigEditorModel> rig_;
  // The Rig window's preview geometry: the character's mesh as batch geometry, rebuilt when
  // the character changes.
  const Character* rig_preview_key_ = nullptr;
  SpriteMesh rig_preview_mesh_;
  std::optional<Texture> rig_preview_texture_;  // the mesh's texture (none: drawn grey)

  // Viewport state.
  bool mouse_was_down_ = false;
  bool mouse_drag_ = false;
  std::optional<int> hovered_box_;
  Camera2D last_camera_;
  glm::vec2 last_viewport_px_{1.0f};

  // Spline canvases: walk, run, preview.
  std::unique_ptr<Canvas[]> canvases_;
  float preview_w_ = 0.0f;
  bool preview_follow_player_ = true;

  // Files and popups.
  std::vector<std::string> level_files_;
  float level_files_age_ = 1e9f;
  float poll_timer_ = 0.0f;
  char level_path_buf_[512] = {};
  bool reset_layout_ = false;  // Windows > Reset layout: place every window anew this frame
  char tiled_path_buf_[512] = {};
  char proto_path_buf_[512] = {};
  char genome_path_buf_[512] = {};
  char gltf_path_buf_[512] = {};
  char svg_path_buf_[512] = {};
  char png_path_buf_[512] = {};
  int png_size_[2] = {800, 600};  // pixels
  bool png_transparent_ = true;
  float png_background_[3] = {0.55f, 0.70f, 0.85f};  // the game's sky
  char tuning_path_buf_[512] = {};
  std::function<void()> pending_discard_;
  bool open_discard_popup_ = false;
  bool quit_confirmed_ = false;
  float variation_sigma_ = 0.5f;
  std::string colour_edit_;  // the body colour whose picker is open (one undo step)
  int creature_example_ = 0;
  int creature_character_ = 0;
  std::string character_message_;
  char rig_path_buf_[512] = {};
  char rig_mesh_buf_[512] = {};
};

}  // namespace ossa
