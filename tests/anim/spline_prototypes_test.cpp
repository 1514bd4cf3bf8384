#include "ossa/anim/spline_prototypes.h"

#include <catch2/catch.hpp>

#include <filesystem>

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
