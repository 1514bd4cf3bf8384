#include "ossa/anim/spline_prototypes.h"

#include <cmath>

#include "ossa/io/file.h"
#include "ossa/io/json.h"

namespace ossa {

namespace {

constexpr const char* kFormat = "ossa.prototypes";
constexpr int kVersion = 1;

HermiteSpline spline(std::initializer_list<HermiteKey> keys) { return HermiteSpline(std::vector<HermiteKey>(keys)); }

Json spline_to_json(const HermiteSpline& s) {
  Json keys = Json::array();
  for (const HermiteKey& k : s.keys) {
    keys.push_back({{"t", json_float(k.t)}, {"p", json_float(k.p)}, {"m", json_float(k.m)}});
  }
  return keys;
}

}  // namespace

const char* prototype_name(PrototypeId id) {
  switch (id) {
    case PrototypeId::kLegSwingX: return "leg_swing_x";
    case PrototypeId::kLegSwingY: return "leg_swing_y";
    case PrototypeId::kPelvisY: return "pelvis_y";
    case PrototypeId::kArmSwing: return "arm_swing";
    case PrototypeId::kArmBend: return "arm_bend";
    case PrototypeId::kIdleY: return "idle_y";
    case PrototypeId::kCount: break;
  }
  return "unknown";
}

SplinePrototypes SplinePrototypes::defaults() {
  SplinePrototypes p;
  // Swing: the foot leaves slowly, crosses fast and sets down gently; the run version
  // reaches forward earlier and lifts higher.
  p[PrototypeId::kLegSwingX] = {spline({{0.0f, 0.0f, 0.2f}, {0.5f, 0.55f, 1.6f}, {1.0f, 1.0f, 0.0f}}),
                                spline({{0.0f, 0.0f, 0.4f}, {0.45f, 0.62f, 1.7f}, {1.0f, 1.0f, 0.0f}})};
  p[PrototypeId::kLegSwingY] = {spline({{0.0f, 0.0f, 0.6f}, {0.4f, 0.12f, 0.0f}, {1.0f, 0.0f, -0.3f}}),
                                spline({{0.0f, 0.0f, 1.0f}, {0.35f, 0.22f, 0.0f}, {1.0f, 0.0f, -0.6f}})};
  // Pelvis: the designer's extra bob, twice per stride, over the one the footfalls give
  // (trunk_bob.h); none by default.
  p[PrototypeId::kPelvisY] = {spline({{0.0f, 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}),
                              spline({{0.0f, 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}})};
  // Arms: a pendulum over the stride, counter to the same-side leg.
  p[PrototypeId::kArmSwing] = {spline({{0.0f, 0.3f, 0.0f}, {0.5f, -0.3f, 0.0f}, {1.0f, 0.3f, 0.0f}}),
                               spline({{0.0f, 0.65f, 0.0f}, {0.5f, -0.65f, 0.0f}, {1.0f, 0.65f, 0.0f}})};
  p[PrototypeId::kArmBend] = {spline({{0.0f, 0.2f, 0.0f}, {0.5f, 0.05f, 0.0f}, {1.0f, 0.2f, 0.0f}}),
                              spline({{0.0f, 0.9f, 0.0f}, {0.5f, 0.6f, 0.0f}, {1.0f, 0.9f, 0.0f}})};
  // Idle: slow breathing bob.
  p[PrototypeId::kIdleY] = {spline({{0.0f, 0.0f, 0.0f}, {0.5f, -0.012f, 0.0f}, {1.0f, 0.0f, 0.0f}}),
                            spline({{0.0f, 0.0f, 0.0f}, {0.5f, -0.025f, 0.0f}, {1.0f, 0.0f, 0.0f}})};
  return p;
}

bool SplinePrototypes::is_valid() const {
  for (const PrototypePair& pair : pairs) {
    for (const HermiteSpline* s : {&pair.walk, &pair.run}) {
      if (!s->is_valid() || s->keys.front().t < 0.0f || s->keys.back().t > 1.0f) return false;
    }
    if (pair.walk.keys.size() != pair.run.keys.size()) return false;
  }
  return true;
}

Json prototypes_to_json(const SplinePrototypes& p) {
  Json all = Json::object();
  for (int i = 0; i < kPrototypeCount; ++i) {
    all[prototype_name(static_cast<PrototypeId>(i))] = {{"walk", spline_to_json(p.pairs[i].walk)},
                                                        {"run", spline_to_json(p.pairs[i].run)}};
  }
  return Json{{"format", kFormat}, {"version", kVersion}, {"prototypes", all}};
}

Result<SplinePrototypes> prototypes_from_json(const Json& doc, std::string_view file) {
  JsonReader r{std::string(file)};
  if (!r.expect_object(doc, "")) return r.error();
  const std::string format = r.string(doc, "", "format");
  if (!r.failed() && format != kFormat) r.fail("format", std::string("expected \"") + kFormat + "\", got \"" + format + "\"");
  const long long version = r.integer(doc, "", "version", 1, 1000000);
  if (!r.failed() && version != kVersion) r.fail("version", "expected 1, got " + std::to_string(version));
  SplinePrototypes p;
  const Json* all = r.object(doc, "", "prototypes");
  for (int i = 0; i < kPrototypeCount && all && !r.failed(); ++i) {
    const char* name = prototype_name(static_cast<PrototypeId>(i));
    const std::string path = json_path("prototypes", name);
    const Json* pair = r.object(*all, "prototypes", name);
    if (!pair) break;
    for (int which = 0; which < 2 && !r.failed(); ++which) {
      const char* key = which == 0 ? "walk" : "run";
      const std::string spath = json_path(path, key);
      const Json* keys = r.array(*pair, path, key);
      if (!keys) break;
      if (keys->empty() || keys->size() > 64) {
        r.fail(spath, "expected 1 to 64 keys, got " + std::to_string(keys->size()));
        break;
      }
      HermiteSpline s;
      for (size_t k = 0; k < keys->size() && !r.failed(); ++k) {
        const std::string kpath = json_path(spath, k);
        const Json& kj = (*keys)[k];
        if (!r.expect_object(kj, kpath)) break;
        HermiteKey key_value;
        key_value.t = r.number_f(kj, kpath, "t", 0.0, 1.0);
        const PrototypeRange range = prototype_range(static_cast<PrototypeId>(i));
        key_value.p = r.number_f(kj, kpath, "p", range.min, range.max);
        key_value.m = r.number_f(kj, kpath, "m", -kMaxPrototypeTangent, kMaxPrototypeTangent);
        if (!r.failed() && !s.keys.empty() && !(key_value.t > s.keys.back().t)) {
          r.fail(json_path(kpath, "t"), "expected a time greater than the previous key's " +
                                            std::to_string(s.keys.back().t) + ", got " + std::to_string(key_value.t));
        }
        s.keys.push_back(key_value);
      }
      (which == 0 ? p.pairs[i].walk : p.pairs[i].run) = std::move(s);
    }
    if (!r.failed() && p.pairs[i].walk.keys.size() != p.pairs[i].run.keys.size()) {
      r.fail(json_path(path, "run"), "expected as many keys as \"walk\" (" + std::to_string(p.pairs[i].walk.keys.size()) +
                                         "), got " + std::to_string(p.pairs[i].run.keys.size()));
    }
  }
  if (r.failed()) return r.error();
  return p;
}

Result<SplinePrototypes> load_prototypes(const std::string& path) {
  Result<Json> doc = read_json_file(path);
  if (!doc) return doc.error();
  return prototypes_from_json(*doc, path);
}

Status save_prototypes(const std::string& path, const SplinePrototypes& prototypes) {
  return write_json_atomic(path, prototypes_to_json(prototypes));
}

}  // namespace ossa
