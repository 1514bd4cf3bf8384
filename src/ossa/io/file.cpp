#include "ossa/io/file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace ossa {

namespace {

std::string errno_text(int err) { return std::strerror(err); }

// Writes all of data to fd, retrying on short writes and EINTR.
bool write_all(int fd, std::string_view data) {
  const char* p = data.data();
  size_t left = data.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

Result<std::string> read_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return Error::at(path, "", "is a folder, expected a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    if (!std::filesystem::exists(path, ec)) return Error::at(path, "", "no such file");
    return Error::at(path, "", "cannot open: " + errno_text(err));
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return Error::at(path, "", "read error");
  return ss.str();
}

Status write_file_atomic(const std::string& path, std::string_view data) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  fs::path folder = target.parent_path();
  if (folder.empty()) folder = ".";
  std::string temp_name = ".";
  temp_name += target.filename().string();
  temp_name += ".tmp.XXXXXX";
  std::string tmpl = (folder / temp_name).string();

  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) {
    return Error::at(path, "", "cannot create a temporary file in " + folder.string() + ": " +
                                   errno_text(errno));
  }
  // mkstemp makes the file 0600; give it the usual permissions (or the target's own).
  struct stat st {};
  const mode_t mode = (::stat(path.c_str(), &st) == 0) ? (st.st_mode & 07777) : 0644;
  ::fchmod(fd, mode);

  auto fail = [&](const std::string& what) -> Status {
    const int err = errno;
    ::close(fd);
    ::unlink(tmpl.c_str());
    return Error::at(path, "", what + ": " + errno_text(err));
  };
  if (!write_all(fd, data)) return fail("write failed");
  if (::fsync(fd) != 0) return fail("fsync failed");
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmpl.c_str());
    return Error::at(path, "", "close failed: " + errno_text(err));
  }
  if (::rename(tmpl.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmpl.c_str());
    return Error::at(path, "", "cannot replace the file: " + errno_text(err));
  }
  // Make the rename itself durable.
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
  return {};
}

Status write_json_atomic(const std::string& path, const Json& doc) {
  std::string text = doc.dump(2);
  text.push_back('\n');
  return write_file_atomic(path, text);
}

}  // namespace ossa
