#include "ossa/editor/file_watch.h"

#include <system_error>

namespace ossa {

void FileWatch::watch(std::string path) {
  path_ = std::move(path);
  rearm();
}

void FileWatch::rearm() {
  std::error_code ec;
  mtime_ = std::filesystem::last_write_time(path_, ec);
  exists_ = !ec;
}

bool FileWatch::poll() {
  if (path_.empty()) return false;
  std::error_code ec;
  const auto t = std::filesystem::last_write_time(path_, ec);
  // A file deleted mid-save (rename) reads as missing for a moment: no change until it is back.
  if (ec) return false;
  if (exists_ && t == mtime_) return false;
  mtime_ = t;
  exists_ = true;
  return true;
}

}  // namespace ossa
