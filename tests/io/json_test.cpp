#include "ossa/io/file.h"
#include "ossa/io/json.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace ossa;

TEST_CASE("parse errors name the file, line and column", "[io]") {
  Result<Json> r = parse_json("{\n  \"a\": 1,\n  \"b\": ]\n}", "levels/x.json");
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::Contains("levels/x.json"));
  CHECK_THAT(r.message(), Catch::Contains("line 3"));
}

TEST_CASE("JsonReader names the field path and what was expected", "[io]") {
  Result<Json> doc = parse_json(R"({"colliders":[{"w":1},{"w":-2}], "name": 3})", "f.json");
  REQUIRE(doc.ok());
  JsonReader r("f.json");
  const Json* cs = r.array(*doc, "", "colliders");
  REQUIRE(cs);
  CHECK(r.number(cs->at(0), json_path("colliders", 0), "w", 0.0) == 1.0);
  CHECK_FALSE(r.failed());
  r.number(cs->at(1), json_path("colliders", 1), "w", 0.0);
  REQUIRE(r.failed());
  CHECK(r.error().message == "f.json: colliders[1].w: expected a number >= 0, got -2");
  // The first error is kept.
  r.string(*doc, "", "name");
  CHECK_THAT(r.error().message, Catch::Contains("colliders[1].w"));
}

TEST_CASE("JsonReader reports missing fields and wrong types", "[io]") {
  Json doc = Json::parse(R"({"a":"x","i":2.5,"b":1})");
  {
    JsonReader r("g.json");
    r.number(doc, "root", "missing");
    CHECK(r.error().message == "g.json: root.missing: missing (required field)");
  }
  {
    JsonReader r("g.json");
    r.number(doc, "", "a");
    CHECK_THAT(r.error().message, Catch::Contains("a: expected a finite number, got a string \"x\""));
  }
  {
    JsonReader r("g.json");
    r.integer(doc, "", "i", 0, 10);
    CHECK_THAT(r.error().message, Catch::Contains("i: expected an integer in [0, 10], got 2.5"));
  }
  {
    JsonReader r("g.json");
    r.boolean(doc, "", "b");
    CHECK_THAT(r.error().message, Catch::Contains("b: expected true or false, got 1"));
  }
  {
    JsonReader r("g.json");
    CHECK(r.number_or(doc, "", "absent", 7.0) == 7.0);
    CHECK(r.string_or(doc, "", "a", "y") == "x");
    CHECK_FALSE(r.failed());
  }
}

TEST_CASE("atomic write replaces the file and leaves no temporary behind", "[io]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "ossa_io_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "a.json").string();
  REQUIRE(write_file_atomic(path, "first").ok());
  REQUIRE(write_file_atomic(path, "second").ok());
  CHECK(read_file(path).value() == "second");
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);

  // A failing save (the target is a folder) leaves nothing behind and reports the path.
  fs::create_directories(dir / "sub.json");
  Status s = write_file_atomic((dir / "sub.json").string(), "x");
  REQUIRE_FALSE(s.ok());
  CHECK_THAT(s.message(), Catch::Contains("sub.json"));
  files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 2);
  CHECK(read_file(path).value() == "second");

  // A missing folder is an error, not a crash.
  CHECK_FALSE(write_file_atomic((dir / "no" / "such" / "x.json").string(), "x").ok());
  fs::remove_all(dir);
}

TEST_CASE("read_file errors name the file", "[io]") {
  Result<std::string> r = read_file("/nonexistent/ossa.json");
  REQUIRE_FALSE(r.ok());
  CHECK(r.message() == "/nonexistent/ossa.json: no such file");
  Result<std::string> d = read_file("/tmp");
  REQUIRE_FALSE(d.ok());
  CHECK_THAT(d.message(), Catch::Contains("is a folder"));
}
