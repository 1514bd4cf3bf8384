#include "ossa/anim/spline_prototypes.h"

#include <catch2/catch.hpp>

#include <filesystem>

#include "ossa/io/json.h"
#include "shared/scenes.h"

using namespace ossa;

TEST_CASE("the shipped prototypes load and equal the built-in defaults", "[anim][prototypes]") {
  Result<SplinePrototypes> p = load_prototypes(scenes::source_path("assets/animation/prototypes.json"));
  REQUIRE(p.ok());
  CHECK(p->is_valid());
  CHECK(prototypes_to_json(*p) == prototypes_to_json(SplinePrototypes::defaults()));
}

TEST_CASE("prototypes round-trip through a file", "[anim][prototypes]") {
  SplinePrototypes p = SplinePrototypes::defaults();
  p[PrototypeId::kLegSwingY].run.keys[1].p = 0.31f;
  const std::string path = (std::filesystem::temp_directory_path() / "ossa_prototypes_test.json").string();
  REQUIRE(save_prototypes(path, p).ok());
  Result<SplinePrototypes> back = load_prototypes(path);
  REQUIRE(back.ok());
  CHECK(back->pairs[static_cast<int>(PrototypeId::kLegSwingY)].run.keys[1].p == 0.31f);
  CHECK(prototypes_to_json(*back) == prototypes_to_json(p));
  std::filesystem::remove(path);
}

TEST_CASE("bad prototype files name the file and the field", "[anim][prototypes]") {
  const Json good = prototypes_to_json(SplinePrototypes::defaults());
  auto error_for = [&](auto mutate) {
    Json j = good;
    mutate(j);
    Result<SplinePrototypes> r = prototypes_from_json(j, "p.json");
    REQUIRE_FALSE(r.ok());
    return r.message();
  };
  CHECK_THAT(error_for([](Json& j) { j["prototypes"].erase("pelvis_y"); }), Catch::Contains("p.json: prototypes.pelvis_y: missing"));
  CHECK_THAT(error_for([](Json& j) { j["prototypes"]["leg_swing_x"]["run"].erase(1); }),
             Catch::Contains("prototypes.leg_swing_x.run: expected as many keys as \"walk\""));
  CHECK_THAT(error_for([](Json& j) { j["prototypes"]["arm_swing"]["walk"][1]["t"] = 0.0; }),
             Catch::Contains("prototypes.arm_swing.walk[1].t: expected a time greater"));
  CHECK_THAT(error_for([](Json& j) { j["prototypes"]["idle_y"]["walk"][0]["p"] = "high"; }),
             Catch::Contains("prototypes.idle_y.walk[0].p"));
  CHECK_THAT(error_for([](Json& j) { j["version"] = 2; }), Catch::Contains("version"));
  CHECK_THAT(load_prototypes("/no/such/prototypes.json").message(), Catch::Contains("/no/such/prototypes.json"));
}

TEST_CASE("keys outside a prototype's range are refused, naming the range", "[anim][prototypes]") {
  Json j = prototypes_to_json(SplinePrototypes::defaults());
  j["prototypes"]["pelvis_y"]["walk"][1]["p"] = 100;
  CHECK(prototypes_from_json(j, "p.json").message() ==
        "p.json: prototypes.pelvis_y.walk[1].p: expected a number in [-0.0625, 0.0625], got 100");
  j = prototypes_to_json(SplinePrototypes::defaults());
  j["prototypes"]["leg_swing_y"]["run"][1]["p"] = -0.5;
  CHECK(prototypes_from_json(j, "p.json").message() ==
        "p.json: prototypes.leg_swing_y.run[1].p: expected a number in [0, 1], got -0.5");
  j = prototypes_to_json(SplinePrototypes::defaults());
  j["prototypes"]["arm_bend"]["walk"][0]["m"] = 1001;
  CHECK(prototypes_from_json(j, "p.json").message() ==
        "p.json: prototypes.arm_bend.walk[0].m: expected a number in [-1000, 1000], got 1001");
  // The bounds themselves read back.
  for (int i = 0; i < kPrototypeCount; ++i) {
    const PrototypeRange range = prototype_range(static_cast<PrototypeId>(i));
    for (float p : {range.min, range.max}) {
      j = prototypes_to_json(SplinePrototypes::defaults());
      j["prototypes"][prototype_name(static_cast<PrototypeId>(i))]["walk"][0]["p"] = json_float(p);
      CHECK(prototypes_from_json(j, "p.json").ok());
    }
  }
}
