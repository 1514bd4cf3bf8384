#pragma once
// Where the tools, the game, the tests and the benchmarks find the shipped data (levels/,
// assets/, shaders/, and in a source tree the tests/ fixtures): one lookup for all of them.
//
// The data folder is, in this order:
//  1. the OSSA_SOURCE_DIR environment variable, when it is set and not empty (CTest sets it
//     for every test);
//  2. an installed copy next to the running executable: <bin>/../share/ossa (the executable's
//     folder, then CMAKE_INSTALL_DATADIR/ossa relative to CMAKE_INSTALL_BINDIR) when it holds
//     levels/ — what `cmake --install` lays out, so installed tools find their data from any
//     folder, wherever the prefix was moved;
//  3. the source tree this library was compiled from (a build tree's executables).
// An embedder's own executable is rarely installed into ossa's prefix: it passes its own paths
// to the loaders (find_package(ossa) sets ossa_DATA_DIR to the installed copy of levels/,
// assets/ and shaders/), or sets OSSA_SOURCE_DIR.

#include <string>
#include <string_view>

namespace ossa {

// The data folder, without a trailing slash.
std::string data_dir();

// data_dir() + "/" + relative, e.g. data_path("levels/default.json"). `relative` is not
// checked: the loaders report a missing file with its full path.
std::string data_path(std::string_view relative);

}  // namespace ossa
