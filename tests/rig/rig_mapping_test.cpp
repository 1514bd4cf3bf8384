// RigMapping (*.rig.json): every field checked with file and field in the message, a bone
// used twice refused naming both fields, and what save writes, load reads back.

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "ossa/io/json.h"
#include "ossa/rig/rig_mapping.h"
#include "ossa/io/file.h"
#include "ossa/math/rng.h"

using namespace ossa;

namespace {

const char* kValid = R"({"format": "ossa.rig", "version": 1, "mesh": "meshes/biped.gltf", "scale": 0.01,
  "root": "hips", "spine": ["spine_01", "spine_02"], "neck": "neck_01", "head": "head",
  "tail": ["tail_01", "tail_02"],
  "legs": [{"side": "near", "upper": "thigh_l", "lower": "calf_l", "foot": "foot_l", "contact": [12.5, 0]},
           {"side": "far", "upper": "thigh_r", "lower": "calf_r", "foot": "foot_r", "knee": "back", "pair": 0}],
  "arms": [{"side": "near", "upper": "upperarm_l", "lower": "lowerarm_l", "hand": "hand_l"}]})";

std::string error_of(const std::string& text, const std::string& file = "x.rig.json") {
  Result<RigMapping> m = parse_rig_mapping(text, file);
  return m.ok() ? std::string("(loaded)") : m.message();
}

// kValid with `from` replaced by `to`.
std::string with(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const size_t at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("a rig mapping loads every part, with the mesh found next to it", "[anim][rig]") {
  Result<RigMapping> m = parse_rig_mapping(kValid, "chars/biped.rig.json");
  INFO((m.ok() ? std::string() : m.message()));
  REQUIRE(m.ok());
  CHECK(m->mesh_path == "chars/meshes/biped.gltf");
  CHECK(m->scale == Approx(0.01f));
  CHECK(m->root == "hips");
  CHECK(m->spine == std::vector<std::string>{"spine_01", "spine_02"});
  CHECK(m->neck == std::vector<std::string>{"neck_01"});  // one name or a list
  CHECK(m->tail.size() == 2);
  REQUIRE(m->legs.size() == 2);
  CHECK(m->legs[0].side == Side::kNear);
  CHECK(m->legs[0].contact == glm::vec2(12.5f, 0.0f));
  CHECK_FALSE(m->legs[1].contact);
  CHECK(m->legs[1].knee == -1);
  CHECK(m->leg_pair(0) == 0);
  CHECK(m->leg_pair(1) == 0);
  REQUIRE(m->arms.size() == 1);
  CHECK(m->arms[0].end == "hand_l");
  // Only root, mesh and one leg are required.
  Result<RigMapping> small = parse_rig_mapping(R"({"format": "ossa.rig", "version": 1, "mesh": "m.glb", "root": "r",
      "legs": [{"side": "near", "upper": "a", "lower": "b", "foot": "c"}]})", "s.rig.json");
  REQUIRE(small.ok());
  CHECK(small->head.empty());
  CHECK(small->scale == 1.0f);
  CHECK(small->leg_pair(0) == 0);
}

TEST_CASE("a rig mapping that cannot work is refused naming the file, the field and the bone", "[anim][rig]") {
  CHECK_THAT(error_of(with("\"ossa.rig\"", "\"ossa.level\"")), Catch::StartsWith("x.rig.json: format: expected \"ossa.rig\""));
  CHECK_THAT(error_of(with("\"version\": 1", "\"version\": 2")), Catch::Contains("x.rig.json: version: expected 1, got 2"));
  CHECK_THAT(error_of(with("\"side\": \"far\"", "\"side\": \"left\"")), Catch::Contains("x.rig.json: legs[1].side: expected \"near\" or \"far\""));
  CHECK_THAT(error_of(with("\"upper\": \"thigh_r\"", "\"upper\": \"\"")), Catch::Contains("legs[1].upper: expected a bone name"));
  CHECK_THAT(error_of(with("\"upper\": \"thigh_r\"", "\"upper\": \"thigh_l\"")),
             Catch::Contains("x.rig.json: legs[1].upper: bone \"thigh_l\" is already legs[0].upper"));
  CHECK_THAT(error_of(with("\"head\": \"head\"", "\"head\": \"hips\"")), Catch::Contains("head: bone \"hips\" is already root"));
  CHECK_THAT(error_of(with("\"knee\": \"back\"", "\"knee\": \"sideways\"")), Catch::Contains("legs[1].knee: expected \"forward\" or \"back\""));
  CHECK_THAT(error_of(with("\"pair\": 0", "\"pair\": -2")), Catch::Contains("legs[1].pair"));
  CHECK_THAT(error_of(with("\"contact\": [12.5, 0]", "\"contact\": [12.5]")), Catch::Contains("legs[0].contact: expected [x, y]"));
  CHECK_THAT(error_of(with("\"hand\": \"hand_l\"", "\"hand\": \"hand_l\", \"contact\": [0, 0]")),
             Catch::Contains("arms[0].contact: only legs have this field"));
  CHECK_THAT(error_of(with("\"scale\": 0.01", "\"scale\": -1")), Catch::Contains("scale"));
  CHECK_THAT(error_of(with("\"spine\": [\"spine_01\", \"spine_02\"]", "\"spine\": [\"spine_01\", 3]")),
             Catch::Contains("spine[1]: expected a bone name"));
  CHECK_THAT(error_of(with("\"root\": \"hips\",", "\"root\": \"hips\", \"hips\": 1,")), Catch::Contains("hips: unknown field"));
  CHECK_THAT(error_of(R"({"format": "ossa.rig", "version": 1, "mesh": "m.glb", "root": "r", "legs": []})"),
             Catch::Contains("legs: expected at least one leg"));
  CHECK_THAT(error_of("{\"format\": \"ossa.rig\""), Catch::StartsWith("x.rig.json"));
  CHECK_THAT(error_of("[1, 2]"), Catch::StartsWith("x.rig.json"));
}

TEST_CASE("a saved rig mapping loads back the same", "[anim][rig]") {
  const RigMapping m = parse_rig_mapping(kValid, "biped.rig.json").value();
  const auto dir = std::filesystem::temp_directory_path() / ("ossa_rig_mapping_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "biped.rig.json").string();
  REQUIRE(save_rig_mapping(path, m).ok());
  const Result<RigMapping> back = load_rig_mapping(path);
  REQUIRE(back.ok());
  CHECK(rig_mapping_to_json(*back) == rig_mapping_to_json(m));
  CHECK(rig_mapping_bones(*back) == rig_mapping_bones(m));
  CHECK(rig_mapping_bones(m).front() == std::pair<std::string, std::string>{"root", "hips"});
  // Format and version come first in the file.
  const std::string text = read_file(path).value();
  CHECK(text.find("\"format\"") < text.find("\"version\""));
  CHECK(text.find("\"version\"") < text.find("\"legs\""));
  std::filesystem::remove_all(dir);
}

TEST_CASE("random rig mappings at the ends of their ranges save and load back the same", "[anim][rig]") {
  // Issue 33's round-trip rule for mappings: contact points up to ±1e6 mesh units, scale up to
  // 1000, pairs up to 63, names of any UTF-8 text.
  Rng rng(4242);
  const auto dir = std::filesystem::temp_directory_path() / ("ossa_rig_random_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "r.rig.json").string();
  const auto edge = [&](double lo, double hi) {
    const double u = rng.uniform(0.0, 1.0);
    return static_cast<float>(u < 0.25 ? lo : u < 0.5 ? hi : rng.uniform(lo, hi));
  };
  int bone = 0;
  const auto name = [&] {
    ++bone;
    return "b\xc3\xa9" + std::to_string(bone) + (bone % 3 ? ".L" : " r");
  };
  for (int round = 0; round < 100; ++round) {
    RigMapping m;
    m.mesh = "m.gltf";
    m.scale = rng.uniform(0.0, 1.0) < 0.3 ? 1000.0f : edge(1e-6, 1000.0);
    m.root = name();
    for (int i = 0, n = static_cast<int>(rng.uniform(0.0, 3.0)); i < n; ++i) m.spine.push_back(name());
    if (rng.uniform(0.0, 1.0) < 0.5) m.head = name();
    for (int i = 0, n = 1 + static_cast<int>(rng.uniform(0.0, 6.0)); i < n; ++i) {
      RigChain leg;
      leg.side = i % 2 ? Side::kFar : Side::kNear;
      leg.upper = name();
      leg.lower = name();
      leg.end = name();
      if (rng.uniform(0.0, 1.0) < 0.7) leg.contact = glm::vec2(edge(-1e6, 1e6), edge(-1e6, 1e6));
      if (rng.uniform(0.0, 1.0) < 0.5) leg.pair = static_cast<int>(edge(0.0, 63.0));
      leg.knee = rng.uniform(0.0, 1.0) < 0.5 ? 1 : -1;
      m.legs.push_back(leg);
    }
    INFO("round " << round);
    REQUIRE(save_rig_mapping(path, m).ok());
    const Result<RigMapping> back = load_rig_mapping(path);
    INFO((back.ok() ? std::string() : back.message()));
    REQUIRE(back.ok());
    CHECK(rig_mapping_to_json(*back) == rig_mapping_to_json(m));
  }
  std::filesystem::remove_all(dir);
}
