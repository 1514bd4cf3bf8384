#include "shared/scenes.h"

#include <cstdlib>

namespace ossa::scenes {

std::string source_path(const std::string& relative) {
  const char* env = std::getenv("OSSA_SOURCE_DIR");
  std::string root = env && *env ? env : OSSA_SOURCE_DIR;
  return root + "/" + relative;
}

}  // namespace ossa::scenes
