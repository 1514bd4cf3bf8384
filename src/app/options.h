#pragma once
// The `ossa` command line → GameOptions. Every bad argument gives an Error with a message
// naming the flag and what was expected; --help gives the usage text.

#include <string>
#include <vector>

#include "app/game.h"
#include "ossa/io/result.h"

namespace ossa {

extern const char* const kGameUsage;

struct ParsedArgs {
  GameOptions options;
  bool help = false;  // --help: print kGameUsage and exit 0
};

Result<ParsedArgs> parse_game_args(const std::vector<std::string>& args);

}  // namespace ossa
