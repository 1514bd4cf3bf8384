#include "ossa/io/json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <vector>

#include "ossa/io/file.h"

namespace ossa {

namespace {

// glibc malloc's chunk for an n-byte request (16-byte aligned, 8 bytes of header, 32 at least):
// what the memory estimate below counts.
constexpr size_t chunk(size_t n) { return std::max<size_t>(32, (n + 8 + 15) & ~size_t{15}); }

// Builds the document from nlohmann's SAX events (its parser is iterative, so no input nests
// it into a stack overflow) and enforces what json.h promises: a key given twice in one object
// is an error naming its path (nlohmann::json would silently keep the last one: a second
// "colliders": [] would empty a level), nesting stops at kMaxJsonDepth before anything
// recursive sees the document, and the estimated memory of the document stays within
// kJsonBytesPerInputByte of the text's size. Every event costs O(1) (a key lookup O(log n) in
// its own object), so parsing is linear in the text.
class DomBuilder {
 public:
  DomBuilder(Json& root, size_t text_size)
      : root_(root), budget_(kJsonBytesPerInputByte * static_cast<long double>(text_size) + 65536.0L) {}

  // What went wrong, for parse_json's message (empty when the parser reported a syntax error).
  std::string field;
  std::string what;

  bool null() { return add(Json(nullptr), 0); }
  bool boolean(bool v) { return add(Json(v), 0); }
  bool number_integer(Json::number_integer_t v) { return add(Json(v), 0); }
  bool number_unsigned(Json::number_unsigned_t v) { return add(Json(v), 0); }
  bool number_float(Json::number_float_t v, const std::string&) { return add(Json(v), 0); }
  bool string(std::string& v) {
    const size_t heap = chunk(sizeof(std::string)) + (v.size() > 15 ? chunk(v.size() + 1) : 0);
    return add(Json(std::move(v)), heap);
  }
  bool binary(Json::binary_t&) { return fail_at("", "binary data is not JSON"); }
  bool start_object(size_t) { return open(Json::object(), chunk(48)); }
  bool start_array(size_t) { return open(Json::array(), chunk(sizeof(std::vector<Json>))); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    Frame& f = stack_.back();
    if (f.value->contains(k)) return fail_at(path_to(&k), "duplicate key (a key may appear only once in an object)");
    // A map node holds the key, the value and the tree links.
    if (!charge(chunk(32 + sizeof(std::string) + sizeof(Json)) + (k.size() > 15 ? chunk(k.size() + 1) : 0))) return false;
    auto [it, inserted] = f.value->get_ref<Json::object_t&>().emplace(std::move(k), Json());
    f.key = &it->first;
    f.slot = &it->second;
    return true;
  }
  bool parse_error(size_t position, const std::string&, const nlohmann::detail::exception& e) {
    syntax_byte = position;
    syntax_what = e.what();
    return false;
  }

  size_t syntax_byte = 0;
  std::string syntax_what;

 private:
  struct Frame {
    Json* value = nullptr;           // the open array or object
    const std::string* key = nullptr;  // objects: the key being read
    Json* slot = nullptr;            // objects: where that key's value goes
  };

  bool charge(size_t bytes) {
    used_ += bytes;
    if (used_ <= budget_) return true;
    char what[200];
    std::snprintf(what, sizeof what,
                  "the document would take more than %.0f MiB in memory (%d times the text's size): "
                  "too many small values",
                  static_cast<double>(budget_ / (1024.0L * 1024.0L)), kJsonBytesPerInputByte);
    return fail_at("", what);
  }

  // Where a new value goes: the root, the end of the open array, or the slot of the last key.
  Json* place(Json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& f = stack_.back();
    if (f.value->is_array()) {
      auto& a = f.value->get_ref<Json::array_t&>();
      a.push_back(std::move(v));
      return &a.back();
    }
    *f.slot = std::move(v);
    return f.slot;
  }

  bool add(Json&& v, size_t heap) {
    // An array element costs its slot twice (a vector grows by doubling); an object's value
    // lives in the map node charged by key().
    const bool in_array = !stack_.empty() && stack_.back().value->is_array();
    if (!charge(heap + (in_array ? 2 * sizeof(Json) : 0))) return false;
    place(std::move(v));
    return true;
  }

  bool open(Json&& container, size_t heap) {
    if (stack_.size() >= static_cast<size_t>(kMaxJsonDepth)) {
      return fail_at(path_to(nullptr),
                     "nested more than " + std::to_string(kMaxJsonDepth) + " arrays or objects deep");
    }
    const bool in_array = !stack_.empty() && stack_.back().value->is_array();
    if (!charge(heap + (in_array ? 2 * sizeof(Json) : 0))) return false;
    Json* at = place(std::move(container));
    stack_.push_back({at, nullptr, nullptr});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  bool fail_at(std::string f, std::string w) {
    field = std::move(f);
    what = std::move(w);
    return false;
  }

  // The path of the value about to be read: in each open container the child being read (an
  // array's last element; the next one in the innermost array), ending in `key` when given.
  // Deep paths are cut after kPathLevels containers ("a[0][0]...": 256 levels of "[0]" say
  // nothing more).
  std::string path_to(const std::string* key) const {
    constexpr size_t kPathLevels = 8;
    std::string p;
    for (size_t i = 0; i < stack_.size(); ++i) {
      if (i == kPathLevels && stack_.size() > kPathLevels + 1) {
        p += "...";
        if (key) p += "." + *key;
        break;
      }
      const Frame& f = stack_[i];
      const bool innermost = i + 1 == stack_.size();
      if (f.value->is_array()) {
        const size_t n = f.value->size();
        p = json_path(p, innermost || n == 0 ? n : n - 1);
      } else if (innermost && key) {
        p = json_path(p, *key);
      } else if (f.key) {
        p = json_path(p, *f.key);
      }
    }
    return p.empty() ? "(document)" : p;
  }

  Json& root_;
  long double budget_;
  long double used_ = 0;
  std::vector<Frame> stack_;
};

}  // namespace

std::optional<std::string> non_utf8_encoding(std::string_view text) {
  const auto b = [&](size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0x100u; };
  if (b(0) == 0x00 && b(1) == 0x00 && b(2) == 0xFE && b(3) == 0xFF) return "UTF-32 (big-endian)";
  if (b(0) == 0xFF && b(1) == 0xFE && b(2) == 0x00 && b(3) == 0x00) return "UTF-32 (little-endian)";
  if (b(0) == 0xFE && b(1) == 0xFF) return "UTF-16 (big-endian)";
  if (b(0) == 0xFF && b(1) == 0xFE) return "UTF-16 (little-endian)";
  // Without a byte order mark: an ASCII character and a zero byte, in either order.
  if (text.size() >= 4 && b(0) == 0x00 && b(1) != 0x00 && b(1) < 0x80 && b(2) == 0x00) return "UTF-16 (big-endian)";
  if (text.size() >= 4 && b(0) != 0x00 && b(0) < 0x80 && b(1) == 0x00 && b(3) == 0x00 && b(2) != 0x00) {
    return "UTF-16 (little-endian)";
  }
  return std::nullopt;
}

Result<Json> parse_json(std::string_view text, std::string_view file) {
  if (auto enc = non_utf8_encoding(text)) {
    return Error::at(file, "", "is " + *enc + " text; JSON must be UTF-8 (save the file as UTF-8)");
  }
  Json root;
  DomBuilder builder(root, text.size());
  try {
    if (Json::sax_parse(text.begin(), text.end(), &builder)) return root;
  } catch (const std::bad_alloc&) {
    return Error::at(file, "", "out of memory while reading the JSON document");
  } catch (const std::exception& e) {
    return Error::at(file, "", std::string("not valid JSON (") + e.what() + ")");
  }
  if (!builder.what.empty()) return Error::at(file, builder.field, builder.what);
  // A syntax error: the byte offset (1-based) of the offending byte as line and column.
  size_t line = 1, column = 1;
  const size_t end = std::min<size_t>(builder.syntax_byte == 0 ? 0 : builder.syntax_byte - 1, text.size());
  for (size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return Error::at(file, "", "not valid JSON at line " + std::to_string(line) + ", column " + std::to_string(column) +
                                 " (" + builder.syntax_what + ")");
}

std::string json_text(const Json& value, int indent) {
  return value.dump(indent, ' ', false, Json::error_handler_t::replace);
}

Result<Json> read_json_file(const std::string& path) {
  Result<std::string> text = read_file(path);
  if (!text) return text.error();
  return parse_json(*text, path);
}

double json_float(float value) {
  if (!std::isfinite(value)) return static_cast<double>(value);
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  *result.ptr = '\0';
  return std::strtod(buf, nullptr);
}

std::string json_path(std::string_view parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  std::string p(parent);
  p.append(".").append(key);
  return p;
}

std::string json_path(std::string_view parent, size_t index) {
  std::string p(parent);
  p.append("[").append(std::to_string(index)).append("]");
  return p;
}

size_t first_invalid_utf8(std::string_view text) {
  size_t i = 0;
  while (i < text.size()) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x80) {
      ++i;
      continue;
    }
    // Length and the allowed range of the second byte (Unicode 15, table 3-7).
    size_t len = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (b >= 0xC2 && b <= 0xDF) {
      len = 2;
    } else if (b >= 0xE0 && b <= 0xEF) {
      len = 3;
      if (b == 0xE0) lo = 0xA0;
      if (b == 0xED) hi = 0x9F;
    } else if (b >= 0xF0 && b <= 0xF4) {
      len = 4;
      if (b == 0xF0) lo = 0x90;
      if (b == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    if (i + len > text.size()) return i;
    for (size_t k = 1; k < len; ++k) {
      const auto c = static_cast<unsigned char>(text[i + k]);
      if (c < (k == 1 ? lo : 0x80) || c > (k == 1 ? hi : 0xBF)) return i;
    }
    i += len;
  }
  return std::string_view::npos;
}

std::string describe_json(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case Json::value_t::string: {
      std::string s = v.get<std::string>();
      if (s.size() > 40) s = s.substr(0, 40) + "...";
      return "a string \"" + s + "\"";
    }
    case Json::value_t::binary: return "binary data";
    default: return v.dump();
  }
}

void JsonReader::fail(std::string_view field, std::string_view what) {
  if (failed_) return;
  failed_ = true;
  error_ = Error::at(file_, field, what);
}

bool JsonReader::has(const Json& parent, std::string_view key) const {
  if (!parent.is_object()) return false;
  auto it = parent.find(key);
  return it != parent.end() && !it->is_null();
}

const Json* JsonReader::field(const Json& parent, std::string_view path, std::string_view key) {
  if (!parent.is_object()) {
    fail(path, "expected an object, got " + describe_json(parent));
    return nullptr;
  }
  auto it = parent.find(key);
  if (it == parent.end()) {
    fail(json_path(path, key), "missing (required field)");
    return nullptr;
  }
  return &*it;
}

bool JsonReader::expect_object(const Json& value, std::string_view path) {
  if (value.is_object()) return true;
  fail(path.empty() ? "(document)" : path, "expected an object, got " + describe_json(value));
  return false;
}

bool JsonReader::expect_array(const Json& value, std::string_view path) {
  if (value.is_array()) return true;
  fail(path.empty() ? "(document)" : path, "expected an array, got " + describe_json(value));
  return false;
}

static std::string range_text(double min, double max) {
  auto num = [](double x) {
    std::string s = std::to_string(x);
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  if (std::isinf(min) && std::isinf(max)) return "a finite number";
  if (std::isinf(max)) return "a number >= " + num(min);
  if (std::isinf(min)) return "a number <= " + num(max);
  return "a number in [" + num(min) + ", " + num(max) + "]";
}

double JsonReader::as_number(const Json& v, std::string_view path, double min, double max) {
  if (!v.is_number()) {
    fail(path, "expected " + range_text(min, max) + ", got " + describe_json(v));
    return std::isfinite(min) ? min : 0.0;
  }
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < min || x > max) {
    fail(path, "expected " + range_text(min, max) + ", got " + describe_json(v));
    return std::isfinite(min) ? min : 0.0;
  }
  return x;
}

const Json* JsonReader::object(const Json& parent, std::string_view path, std::string_view key) {
  const Json* f = field(parent, path, key);
  if (f && !expect_object(*f, json_path(path, key))) return nullptr;
  return f;
}

const Json* JsonReader::array(const Json& parent, std::string_view path, std::string_view key) {
  const Json* f = field(parent, path, key);
  if (f && !expect_array(*f, json_path(path, key))) return nullptr;
  return f;
}

double JsonReader::number(const Json& parent, std::string_view path, std::string_view key,
                          double min, double max) {
  const Json* f = field(parent, path, key);
  if (!f) return std::isfinite(min) ? min : 0.0;
  return as_number(*f, json_path(path, key), min, max);
}

float JsonReader::number_f(const Json& parent, std::string_view path, std::string_view key, double min,
                           double max) {
  const double fmin = std::isfinite(min) ? static_cast<double>(static_cast<float>(min)) : min;
  const double fmax = std::isfinite(max) ? static_cast<double>(static_cast<float>(max)) : max;
  const Json* f = field(parent, path, key);
  if (!f) return static_cast<float>(std::isfinite(min) ? min : 0.0);
  const std::string p = json_path(path, key);
  const bool representable = f->is_number() && std::fabs(f->get<double>()) <= std::numeric_limits<float>::max();
  if (representable) {
    const double x = static_cast<double>(static_cast<float>(f->get<double>()));
    if (x >= fmin && x <= fmax) return static_cast<float>(x);
  }
  fail(p, "expected " + range_text(min, max) + ", got " + describe_json(*f));
  return static_cast<float>(std::isfinite(min) ? min : 0.0);
}

long long JsonReader::integer(const Json& parent, std::string_view path, std::string_view key,
                              long long min, long long max) {
  const Json* f = field(parent, path, key);
  if (!f) return min > 0 ? min : 0;
  const std::string p = json_path(path, key);
  const std::string expected =
      "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (f->is_number_integer()) {
    // Unsigned values above LLONG_MAX are out of every range we use.
    if (f->is_number_unsigned() && f->get<unsigned long long>() >
                                       static_cast<unsigned long long>(std::numeric_limits<long long>::max())) {
      fail(p, "expected " + expected + ", got " + describe_json(*f));
      return min > 0 ? min : 0;
    }
    const long long x = f->get<long long>();
    if (x < min || x > max) {
      fail(p, "expected " + expected + ", got " + describe_json(*f));
      return min > 0 ? min : 0;
    }
    return x;
  }
  if (f->is_number_float()) {
    const double x = f->get<double>();
    if (std::isfinite(x) && x == std::floor(x) && x >= static_cast<double>(min) &&
        x <= static_cast<double>(max)) {
      return static_cast<long long>(x);
    }
  }
  fail(p, "expected " + expected + ", got " + describe_json(*f));
  return min > 0 ? min : 0;
}

bool JsonReader::boolean(const Json& parent, std::string_view path, std::string_view key) {
  const Json* f = field(parent, path, key);
  if (!f) return false;
  if (!f->is_boolean()) {
    fail(json_path(path, key), "expected true or false, got " + describe_json(*f));
    return false;
  }
  return f->get<bool>();
}

std::string JsonReader::string(const Json& parent, std::string_view path, std::string_view key) {
  const Json* f = field(parent, path, key);
  if (!f) return {};
  if (!f->is_string()) {
    fail(json_path(path, key), "expected a string, got " + describe_json(*f));
    return {};
  }
  return f->get<std::string>();
}

double JsonReader::number_or(const Json& parent, std::string_view path, std::string_view key,
                             double fallback, double min, double max) {
  return has(parent, key) ? number(parent, path, key, min, max) : fallback;
}

long long JsonReader::integer_or(const Json& parent, std::string_view path, std::string_view key,
                                 long long fallback, long long min, long long max) {
  return has(parent, key) ? integer(parent, path, key, min, max) : fallback;
}

bool JsonReader::boolean_or(const Json& parent, std::string_view path, std::string_view key,
                            bool fallback) {
  return has(parent, key) ? boolean(parent, path, key) : fallback;
}

std::string JsonReader::string_or(const Json& parent, std::string_view path, std::string_view key,
                                  std::string fallback) {
  return has(parent, key) ? string(parent, path, key) : std::move(fallback);
}

}  // namespace ossa
