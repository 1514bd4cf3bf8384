#include "ossa/io/json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <unordered_set>
#include <vector>

#include "ossa/io/file.h"

namespace ossa {

namespace {

// Thrown from the parser callback on a key that its object already has.
struct DuplicateKey {
  std::string path;
};

// Follows the parser's events to know the path of the value being read, and keeps each open
// object's keys so a repeated key is caught (nlohmann::json would silently keep the last one:
// a second "colliders": [] would empty a level).
class DuplicateKeyCheck {
 public:
  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
    using E = Json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        begin_element();
        frames_.emplace_back();
        frames_.back().array = event == E::array_start;
        break;
      case E::object_end:
      case E::array_end:
        if (!frames_.empty()) frames_.pop_back();
        break;
      case E::key: {
        Frame& f = frames_.back();
        std::string key = parsed.get<std::string>();
        if (f.has(key)) throw DuplicateKey{path_with(key)};
        f.add(key);
        f.key = std::move(key);
        break;
      }
      case E::value: begin_element(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array = false;
    long long index = -1;                  // arrays: the element being read
    std::string key;                       // objects: the key being read
    std::vector<std::string> small;        // objects: keys seen, while few
    std::unordered_set<std::string> many;  // ... and once there are many

    bool has(const std::string& k) const {
      if (!many.empty()) return many.count(k) != 0;
      return std::find(small.begin(), small.end(), k) != small.end();
    }
    void add(const std::string& k) {
      if (many.empty() && small.size() < 16) {
        small.push_back(k);
        return;
      }
      if (many.empty()) many.insert(small.begin(), small.end());
      many.insert(k);
    }
  };

  void begin_element() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }

  std::string path_with(const std::string& key) const {
    std::string p;
    for (size_t i = 0; i + 1 < frames_.size(); ++i) {
      p = frames_[i].array ? json_path(p, static_cast<size_t>(frames_[i].index)) : json_path(p, frames_[i].key);
    }
    return json_path(p, key);
  }

  std::vector<Frame> frames_;
};

}  // namespace

Result<Json> parse_json(std::string_view text, std::string_view file) {
  try {
    return Json::parse(text.begin(), text.end(), DuplicateKeyCheck{});
  } catch (const DuplicateKey& d) {
    return Error::at(file, d.path, "duplicate key (a key may appear only once in an object)");
  } catch (const Json::parse_error& e) {
    // e.byte is the 1-based offset of the offending byte; turn it into line and column.
    size_t line = 1, column = 1;
    const size_t end = std::min<size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    for (size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
    }
    std::string what = "not valid JSON at line " + std::to_string(line) + ", column " +
                       std::to_string(column) + " (" + e.what() + ")";
    return Error::at(file, "", what);
  } catch (const std::exception& e) {
    return Error::at(file, "", std::string("not valid JSON (") + e.what() + ")");
  }
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
