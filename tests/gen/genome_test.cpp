#include "ossa/gen/genome.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>
#include <string>

#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/math/rng.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / name).string();
}

// Writes `doc` to `path` and loads it back as a genome file.
Result<Genome> load_written(const std::string& path, const Json& doc) {
  REQUIRE(write_file_atomic(path, doc.dump(2)).ok());
  return load_genome(path);
}

}  // namespace

TEST_CASE("options.smooth_skinning: saved, loaded, true when missing, refused when not a boolean",
          "[gen][io]") {
  const Generator& gen = scenes::generator();
  const std::string path = temp_path("ossa_smooth_skinning.creature.json");
  Genome g = gen.example("horse").value();
  CHECK(g.options.smooth_skinning);  // the default

  // Either value survives save and load, and reaches the built creature.
  for (bool smooth : {false, true}) {
    INFO("smooth_skinning " << smooth);
    g.options.smooth_skinning = smooth;
    REQUIRE(save_genome(path, g).ok());
    CHECK(read_json_file(path).value()["options"]["smooth_skinning"] == smooth);
    Result<Genome> loaded = load_genome(path);
    REQUIRE(loaded.ok());
    CHECK(loaded->options.smooth_skinning == smooth);
    CHECK(build_creature(*loaded).value().smooth_skinning == smooth);
  }

  // A file written before the option existed loads smooth: without the key (or null, which
  // every optional genome field reads as missing, JsonReader::has), or without options.
  g.options.smooth_skinning = false;
  Json doc = genome_to_json(g);
  doc["options"].erase("smooth_skinning");
  Result<Genome> without_key = load_written(path, doc);
  REQUIRE(without_key.ok());
  CHECK(without_key->options.smooth_skinning);
  doc["options"]["smooth_skinning"] = nullptr;
  Result<Genome> null_key = load_written(path, doc);
  REQUIRE(null_key.ok());
  CHECK(null_key->options.smooth_skinning);
  doc.erase("options");
  Result<Genome> without_options = load_written(path, doc);
  REQUIRE(without_options.ok());
  CHECK(without_options->options.smooth_skinning);

  // Anything but true or false is refused, naming the file and the field.
  for (const Json& bad : {Json("yes"), Json(1), Json(0.0), Json::array({true}), Json::object()}) {
    INFO(bad.dump());
    doc = genome_to_json(g);
    doc["options"]["smooth_skinning"] = bad;
    Result<Genome> r = load_written(path, doc);
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::StartsWith(path + ": options.smooth_skinning: expected true or false, got "));
  }
  doc["options"]["smooth_skinning"] = "yes";
  CHECK(load_written(path, doc).message() ==
        path + ": options.smooth_skinning: expected true or false, got a string \"yes\"");
  std::filesystem::remove(path);
}

TEST_CASE("look, appendages and skull shape: saved, loaded, checked, and version 1 files still load", "[gen][io]") {
  const Generator& gen = scenes::generator();
  const std::string path = temp_path("ossa_look.creature.json");
  Genome g = gen.example("giraffe").value();
  // The example's own: patches, ears, ossicones and a mane, a long skull.
  CHECK(g.look.pattern == CoatPattern::kPatches);
  REQUIRE(g.appendages.size() == 3);
  CHECK(g.appendages[0].kind == AppendageKind::kEars);
  CHECK(g.skull_shape.length == Approx(0.45f));

  // Every field round-trips (through "#rrggbb" colours: a byte per channel).
  g.look.base = *colour_from_hex("#123456");
  g.look.belly = *colour_from_hex("#abcdef");
  g.look.pattern_colour = *colour_from_hex("#010203");
  g.look.pattern = CoatPattern::kRosettes;
  g.look.pattern_scale = 0.37f;
  g.look.fatness = 1.45f;
  g.look.wings = WingCover::kMembrane;
  g.appendages = {{AppendageKind::kAntlers, 2.5f}, {AppendageKind::kTailFin, 0.3f}};
  g.skull_shape = {0.61f, 0.33f, 0.72f};
  REQUIRE(save_genome(path, g).ok());
  const Json written = read_json_file(path).value();
  CHECK(written["version"] == 2);
  CHECK(written["look"]["base"] == "#123456");
  CHECK(written["look"]["pattern"] == "rosettes");
  CHECK(written["appendages"][0]["kind"] == "antlers");
  Result<Genome> loaded = load_genome(path);
  REQUIRE(loaded.ok());
  CHECK(loaded->look == g.look);
  REQUIRE(loaded->appendages.size() == 2);
  CHECK(loaded->appendages[0].kind == AppendageKind::kAntlers);
  CHECK(loaded->appendages[0].size == 2.5f);
  CHECK(loaded->appendages[1].kind == AppendageKind::kTailFin);
  CHECK(loaded->skull_shape == g.skull_shape);
  const Creature c = build_creature(*loaded).value();
  CHECK(c.look == g.look);
  CHECK(c.skull_snout == 0.72f);
  CHECK(c.skeleton.length(c.skull) == Approx(0.61f * [&] {
          float back = 0.0f;
          for (int b : c.back) back += c.skeleton.length(b);
          return back;
        }()).epsilon(0.02));

  // Version 1 (no look, appendages or skull shape) loads: the look drawn from the seed, no
  // appendages, the variant's default skull — the skeleton it was built with.
  Json v1 = genome_to_json(g);
  v1["version"] = 1;
  v1.erase("look");
  v1.erase("appendages");
  v1.erase("skull_shape");
  Result<Genome> old = load_written(path, v1);
  REQUIRE(old.ok());
  CHECK(old->appendages.empty());
  CHECK(old->skull_shape == default_skull_shape(old->skull_variant));
  CHECK(old->look == random_look(old->seed, old->skull_variant, false));
  v1["look"] = look_to_json(g.look);
  CHECK_THAT(load_written(path, v1).message(), Catch::StartsWith(path + ": look: needs version 2"));

  // Out of range or malformed: refused, naming the file and the field.
  const auto refused = [&](const std::function<void(Json&)>& spoil, const std::string& message) {
    Json doc = genome_to_json(g);
    spoil(doc);
    const Result<Genome> r = load_written(path, doc);
    REQUIRE_FALSE(r.ok());
    CHECK(r.message() == path + ": " + message);
  };
  refused([](Json& d) { d["look"]["fatness"] = 3.0; }, "look.fatness: expected a number in [0.6, 1.6], got 3.0");
  refused([](Json& d) { d["look"]["base"] = "brown"; }, "look.base: expected a colour \"#rrggbb\" (six hex digits), got \"brown\"");
  refused([](Json& d) { d["look"]["pattern"] = "tartan"; },
          "look.pattern: expected \"none\", \"stripes\", \"spots\", \"rosettes\", \"dapples\" or \"patches\", got \"tartan\"");
  refused([](Json& d) { d["look"]["pattern_scale"] = 0.0; }, "look.pattern_scale: expected a number in [0.02, 1], got 0.0");
  refused([](Json& d) { d["look"]["wings"] = "scales"; }, "look.wings: expected \"feathered\" or \"membrane\", got \"scales\"");
  refused([](Json& d) { d["look"]["fur"] = true; },
          "look.fur: unknown field (expected base, belly, pattern, pattern_colour, pattern_scale, fatness or wings)");
  refused([](Json& d) { d["appendages"][0]["kind"] = "wheels"; },
          "appendages[0].kind: expected one of ears, horns, antlers, frill, crest, mane, trunk, hump, sail, plates, shell, dorsal_fin, tail_fin, got \"wheels\"");
  refused([](Json& d) { d["appendages"][1]["kind"] = "antlers"; },
          "appendages[1].kind: expected each kind once, but \"antlers\" is given twice");
  refused([](Json& d) { d["appendages"][0]["size"] = 9.0; }, "appendages[0].size: expected a number in [0.25, 3], got 9.0");
  refused([](Json& d) { d["skull_shape"]["snout"] = 0.95; }, "skull_shape.snout: expected a number in [0.1, 0.85], got 0.95");
  refused([](Json& d) { d["skull_shape"]["length"] = -1.0; }, "skull_shape.length: expected a number in [0.08, 0.8], got -1.0");
  std::filesystem::remove(path);
}

TEST_CASE("random creatures wear plausible, seeded looks, and clamping keeps every field in range", "[gen]") {
  const Generator& gen = scenes::generator();
  int patterned = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    const Genome a = gen.random(seed), b = gen.random(seed);
    CHECK(a.look == b.look);  // the seed decides
    CHECK(a.look.fatness >= 0.9f);
    CHECK(a.look.fatness <= 1.1f);
    patterned += a.look.pattern != CoatPattern::kNone;
    // The belly lighter than the back (countershading).
    CHECK(a.look.belly.r + a.look.belly.g + a.look.belly.b > a.look.base.r + a.look.base.g + a.look.base.b);
    for (const Appendage& x : a.appendages) {
      CHECK(x.size >= kMinAppendageSize);
      CHECK(x.size <= kMaxAppendageSize);
    }
  }
  CHECK(patterned > 5);
  CHECK(patterned < 50);
  Genome wild = gen.random(3);
  wild.look.fatness = 99.0f;
  wild.look.pattern_scale = -1.0f;
  wild.look.base = glm::vec3(-2.0f, 0.5f, 7.0f);
  wild.appendages = {{AppendageKind::kEars, 50.0f}, {AppendageKind::kEars, 1.0f}};
  wild.skull_shape = {9.0f, -1.0f, 0.5f};
  clamp_to_genome_limits(wild);
  CHECK(wild.look.fatness == kMaxFatness);
  CHECK(wild.look.pattern_scale == kMinPatternScale);
  CHECK(wild.look.base == glm::vec3(0.0f, 0.5f, 1.0f));
  REQUIRE(wild.appendages.size() == 1);
  CHECK(wild.appendages[0].size == kMaxAppendageSize);
  CHECK(wild.skull_shape.length == kMaxSkullLength);
  CHECK(wild.skull_shape.height == kMinSkullHeight);
  const Result<Genome> back = genome_from_json(genome_to_json(wild), "wild");
  INFO((back.ok() ? std::string() : back.message()));
  CHECK(back.ok());
}

TEST_CASE("random genomes at the ends of every range save and load back the same", "[gen]") {
  // Issue 33's round-trip rule: whatever the writer emits, the reader accepts, at every range
  // edge (floats written as their shortest decimal, read back against float range ends).
  const Generator& gen = scenes::generator();
  const std::string path = temp_path("ossa_genome_edges.creature.json");
  Rng rng(3333);
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    Genome g = gen.random(seed);
    const auto pick = [&](float lo, float hi) { return rng.uniform(0.0, 1.0) < 0.5 ? lo : hi; };
    g.scale = pick(kMinGenomeScale, kMaxGenomeScale);
    g.rib_interval = pick(0.0f, 1.0f);
    for (LimbGene& l : g.limbs) {
      for (float& a : l.angles) a = pick(-10.0f, 10.0f);
    }
    g.neck_vertebrae = rng.uniform(0.0, 1.0) < 0.5 ? 0 : kMaxNeckVertebrae;
    g.tail_vertebrae = rng.uniform(0.0, 1.0) < 0.5 ? 0 : kMaxTailVertebrae;
    if (!build_creature(g).ok()) continue;  // the loader refuses what does not build
    INFO("seed " << seed);
    REQUIRE(save_genome(path, g).ok());
    Result<Genome> back = load_genome(path);
    INFO((back.ok() ? std::string() : back.message()));
    REQUIRE(back.ok());
    CHECK(genome_to_json(*back) == genome_to_json(g));
  }
  std::filesystem::remove(path);
}
