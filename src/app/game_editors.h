#pragma once
// GameEditors — the editors (DESIGN.md §10) wired into a Game through its hooks: on_ui (the
// shortcuts from the frame's key presses, F2 included, then the windows), on_viewport,
// on_quit / should_quit (unsaved work asks first). `ossa` and the tests make the same wiring.
//
//   Game game;  game.init(options);
//   GameEditors editors(game, options);
//   game.run();

#include <optional>

#include "app/game.h"
#include "ossa/editor/editor_suite.h"
#include "ossa/gen/generator.h"

namespace ossa {

class GameEditors {
 public:
  // Builds the editors over game.world() with the options' files (the level, the prototypes,
  // out_dir for saved genomes, tuning and exports) and loads a tuning saved before; shown at
  // once when the environment sets OSSA_EDITORS. `game` must outlive this.
  GameEditors(Game& game, const GameOptions& options);
  // Unhooks the editors from the game.
  ~GameEditors();
  GameEditors(const GameEditors&) = delete;
  GameEditors& operator=(const GameEditors&) = delete;

  EditorSuite& suite() { return *suite_; }

 private:
  Game* game_;
  std::optional<Generator> generator_;
  std::optional<EditorSuite> suite_;
};

}  // namespace ossa
