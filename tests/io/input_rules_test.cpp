// The one rule every input and output follows (io/file.h, io/json.h, io/image_info.h):
// regular files only, nesting and memory bounded before anything recursive or large happens,
// linear parsing, file names as bytes, outputs that never destroy inputs (issue 33).
#include "ossa/io/file.h"
#include "ossa/io/image_info.h"
#include "ossa/io/json.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>

#include "shared/scratch_files.h"

using namespace ossa;
using namespace ossa::test;
namespace fs = std::filesystem;

namespace {

}  // namespace

TEST_CASE("JSON nested deeper than kMaxJsonDepth is refused while parsing, with its path", "[io]") {
  // 300 000 deep used to overflow the stack when a loader copied or printed the value.
  const std::string deep = "{\"a\": " + std::string(300000, '[') + std::string(300000, ']') + "}";
  Result<Json> r = parse_json(deep, "deep.json");
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::StartsWith("deep.json: a"));
  CHECK_THAT(r.message(), Catch::Contains("nested more than 256 arrays or objects deep"));
  // Objects too, and the path names where it happened.
  std::string objects;
  for (int i = 0; i < 300; ++i) objects += "{\"k\":";
  Result<Json> o = parse_json(objects + "1" + std::string(300, '}'), "o.json");
  REQUIRE_FALSE(o.ok());
  CHECK_THAT(o.message(), Catch::StartsWith("o.json: k.k.k."));
  // 30 MB of '[' stops at the limit (it used to take 3 GB).
  const std::string brackets(30u << 20, '[');
  CHECK_THAT(parse_json(brackets, "b.json").message(), Catch::Contains("nested more than 256"));
  // At the limit it parses, and copies and prints.
  const std::string ok = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  Result<Json> at = parse_json(ok, "ok.json");
  REQUIRE(at.ok());
  const Json copy = *at;
  CHECK(json_text(copy) == ok);
}

TEST_CASE("a JSON document's memory stays within kJsonBytesPerInputByte of its text", "[io]") {
  // An array of empty objects is the costliest text per byte (a map per 3 bytes).
  std::string objects = "[";
  for (int i = 0; i < 200000; ++i) objects += i ? ",{}" : "{}";
  objects += "]";
  Result<Json> r = parse_json(objects, "objects.json");
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::Contains("objects.json: the document would take more than"));
  CHECK_THAT(r.message(), Catch::Contains("24 times the text's size"));
  // A level's colliders written without a space (the densest real file) are fine.
  std::string level = "{\"colliders\":[";
  for (int i = 0; i < 200000; ++i) level += std::string(i ? "," : "") + "{\"x\":0,\"y\":0,\"w\":1,\"h\":1}";
  level += "]}";
  Result<Json> l = parse_json(level, "level.json");
  REQUIRE(l.ok());
  CHECK(l->at("colliders").size() == 200000);
}

TEST_CASE("duplicate keys are still refused in long arrays of objects", "[io]") {
  std::string text = "[";
  for (int i = 0; i < 100000; ++i) text += std::string(i ? "," : "") + "{\"x\":" + std::to_string(i) + ",\"y\":1}";
  REQUIRE(parse_json(text + "]", "a.json").ok());
  Result<Json> dup = parse_json(text + ",{\"x\":1,\"x\":2}]", "a.json");
  REQUIRE_FALSE(dup.ok());
  CHECK(dup.message() == "a.json: [100000].x: duplicate key (a key may appear only once in an object)");
}

TEST_CASE("UTF-16 text is named as such, not reported as broken JSON", "[io]") {
  const std::string utf16le("\xFF\xFE{\0}\0", 6);
  CHECK(non_utf8_encoding(utf16le) == "UTF-16 (little-endian)");
  CHECK(non_utf8_encoding(std::string("<\0?\0x\0m\0", 8)) == "UTF-16 (little-endian)");
  CHECK(non_utf8_encoding(std::string("\0<\0?\0x", 6)) == "UTF-16 (big-endian)");
  CHECK_FALSE(non_utf8_encoding("{\"a\": 1}").has_value());
  CHECK_FALSE(non_utf8_encoding("\xEF\xBB\xBF{}").has_value());
  CHECK(parse_json(utf16le, "m.json").message() ==
        "m.json: is UTF-16 (little-endian) text; JSON must be UTF-8 (save the file as UTF-8)");
  CHECK(parse_json("\xEF\xBB\xBF{\"a\": 1}", "bom.json").ok());
}

TEST_CASE("JSON output never throws on file names that are not UTF-8", "[io]") {
  // A file name is bytes: \xff is a valid name on Linux, and nlohmann's dump() threw on it.
  const Json doc = {{"format", "ossa.x"}, {"version", 1}, {"file", std::string("lev\xff" "el.json")}};
  CHECK(json_text(doc) == "{\"file\":\"lev\xEF\xBF\xBD" "el.json\",\"format\":\"ossa.x\",\"version\":1}");
  CHECK_THAT(json_file_text(doc), Catch::Contains("lev\xEF\xBF\xBD" "el.json"));
  const fs::path dir = fresh_dir("ossa_bytes_test");
  const std::string name = (dir / "\xff\xfe.json").string();
  REQUIRE(write_json_atomic(name, doc).ok());
  Result<Json> back = read_json_file(name);
  REQUIRE(back.ok());
  CHECK(back->at("file") == "lev\xEF\xBF\xBD" "el.json");
  fs::remove_all(dir);
}

TEST_CASE("number_f accepts the float ends of its range", "[io]") {
  // The tuning loader refused its own documented range end: 1.05 > double(1.05f).
  const Json doc = Json::parse(R"({"a": 1.05, "b": 0.7, "c": 1.0500001, "d": 1e300})");
  JsonReader r("t.json");
  CHECK(r.number_f(doc, "", "a", 0.7f, 1.05f) == 1.05f);
  CHECK(r.number_f(doc, "", "b", 0.7f, 1.05f) == 0.7f);
  CHECK_FALSE(r.failed());
  r.number_f(doc, "", "c", 0.7f, 1.05f);
  CHECK(r.error().message == "t.json: c: expected a number in [0.7, 1.05], got 1.0500001");
  JsonReader q("t.json");
  q.number_f(doc, "", "d");
  CHECK(q.failed());  // beyond a float
}

TEST_CASE("read_file refuses a pipe at once instead of waiting for a writer", "[io]") {
  const fs::path dir = fresh_dir("ossa_fifo_test");
  const std::string fifo = (dir / "level.json").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  const auto start = std::chrono::steady_clock::now();
  Result<std::string> r = read_file(fifo);
  REQUIRE_FALSE(r.ok());
  CHECK(r.message() == fifo + ": is not a regular file (a device, pipe or socket), expected a file");
  CHECK(read_json_file(fifo).message() == r.message());
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
  fs::remove_all(dir);
}

TEST_CASE("saves write through symbolic links and refuse read-only files", "[io]") {
  const fs::path dir = fresh_dir("ossa_save_rules_test");
  const std::string target = (dir / "real.json").string(), link = (dir / "link.json").string();
  REQUIRE(write_file_atomic(target, "old").ok());
  fs::create_symlink("real.json", link);
  REQUIRE(write_file_atomic(link, "new").ok());
  CHECK(fs::is_symlink(link));                 // the link stays a link
  CHECK(read_file(target).value() == "new");   // and its target has the new contents
  // A link to a file that does not exist yet creates the target.
  fs::create_symlink("later.json", dir / "dangling.json");
  REQUIRE(write_file_atomic((dir / "dangling.json").string(), "x").ok());
  CHECK(fs::is_symlink(dir / "dangling.json"));
  CHECK(read_file((dir / "later.json").string()).value() == "x");

  // Read-only: refused (even for root, who could rename over it), the file untouched.
  REQUIRE(::chmod(target.c_str(), 0444) == 0);
  Status s = write_file_atomic(target, "newer");
  REQUIRE_FALSE(s.ok());
  CHECK(s.message() == target + ": is read-only (mode 0444); not overwritten (make it writable or save elsewhere)");
  CHECK(read_file(target).value() == "new");
  CHECK_FALSE(write_file_atomic(link, "newer").ok());
  ::chmod(target.c_str(), 0644);
  CHECK(write_file_atomic("", "x").message() == "expected a file name to write, got an empty string");
  fs::remove_all(dir);
}

TEST_CASE("an output that is one of the inputs is refused, whatever it is called", "[io]") {
  const fs::path dir = fresh_dir("ossa_output_rules_test");
  const std::string in = (dir / "m.gltf").string();
  REQUIRE(write_file_atomic(in, "mesh").ok());
  fs::create_symlink("m.gltf", dir / "alias.gltf");
  fs::create_hard_link(in, dir / "hard.gltf");
  CHECK(check_output_path("--out", (dir / "out.json").string(), {in}).ok());
  Status same = check_output_path("--out", in, {in});
  REQUIRE_FALSE(same.ok());
  CHECK(same.message() == "--out: \"" + in + "\" is the input " + in + ": refusing to write over it; give another output file");
  CHECK_THAT(check_output_path("--out", (dir / "alias.gltf").string(), {in}).message(), Catch::Contains("names the same file"));
  CHECK_FALSE(check_output_path("--out", (dir / "hard.gltf").string(), {in}).ok());
  CHECK_FALSE(check_output_path("OUT", (dir / "." / "m.gltf").string(), {"x", in}).ok());
  CHECK(check_output_path("OUT", "", {in}).message() == "OUT: expected a file name to write, got an empty string");
  fs::remove_all(dir);
}

TEST_CASE("images are sized from their header and refused before decoding", "[io]") {
  Result<ImageInfo> small = check_image(png_header(64, 32), "a.png");
  REQUIRE(small.ok());
  CHECK(small->format == "PNG");
  CHECK(small->width == 64);
  CHECK(small->height == 32);
  // 16384² at 1 bit per pixel is a 55 KB file and 1 GiB as RGBA: refused.
  Result<ImageInfo> huge = check_image(png_header(16384, 16384), "t.png");
  REQUIRE_FALSE(huge.ok());
  CHECK(huge.message() == "t.png: is 16384 × 16384 pixels (PNG); images may be at most 16384 pixels on a side and "
                          "16777216 pixels in all");
  CHECK_FALSE(check_image(png_header(1, 1000000), "strip.png").ok());  // a side too long
  CHECK(check_image(png_header(1, 16384), "strip.png").ok());
  CHECK_THAT(check_image(png_header(0, 5), "z.png").message(), Catch::Contains("expected at least 1 × 1"));
  // JPEG: the frame header after other segments; BMP: both header kinds.
  const std::string jpeg("\xFF\xD8\xFF\xE0\x00\x04\x00\x00\xFF\xC0\x00\x11\x08\x01\x00\x02\x00\x03", 18);
  Result<ImageInfo> j = read_image_info(jpeg, "p.jpg");
  REQUIRE(j.ok());
  CHECK((j->width == 512 && j->height == 256));
  std::string bmp(26, '\0');
  bmp[0] = 'B';
  bmp[1] = 'M';
  bmp[14] = 40;
  bmp[18] = 10;
  bmp[22] = static_cast<char>(-20);
  for (int k = 23; k < 26; ++k) bmp[static_cast<size_t>(k)] = static_cast<char>(0xFF);
  Result<ImageInfo> b = read_image_info(bmp, "b.bmp");
  REQUIRE(b.ok());
  CHECK((b->width == 10 && b->height == 20));  // a top-down bitmap's negative height
  CHECK(read_image_info("GIF89a....", "g.gif").message() == "g.gif: is not a PNG, JPEG or BMP image (images must be one of these)");
  CHECK_THAT(read_image_info("", "e.png").message(), Catch::Contains("is empty"));
}
