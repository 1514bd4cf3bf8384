#include "ossa/gen/genome.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/io/parse_arg.h"

namespace ossa {

namespace {

constexpr const char* kFormat = "ossa.creature";

template <class E, size_t N>
bool parse_enum(const std::string& text, const std::array<E, N>& values, const char* (*name)(E), E* out) {
  for (E v : values) {
    if (text == name(v)) {
      *out = v;
      return true;
    }
  }
  return false;
}

constexpr std::array<LimbKind, 4> kLimbKinds = {LimbKind::kLeg, LimbKind::kArm, LimbKind::kWing, LimbKind::kFin};
constexpr std::array<GirdleKind, 3> kGirdleKinds = {GirdleKind::kNeck, GirdleKind::kShoulder, GirdleKind::kHip};
constexpr std::array<ContactMode, 2> kContactModes = {ContactMode::kTip, ContactMode::kFlat};

}  // namespace

PcaRange pca_range(int dim) {
  if (dim == kWings) return {-1.0, 2.0};
  if (dim == kLegPairs) return {-1.0, 3.0};
  if (dim == kWeightKg) return {0.001, 1e6};
  if (dim >= kFrontUpper) return {0.0, 1000.0};
  return {-1000.0, 2000.0};  // spine points
}

void clamp_to_genome_limits(Genome& g) {
  const auto clamp = [](auto v, auto lo, auto hi) { return v >= lo ? (v <= hi ? v : hi) : lo; };  // NaN → lo
  for (int d = 0; d < kPcaDims; ++d) g.pca[d] = clamp(g.pca[d], pca_range(d).min, pca_range(d).max);
  g.neck_vertebrae = clamp(g.neck_vertebrae, 0, kMaxNeckVertebrae);
  g.back_vertebrae = clamp(g.back_vertebrae, 2, kMaxBackVertebrae);
  g.tail_vertebrae = clamp(g.tail_vertebrae, 0, kMaxTailVertebrae);
  g.rib_interval = clamp(g.rib_interval, 0.0f, 1.0f);
  g.scale = clamp(g.scale, kMinGenomeScale, kMaxGenomeScale);
  for (LimbGene& l : g.limbs) {
    for (float& a : l.angles) a = clamp(a, -10.0f, 10.0f);
  }
  g.skull_shape.length = clamp(g.skull_shape.length, kMinSkullLength, kMaxSkullLength);
  g.skull_shape.height = clamp(g.skull_shape.height, kMinSkullHeight, kMaxSkullHeight);
  g.skull_shape.snout = clamp(g.skull_shape.snout, kMinSnout, kMaxSnout);
  clamp_look(g.look);
  clamp_appendages(g.appendages);
}

SkullShape default_skull_shape(int variant) {
  static constexpr float kLength[kSkullVariants] = {0.30f, 0.22f, 0.30f, 0.34f};
  static constexpr float kHeight[kSkullVariants] = {0.42f, 0.5f, 0.36f, 0.45f};
  static constexpr float kSnout[kSkullVariants] = {0.5f, 0.55f, 0.6f, 0.4f};
  const int v = std::clamp(variant, 0, kSkullVariants - 1);
  return {kLength[v], kHeight[v], kSnout[v]};
}

const char* skull_variant_name(int variant) {
  switch (variant) {
    case 0: return "mammal";
    case 1: return "bird";
    case 2: return "reptile";
    case 3: return "fish";
  }
  return "unknown";
}

Result<SizeChoice> parse_size_arg(std::string_view flag, std::string_view text) {
  if (text == "true") return SizeChoice{};
  // The range's ends as floats (the documented "0.05" is a little below 0.05f as a double).
  Result<double> frame = parse_number_arg(flag, text, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  const float frame_m = frame ? static_cast<float>(*frame) : 0.0f;
  if (!frame || !(frame_m >= kMinFrameMetres && frame_m <= kMaxFrameMetres)) {
    char range[64];
    std::snprintf(range, sizeof range, "[%g, %g]", static_cast<double>(kMinFrameMetres), static_cast<double>(kMaxFrameMetres));
    return Error{std::string(flag) + ": expected true or a frame in metres (a number in " + range + "), got \"" +
                 std::string(text) + "\""};
  }
  return SizeChoice{false, frame_m};
}

Json genome_to_json(const Genome& g) {
  Json pca = Json::object();
  for (int d = 0; d < kPcaDims; ++d) pca[dim_name(d)] = g.pca[d];
  Json limbs = Json::array();
  for (const LimbGene& l : g.limbs) {
    limbs.push_back({{"kind", limb_kind_name(l.kind)},
                     {"girdle", girdle_kind_name(l.girdle)},
                     {"slot", l.slot},
                     {"angles", {json_float(l.angles[0]), json_float(l.angles[1]), json_float(l.angles[2])}}});
  }
  return Json{{"format", kFormat},
              {"version", Genome::kVersion},
              {"name", g.name},
              {"seed", g.seed},
              {"pca", pca},
              {"vertebrae", {{"neck", g.neck_vertebrae}, {"back", g.back_vertebrae}, {"tail", g.tail_vertebrae}}},
              {"rib_interval", json_float(g.rib_interval)},
              {"limbs", limbs},
              {"contact", contact_mode_name(g.contact)},
              {"skull", g.skull_variant},
              {"skull_shape",
               {{"length", json_float(g.skull_shape.length)},
                {"height", json_float(g.skull_shape.height)},
                {"snout", json_float(g.skull_shape.snout)}}},
              {"size", g.options.true_size ? Json("true") : Json(json_float(g.options.frame_m))},
              {"scale", json_float(g.scale)},
              {"options",
               {{"arc_length_vertebrae", g.options.arc_length_vertebrae},
                {"neck_girdle", g.options.neck_girdle},
                {"multi_limb", g.options.multi_limb},
                {"smooth_skinning", g.options.smooth_skinning}}},
              {"gait_family", gait_family_name(g.gait_family)},
              {"look", look_to_json(g.look)},
              {"appendages", appendages_to_json(g.appendages)}};
}

Result<Genome> genome_from_json(const Json& doc, std::string_view file) {
  JsonReader r{std::string(file)};
  if (!r.expect_object(doc, "")) return r.error();
  const std::string format = r.string(doc, "", "format");
  if (!r.failed() && format != kFormat) {
    r.fail("format", std::string("expected \"") + kFormat + "\", got \"" + format + "\"");
  }
  const long long version = r.integer(doc, "", "version", 1, 1000000);
  if (!r.failed() && version > Genome::kVersion) {
    r.fail("version", "expected 1 to " + std::to_string(Genome::kVersion) + " (this build reads versions up to " +
                          std::to_string(Genome::kVersion) + "), got " + std::to_string(version));
  }
  Genome g;
  g.name = r.string_or(doc, "", "name", "");
  if (r.has(doc, "seed")) {
    const Json& s = doc["seed"];
    if (s.is_number_unsigned()) {
      g.seed = s.get<uint64_t>();
    } else {
      g.seed = static_cast<uint64_t>(r.integer(doc, "", "seed", 0));
    }
  }
  if (const Json* pca = r.object(doc, "", "pca")) {
    for (int d = 0; d < kPcaDims; ++d) {
      g.pca[d] = r.number(*pca, "pca", dim_name(d), pca_range(d).min, pca_range(d).max);
    }
  }
  if (const Json* v = r.object(doc, "", "vertebrae")) {
    g.neck_vertebrae = static_cast<int>(r.integer(*v, "vertebrae", "neck", 0, kMaxNeckVertebrae));
    g.back_vertebrae = static_cast<int>(r.integer(*v, "vertebrae", "back", 2, kMaxBackVertebrae));
    g.tail_vertebrae = static_cast<int>(r.integer(*v, "vertebrae", "tail", 0, kMaxTailVertebrae));
  }
  g.rib_interval = r.number_f(doc, "", "rib_interval", 0.0, 1.0);
  if (const Json* limbs = r.array(doc, "", "limbs")) {
    if (limbs->size() > kMaxLimbPairs) {
      r.fail("limbs", "expected at most " + std::to_string(kMaxLimbPairs) + " limb pairs, got " + std::to_string(limbs->size()));
    }
    for (size_t i = 0; i < limbs->size() && !r.failed(); ++i) {
      const std::string path = json_path("limbs", i);
      const Json& lj = (*limbs)[i];
      if (!r.expect_object(lj, path)) break;
      LimbGene l;
      const std::string kind = r.string(lj, path, "kind");
      if (!r.failed() && !parse_enum(kind, kLimbKinds, limb_kind_name, &l.kind)) {
        r.fail(json_path(path, "kind"), "expected \"leg\", \"arm\", \"wing\" or \"fin\", got \"" + kind + "\"");
      }
      const std::string girdle = r.string(lj, path, "girdle");
      if (!r.failed() && !parse_enum(girdle, kGirdleKinds, girdle_kind_name, &l.girdle)) {
        r.fail(json_path(path, "girdle"), "expected \"neck\", \"shoulder\" or \"hip\", got \"" + girdle + "\"");
      }
      l.slot = static_cast<int>(r.integer(lj, path, "slot", 0, 1));
      if (const Json* angles = r.array(lj, path, "angles")) {
        if (angles->size() != 3) {
          r.fail(json_path(path, "angles"), "expected 3 angles, got " + std::to_string(angles->size()));
        } else {
          for (int k = 0; k < 3; ++k) {
            l.angles[k] = static_cast<float>(r.as_number((*angles)[k], json_path(json_path(path, "angles"), k), -10.0, 10.0));
          }
        }
      }
      g.limbs.push_back(l);
    }
  }
  const std::string contact = r.string_or(doc, "", "contact", "tip");
  if (!r.failed() && !parse_enum(contact, kContactModes, contact_mode_name, &g.contact)) {
    r.fail("contact", "expected \"tip\" or \"flat\", got \"" + contact + "\"");
  }
  g.skull_variant = static_cast<int>(r.integer_or(doc, "", "skull", 0, 0, kSkullVariants - 1));
  g.scale = r.number_f(doc, "", "scale", kMinGenomeScale, kMaxGenomeScale);
  if (r.has(doc, "options")) {
    if (const Json* o = r.object(doc, "", "options")) {
      g.options.arc_length_vertebrae = r.boolean_or(*o, "options", "arc_length_vertebrae", true);
      g.options.neck_girdle = r.boolean_or(*o, "options", "neck_girdle", false);
      g.options.multi_limb = r.boolean_or(*o, "options", "multi_limb", false);
      g.options.true_size = r.boolean_or(*o, "options", "true_size", false);  // before "size"
      g.options.smooth_skinning = r.boolean_or(*o, "options", "smooth_skinning", true);
    }
  }
  // The size choice; files from before it keep the frame their scale gives (see genome.h).
  if (!r.has(doc, "options")) g.options.true_size = false;
  if (!r.failed()) g.options.frame_m = std::clamp(g.scale * 1000.0f, kMinFrameMetres, kMaxFrameMetres);
  if (r.has(doc, "size")) {
    const Json& size = doc["size"];
    if (size.is_string() && size.get<std::string>() == "true") {
      g.options.true_size = true;
    } else if (size.is_number()) {
      g.options.true_size = false;
      g.options.frame_m = r.number_f(doc, "", "size", kMinFrameMetres, kMaxFrameMetres);
    } else {
      r.fail("size", "expected \"true\" or a frame in metres (a number in [0.05, 50])");
    }
  }
  const std::string family = r.string_or(doc, "", "gait_family", "auto");
  if (!r.failed() && !parse_gait_family(family, &g.gait_family)) {
    std::string names;
    for (int i = 0; i < kGaitFamilyCount; ++i) names += std::string(i ? ", " : "") + gait_family_name(static_cast<GaitFamily>(i));
    r.fail("gait_family", "expected one of " + names + ", got \"" + family + "\"");
  }
  // Version 2: the body's look and appendages. A version 1 file wears a look drawn from its
  // seed and no appendages (it was written before bodies existed).
  g.look = random_look(g.seed, g.skull_variant, std::any_of(g.limbs.begin(), g.limbs.end(), [](const LimbGene& l) {
                         return l.kind == LimbKind::kWing;
                       }));
  g.skull_shape = default_skull_shape(g.skull_variant);
  if (version >= 2) {
    if (r.has(doc, "skull_shape")) {
      if (const Json* ss = r.object(doc, "", "skull_shape")) {
        g.skull_shape.length = r.number_f(*ss, "skull_shape", "length", json_float(kMinSkullLength), json_float(kMaxSkullLength));
        g.skull_shape.height = r.number_f(*ss, "skull_shape", "height", json_float(kMinSkullHeight), json_float(kMaxSkullHeight));
        g.skull_shape.snout = r.number_f(*ss, "skull_shape", "snout", json_float(kMinSnout), json_float(kMaxSnout));
      }
    }
    if (r.has(doc, "look")) read_look(r, doc, "", "look", g.look);
    if (r.has(doc, "appendages")) read_appendages(r, doc, "", "appendages", g.appendages);
  } else if (!r.failed()) {
    for (const char* key : {"look", "appendages", "skull_shape"}) {
      if (r.has(doc, key)) {
        r.fail(key, "needs version 2 (version 1 files have no look, appendages or skull_shape)");
        break;
      }
    }
  }
  if (!r.failed()) {
    for (size_t i = 0; i < g.limbs.size(); ++i) {
      if (g.limbs[i].slot == 1 && !g.options.multi_limb) {
        r.fail(json_path(json_path("limbs", i), "slot"), "expected 0 (slot 1 needs options.multi_limb), got 1");
        break;
      }
      for (size_t k = 0; k < i; ++k) {
        if (g.limbs[k].girdle == g.limbs[i].girdle && g.limbs[k].slot == g.limbs[i].slot) {
          r.fail(json_path("limbs", i), "expected a free girdle slot, but limbs[" + std::to_string(k) +
                                            "] already uses " + girdle_kind_name(g.limbs[i].girdle) +
                                            " slot " + std::to_string(g.limbs[i].slot));
        }
      }
    }
  }
  if (r.failed()) return r.error();
  // Accepted means buildable: the body plan decides which girdles exist (a neck girdle needs
  // a long neck), so a limb on a girdle this body lacks is caught here, naming the file.
  if (Result<Creature> built = build_creature(g); !built) return Error::at(file, "", built.message());
  return g;
}

Result<Genome> parse_genome(std::string_view text, std::string_view file) {
  Result<Json> doc = parse_json(text, file);
  if (!doc) return doc.error();
  return genome_from_json(*doc, file);
}

Result<Genome> load_genome(const std::string& path) {
  Result<std::string> text = read_file(path);
  if (!text) return text.error();
  return parse_genome(*text, path);
}

Status save_genome(const std::string& path, const Genome& genome) {
  return write_json_atomic(path, genome_to_json(genome));
}

}  // namespace ossa
