#include "ossa/gen/dataset.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "ossa/io/file.h"
#include "ossa/io/json.h"

namespace ossa {
namespace {

constexpr double kFrameSize = 1000.0;
constexpr double kMaxWeightKg = 1.0e7;  // generous: the blue whale, the heaviest, is 1.2e5

std::string lower_ascii(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

// A value for a message: arrays are shown as written (they are what a point looks like).
std::string describe_value(const Json& v) {
  if (!v.is_array()) return describe_json(v);
  std::string s = v.dump();
  if (s.size() > 60) s = s.substr(0, 60) + "...";
  return s;
}

bool read_point(JsonReader& r, const Json& v, const std::string& path, glm::vec2* out) {
  const bool ok = v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number() &&
                  std::isfinite(v[0].get<double>()) && std::isfinite(v[1].get<double>()) &&
                  v[0].get<double>() >= 0.0 && v[0].get<double>() <= kFrameSize &&
                  v[1].get<double>() >= 0.0 && v[1].get<double>() <= kFrameSize;
  if (!ok) {
    r.fail(path, "expected a point [x, y] with 0 <= x, y <= 1000, got " + describe_value(v));
    return false;
  }
  *out = glm::vec2(static_cast<float>(v[0].get<double>()), static_cast<float>(v[1].get<double>()));
  return true;
}

LimbLengths read_limb(JsonReader& r, const Json& animal, const std::string& path,
                      const char* key, const char* distal_key) {
  LimbLengths limb;
  const Json* o = r.object(animal, path, key);
  if (!o) return limb;
  const std::string p = json_path(path, key);
  limb.upper = r.number(*o, p, "upper", 0.0, kFrameSize);
  limb.lower = r.number(*o, p, "lower", 0.0, kFrameSize);
  limb.distal = r.number(*o, p, distal_key, 0.0, kFrameSize);
  return limb;
}

Animal read_animal(JsonReader& r, const Json& v, size_t index) {
  Animal a;
  std::string path = json_path("animals", index);
  if (!r.expect_object(v, path)) return a;
  a.name = r.string(v, path, "name");
  if (!r.failed() && a.name.empty()) r.fail(json_path(path, "name"), "expected a non-empty name");
  if (r.failed()) return a;
  // From here on every message names the animal: "animals[3] (giraffe).spine[2]".
  path += " (" + a.name + ")";
  a.name_de = r.string(v, path, "name_de");
  if (!r.failed() && a.name_de.empty()) {
    r.fail(json_path(path, "name_de"), "expected a non-empty name");
  }
  a.animal_class = r.string(v, path, "class");
  a.wings = static_cast<int>(r.integer(v, path, "wings", 0, 1));
  a.leg_pairs = static_cast<int>(r.integer(v, path, "leg_pairs", 0, 2));
  a.weight_kg = r.number(v, path, "weight_kg", 0.0, kMaxWeightKg);
  (void)r.string_or(v, path, "note", "");
  if (r.has(v, "posture")) {
    const std::string posture = r.string(v, path, "posture");
    bool known = false;
    for (LimbPosture p : {LimbPosture::kUnguligrade, LimbPosture::kDigitigrade, LimbPosture::kPlantigrade}) {
      if (posture == limb_posture_name(p)) {
        a.posture = p;
        known = true;
      }
    }
    if (!r.failed() && !known) {
      r.fail(json_path(path, "posture"), "expected \"unguligrade\", \"digitigrade\" or \"plantigrade\", got \"" + posture + "\"");
    }
  }
  if (const Json* spine = r.array(v, path, "spine")) {
    const std::string sp = json_path(path, "spine");
    if (spine->size() != kSpinePoints) {
      r.fail(sp, "expected 10 points (neck P0-P3, back P3-P6, tail P6-P9), got " +
                     std::to_string(spine->size()));
    } else {
      for (int i = 0; i < kSpinePoints && !r.failed(); ++i) {
        read_point(r, (*spine)[i], json_path(sp, i), &a.spine[i]);
      }
    }
  }
  a.front = read_limb(r, v, path, "front", "hand");
  a.hind = read_limb(r, v, path, "hind", "foot");
  // Optional: the skull's proportions (skull_shape.h), how the body looks and its appendages
  // (look.h).
  if (r.has(v, "skull")) {
    if (const Json* sk = r.object(v, path, "skull")) {
      const std::string sp = json_path(path, "skull");
      SkullShape shape;
      shape.length = r.number_f(*sk, sp, "length", json_float(kMinSkullLength), json_float(kMaxSkullLength));
      shape.height = r.number_f(*sk, sp, "height", json_float(kMinSkullHeight), json_float(kMaxSkullHeight));
      shape.snout = r.number_f(*sk, sp, "snout", json_float(kMinSnout), json_float(kMaxSnout));
      if (!r.failed()) a.skull = shape;
    }
  }
  // Optional: how the animal's body looks and its appendages (gen/look.h).
  if (r.has(v, "look")) {
    Look look;
    read_look(r, v, path, "look", look);
    if (!r.failed()) a.look = look;
  }
  if (r.has(v, "appendages")) read_appendages(r, v, path, "appendages", a.appendages);
  return a;
}

}  // namespace

const char* limb_posture_name(LimbPosture posture) {
  switch (posture) {
    case LimbPosture::kUnguligrade: return "unguligrade";
    case LimbPosture::kDigitigrade: return "digitigrade";
    case LimbPosture::kPlantigrade: return "plantigrade";
  }
  return "?";
}

const Animal* Dataset::find(std::string_view name_en_or_de) const {
  const std::string key = lower_ascii(name_en_or_de);
  for (const Animal& a : animals) {
    if (lower_ascii(a.name) == key || lower_ascii(a.name_de) == key) return &a;
  }
  return nullptr;
}

Result<Dataset> parse_dataset(std::string_view text, std::string_view file) {
  Result<Json> doc = parse_json(text, file);
  if (!doc) return doc.error();
  JsonReader r{std::string(file)};
  if (!r.expect_object(*doc, "")) return r.error();
  const std::string format = r.string(*doc, "", "format");
  if (!r.failed() && format != "ossa.examples") {
    r.fail("format", "expected \"ossa.examples\", got " + describe_json((*doc)["format"]));
  }
  (void)r.integer(*doc, "", "version", 1, 1);
  const Json* animals = r.array(*doc, "", "animals");
  if (r.failed()) return r.error();
  if (animals->empty()) return Error::at(file, "animals", "expected at least one animal, got none");

  Dataset data;
  data.animals.reserve(animals->size());
  // Lower-cased English and German names → index of the animal using them.
  std::map<std::string, size_t> names;
  for (size_t i = 0; i < animals->size(); ++i) {
    Animal a = read_animal(r, (*animals)[i], i);
    if (r.failed()) return r.error();
    for (const auto& [key, name] : {std::pair{"name", &a.name}, std::pair{"name_de", &a.name_de}}) {
      auto [it, inserted] = names.emplace(lower_ascii(*name), i);
      if (!inserted && it->second != i) {
        return Error::at(file, json_path(json_path("animals", i) + " (" + a.name + ")", key),
                         "duplicate name \"" + *name + "\" (also used by " +
                             json_path("animals", it->second) + ")");
      }
    }
    data.animals.push_back(std::move(a));
  }
  return data;
}

Result<Dataset> load_dataset(const std::string& path) {
  Result<std::string> text = read_file(path);
  if (!text) return text.error();
  return parse_dataset(*text, path);
}

// ---------------------------------------------------------------------------------------
namespace {
constexpr const char* kDimNames[kPcaDims] = {
    "wings",       "leg_pairs",   "weight_kg",   "spine[0].x",  "spine[0].y",  "spine[1].x",
    "spine[1].y",  "spine[2].x",  "spine[2].y",  "spine[3].x",  "spine[3].y",  "spine[4].x",
    "spine[4].y",  "spine[5].x",  "spine[5].y",  "spine[6].x",  "spine[6].y",  "spine[7].x",
    "spine[7].y",  "spine[8].x",  "spine[8].y",  "spine[9].x",  "spine[9].y",  "front.upper",
    "front.lower", "front.hand",  "hind.upper",  "hind.lower",  "hind.foot"};
static_assert(kSpine9Y == spine_y_dim(kSpinePoints - 1));
static_assert(kFrontUpper == kSpine9Y + 1 && kHindFoot == kPcaDims - 1);
}  // namespace

const char* dim_name(int dim) {
  OSSA_ASSERT(dim >= 0 && dim < kPcaDims, "dim_name: dimension out of range");
  return kDimNames[dim];
}

int dim_from_name(std::string_view name) {
  for (int d = 0; d < kPcaDims; ++d) {
    if (name == kDimNames[d]) return d;
  }
  return -1;
}

}  // namespace ossa
