// ossa — the playable runtime (DESIGN.md §8). See `ossa --help` (app/options.cpp).

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/game.h"
#include "app/options.h"

// Editors (DESIGN.md §10), wired through the Game's on_ui / on_viewport hooks.
#include <SDL.h>
#include <imgui.h>
#include "ossa/editor/editor_suite.h"
#include "ossa/editor/tuning_model.h"
#include "ossa/gen/generator.h"
#include "ossa/render/character_mesh.h"

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    auto parsed = ossa::parse_game_args(args);
    if (!parsed.ok()) {
      std::fprintf(stderr, "ossa: %s\n", parsed.message().c_str());
      return 2;
    }
    if (parsed->help) {
      std::fputs(ossa::kGameUsage, stdout);
      return 0;
    }
    ossa::Game game;
    if (auto s = game.init(parsed->options); !s.ok()) {
      std::fprintf(stderr, "ossa: %s\n", s.message().c_str());
      return 1;
    }
    // ---- Editors: F2 shows / hides them (spline, level, creature and tuning panels). ----
    const ossa::GameOptions& o = parsed->options;
    auto generator = ossa::Generator::load(ossa::resolve_data_path("assets/creatures/examples.json"));
    ossa::EditorPaths paths;
    paths.levels_dir = ossa::resolve_data_path("levels");
    paths.level_file = ossa::resolve_data_path(o.level.empty() ? "levels/default.json" : o.level);
    paths.prototypes_file = ossa::resolve_data_path("assets/animation/prototypes.json");
    paths.genome_file = o.out_dir + "/creature.json";
    paths.tuning_file = o.out_dir + "/tuning.json";
    paths.export_dir = o.out_dir;
    paths.rig_file = ossa::resolve_data_path(o.character.empty() ? "assets/characters/humanoid.rig.json" : o.character);
    paths.characters = ossa::shipped_characters();
    // Tuning saved from the tuning panel is loaded again at start.
    std::error_code tuning_missing;  // (exists, not an open: a pipe would block here)
    if (std::filesystem::exists(paths.tuning_file, tuning_missing)) {
      if (auto params = ossa::load_params(paths.tuning_file); params.ok()) {
        game.world().set_params(*params);
      } else {
        std::fprintf(stderr, "ossa: %s (keeping the default tuning)\n", params.message().c_str());
      }
    }
    ossa::EditorSuite editors(game.world(), generator.ok() ? &generator.value() : nullptr, paths);
    editors.level_editor().options.pixels_per_metre_tiled = o.pixels_per_metre;  // --pixels-per-metre
    editors.apply_character = [&game](const std::string& rig_path) { return game.set_player_character(rig_path); };
    editors.enabled = std::getenv("OSSA_EDITORS") != nullptr;  // start shown with OSSA_EDITORS=1
    game.on_ui = [&](float dt) {
      const ImGuiIO& io = ImGui::GetIO();
      if (ImGui::IsKeyPressed(SDL_SCANCODE_F2, false)) editors.enabled = !editors.enabled;
      editors.update(dt);
      editors.handle_mouse({io.MousePos.x, io.MousePos.y}, io.MouseDown[0], io.MouseWheel, game.camera(),
                           {io.DisplaySize.x, io.DisplaySize.y});
      editors.draw_ui();
    };
    game.on_viewport = [&](ossa::DebugDraw& draw) { editors.draw_viewport(draw); };
    // Quitting with unsaved editor work asks first (the editors show the prompt).
    game.on_quit = [&] {
      if (editors.request_quit()) return true;
      editors.enabled = true;
      return false;
    };
    game.should_quit = [&] { return editors.quit_confirmed(); };
    // ---- end of the editors ----
    return game.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ossa: unexpected error: %s\n", e.what());
    return 1;
  }
}
