#include "ossa/gen/dataset.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "ossa/gen/pca_model.h"
#include "ossa/io/json.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

Dataset load_examples() {
  Result<Dataset> d = load_dataset(scenes::source_path("assets/creatures/examples.json"));
  INFO((d.ok() ? std::string() : d.message()));
  REQUIRE(d.ok());
  return std::move(d).value();
}

// A valid two-animal file; `animal2` replaces the second animal's fields.
std::string file_with(const std::string& animal2) {
  return R"({"format":"ossa.examples","version":1,"animals":[
    {"name":"frog","name_de":"Frosch","class":"amphibian","wings":0,"leg_pairs":2,"weight_kg":0.01,
     "spine":[[500,300],[500,300],[500,300],[500,300],[400,280],[300,260],[250,250],[250,250],[250,250],[250,250]],
     "front":{"upper":100,"lower":80,"hand":90},"hind":{"upper":250,"lower":270,"foot":350}},
    )" + animal2 + "]}";
}

const char* kGiraffe =
    R"({"name":"giraffe","name_de":"Giraffe","class":"mammal","wings":0,"leg_pairs":2,"weight_kg":2000,
        "spine":[[600,950],[560,830],[500,630],[450,500],[370,490],[270,440],[210,410],[190,380],[180,310],[170,230]],
        "front":{"upper":100,"lower":150,"hand":180},"hind":{"upper":110,"lower":130,"foot":190}})";

std::string error_of(const std::string& text) {
  Result<Dataset> d = parse_dataset(text, "examples.json");
  REQUIRE_FALSE(d.ok());
  return d.message();
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("examples.json loads 44 animals with unique names and sane values", "[gen]") {
  const Dataset d = load_examples();
  REQUIRE(d.animals.size() == 44);
  std::set<std::string> names, names_de;
  int winged = 0, legs[3] = {0, 0, 0};
  for (const Animal& a : d.animals) {
    INFO(a.name);
    CHECK(names.insert(a.name).second);
    CHECK(names_de.insert(a.name_de).second);
    CHECK_FALSE(a.animal_class.empty());
    winged += a.wings;
    ++legs[a.leg_pairs];
    // Cropped and bottom-centred [Z 9.6]: legged animals stand on y = 0 and no point is
    // outside the frame; birds have wings, and wings are front limbs.
    if (a.wings) CHECK(a.front.total() > 0.0);
    if (a.leg_pairs > 0) CHECK(a.hind.total() + a.front.total() > 0.0);
  }
  // [Z fig. 6.6]: mean wings 0.159 (7 of 44), mean ground-contact leg pairs 1.39 (61 of 44).
  CHECK(winged == 7);
  CHECK(legs[0] == 8);
  CHECK(legs[1] == 11);
  CHECK(legs[2] == 25);
}

TEST_CASE("animals read as themselves in the side view", "[gen]") {
  const Dataset d = load_examples();
  const Animal& giraffe = *d.find("giraffe");
  // Long steep neck: the head end is far above the shoulder.
  CHECK(giraffe.spine[kSpineHead].y - giraffe.spine[kSpineShoulder].y > 300.0f);
  const Animal& snake = *d.find("snake");
  CHECK(snake.leg_pairs == 0);
  CHECK(snake.front.total() == 0.0);
  CHECK(snake.hind.total() == 0.0);
  for (const glm::vec2& p : snake.spine) CHECK(p.y < 50.0f);
  const Animal& frog = *d.find("frog");
  for (int i = kSpineHip; i <= kSpineTailTip; ++i) CHECK(frog.spine[i] == frog.spine[kSpineHip]);
  const Animal& kangaroo = *d.find("kangaroo");
  CHECK(kangaroo.spine[kSpineShoulder].y > kangaroo.spine[kSpineHip].y + 100.0f);  // upright
  CHECK(kangaroo.spine[kSpineTailTip].y < 100.0f);                                // tail on the ground
  // Every head is on the right (+x facing) of the hip.
  for (const Animal& a : d.animals) {
    INFO(a.name);
    CHECK(a.spine[kSpineHead].x >= a.spine[kSpineHip].x);
    CHECK(a.spine[kSpineShoulder].x > a.spine[kSpineTailTip].x);
  }
}

TEST_CASE("find() matches English and German names, ignoring case", "[gen]") {
  const Dataset d = load_examples();
  const Animal* horse = d.find("horse");
  REQUIRE(horse);
  CHECK(horse->name_de == "Pferd");
  CHECK(d.find("PFERD") == horse);
  CHECK(d.find("Horse") == horse);
  REQUIRE(d.find("Känguru"));
  CHECK(d.find("Känguru")->name == "kangaroo");
  CHECK(d.find("blue whale")->weight_kg == 120000.0);
  CHECK(d.find("unicorn") == nullptr);
  CHECK(d.find("") == nullptr);
}

TEST_CASE("a small valid file parses field by field", "[gen]") {
  Result<Dataset> d = parse_dataset(file_with(kGiraffe), "examples.json");
  INFO((d.ok() ? std::string() : d.message()));
  REQUIRE(d.ok());
  REQUIRE(d->animals.size() == 2);
  const Animal& g = d->animals[1];
  CHECK(g.name == "giraffe");
  CHECK(g.spine[2] == glm::vec2(500.0f, 630.0f));
  CHECK(g.front.distal == 180.0);
  CHECK(g.hind.distal == 190.0);
  CHECK_FALSE(g.posture.has_value());
  Result<Dataset> p = parse_dataset(replaced(file_with(kGiraffe), "\"weight_kg\":2000", "\"weight_kg\":2000,\"posture\":\"unguligrade\""),
                                    "examples.json");
  REQUIRE(p.ok());
  CHECK(p->animals[1].posture == LimbPosture::kUnguligrade);
}

TEST_CASE("bad inputs name the animal and the field", "[gen]") {
  const std::string good = file_with(kGiraffe);
  CHECK(error_of(replaced(good, "[500,630]", "[12,1200]")) ==
        "examples.json: animals[1] (giraffe).spine[2]: expected a point [x, y] with 0 <= x, y <= "
        "1000, got [12,1200]");
  CHECK_THAT(error_of(replaced(good, "[500,630]", "[500]")),
             Catch::Contains("animals[1] (giraffe).spine[2]: expected a point"));
  CHECK_THAT(error_of(replaced(good, "[500,630],", "")),
             Catch::Contains("animals[1] (giraffe).spine: expected 10 points"));
  CHECK_THAT(error_of(replaced(good, "\"leg_pairs\":2,\"weight_kg\":2000", "\"leg_pairs\":3,\"weight_kg\":2000")),
             Catch::Contains("animals[1] (giraffe).leg_pairs: expected an integer in [0, 2], got 3"));
  CHECK_THAT(error_of(replaced(good, "\"weight_kg\":2000", "\"weight_kg\":-5")),
             Catch::Contains("animals[1] (giraffe).weight_kg: expected a number in [0,"));
  CHECK_THAT(error_of(replaced(good, "\"hand\":180", "\"hnd\":180")),
             Catch::Contains("animals[1] (giraffe).front.hand: missing (required field)"));
  CHECK_THAT(error_of(replaced(good, "\"foot\":190", "\"foot\":\"long\"")),
             Catch::Contains("animals[1] (giraffe).hind.foot: expected a number in [0, 1000], got a string"));
  CHECK_THAT(error_of(replaced(good, "\"name\":\"giraffe\",", "")),
             Catch::Contains("examples.json: animals[1].name: missing (required field)"));
  CHECK_THAT(error_of(replaced(good, "\"wings\":0,\"leg_pairs\":2,\"weight_kg\":2000", "\"wings\":true,\"leg_pairs\":2,\"weight_kg\":2000")),
             Catch::Contains("animals[1] (giraffe).wings"));
  CHECK_THAT(error_of(replaced(good, "\"weight_kg\":2000", "\"weight_kg\":2000,\"posture\":\"hooved\"")),
             Catch::Contains("animals[1] (giraffe).posture: expected \"unguligrade\", \"digitigrade\" or \"plantigrade\", got \"hooved\""));
}

TEST_CASE("duplicate names are rejected, in English and German", "[gen]") {
  CHECK_THAT(error_of(file_with(replaced(kGiraffe, "\"giraffe\"", "\"Frog\""))),
             Catch::Contains("animals[1] (Frog).name: duplicate name \"Frog\" (also used by animals[0])"));
  CHECK_THAT(error_of(file_with(replaced(kGiraffe, "\"Giraffe\"", "\"frosch\""))),
             Catch::Contains("animals[1] (giraffe).name_de: duplicate name"));
}

TEST_CASE("the document itself is checked", "[gen]") {
  CHECK_THAT(error_of("[]"), Catch::Contains("expected an object"));
  CHECK_THAT(error_of("{\"format\":\"x\",\"version\":1,\"animals\":[]}"), Catch::Contains("format: expected \"ossa.examples\""));
  CHECK_THAT(error_of(replaced(file_with(kGiraffe), "\"version\":1", "\"version\":2")),
             Catch::Contains("version: expected an integer in [1, 1], got 2"));
  CHECK_THAT(error_of("{\"format\":\"ossa.examples\",\"version\":1,\"animals\":[]}"),
             Catch::Contains("animals: expected at least one animal"));
  CHECK_THAT(error_of("{\"format\":"), Catch::Contains("not valid JSON"));
  CHECK_THAT(error_of(file_with("42")), Catch::Contains("animals[1]: expected an object, got 42"));
  Result<Dataset> missing = load_dataset("/nonexistent/examples.json");
  REQUIRE_FALSE(missing.ok());
  CHECK_THAT(missing.message(), Catch::Contains("/nonexistent/examples.json"));
}

TEST_CASE("raw vectors round-trip and every dimension has a name", "[gen]") {
  const Dataset d = load_examples();
  for (const Animal& a : d.animals) {
    const PcaVector v = to_vector(a);
    const Animal b = from_vector(v);
    CHECK(b.name.empty());
    CHECK(b.wings == a.wings);
    CHECK(b.leg_pairs == a.leg_pairs);
    CHECK(b.weight_kg == a.weight_kg);
    CHECK(b.spine == a.spine);
    CHECK(b.front.upper == a.front.upper);
    CHECK(b.hind.distal == a.hind.distal);
    CHECK(to_vector(b) == v);
  }
  std::set<std::string> names;
  for (int dim = 0; dim < kPcaDims; ++dim) {
    CHECK(names.insert(dim_name(dim)).second);
    CHECK(dim_from_name(dim_name(dim)) == dim);
  }
  CHECK(std::string(dim_name(kWeightKg)) == "weight_kg");
  CHECK(std::string(dim_name(spine_x_dim(3))) == "spine[3].x");
  CHECK(std::string(dim_name(spine_y_dim(9))) == "spine[9].y");
  CHECK(std::string(dim_name(kFrontHand)) == "front.hand");
  CHECK(std::string(dim_name(kHindFoot)) == "hind.foot");
  CHECK(dim_from_name("tail") == -1);
  // Continuous samples round to valid counts.
  PcaVector v = to_vector(d.animals[0]);
  v[kWings] = 0.7;
  v[kLegPairs] = 5.0;
  CHECK(from_vector(v).wings == 1);
  CHECK(from_vector(v).leg_pairs == 2);
}

TEST_CASE("a spine point nested 300 000 deep is refused, not a crash", "[gen]") {
  // The message used to print the point with dump(), recursively: a stack overflow.
  const std::string deep = std::string(300000, '[') + std::string(300000, ']');
  const std::string message = error_of(replaced(file_with(kGiraffe), "[500,630]", deep));
  CHECK_THAT(message, Catch::StartsWith("examples.json: animals[1].spine[2]"));
  CHECK_THAT(message, Catch::Contains("nested more than 256 arrays or objects deep"));
}
