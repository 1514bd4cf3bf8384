#include "ossa/io/data_dir.h"

#include <cstdlib>

// ossa_core is compiled with OSSA_SOURCE_DIR, the source tree's absolute path (CMakeLists.txt).
#ifndef OSSA_SOURCE_DIR
#error "OSSA_SOURCE_DIR must be defined when building ossa_core"
#endif

namespace ossa {

std::string data_dir() {
  const char* env = std::getenv("OSSA_SOURCE_DIR");
  return env && *env ? std::string(env) : std::string(OSSA_SOURCE_DIR);
}

std::string data_path(std::string_view relative) {
  std::string path = data_dir();
  path += '/';
  path += relative;
  return path;
}

}  // namespace ossa
