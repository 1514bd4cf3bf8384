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

TEST_CASE("a key twice in one object is an error naming its path", "[io]") {
  // nlohmann::json alone keeps the last value: a second "colliders": [] would empty a level.
  Result<Json> top = parse_json(R"({"colliders": [{"x": 1}], "colliders": []})", "levels/x.json");
  REQUIRE_FALSE(top.ok());
  CHECK(top.message() == "levels/x.json: colliders: duplicate key (a key may appear only once in an object)");
  Result<Json> nested = parse_json(R"({"a": [{"x": 1}, {"y": 2, "y": 3}]})", "f.json");
  REQUIRE_FALSE(nested.ok());
  CHECK_THAT(nested.message(), Catch::StartsWith("f.json: a[1].y: duplicate key"));
  // The same key in different objects, and many keys in one object, are fine.
  CHECK(parse_json(R"({"a": {"x": 1}, "b": {"x": 2}, "x": [{"x": 3}, {"x": 4}]})", "f.json").ok());
  std::string many = "{";
  for (int i = 0; i < 200; ++i) many += (i ? ",\"k" : "\"k") + std::to_string(i) + "\": " + std::to_string(i);
  CHECK(parse_json(many + "}", "f.json").ok());
  CHECK_FALSE(parse_json(many + ", \"k150\": 0}", "f.json").ok());
}

TEST_CASE("read_file reads regular files only, up to a size limit", "[io]") {
  const auto dir = std::filesystem::temp_directory_path() / "ossa_read_file_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "five.txt").string();
  REQUIRE(write_file_atomic(path, "12345").ok());
  CHECK(read_file(path).value() == "12345");
  CHECK(read_file(path, 5).ok());
  Result<std::string> big = read_file(path, 4);
  REQUIRE_FALSE(big.ok());
  CHECK_THAT(big.message(), Catch::Contains("five.txt: is 5 bytes, expected at most 4 bytes"));
  // A device never ends: refused before a byte is read (this used to grow to gigabytes).
  Result<std::string> zero = read_file("/dev/zero");
  REQUIRE_FALSE(zero.ok());
  CHECK(zero.message() == "/dev/zero: is not a regular file (a device, pipe or socket), expected a file");
  CHECK_THAT(read_file(dir.string()).message(), Catch::Contains("is a folder"));
  CHECK_THAT(read_file((dir / "nope").string()).message(), Catch::Contains("nope: no such file"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("written files start with \"format\" and \"version\"", "[io]") {
  const Json doc = {{"contact", "tip"}, {"version", 1}, {"format", "ossa.creature"}, {"alpha", 2}};
  const std::string text = json_file_text(doc);
  CHECK_THAT(text, Catch::StartsWith("{\n  \"format\": \"ossa.creature\",\n  \"version\": 1,\n"));
  CHECK(parse_json(text, "t.json").value() == doc);
  // Documents without a header keep their plain sorted form.
  CHECK(json_file_text(Json{{"b", 1}, {"a", 2}}) == "{\n  \"a\": 2,\n  \"b\": 1\n}\n");
}
