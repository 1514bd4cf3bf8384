#pragma once
// JSON helpers: parse with file/line/column in the error, and a JsonReader that reads fields
// one by one, checks type and range, and keeps the first error with the file and the full
// field path ("colliders[3].size.x"). Readers return defaults after an error so loaders can
// be written straight through and check failed() once.

#include <limits>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "ossa/io/result.h"

namespace ossa {

using Json = nlohmann::json;

// Parses text; errors name `file` and the line and column of the syntax error, or the path of
// a key that appears twice in one object (an error: JSON parsers disagree on which one wins).
Result<Json> parse_json(std::string_view text, std::string_view file);
// Reads (read_file: regular files of at most kMaxDataFileBytes) and parses a file; errors name
// the file.
Result<Json> read_json_file(const std::string& path);

// "parent.key" (or "key" when parent is empty) and "parent[index]".
std::string json_path(std::string_view parent, std::string_view key);
std::string json_path(std::string_view parent, size_t index);

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
  float number_f(const Json& parent, std::string_view path, std::string_view key,
                 double min = -kInf, double max = kInf) {
    return static_cast<float>(number(parent, path, key, min, max));
  }
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
