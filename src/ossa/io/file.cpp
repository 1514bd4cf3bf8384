#include "ossa/io/file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "ossa/io/json.h"

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

Result<std::string> read_file(const std::string& path, long long max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int err = errno;
    if (err == ENOENT) return Error::at(path, "", "no such file");
    return Error::at(path, "", "cannot open: " + errno_text(err));
  }
  if (S_ISDIR(st.st_mode)) return Error::at(path, "", "is a folder, expected a file");
  if (!S_ISREG(st.st_mode)) return Error::at(path, "", "is not a regular file (a device, pipe or socket), expected a file");
  const auto too_large = [&](long long size) {
    return Error::at(path, "", "is " + std::to_string(size) + " bytes, expected at most " +
                                   std::to_string(max_bytes) + " bytes");
  };
  if (st.st_size > max_bytes) return too_large(st.st_size);

  // Non-blocking, so that a file replaced by a pipe since the stat cannot hang the open; what
  // was opened is checked again.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return Error::at(path, "", "cannot open: " + errno_text(errno));
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return Error::at(path, "", "is not a regular file (a device, pipe or socket), expected a file");
  }
  if (st.st_size > max_bytes) {
    ::close(fd);
    return too_large(st.st_size);
  }
  // Read to the end rather than trusting st_size, but never past max_bytes: a file that grows
  // while we read stops at the limit.
  std::string data;
  data.reserve(static_cast<size_t>(st.st_size));
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      return Error::at(path, "", "read error: " + errno_text(err));
    }
    if (n == 0) break;
    data.append(buf, static_cast<size_t>(n));
    if (static_cast<long long>(data.size()) > max_bytes) {
      ::close(fd);
      return too_large(static_cast<long long>(data.size()));
    }
  }
  ::close(fd);
  return data;
}

namespace {

// Where a save to `path` lands: `path` itself, or, when it is a symbolic link (a chain of
// them), the file the link points at (which may not exist yet). Empty after a link loop.
std::string link_target(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    std::error_code ec;
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) return p.string();
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return {};
}

std::string mode_text(mode_t mode) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04o", static_cast<unsigned>(mode & 07777));
  return buf;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

Status check_output_path(std::string_view what, const std::string& output, const std::vector<std::string>& inputs) {
  if (output.empty()) return Error::at(what, "", "expected a file name to write, got an empty string");
  for (const std::string& input : inputs) {
    if (!input.empty() && same_file(output, input)) {
      const std::string also = input == output ? "" : " (\"" + output + "\" names the same file)";
      return Error::at(what, "", "\"" + output + "\" is the input " + input + also +
                                     ": refusing to write over it; give another output file");
    }
  }
  return {};
}

Status write_file_atomic(const std::string& path, std::string_view data) {
  namespace fs = std::filesystem;
  if (path.empty()) return Error{"expected a file name to write, got an empty string"};
  // A link is written through: the temporary file goes next to its target and replaces that.
  const std::string resolved = link_target(path);
  if (resolved.empty()) return Error::at(path, "", "is a loop of symbolic links; not written");
  struct stat existing {};
  const bool exists = ::stat(resolved.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) return Error::at(path, "", "is a folder; not written");
  if (exists && !S_ISREG(existing.st_mode)) {
    return Error::at(path, "", "is not a regular file (a device, pipe or socket); not replaced");
  }
  // rename() would replace a file its owner may not write (and root writes anything): a
  // read-only file is refused, as an editor does.
  if (exists && ((existing.st_mode & S_IWUSR) == 0 || ::access(resolved.c_str(), W_OK) != 0)) {
    return Error::at(path, "", "is read-only (mode " + mode_text(existing.st_mode) +
                                   "); not overwritten (make it writable or save elsewhere)");
  }
  const fs::path target(resolved);
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
  const mode_t mode = exists ? (existing.st_mode & 07777) : 0644;
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
  if (::rename(tmpl.c_str(), resolved.c_str()) != 0) {
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

std::string json_file_text(const Json& doc) {
  std::string text;
  if (doc.is_object() && (doc.contains("format") || doc.contains("version"))) {
    // nlohmann::json keeps keys sorted; an ordered copy of the top level puts the header first.
    nlohmann::ordered_json ordered = nlohmann::ordered_json::object();
    for (const char* key : {"format", "version"}) {
      if (doc.contains(key)) ordered[key] = nlohmann::ordered_json(doc.at(key));
    }
    for (const auto& [key, value] : doc.items()) {
      if (key != "format" && key != "version") ordered[key] = nlohmann::ordered_json(value);
    }
    text = ordered.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  } else {
    text = json_text(doc, 2);
  }
  text.push_back('\n');
  return text;
}

Status write_json_atomic(const std::string& path, const Json& doc) {
  return write_file_atomic(path, json_file_text(doc));
}

}  // namespace ossa
