#include "app/game_editors.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <imgui.h>

#include "ossa/body/body_mesh.h"
#include "ossa/editor/tuning_model.h"
#include "ossa/render/character_mesh.h"

namespace ossa {

GameEditors::GameEditors(Game& game, const GameOptions& o) : game_(&game) {
  if (auto generator = Generator::load(resolve_data_path("assets/creatures/examples.json"), ossa::body_volume_m3); generator.ok()) {
    generator_.emplace(std::move(generator.value()));
  }
  EditorPaths paths;
  paths.levels_dir = resolve_data_path("levels");
  paths.level_file = resolve_data_path(o.level.empty() ? "levels/default.json" : o.level);
  paths.prototypes_file = resolve_data_path("assets/animation/prototypes.json");
  paths.genome_file = o.out_dir + "/creature.json";
  paths.tuning_file = o.out_dir + "/tuning.json";
  paths.export_dir = o.out_dir;
  paths.rig_file = resolve_data_path(o.character.empty() ? "assets/characters/humanoid.rig.json" : o.character);
  paths.characters = shipped_characters();
  // Tuning saved from the tuning panel is loaded again at start.
  std::error_code tuning_missing;  // (exists, not an open: a pipe would block here)
  if (std::filesystem::exists(paths.tuning_file, tuning_missing)) {
    if (auto params = load_params(paths.tuning_file); params.ok()) {
      game.world().set_params(*params);
    } else {
      std::fprintf(stderr, "ossa: %s (keeping the default tuning)\n", params.message().c_str());
    }
  }
  suite_.emplace(game.world(), generator_ ? &*generator_ : nullptr, paths);
  EditorSuite& editors = *suite_;
  editors.level_editor().options.pixels_per_metre_tiled = o.pixels_per_metre;  // --pixels-per-metre
  editors.apply_character = [&game](const std::string& rig_path) { return game.set_player_character(rig_path); };
  editors.enabled = std::getenv("OSSA_EDITORS") != nullptr;  // start shown with OSSA_EDITORS=1
  game.on_ui = [&game, &editors](float dt) {
    const ImGuiIO& io = ImGui::GetIO();
    editors.handle_keys(game.key_presses());  // F2, Ctrl+Z, Ctrl+Y, Ctrl+S, Delete
    editors.update(dt);
    editors.handle_mouse({io.MousePos.x, io.MousePos.y}, io.MouseDown[0], io.MouseWheel, game.camera(),
                         {io.DisplaySize.x, io.DisplaySize.y});
    editors.draw_ui();
  };
  game.on_viewport = [&editors](DebugDraw& draw) { editors.draw_viewport(draw); };
  // Quitting with unsaved editor work asks first (the editors show the prompt).
  game.on_quit = [&editors] {
    if (editors.request_quit()) return true;
    editors.enabled = true;
    return false;
  };
  game.should_quit = [&editors] { return editors.quit_confirmed(); };
  game.hide_hud = [&editors] { return editors.enabled; };
}

GameEditors::~GameEditors() {
  game_->on_ui = nullptr;
  game_->on_viewport = nullptr;
  game_->on_quit = nullptr;
  game_->should_quit = nullptr;
  game_->hide_hud = nullptr;
}

}  // namespace ossa
