// ossa-gen — generate vertebrate skeletons from the example PCA model and export them
// (issue "Creature generator", DESIGN.md §5). Every failure prints one clear message on stderr
// and exits non-zero; no input, however malformed, may crash it (DESIGN.md §11).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/export_obj.h"
#include "ossa/gen/export_svg.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/pca_model.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/io/parse_arg.h"
#include "ossa/body/body_svg.h"
#include "ossa/render/gltf_export.h"
#ifdef OSSA_GEN_HAVE_RENDER
#include "ossa/platform/window.h"
#include "ossa/render/capture.h"
#include "ossa/render/creature_sheet.h"
#include "ossa/render/renderer.h"
#include "ossa/render/texture.h"
#endif

namespace {

using namespace ossa;

constexpr const char* kUsage = R"(usage: ossa-gen SOURCE [CONDITIONS] [VARIATIONS] [OUTPUTS]
       ossa-gen --stats | --sheet F.svg [--dataset F]

Generate vertebrate skeletons from the PCA model of 44 example animals and export them.

source (one of):
  --example NAME        an example animal by English or German name (e.g. horse, Pferd)
  --random              a random creature from the PCA model
  --in F.creature.json  load a saved genome instead of generating one
  --seed N              seed of the random choices (default 1)
size (of every creature made, variations and --sheet too):
  --size true|FRAME_M   true (default: the animal's true size from its weight and body plan)
                        or a fixed frame of FRAME_M metres (0.05 to 50; 2: every creature as
                        big as a pony); saved as the genome's "size". With --in the genome is
                        resized (without --size: as saved)
conditions (--example, --random):
  --wings 0|1           condition on wings
  --leg-pairs 0|1|2     condition on ground-contact leg pairs
  --weight KG           condition on the weight (kg, 0.001 to 1000000)
  --neck-girdle         allow a girdle below the head (centaur)
  --multi-limb          allow two limb pairs per girdle (pegasus)
variations:
  --variations K        K variations of the creature (seeds seed+1 .. seed+K)
  --sigma S             step size in sigma units of the principal components (0 to 10, default 0.3)
outputs (with variations, F-1.ext .. F-K.ext):
  --out F.creature.json save the genome
  --svg F.svg           side view of the skeleton
  --gltf F.gltf         glTF 2.0 via Assimp: the node hierarchy and, by --look, the skinned
                        body (vertex colours), the bone sprite mesh, or both
  --obj F.obj           box proxies, one box per bone
  --summary             JSON description of the creature(s) on stdout (the default output):
                        limbs, bones, weight, scale (metres per frame unit), size, ...
  --count N             with --random --summary: N creatures from consecutive seeds, print
                        counts, limb-layout histogram and throughput
model:
  --stats               JSON statistics of the PCA model on stdout
  --sheet F.svg|F.png   all examples (seed 1 each) in a grid with their names: an SVG, or a
                        PNG drawn by the game's renderer offscreen (no display needed)
  --sheet-random N      with --sheet: N random creatures (seeds 1..N) after the examples
  --look L              how --sheet, --svg and --gltf show creatures: body (default), xray
                        (the body translucent over the bones) or bones
  --dataset F           examples file (default: assets/creatures/examples.json of the data folder)
  --help                this text
)";

struct Args {
  std::optional<std::string> example, in, dataset, out, svg, gltf, obj, sheet;
  bool random = false, stats = false, summary = false, help = false;
  uint64_t seed = 1;
  std::optional<int> wings, leg_pairs, variations;
  std::optional<double> weight, sigma;
  std::optional<long long> count;
  std::optional<int> sheet_random;
  std::optional<SizeChoice> size;
  CreatureLook look = CreatureLook::kBody;
  bool neck_girdle = false, multi_limb = false;
};

struct UsageError {
  std::string message;
};

[[noreturn]] void usage_error(const std::string& message) { throw UsageError{message}; }

long long parse_int(const std::string& flag, const std::string& text, long long lo, long long hi) {
  Result<long long> v = parse_int_arg(flag, text, lo, hi);
  if (!v) usage_error(v.message());
  return *v;
}

// A finite number in [lo, hi] (or (lo, hi] when lo_open); the message names the flag and
// the range, e.g. "--sigma: expected a number in (0, 10], got "1e6"".
double parse_double(const std::string& flag, const std::string& text, double lo, bool lo_open, double hi) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || (lo_open && v == lo) || v > hi) {
    const auto num = [](double x) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", x);
      return std::string(buf);
    };
    usage_error(flag + ": expected a number in " + (lo_open ? "(" : "[") + num(lo) + ", " + num(hi) + "], got \"" +
                text + "\"");
  }
  return v;
}

Args parse_args(int argc, char** argv) {
  Args a;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size() || (args[i + 1].rfind("--", 0) == 0 && args[i + 1].size() > 2)) {
        usage_error(flag + ": missing value");
      }
      return args[++i];
    };
    auto once = [&](auto& field, auto v) {
      if (field) usage_error(flag + ": given twice");
      field = v;
    };
    if (flag == "--help" || flag == "-h") a.help = true;
    else if (flag == "--example") once(a.example, value());
    else if (flag == "--random") a.random = true;
    else if (flag == "--in") once(a.in, value());
    else if (flag == "--seed") a.seed = static_cast<uint64_t>(parse_int(flag, value(), 0, 9007199254740991LL));
    else if (flag == "--wings") once(a.wings, static_cast<int>(parse_int(flag, value(), 0, 1)));
    else if (flag == "--leg-pairs") once(a.leg_pairs, static_cast<int>(parse_int(flag, value(), 0, 2)));
    else if (flag == "--weight") {
      once(a.weight, parse_double(flag, value(), pca_range(kWeightKg).min, false, pca_range(kWeightKg).max));
    }
    else if (flag == "--size") {
      Result<SizeChoice> size = parse_size_arg(flag, value());
      if (!size) usage_error(size.message());
      once(a.size, *size);
    }
    else if (flag == "--neck-girdle") a.neck_girdle = true;
    else if (flag == "--multi-limb") a.multi_limb = true;
    else if (flag == "--variations") once(a.variations, static_cast<int>(parse_int(flag, value(), 1, 10000)));
    else if (flag == "--sigma") once(a.sigma, parse_double(flag, value(), 0.0, false, kMaxVariationSigma));
    else if (flag == "--out") once(a.out, value());
    else if (flag == "--svg") once(a.svg, value());
    else if (flag == "--gltf") once(a.gltf, value());
    else if (flag == "--obj") once(a.obj, value());
    else if (flag == "--sheet") once(a.sheet, value());
    else if (flag == "--dataset") once(a.dataset, value());
    else if (flag == "--sheet-random") once(a.sheet_random, static_cast<int>(parse_int(flag, value(), 0, 1000)));
    else if (flag == "--look") {
      const std::string v = value();
      const auto look = creature_look_from_name(v);
      if (!look) usage_error("--look: expected body, xray or bones, got \"" + v + "\"");
      a.look = *look;
    }
    else if (flag == "--stats") a.stats = true;
    else if (flag == "--summary") a.summary = true;
    else if (flag == "--count") once(a.count, parse_int(flag, value(), 1, 100000000));
    else usage_error("unknown argument \"" + flag + "\"");
  }
  if (a.help) return a;
  const int sources = (a.example ? 1 : 0) + (a.random ? 1 : 0) + (a.in ? 1 : 0);
  if (sources > 1) usage_error("--example, --random and --in exclude each other");
  const bool creature_outputs = a.out || a.svg || a.gltf || a.obj || a.summary;
  if (sources == 0 && (creature_outputs || a.variations || a.count)) {
    usage_error("no creature source: give --example NAME, --random or --in F.creature.json");
  }
  if (sources == 0 && !a.stats && !a.sheet) {
    usage_error("nothing to do: give a creature source, --stats or --sheet (see --help)");
  }
  const bool conditions = a.wings || a.leg_pairs || a.weight || a.neck_girdle || a.multi_limb;
  if (a.in && conditions) usage_error("conditions apply to generated creatures, not to --in");
  if (a.count && !(a.random && a.summary)) usage_error("--count needs --random and --summary");
  if (a.count && (a.variations || a.out || a.svg || a.gltf || a.obj)) {
    usage_error("--count only prints a summary; drop --variations and file outputs");
  }
  if (a.sigma && !a.variations) usage_error("--sigma needs --variations");
  if (a.sheet_random && !a.sheet) usage_error("--sheet-random needs --sheet");
  return a;
}

// "F.creature.json" → "F-3.creature.json"; "F.svg" → "F-3.svg" (suffix before the extension).
std::string numbered(const std::string& path, int index, int total) {
  if (total <= 1) return path;
  const size_t slash = path.find_last_of('/');
  const size_t from = slash == std::string::npos ? 0 : slash + 1;
  size_t dot = path.find(".creature.json", from);
  if (dot == std::string::npos) dot = path.find_last_of('.');
  if (dot == std::string::npos || dot < from) dot = path.size();
  return path.substr(0, dot) + "-" + std::to_string(index) + path.substr(dot);
}

Status write_text(const std::string& path, const std::string& text) {
  return write_file_atomic(path, text);
}

Json creature_summary(const Genome& g, const Creature& c) {
  const Skeleton& s = c.skeleton;
  Json j;
  j["name"] = c.name;
  j["seed"] = g.seed;
  j["legs"] = c.count(LimbKind::kLeg);
  j["arms"] = c.count(LimbKind::kArm);
  j["wings"] = c.count(LimbKind::kWing);
  j["fins"] = c.count(LimbKind::kFin);
  j["bones"] = s.bone_count();
  j["vertebrae"] = {{"neck", s.count(BoneKind::kNeckVertebra)},
                    {"back", s.count(BoneKind::kBackVertebra)},
                    {"tail", s.count(BoneKind::kTailVertebra)}};
  j["ribs"] = s.count(BoneKind::kRib);
  j["weight_kg"] = g.pca[kWeightKg];
  j["contact"] = contact_mode_name(c.contact);
  j["skull"] = skull_variant_name(g.skull_variant);
  j["scale"] = c.scale;
  j["size"] = g.options.true_size ? Json("true") : Json(json_float(g.options.frame_m));  // as the genome file says
  Json limbs = Json::array();
  for (const Limb& l : c.limbs) {
    if (l.side != Side::kNear) continue;
    limbs.push_back({{"kind", limb_kind_name(l.kind)}, {"girdle", girdle_kind_name(l.girdle)},
                     {"slot", l.slot}});
  }
  j["limb_pairs"] = limbs;
  return j;
}

std::string layout_key(const Creature& c) {
  return "legs" + std::to_string(c.count(LimbKind::kLeg)) + "-arms" +
         std::to_string(c.count(LimbKind::kArm)) + "-wings" +
         std::to_string(c.count(LimbKind::kWing)) + "-fins" +
         std::to_string(c.count(LimbKind::kFin));
}

Json model_stats(const Generator& gen) {
  const PcaModel& m = gen.model();
  Json j;
  j["samples"] = m.example_count();
  j["dimensions"] = kPcaDims;
  Json ev = Json::array();
  for (int i = 0; i < kPcaDims; ++i) ev.push_back(m.eigenvalues()[i]);
  j["eigenvalues"] = ev;
  Json explained = Json::array();
  for (int k = 1; k <= kPcaDims; ++k) explained.push_back(m.explained_variance(k));
  j["explained_variance"] = explained;
  const PcaVector mean = m.mean_raw();
  Json mean_j = Json::object();
  for (int d = 0; d < kPcaDims; ++d) mean_j[dim_name(d)] = mean[d];
  j["mean"] = mean_j;
  double best = 1e300, worst = -1.0;
  std::string nearest, farthest;
  for (const Animal& a : gen.dataset().animals) {
    const double dist = (PcaModel::preprocess(to_vector(a)) - m.mean_preprocessed()).norm();
    if (dist < best) best = dist, nearest = a.name;
    if (dist > worst) worst = dist, farthest = a.name;
  }
  j["nearest_to_mean"] = {{"name", nearest}, {"distance", best}};
  j["farthest_from_mean"] = {{"name", farthest}, {"distance", worst}};
  return j;
}

// A PNG contact sheet drawn by the game's renderer in an offscreen window.
Status write_sheet_png(const std::string& path, const std::vector<std::pair<std::string, Creature>>& sheet,
                       CreatureLook look) {
#ifdef OSSA_GEN_HAVE_RENDER
  setenv("SDL_VIDEODRIVER", "offscreen", 0);
  WindowDesc desc;
  desc.title = "ossa-gen";
  desc.width = 64;
  desc.height = 64;
  desc.offscreen = true;
  auto window = Window::create(desc);
  if (!window.ok()) return Error::at(path, "", window.message());
  auto renderer = Renderer::create(default_shader_dir());
  if (!renderer.ok()) return Error::at(path, "", renderer.message());
  const Atlas atlas = Atlas::load(default_sprite_dir());
  SheetOptions o;
  o.look = look;
  auto image = render_sheet(*renderer, atlas, sheet, o);
  if (!image.ok()) return Error::at(path, "", image.message());
  return write_png(path, *image);
#else
  (void)sheet;
  (void)look;
  return Error::at(path, "", "this ossa-gen was built without the renderer (SDL2/GL): write an .svg sheet");
#endif
}

int fail(const std::string& message) {
  std::fprintf(stderr, "ossa-gen: %s\n", message.c_str());
  return 1;
}

int run(const Args& a) {
  const std::string dataset_path =
      a.dataset ? *a.dataset : data_path("assets/creatures/examples.json");
  // No output may be one of the inputs (io/file.h): checked for every file name written.
  std::vector<std::string> inputs = {dataset_path};
  if (a.in) inputs.push_back(*a.in);
  const auto output = [&](const char* flag, const std::string& path) -> std::optional<int> {
    if (Status st = check_output_path(flag, path, inputs); !st) return fail(st.message());
    return std::nullopt;
  };
  for (const auto& [flag, path] : {std::pair{"--out", &a.out}, std::pair{"--svg", &a.svg}, std::pair{"--gltf", &a.gltf},
                                   std::pair{"--obj", &a.obj}, std::pair{"--sheet", &a.sheet}}) {
    if (*path) {
      if (auto code = output(flag, **path)) return *code;
    }
  }
  std::optional<Generator> generator;
  if (a.example || a.random || a.stats || a.sheet || a.variations || (a.in && a.size)) {
    Result<Generator> g = Generator::load(dataset_path, ossa::body_volume_m3);
    if (!g) return fail(g.message());
    generator.emplace(std::move(*g));
  }

  if (a.stats) std::cout << json_text(model_stats(*generator), 2) << "\n";

  if (a.sheet) {
    GenerateOptions sheet_options;  // the examples as they are, in the size asked for
    if (a.size) a.size->apply_to(sheet_options.genome);
    std::vector<std::pair<std::string, Creature>> sheet;
    std::vector<int> skulls;
    for (const Animal& animal : generator->dataset().animals) {
      Result<Genome> genome = generator->example(animal.name, 1, sheet_options);
      if (!genome) return fail(animal.name + ": " + genome.message());
      Result<Creature> creature = build_creature(*genome);
      if (!creature) return fail(animal.name + ": " + creature.message());
      sheet.emplace_back(animal.name + " (" + animal.name_de + ")", std::move(*creature));
      skulls.push_back(genome->skull_variant);
    }
    for (int k = 1; k <= a.sheet_random.value_or(0); ++k) {
      const Genome genome = generator->random(static_cast<uint64_t>(k), sheet_options);
      Result<Creature> creature = build_creature(genome);
      if (!creature) return fail("random " + std::to_string(k) + ": " + creature.message());
      sheet.emplace_back("random, seed " + std::to_string(k), std::move(*creature));
      skulls.push_back(genome.skull_variant);
    }
    const bool png = a.sheet->size() > 4 && a.sheet->substr(a.sheet->size() - 4) == ".png";
    if (png) {
      if (Status st = write_sheet_png(*a.sheet, sheet, a.look); !st) return fail(st.message());
    } else if (Status st = write_text(*a.sheet, look_sheet_svg(sheet, 6, skulls, a.look)); !st) {
      return fail(st.message());
    }
  }

  if (!a.example && !a.random && !a.in) return 0;

  GenerateOptions options;
  options.wings = a.wings;
  options.leg_pairs = a.leg_pairs;
  options.weight_kg = a.weight;
  options.genome.neck_girdle = a.neck_girdle;
  options.genome.multi_limb = a.multi_limb;
  if (a.size) a.size->apply_to(options.genome);

  if (a.count) {
    std::map<std::string, long long> layouts;
    long long with_wings = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (long long k = 0; k < *a.count; ++k) {
      const Genome genome = generator->random(a.seed + static_cast<uint64_t>(k), options);
      Result<Creature> creature = build_creature(genome);
      if (!creature) {
        return fail("seed " + std::to_string(a.seed + static_cast<uint64_t>(k)) + ": " +
                    creature.message());
      }
      with_wings += creature->count(LimbKind::kWing) > 0;
      ++layouts[layout_key(*creature)];
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Json j;
    j["count"] = *a.count;
    j["first_seed"] = a.seed;
    j["with_wings"] = with_wings;
    j["limb_layouts"] = layouts;
    j["seconds"] = seconds;
    j["per_second"] = seconds > 0.0 ? static_cast<double>(*a.count) / seconds : 0.0;
    std::cout << json_text(j, 2) << "\n";
    return 0;
  }

  Genome base;
  if (a.in) {
    Result<Genome> g = load_genome(*a.in);
    if (!g) return fail(g.message());
    base = std::move(*g);
    if (a.size) {  // resized: the saved genome's scale made again for the size asked for
      a.size->apply_to(base.options);
      generator->apply_size(base);
    }
  } else if (a.example) {
    Result<Genome> g = generator->example(*a.example, a.seed, options);
    if (!g) return fail("--example " + *a.example + ": " + g.message());
    base = std::move(*g);
  } else {
    base = generator->random(a.seed, options);
  }

  std::vector<Genome> genomes;
  if (a.variations) {
    for (int k = 1; k <= *a.variations; ++k) {
      genomes.push_back(generator->variation(base, base.seed + static_cast<uint64_t>(k),
                                             a.sigma.value_or(0.3)));
    }
  } else {
    genomes.push_back(std::move(base));
  }

  const int total = static_cast<int>(genomes.size());
  Json summaries = Json::array();
  const std::string atlas = data_path("assets/sprites/bones/atlas.png");
  for (int k = 0; k < total; ++k) {
    const Genome& genome = genomes[static_cast<size_t>(k)];
    Result<Creature> built = build_creature(genome);
    if (!built) return fail((a.in ? *a.in + ": " : std::string()) + built.message());
    const Creature& c = *built;
    for (const auto& [flag, path] : {std::pair{"--out", &a.out}, std::pair{"--svg", &a.svg}, std::pair{"--gltf", &a.gltf},
                                     std::pair{"--obj", &a.obj}}) {
      if (*path) {
        if (auto code = output(flag, numbered(**path, k + 1, total))) return *code;
      }
    }
    if (a.out) {
      if (Status st = save_genome(numbered(*a.out, k + 1, total), genome); !st) return fail(st.message());
    }
    if (a.svg) {
      SvgOptions o;
      o.skull_variant = genome.skull_variant;
      if (Status st = write_text(numbered(*a.svg, k + 1, total), look_svg(c, a.look, o)); !st) {
        return fail(st.message());
      }
    }
    if (a.obj) {
      if (Status st = write_text(numbered(*a.obj, k + 1, total), creature_obj(c)); !st) {
        return fail(st.message());
      }
    }
    if (a.gltf) {
      GltfOptions o;
      o.atlas_path = atlas;
      o.look = a.look;
      if (Status st = export_gltf(c, numbered(*a.gltf, k + 1, total), o); !st) {
        return fail(st.message());
      }
    }
    summaries.push_back(creature_summary(genome, c));
  }
  const bool file_outputs = a.out || a.svg || a.obj || a.gltf;
  if (a.summary || !file_outputs) {
    std::cout << json_text(total == 1 ? summaries[0] : summaries, 2) << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Args args = parse_args(argc, argv);
    if (args.help) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    return run(args);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "ossa-gen: %s\n(see ossa-gen --help)\n", e.message.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ossa-gen: error: %s\n", e.what());
    return 1;
  }
}
