// Creature panel exports (creature_panel_model.h): glTF re-imported by Assimp, PNG drawn under
// SDL's offscreen GL context and decoded with stb_image, and failing paths that must name the
// file and leave existing files and the genome as they were.
#include <catch2/catch.hpp>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

// stb_image, static so that it cannot clash with ossa::render's own copy.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#pragma GCC diagnostic pop

#include "ossa/editor/creature_panel_model.h"
#include "ossa/gen/genome.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/platform/window.h"
#include "shared/scenes.h"
#include "shared/scratch_files.h"

namespace ossa {
namespace {

namespace fs = std::filesystem;

using test::fresh_dir;

// The panel draws with whatever GL context is current (the game's); tests make one with SDL's
// offscreen driver unless another test of this process already did.
void ensure_gl_context() {
  if (gl_context_is_current()) return;
  setenv("SDL_VIDEODRIVER", "offscreen", 1);
  static std::unique_ptr<Window> window;
  WindowDesc desc;
  desc.width = 64;
  desc.height = 64;
  desc.offscreen = true;
  auto w = Window::create(desc);
  INFO((w.ok() ? std::string() : w.message()));
  REQUIRE(w.ok());
  window = std::make_unique<Window>(std::move(w.value()));
  REQUIRE(gl_context_is_current());
}

struct Png {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
  const uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
};

Png decode_png(const std::string& path) {
  Png png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 4);
  INFO(path << ": " << (data ? "" : stbi_failure_reason()));
  REQUIRE(data != nullptr);
  png.rgba.assign(data, data + static_cast<size_t>(png.width) * png.height * 4);
  stbi_image_free(data);
  return png;
}

}  // namespace

TEST_CASE("creature panel: glTF export re-imports with the creature's bones", "[editor][export]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const fs::path dir = fresh_dir("ossa_editor_export_gltf");
  for (const char* name : {"horse", "pigeon"}) {
    INFO(name);
    REQUIRE(m.pick_example(name).ok());
    const std::string path = (dir / (std::string(name) + ".gltf")).string();
    const Status st = m.export_gltf(path);
    INFO((st.ok() ? std::string() : st.message()));
    REQUIRE(st.ok());
    CHECK(m.last_error().empty());
    CHECK(m.last_note() == "exported " + path);
    CHECK(fs::is_regular_file(dir / (std::string(name) + ".bin")));

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    INFO(importer.GetErrorString());
    REQUIRE(scene != nullptr);
    REQUIRE(scene->mNumMeshes >= 1);
    const Skeleton& s = m.creature()->skeleton;
    CHECK(scene->mMeshes[0]->mNumBones == static_cast<unsigned>(s.bone_count()));
    int nodes = 0;
    for (int i = 0; i < s.bone_count(); ++i) nodes += scene->mRootNode->FindNode(s.name(i).c_str()) != nullptr;
    CHECK(nodes == s.bone_count());
  }
}

// CTest runs every test case in a process of its own, so no GL context exists yet here; in a
// run of the whole executable this file's cases come first (link order), before any context.
TEST_CASE("creature panel: PNG export without a GL context reports it and writes nothing", "[editor][export]") {
  if (gl_context_is_current()) {
    WARN("a GL context already exists in this process; run this case on its own");
    return;
  }
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const fs::path dir = fresh_dir("ossa_editor_export_nogl");
  const std::string path = (dir / "horse.png").string();
  const Status st = m.export_png(path);
  REQUIRE_FALSE(st.ok());
  CHECK(st.message().find(path) != std::string::npos);
  CHECK(st.message().find("OpenGL context") != std::string::npos);
  CHECK(m.last_error() == st.message());
  CHECK_FALSE(fs::exists(path));
}

TEST_CASE("creature panel: PNG export draws the creature offscreen at the asked size", "[editor][export]") {
  ensure_gl_context();
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const fs::path dir = fresh_dir("ossa_editor_export_png");
  const std::string path = (dir / "horse.png").string();
  CreatureImageOptions o;
  o.width = 640;
  o.height = 400;
  const Status st = m.export_png(path, o);
  INFO((st.ok() ? std::string() : st.message()));
  REQUIRE(st.ok());
  CHECK(m.last_note() == "exported " + path);

  const Png png = decode_png(path);
  REQUIRE((png.width == 640 && png.height == 400));
  // Transparent background, creature pixels in the middle and fully in frame.
  int creature = 0, x0 = png.width, x1 = -1, y0 = png.height, y1 = -1;
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      if (png.pixel(x, y)[3] == 0) continue;
      ++creature;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  CHECK(png.pixel(0, 0)[3] == 0);
  CHECK(png.pixel(png.width - 1, png.height - 1)[3] == 0);
  CHECK(creature > png.width * png.height / 20);
  CHECK((x0 > 0 && y0 > 0 && x1 < png.width - 1 && y1 < png.height - 1));
  // The body look (the default): opaque pixels wear the horse's coat, a bay brown — red above
  // green above blue, not black (straight alpha, the coat found).
  int coat = 0;
  for (size_t i = 0; i < png.rgba.size(); i += 4) {
    const uint8_t* p = &png.rgba[i];
    coat += p[3] == 255 && p[0] > p[1] && p[1] > p[2] && p[0] > 60;
  }
  CHECK(coat > creature / 2);
  // The bones look: opaque sprite pixels are bone-coloured.
  CreatureImageOptions bones = o;
  bones.look = CreatureLook::kBones;
  REQUIRE(m.export_png(path, bones).ok());
  const Png sprites = decode_png(path);
  int bright = 0, drawn = 0;
  for (size_t i = 0; i < sprites.rgba.size(); i += 4) {
    drawn += sprites.rgba[i + 3] > 0;
    bright += sprites.rgba[i + 3] == 255 && sprites.rgba[i] + sprites.rgba[i + 1] + sprites.rgba[i + 2] > 300;
  }
  CHECK(bright > drawn / 4);

  // A plain background fills every pixel that is not creature.
  o.background = {0.0f, 0.0f, 1.0f, 1.0f};
  REQUIRE(m.export_png(path, o).ok());
  const Png plain = decode_png(path);
  const uint8_t* corner = plain.pixel(0, 0);
  CHECK((corner[0] == 0 && corner[1] == 0 && corner[2] == 255 && corner[3] == 255));
  int not_blue = 0;
  for (size_t i = 0; i < plain.rgba.size(); i += 4) not_blue += plain.rgba[i + 2] != 255 || plain.rgba[i] != 0;
  CHECK(not_blue > creature / 2);

  if (const char* shots = std::getenv("OSSA_EDITOR_SHOTS"); shots && *shots) {
    fs::create_directories(shots);
    o.background = glm::vec4(0.0f);
    o.width = 1024;
    o.height = 640;
    for (const char* name : {"horse", "giraffe", "pigeon", "kangaroo"}) {
      REQUIRE(m.pick_example(name).ok());
      REQUIRE(m.export_png(std::string(shots) + "/export-" + name + ".png", o).ok());
    }
  }
}

TEST_CASE("creature panel: a failing export names the file and leaves files and genome as they were",
          "[editor][export]") {
  ensure_gl_context();
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "kangaroo");
  m.variation(0.5);
  const std::string genome = genome_to_json(m.genome()).dump();
  const fs::path dir = fresh_dir("ossa_editor_export_fail");
  for (const char* ext : {"gltf", "svg", "png"}) {
    INFO(ext);
    const std::string name = std::string("creature.") + ext;
    const std::string existing = (dir / name).string();
    REQUIRE(write_file_atomic(existing, "previous contents").ok());
    REQUIRE(m.export_svg((dir / "ok.svg").string()).ok());  // a note to be replaced
    const std::string bad = (dir / "missing" / name).string();
    const Status st = ext == std::string("gltf") ? m.export_gltf(bad)
                      : ext == std::string("svg") ? m.export_svg(bad)
                                                  : m.export_png(bad);
    REQUIRE_FALSE(st.ok());
    CHECK(st.message().find("missing/creature.") != std::string::npos);
    CHECK(m.last_error() == st.message());
    CHECK(m.last_note().empty());
    CHECK_FALSE(fs::exists(dir / "missing"));
    CHECK(read_file(existing).value() == "previous contents");
    CHECK(genome_to_json(m.genome()).dump() == genome);
  }
  // A PNG that cannot be drawn (no pixels) does not replace the existing file either.
  CreatureImageOptions o;
  o.width = 0;
  const std::string existing = (dir / "creature.png").string();
  const Status st = m.export_png(existing, o);
  REQUIRE_FALSE(st.ok());
  CHECK(st.message().find(existing) != std::string::npos);
  CHECK(read_file(existing).value() == "previous contents");
  CHECK(genome_to_json(m.genome()).dump() == genome);
  // The next good export clears the error.
  REQUIRE(m.export_png(existing).ok());
  CHECK(m.last_error().empty());
  CHECK(read_file(existing).value() != "previous contents");
}

}  // namespace ossa
