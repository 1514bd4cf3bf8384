#pragma once
// File access for data files. Saves are atomic (DESIGN.md §10): the bytes go to a temporary
// file in the same folder, which is fsync'ed and renamed over the target, and then the folder
// is fsync'ed, so a crash at any point leaves either the old file or the new one, never a mix.

#include <string>
#include <string_view>

#include "ossa/io/json.h"
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

// Serialises `doc` (2-space indent, trailing newline) with "format" and "version" first when
// present (every ossa file starts with them; the other keys follow in sorted order).
std::string json_file_text(const Json& doc);
// Writes json_file_text(doc) atomically.
Status write_json_atomic(const std::string& path, const Json& doc);

}  // namespace ossa
