#include "ossa/gen/genome.h"

#include <catch2/catch.hpp>

#include <filesystem>
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
