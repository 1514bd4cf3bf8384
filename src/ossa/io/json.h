#pragma once
// JSON helpers: parse with file/line/column in the error, and a JsonReader that reads fields
// one by one, checks type and range, and keeps the first error with the file and the full
// field path ("colliders[3].size.x"). Readers return defaults after an error so loaders can
// be written straight through and check failed() once.

#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"

namespace ossa {

// Every JSON document ossa reads (levels, maps, genomes, replays, rig mappings, tuning,
// datasets, the glTF pre-check) goes through parse_json, which enforces these rules:
// - nesting: at most kMaxJsonDepth arrays and objects inside each other. Deeper input is
//   refused while parsing, before anything recursive (copying, printing, comparing a document;
//   Assimp's glTF reader) sees it;
// - duplicate keys: a key given twice in one object is an error naming its path (JSON parsers
//   disagree on which one wins);
// - memory: the document's estimated size in memory (counted as it is built) stays within
//   kJsonBytesPerInputByte bytes per byte of text, else it is refused; files of ordinary
//   structure take 3 to 19 (an indented level 6, a level written without spaces 19);
// - work: linear in the text (each key is checked against its own object in O(log n));
// - encoding: UTF-8 (a UTF-8 byte order mark is skipped); UTF-16 and UTF-32 text is refused
//   with a message saying so.
inline constexpr int kMaxJsonDepth = 256;
inline constexpr int kJsonBytesPerInputByte = 24;

// Parses text; errors name `file` and the line and column of the syntax error, or the path of
// the field that broke one of the rules above.
Result<Json> parse_json(std::string_view text, std::string_view file);
// Reads (read_file: regular files of at most kMaxDataFileBytes) and parses a file; errors name
// the file.
Result<Json> read_json_file(const std::string& path);

// "parent.key" (or "key" when parent is empty) and "parent[index]".
std::string json_path(std::string_view parent, std::string_view key);
std::string json_path(std::string_view parent, size_t index);

// The text of a value as dump(indent) gives it, except that bytes that are not UTF-8 in a
// string (a file name from the file system is bytes, not text) become U+FFFD instead of
// throwing: every JSON that tools print or save goes through this or json_file_text.
std::string json_text(const Json& value, int indent = -1);

// "UTF-16 (little-endian)" and the like when `text` starts like UTF-16 or UTF-32 text (a byte
// order mark, or ASCII interleaved with zero bytes); nullopt otherwise. Text files ossa reads
// must be UTF-8; loaders name the encoding they found.
std::optional<std::string> non_utf8_encoding(std::string_view text);

// The double whose shortest decimal form equals the float's shortest form, so JSON files
// show 0.9 rather than 0.8999999761581421 and still load back to the same float.
double json_float(float value);

// The byte offset of the first byte that is not part of a well-formed UTF-8 sequence
// (overlong forms, surrogates and code points past U+10FFFF count as ill-formed), or
// std::string_view::npos when all of `text` is UTF-8. JSON text must be UTF-8: strings from
// other sources (XML attributes) are checked with this before they go into a Json.
size_t first_invalid_utf8(std::string_view text);

// A short description of a value for messages: `a string "abc"`, `-2`, `an array`.
std::string describe_json(const Json& value);

class JsonReader {
 public:
  explicit JsonReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  bool failed() const { return failed_; }
  const Error& error() const { return error_; }
  // Records an error at `field` unless one was recorded before.
  void fail(std::string_view field, std::string_view what);

  static constexpr double kInf = std::numeric_limits<double>::infinity();

  // Required fields. `parent` must be an object (check with object()); `path` is its path.
  // On a missing field or a wrong type or range, records the error and returns the fallback.
  const Json* object(const Json& parent, std::string_view path, std::string_view key);
  const Json* array(const Json& parent, std::string_view path, std::string_view key);
  double number(const Json& parent, std::string_view path, std::string_view key,
                double min = -kInf, double max = kInf);
  // A number read into a float. The range is checked on the float the value becomes, against
  // the range's ends as floats: a field whose documented range ends at 1.05 accepts 1.05 (which
  // becomes the float 1.05f, the same as the end) and what its writer saved from a float.
  float number_f(const Json& parent, std::string_view path, std::string_view key,
                 double min = -kInf, double max = kInf);
  long long integer(const Json& parent, std::string_view path, std::string_view key,
                    long long min = std::numeric_limits<long long>::min(),
                    long long max = std::numeric_limits<long long>::max());
  bool boolean(const Json& parent, std::string_view path, std::string_view key);
  std::string string(const Json& parent, std::string_view path, std::string_view key);

  // Optional fields: absent (or null) gives `fallback`; present but wrong is an error.
  double number_or(const Json& parent, std::string_view path, std::string_view key, double fallback,
                   double min = -kInf, double max = kInf);
  long long integer_or(const Json& parent, std::string_view path, std::string_view key,
                       long long fallback, long long min = std::numeric_limits<long long>::min(),
                       long long max = std::numeric_limits<long long>::max());
  bool boolean_or(const Json& parent, std::string_view path, std::string_view key, bool fallback);
  std::string string_or(const Json& parent, std::string_view path, std::string_view key,
                        std::string fallback);
  bool has(const Json& parent, std::string_view key) const;

  // Checks a value itself (an array element, the document root).
  bool expect_object(const Json& value, std::string_view path);
  bool expect_array(const Json& value, std::string_view path);
  double as_number(const Json& value, std::string_view path, double min = -kInf, double max = kInf);

 private:
  const Json* field(const Json& parent, std::string_view path, std::string_view key);

  std::string file_;
  Error error_;
  bool failed_ = false;
};

}  // namespace ossa
