#include "ossa/io/data_dir.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

// ossa_core is compiled with OSSA_SOURCE_DIR, the source tree's absolute path, and
// OSSA_INSTALLED_DATA_DIR, the installed data folder relative to the installed executables
// (e.g. "../share/ossa"; CMakeLists.txt).
#ifndef OSSA_SOURCE_DIR
#error "OSSA_SOURCE_DIR must be defined when building ossa_core"
#endif
#ifndef OSSA_INSTALLED_DATA_DIR
#error "OSSA_INSTALLED_DATA_DIR must be defined when building ossa_core"
#endif

namespace ossa {

namespace {

// <folder of the running executable>/OSSA_INSTALLED_DATA_DIR when it holds levels/, else "".
// Linux's /proc/self/exe; where it is missing, the lookup falls through to the source tree.
std::string installed_data_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return {};
  const std::filesystem::path dir = (exe.parent_path() / OSSA_INSTALLED_DATA_DIR).lexically_normal();
  if (!std::filesystem::is_directory(dir / "levels", ec)) return {};
  std::string s = dir.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

}  // namespace

std::string data_dir() {
  const char* env = std::getenv("OSSA_SOURCE_DIR");
  if (env && *env) return std::string(env);
  // The executable does not move while it runs: look once.
  static const std::string installed = installed_data_dir();
  return installed.empty() ? std::string(OSSA_SOURCE_DIR) : installed;
}

std::string data_path(std::string_view relative) {
  std::string path = data_dir();
  path += '/';
  path += relative;
  return path;
}

}  // namespace ossa
