#include "ossa/rig/rig_mapping.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "ossa/io/file.h"
#include "ossa/io/json.h"

namespace ossa {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::string bone_name(JsonReader& r, const Json& parent, std::string_view path, std::string_view key) {
  std::string s = r.string(parent, path, key);
  if (!r.failed() && s.empty()) r.fail(json_path(path, key), "expected a bone name, got an empty string");
  return s;
}

// A list of bone names; `one_or_list` also accepts a single name.
std::vector<std::string> bone_list(JsonReader& r, const Json& doc, std::string_view key, bool one_or_list) {
  std::vector<std::string> out;
  if (!r.has(doc, key) || r.failed()) return out;
  const Json& v = doc.at(std::string(key));
  if (one_or_list && v.is_string()) {
    out.push_back(bone_name(r, doc, "", key));
    return out;
  }
  if (!v.is_array()) {
    r.fail(key, std::string(one_or_list ? "expected a bone name or a list of them" : "expected a list of bone names") +
                    ", got " + describe_json(v));
    return out;
  }
  for (size_t i = 0; i < v.size() && !r.failed(); ++i) {
    if (!v[i].is_string() || v[i].get<std::string>().empty()) {
      r.fail(json_path(key, i), "expected a bone name, got " + describe_json(v[i]));
    } else {
      out.push_back(v[i].get<std::string>());
    }
  }
  return out;
}

void read_chains(JsonReader& r, const Json& doc, std::string_view key, bool legs, std::vector<RigChain>& out) {
  const Json* chains = r.array(doc, "", key);
  if (!chains) return;
  for (size_t i = 0; i < chains->size() && !r.failed(); ++i) {
    const std::string path = json_path(key, i);
    const Json& c = (*chains)[i];
    if (!r.expect_object(c, path)) return;
    RigChain chain;
    const std::string side = r.string(c, path, "side");
    if (!r.failed() && side != "near" && side != "far") {
      r.fail(json_path(path, "side"), "expected \"near\" or \"far\", got " + describe_json(side));
    }
    chain.side = side == "far" ? Side::kFar : Side::kNear;
    chain.upper = bone_name(r, c, path, "upper");
    chain.lower = bone_name(r, c, path, "lower");
    chain.end = bone_name(r, c, path, legs ? "foot" : "hand");
    for (const char* k : {"contact", "pair", "knee"}) {
      if (!legs && !r.failed() && r.has(c, k)) r.fail(json_path(path, k), "only legs have this field");
    }
    if (legs && !r.failed()) {
      if (r.has(c, "contact")) {
        const Json& p = c.at("contact");
        const std::string field = json_path(path, "contact");
        if (!p.is_array() || p.size() != 2) {
          r.fail(field, "expected [x, y] in mesh units, got " + describe_json(p));
        } else {
          const float x = static_cast<float>(r.as_number(p[0], json_path(field, 0), -1e6, 1e6));
          const float y = static_cast<float>(r.as_number(p[1], json_path(field, 1), -1e6, 1e6));
          chain.contact = glm::vec2(x, y);
        }
      }
      chain.pair = static_cast<int>(r.integer_or(c, path, "pair", -1, 0, 63));
      const std::string knee = r.string_or(c, path, "knee", "forward");
      if (!r.failed() && knee != "forward" && knee != "back") {
        r.fail(json_path(path, "knee"), "expected \"forward\" or \"back\", got " + describe_json(knee));
      }
      chain.knee = knee == "back" ? -1 : 1;
    }
    out.push_back(std::move(chain));
  }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> rig_mapping_bones(const RigMapping& m) {
  std::vector<std::pair<std::string, std::string>> out;
  auto add = [&](const std::string& field, const std::string& bone) {
    if (!bone.empty()) out.push_back({field, bone});
  };
  add("root", m.root);
  for (size_t i = 0; i < m.spine.size(); ++i) add(json_path("spine", i), m.spine[i]);
  for (size_t i = 0; i < m.neck.size(); ++i) add(json_path("neck", i), m.neck[i]);
  add("head", m.head);
  for (size_t i = 0; i < m.tail.size(); ++i) add(json_path("tail", i), m.tail[i]);
  for (size_t i = 0; i < m.legs.size(); ++i) {
    add(json_path(json_path("legs", i), "upper"), m.legs[i].upper);
    add(json_path(json_path("legs", i), "lower"), m.legs[i].lower);
    add(json_path(json_path("legs", i), "foot"), m.legs[i].end);
  }
  for (size_t i = 0; i < m.arms.size(); ++i) {
    add(json_path(json_path("arms", i), "upper"), m.arms[i].upper);
    add(json_path(json_path("arms", i), "lower"), m.arms[i].lower);
    add(json_path(json_path("arms", i), "hand"), m.arms[i].end);
  }
  return out;
}

Result<RigMapping> rig_mapping_from_json(const Json& doc, const std::string& file) {
  JsonReader r(file);
  if (!r.expect_object(doc, "")) return r.error();
  const std::string format = r.string(doc, "", "format");
  if (!r.failed() && format != kRigFormat) r.fail("format", std::string("expected \"") + kRigFormat + "\", got " + describe_json(format));
  const long long version = r.integer(doc, "", "version", 1, 1000000);
  if (!r.failed() && version != kRigVersion) {
    r.fail("version", "expected " + std::to_string(kRigVersion) + ", got " + std::to_string(version));
  }
  static const char* const kKeys[] = {"format", "version", "mesh", "scale", "root", "spine", "neck", "head", "tail", "legs", "arms"};
  if (!r.failed()) {
    for (const auto& [key, value] : doc.items()) {
      if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
        r.fail(key, "unknown field (expected one of format, version, mesh, scale, root, spine, neck, head, tail, legs, arms)");
        break;
      }
    }
  }
  RigMapping m;
  m.mesh = r.string(doc, "", "mesh");
  if (!r.failed() && m.mesh.empty()) r.fail("mesh", "expected the mesh file, got an empty string");
  m.scale = static_cast<float>(r.number_or(doc, "", "scale", 1.0, 1e-6, 1000.0));
  m.root = bone_name(r, doc, "", "root");
  m.spine = bone_list(r, doc, "spine", false);
  m.neck = bone_list(r, doc, "neck", true);
  if (r.has(doc, "head")) m.head = bone_name(r, doc, "", "head");
  m.tail = bone_list(r, doc, "tail", false);
  read_chains(r, doc, "legs", true, m.legs);
  if (!r.failed() && m.legs.empty()) r.fail("legs", "expected at least one leg, got an empty list");
  if (r.has(doc, "arms")) read_chains(r, doc, "arms", false, m.arms);
  if (r.failed()) return r.error();
  // One part per bone.
  std::map<std::string, std::string> part;
  for (const auto& [field, bone] : rig_mapping_bones(m)) {
    auto [it, inserted] = part.emplace(bone, field);
    if (!inserted) return Error::at(file, field, "bone " + quoted(bone) + " is already " + it->second);
  }
  const std::filesystem::path folder = std::filesystem::path(file).parent_path();
  m.mesh_path = (folder / m.mesh).lexically_normal().generic_string();
  return m;
}

Result<RigMapping> parse_rig_mapping(std::string_view text, const std::string& file) {
  Result<Json> doc = parse_json(text, file);
  if (!doc.ok()) return doc.error();
  return rig_mapping_from_json(*doc, file);
}

Result<RigMapping> load_rig_mapping(const std::string& path) {
  Result<std::string> text = read_file(path);
  if (!text.ok()) return text.error();
  return parse_rig_mapping(*text, path);
}

Json rig_mapping_to_json(const RigMapping& m) {
  Json doc = {{"format", kRigFormat}, {"version", kRigVersion}, {"mesh", m.mesh}, {"root", m.root}};
  if (m.scale != 1.0f) doc["scale"] = json_float(m.scale);
  if (!m.spine.empty()) doc["spine"] = m.spine;
  if (!m.neck.empty()) doc["neck"] = m.neck;
  if (!m.head.empty()) doc["head"] = m.head;
  if (!m.tail.empty()) doc["tail"] = m.tail;
  auto chains = [&](const std::vector<RigChain>& list, bool legs) {
    Json out = Json::array();
    for (const RigChain& c : list) {
      Json j = {{"side", c.side == Side::kFar ? "far" : "near"}, {"upper", c.upper}, {"lower", c.lower},
                {legs ? "foot" : "hand", c.end}};
      if (legs) {
        if (c.contact) j["contact"] = {json_float(c.contact->x), json_float(c.contact->y)};
        if (c.pair >= 0) j["pair"] = c.pair;
        if (c.knee < 0) j["knee"] = "back";
      }
      out.push_back(j);
    }
    return out;
  };
  doc["legs"] = chains(m.legs, true);
  if (!m.arms.empty()) doc["arms"] = chains(m.arms, false);
  return doc;
}

Status save_rig_mapping(const std::string& path, const RigMapping& mapping) {
  return write_json_atomic(path, rig_mapping_to_json(mapping));
}

}  // namespace ossa
