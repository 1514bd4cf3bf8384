// The render side of issue 33: images sized before decoding and read as regular files only,
// background strips drawn in one call wherever the camera is, and skinned meshes checked for
// nesting, node depth, pipes and sizes before Assimp sees them.

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>

#include "gl_fixture.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/platform/image.h"
#include "ossa/render/background.h"
#include "ossa/render/capture.h"
#include "ossa/render/rigged_mesh.h"

#include "shared/scratch_files.h"

using namespace ossa;
using namespace ossa::test;
namespace fs = std::filesystem;

namespace {

std::string tiny_gltf() { return read_file(scenes::source_path("tests/fuzz/seeds/mesh/tiny_skin.gltf")).value(); }

Result<RiggedMesh> from_text(const std::string& text) {
  return load_rigged_mesh_from_memory(std::vector<uint8_t>(text.begin(), text.end()), "gltf", "m.gltf");
}

template <class F>
double seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST_CASE("images are refused before decoding: pipes, huge sizes, unknown formats", "[render]") {
  const fs::path dir = fresh_dir("ossa_image_limits_test");
  const std::string fifo = (dir / "bg.png").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  // SDL_image opened the pipe and waited for a writer forever.
  Result<Image> pipe = Error{"not run"};
  CHECK(seconds([&] { pipe = load_image(fifo); }) < 5.0);
  REQUIRE_FALSE(pipe.ok());
  CHECK(pipe.message() == fifo + ": is not a regular file (a device, pipe or socket), expected a file");
  // A 55 KB PNG declaring 16384² took 5.3 GB; 20000² aborted with bad_alloc.
  for (const auto& [w, h] : {std::pair{16384u, 16384u}, std::pair{20000u, 20000u}, std::pair{1u, 1000000u}}) {
    const std::string path = (dir / "big.png").string();
    REQUIRE(write_file_atomic(path, png_header(w, h) + std::string(55000, '\0')).ok());
    Result<Image> big = load_image(path);
    REQUIRE_FALSE(big.ok());
    CHECK_THAT(big.message(), Catch::Contains(std::to_string(w) + " × " + std::to_string(h) + " pixels (PNG); images may be at most"));
  }
  REQUIRE(write_file_atomic((dir / "x.gif").string(), "GIF89a\x01\x00\x01\x00").ok());
  CHECK_THAT(load_image((dir / "x.gif").string()).message(), Catch::Contains("is not a PNG, JPEG or BMP image"));
  // The shipped images still load.
  CHECK(load_image(scenes::source_path("tests/level/data/terrain.png")).ok());
  fs::remove_all(dir);
}

TEST_CASE("a background strip is one draw wherever the camera is", "[render]") {
  Gl& g = gl();
  // A 1 × 512 strip: about 900 tiles across the view, 900 draws before.
  Image strip;
  strip.width = 1;
  strip.height = 512;
  strip.rgba.assign(512 * 4, 200);
  const Texture t = Texture::from_image(strip, true, Texture::Wrap::kRepeat);
  for (const float x : {0.0f, 990.0f, -1000.0f}) {
    g.renderer->camera.center_ws = {x, 0.0f};
    g.renderer->camera.half_height = 5.0f;
    g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
    // A 1 × 16384 strip at x = 990 looped forever: its tile count passed 2^24 in a float.
    Image tall = strip;
    tall.height = 16384;
    tall.rgba.assign(16384 * 4, 90);
    const Texture tt = Texture::from_image(tall, true, Texture::Wrap::kRepeat);
    CHECK(seconds([&] {
            draw_background_image(*g.renderer, t, 0.5f);
            draw_background_image(*g.renderer, tt, 0.0f);
          }) < 5.0);
    CHECK(g.renderer->stats.draw_calls == 2);
  }
  // The strip's colour covers the view (cleared to black first), edge to edge.
  g.renderer->camera.center_ws = {3.0f, 0.0f};
  g.renderer->begin_frame(kW, kH, {0.0f, 0.0f, 0.0f});
  draw_background_image(*g.renderer, t, 0.5f);
  const Image frame = read_framebuffer(kW, kH);
  const int centre = frame.pixel(kW / 2, kH / 2)[0];
  CHECK(centre > 100);
  CHECK(frame.pixel(0, 0)[0] == centre);
  CHECK(frame.pixel(kW - 1, kH - 1)[0] == centre);
  CHECK(frame.pixel(1, kH - 2)[0] == centre);
}

TEST_CASE("glTF nesting and node depth are checked before Assimp reads the file", "[render]") {
  const std::string tiny = tiny_gltf();
  REQUIRE(from_text(tiny).ok());
  // "extras" 200 000 deep crashed Assimp's recursive JSON reader.
  const std::string deep = tiny.substr(0, tiny.rfind('}')) + ", \"extras\": " + std::string(200000, '[') + std::string(200000, ']') + "}";
  Result<RiggedMesh> extras = from_text(deep);
  REQUIRE_FALSE(extras.ok());
  CHECK_THAT(extras.message(), Catch::StartsWith("m.gltf: extras"));
  CHECK_THAT(extras.message(), Catch::Contains("nested more than 256"));
  // A node chain 20 000 deep crashed Assimp's recursive node import.
  Json doc = Json::parse(tiny);
  const size_t first = doc["nodes"].size();
  for (size_t i = 0; i < 20000; ++i) {
    Json node = Json::object();
    node["name"] = std::to_string(i);
    if (i + 1 < 20000) node["children"] = {first + i + 1};
    doc["nodes"].push_back(node);
  }
  doc["scenes"][0]["nodes"].push_back(first);
  Result<RiggedMesh> chain = from_text(doc.dump());
  REQUIRE_FALSE(chain.ok());
  CHECK(chain.message() == "m.gltf: nodes: the node hierarchy is more than 1024 nodes deep (at node 1028); a skeleton "
                           "needs far fewer");
  // A chain at the limit loads.
  Json ok = Json::parse(tiny);
  for (size_t i = 0; i < 1023; ++i) {
    Json node = Json::object();
    node["name"] = std::to_string(i);
    if (i + 1 < 1023) node["children"] = {first + i + 1};
    ok["nodes"].push_back(node);
  }
  ok["scenes"][0]["nodes"].push_back(first);
  Result<RiggedMesh> at_limit = from_text(ok.dump());
  INFO((at_limit.ok() ? std::string() : at_limit.message()));
  CHECK(at_limit.ok());
  // A cycle is refused too.
  Json cycle = Json::parse(tiny);
  cycle["nodes"][2]["children"] = {0};
  CHECK_THAT(from_text(cycle.dump()).message(), Catch::Contains("nodes[2].children: node 0 is its own ancestor"));
}

TEST_CASE("files a glTF refers to follow the input rule: no pipes, no giant buffers", "[render]") {
  const fs::path dir = fresh_dir("ossa_gltf_inputs_test");
  Json doc = Json::parse(tiny_gltf());
  doc["buffers"][0]["uri"] = "buffer.bin";
  const std::string mesh = (dir / "m.gltf").string();
  REQUIRE(write_file_atomic(mesh, doc.dump()).ok());
  // A pipe as the buffer: Assimp opened it and waited for ever.
  REQUIRE(::mkfifo((dir / "buffer.bin").c_str(), 0644) == 0);
  Result<RiggedMesh> pipe = Error{"not run"};
  CHECK(seconds([&] { pipe = load_rigged_mesh(mesh); }) < 10.0);
  REQUIRE_FALSE(pipe.ok());
  CHECK(pipe.message() == mesh + ": a file it refers to: " + (dir / "buffer.bin").string() +
                              ": is not a regular file (a device, pipe or socket), expected a file");
  // A 3 GB buffer (sparse here) was read whole.
  fs::remove(dir / "buffer.bin");
  {
    const int fd = ::open((dir / "buffer.bin").c_str(), O_CREAT | O_WRONLY, 0644);
    REQUIRE(fd >= 0);
    REQUIRE(::ftruncate(fd, 3LL << 30) == 0);
    ::close(fd);
  }
  Result<RiggedMesh> big = load_rigged_mesh(mesh);
  REQUIRE_FALSE(big.ok());
  CHECK_THAT(big.message(), Catch::Contains("buffer.bin: is 3221225472 bytes, expected at most 67108864 bytes"));
  fs::remove_all(dir);
}

TEST_CASE("a rigged mesh's texture is sized before it is decoded", "[render]") {
  const fs::path dir = fresh_dir("ossa_gltf_texture_test");
  Json doc = Json::parse(tiny_gltf());
  doc["images"] = {{{"uri", "skin.png"}}};
  doc["textures"] = {{{"source", 0}}};
  doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  doc["meshes"][0]["primitives"][0]["material"] = 0;
  const std::string mesh = (dir / "m.gltf").string();
  REQUIRE(write_file_atomic(mesh, doc.dump()).ok());
  REQUIRE(write_file_atomic((dir / "skin.png").string(), png_header(16384, 16384) + std::string(55000, '\0')).ok());
  Result<RiggedMesh> m = load_rigged_mesh(mesh);
  REQUIRE(m.ok());
  Status s = load_rigged_texture(*m);
  REQUIRE_FALSE(s.ok());
  CHECK(s.message() == (dir / "skin.png").string() + ": is 16384 × 16384 pixels (PNG); images may be at most 16384 pixels "
                                                      "on a side and 16777216 pixels in all");
  CHECK(m->texture_rgba.empty());
  fs::remove_all(dir);
}
