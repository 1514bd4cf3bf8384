#pragma once
// File access for data files. Saves are atomic (DESIGN.md §10): the bytes go to a temporary
// file in the same folder, which is fsync'ed and renamed over the target, and then the folder
// is fsync'ed, so a crash at any point leaves either the old file or the new one, never a mix.

#include <string>
#include <string_view>

#include "ossa/io/json.h"
#include "ossa/io/result.h"

namespace ossa {

// Reads a whole file. Errors name the file and the reason (missing, a folder, unreadable).
Result<std::string> read_file(const std::string& path);

// Writes `data` to `path` atomically. On failure the previous file is untouched and no
// temporary file is left behind.
Status write_file_atomic(const std::string& path, std::string_view data);

// Serialises `doc` (2-space indent, trailing newline) and writes it atomically.
Status write_json_atomic(const std::string& path, const Json& doc);

}  // namespace ossa
