#pragma once
// File access for data files: the one rule every input and every output of ossa follows.
//
// Inputs (read_file): regular files only — a folder, a device or a pipe is refused before a
// byte is read (a pipe never blocks: it is opened non-blocking and checked), and a size limit
// is checked before reading. File names are bytes: any name the file system accepts is read,
// and messages print it as given.
//
// Outputs (write_file_atomic, check_output_path): saves are atomic (DESIGN.md §10): the bytes
// go to a temporary file in the target's folder, which is fsync'ed and renamed over the
// target, and then the folder is fsync'ed, so a crash at any point leaves either the old file
// or the new one, never a mix; on any failure the old file is kept. A symbolic link is
// written through: its target gets the new contents and the link stays a link. A target that
// is read-only (its owner may not write it) or is not a regular file is refused with a
// message, untouched. Tools also refuse an output that is one of their own inputs.

#include <string>
#include <string_view>
#include <vector>

#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"

namespace ossa {

// The largest data file any loader reads (bytes): 64 MiB. Bigger files, and anything that is
// not a regular file (a folder, /dev/zero, a pipe), are refused before a byte is read.
inline constexpr long long kMaxDataFileBytes = 64ll * 1024 * 1024;

// Reads a whole regular file of at most `max_bytes`. Errors name the file and the reason
// (missing, a folder or device, too large, unreadable).
Result<std::string> read_file(const std::string& path, long long max_bytes = kMaxDataFileBytes);

// Writes `data` to `path` atomically. On failure the previous file is untouched and no
// temporary file is left behind.
Status write_file_atomic(const std::string& path, std::string_view data);

// Refuses `output` as an output path when it is empty, or when it names the same file as one of
// `inputs` (after following links: the same device and inode, so a link or a second name of
// an input counts too). `what` names the output in messages (a flag such as "--out", or
// "OUT"). Inputs that do not exist are ignored.
Status check_output_path(std::string_view what, const std::string& output, const std::vector<std::string>& inputs);

// Do `a` and `b` name the same existing file (after following links)?
bool same_file(const std::string& a, const std::string& b);

// Serialises `doc` (2-space indent, trailing newline) with "format" and "version" first when
// present (every ossa file starts with them; the other keys follow in sorted order). Strings
// that are not UTF-8 (file names) are written with U+FFFD in place of the bad bytes.
std::string json_file_text(const Json& doc);
// Writes json_file_text(doc) atomically.
Status write_json_atomic(const std::string& path, const Json& doc);

}  // namespace ossa
