#pragma once
// FileWatch — hot reload by polling a file's modification time (no inotify: portable and
// cheap at a few polls per second). The editors re-arm it after their own saves so that a
// save does not read back as an outside change.
#include <filesystem>
#include <string>

namespace ossa {

class FileWatch {
 public:
  FileWatch() = default;
  explicit FileWatch(std::string path) { watch(std::move(path)); }

  // Watches `path` from now on (its current mtime is the baseline; a missing file is fine).
  void watch(std::string path);
  const std::string& path() const { return path_; }
  // True once per change of the mtime since the last call / rearm().
  bool poll();
  // Takes the current mtime as the baseline (after our own save or load).
  void rearm();

 private:
  std::string path_;
  std::filesystem::file_time_type mtime_{};
  bool exists_ = false;
};

}  // namespace ossa
