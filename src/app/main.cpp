// ossa — the playable runtime (DESIGN.md §8). See `ossa --help` (app/options.cpp).

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/game.h"
#include "app/game_editors.h"
#include "app/options.h"

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
    // The editors (F2 shows / hides them): spline, level, creature, tuning and rig windows.
    ossa::GameEditors editors(game, parsed->options);
    return game.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ossa: unexpected error: %s\n", e.what());
    return 1;
  }
}
