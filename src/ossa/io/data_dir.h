#pragma once
// Where the tools, the game, the tests and the benchmarks of a build tree find the shipped
// data (levels/, assets/, shaders/, tests/ fixtures): one lookup for all of them.
//
// The data folder is the OSSA_SOURCE_DIR environment variable when it is set and not empty
// (CTest sets it for every test), else the source tree this library was compiled from. An
// installed ossa (cmake --install) keeps that compiled-in path, which may not exist on the
// machine it runs on: embedders pass their own paths to the loaders (find_package(ossa) sets
// ossa_DATA_DIR to the installed copy of levels/ and assets/), or set OSSA_SOURCE_DIR.

#include <string>
#include <string_view>

namespace ossa {

// The data folder, without a trailing slash.
std::string data_dir();

// data_dir() + "/" + relative, e.g. data_path("levels/default.json"). `relative` is not
// checked: the loaders report a missing file with its full path.
std::string data_path(std::string_view relative);

}  // namespace ossa
