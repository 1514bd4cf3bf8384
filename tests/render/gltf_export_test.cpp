// glTF export round trip: export with Assimp, re-import with Assimp (and with ossa's rigged
// mesh loader), and compare the node hierarchy and the skin with the skeleton and, for smooth
// skinning, the weights with the sprite mesh's (src/ossa/render/gltf_export.h).

#include <catch2/catch.hpp>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/file.h"
#include "ossa/render/gltf_export.h"
#include "ossa/render/rigged_mesh.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/skeleton/pose.h"
#include "shared/scenes.h"

namespace ossa {
namespace {

std::string temp_path(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ossa-gltf-test";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

// Metres tolerances scale with the creature (true size: a 3 cm frog to a 27 m whale); 0.05
// frame units was 1e-4 m in the 2 m frame the tests were written for, and is far above float
// rounding at every size (about 1e-7 of the creature).
float frame_tolerance(const Creature& c, float frame_units) { return frame_units * c.scale; }

// Re-imports `path` and checks it against the creature's skeleton.
void check_round_trip(const Creature& c, const std::string& path) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  INFO(path << ": " << importer.GetErrorString());
  REQUIRE(scene != nullptr);
  REQUIRE(scene->mRootNode != nullptr);
  const Skeleton& s = c.skeleton;

  // Every bone is a node whose parent node is its parent bone (the root bone hangs from the
  // scene's root node), with the rest-pose local transform.
  for (int i = 0; i < s.bone_count(); ++i) {
    INFO("bone " << s.name(i));
    const aiNode* node = scene->mRootNode->FindNode(s.name(i).c_str());
    REQUIRE(node != nullptr);
    REQUIRE(node->mParent != nullptr);
    if (s.parent(i) >= 0) {
      CHECK(std::string(node->mParent->mName.C_Str()) == s.name(s.parent(i)));
    } else {
      CHECK(node->mParent == scene->mRootNode);
    }
    const BoneLocal& l = c.rest_pose.locals[i];
    const aiMatrix4x4& t = node->mTransformation;
    CHECK(t.a4 == Approx(l.offset_ls.x).margin(frame_tolerance(c, 0.05f)));
    CHECK(t.b4 == Approx(l.offset_ls.y).margin(frame_tolerance(c, 0.05f)));
    CHECK(t.c4 == Approx(0.0).margin(1e-6));
    CHECK(t.a1 == Approx(std::cos(l.angle_ls)).margin(1e-4));
    CHECK(t.b1 == Approx(std::sin(l.angle_ls)).margin(1e-4));
  }

  // One skinned mesh with one bone per skeleton bone: rigid, four vertices per bone weighted
  // 1 to it; smooth, the sprite mesh, each vertex's weights (as stored, before any loader
  // normalises them) summing to 1, at most as many per vertex as the sprite mesh has.
  REQUIRE(scene->mNumMeshes >= 1);
  const aiMesh* mesh = scene->mMeshes[0];
  CHECK(mesh->HasTextureCoords(0));
  if (c.smooth_skinning) {
    const SpriteMesh sprites = build_sprite_mesh(c, default_sprite_set());
    CHECK(mesh->mNumVertices == sprites.vertices.size());
  } else {
    CHECK(mesh->mNumVertices == static_cast<unsigned>(4 * s.bone_count()));
  }
  std::vector<float> vertex_total(mesh->mNumVertices, 0.0f);
  std::vector<int> vertex_weights(mesh->mNumVertices, 0);
  for (unsigned b = 0; b < mesh->mNumBones; ++b) {
    for (unsigned w = 0; w < mesh->mBones[b]->mNumWeights; ++w) {
      const aiVertexWeight& vw = mesh->mBones[b]->mWeights[w];
      REQUIRE(vw.mVertexId < mesh->mNumVertices);
      vertex_total[vw.mVertexId] += vw.mWeight;
      vertex_weights[vw.mVertexId] += vw.mWeight > 0.0f;
    }
  }
  for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
    INFO("vertex " << v);
    CHECK(vertex_total[v] == Approx(1.0f).margin(1e-5));
  }
  const int most = *std::max_element(vertex_weights.begin(), vertex_weights.end());
  CHECK(most == (c.smooth_skinning ? max_weights_per_vertex(build_sprite_mesh(c, default_sprite_set())) : 1));
  CHECK(mesh->mNumBones == static_cast<unsigned>(s.bone_count()));  // a bone without weights too
  std::map<std::string, const aiBone*> bones;
  for (unsigned b = 0; b < mesh->mNumBones; ++b) bones[mesh->mBones[b]->mName.C_Str()] = mesh->mBones[b];
  const std::vector<Mat2x3> model = model_matrices(s, c.rest_pose.locals);
  for (int i = 0; i < s.bone_count(); ++i) {
    INFO("bone " << s.name(i));
    if (c.smooth_skinning && !(s.length(i) > 0.0f)) continue;  // no sprite, no weights
    REQUIRE(bones.count(s.name(i)) == 1);
    const aiBone* bone = bones[s.name(i)];
    CHECK(bone->mNumWeights >= 1);
    float total = 0.0f;
    for (unsigned w = 0; w < bone->mNumWeights; ++w) total += bone->mWeights[w].mWeight;
    if (!c.smooth_skinning) CHECK(total == Approx(4.0f).margin(1e-3));
    // Offset matrix = inverse bind: maps the bone's model-space start to the origin.
    const glm::vec2 start = bone_start(model[i]);
    const aiVector3D local = bone->mOffsetMatrix * aiVector3D(start.x, start.y, 0.0f);
    CHECK(local.x == Approx(0.0).margin(frame_tolerance(c, 0.5f)));  // 1 mm in the 2 m frame
    CHECK(local.y == Approx(0.0).margin(frame_tolerance(c, 0.5f)));
  }
}

}  // namespace

TEST_CASE("glTF export of a hand-built creature re-imports with its skeleton", "[gltf]") {
  for (bool winged : {false, true}) {
    for (bool smooth : {true, false}) {
      Creature c = scenes::hand_built_creature(winged);
      c.smooth_skinning = smooth;
      const std::string path = temp_path(c.name + (smooth ? "_smooth" : "_rigid") + ".gltf");
      const Status st = export_gltf(c, path);
      INFO((st.ok() ? std::string() : st.message()));
      REQUIRE(st.ok());
      check_round_trip(c, path);
    }
  }
}

TEST_CASE("glTF export keeps smooth skinning's weights through ossa's rigged-mesh loader", "[gltf]") {
  // Exported, then loaded as a designer's character would be (load_rigged_mesh): a smooth
  // creature's vertices blend as many bones as its sprite mesh's (2), summing to 1, and its
  // rest pose skins to the sprite mesh's rest pose as drawn; a rigid one's follow one bone.
  Result<Generator> gen = Generator::load(scenes::source_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  REQUIRE(gen.ok());
  for (const char* name : {"horse", "kangaroo", "pigeon", "frog", "tyrannosaurus"}) {
    for (bool smooth : {true, false}) {
      INFO(name << (smooth ? " smooth" : " rigid"));
      Result<Genome> genome = gen->example(name, 1);
      REQUIRE(genome.ok());
      genome->options.smooth_skinning = smooth;
      Result<Creature> c = build_creature(*genome);
      REQUIRE(c.ok());
      const std::string path = temp_path(std::string(name) + (smooth ? "_smooth" : "_rigid") + "_loaded.gltf");
      REQUIRE(export_gltf(*c, path).ok());
      Result<RiggedMesh> loaded = load_rigged_mesh(path);
      INFO((loaded.ok() ? std::string() : loaded.message()));
      REQUIRE(loaded.ok());
      const SpriteMesh sprites = build_sprite_mesh(*c, default_sprite_set());
      int most = 0, blended = 0;
      for (const RiggedVertex& v : loaded->vertices) {
        int count = 0;
        float total = 0.0f;
        for (float w : v.weights) count += w > 0.0f, total += w;
        most = std::max(most, count);
        blended += count > 1;
        CHECK(total == Approx(1.0f).margin(1e-5));
      }
      CHECK(most == max_weights_per_vertex(sprites));
      CHECK(most == (smooth ? 2 : 1));
      CHECK((smooth ? blended > 0 : blended == 0));
      if (!smooth) {
        // A rigid bone without a length (the root) is a small square in the creature's own
        // size: 1 % of its frame across, not a fixed centimetre (a ninth of the frog's frame).
        const std::vector<Mat2x3> model = model_matrices(c->skeleton, c->rest_pose.locals);
        for (const RiggedVertex& v : loaded->vertices) {
          const int bone = c->skeleton.find(loaded->bones[v.bones[0]].name);
          REQUIRE(bone >= 0);
          if (c->skeleton.length(bone) > 0.0f) continue;
          const glm::vec2 start = bone_start(model[static_cast<size_t>(bone)]);
          CHECK(glm::length(v.position - start) <= frame_tolerance(*c, 10.0f * std::sqrt(2.0f) + 0.05f));
        }
        continue;
      }
      // The rest pose: every loaded vertex skinned by the rest palette lies on the sprite mesh
      // as drawn at rest (the same set of points).
      const std::vector<Mat2x3> palette = rigged_palette(*loaded, rest_locals(*loaded));
      for (size_t i = 0; i < loaded->vertices.size(); i += 7) {
        const glm::vec2 p = skin_position(loaded->vertices[i], palette);
        float nearest = 1e30f;
        for (const glm::vec2 q : sprites.rest_positions) nearest = std::min(nearest, glm::length(p - q));
        CHECK(nearest < frame_tolerance(*c, 0.05f));
      }
    }
  }
}

TEST_CASE("glTF export references the atlas only when it exists", "[gltf]") {
  const Creature c = scenes::hand_built_creature();
  const std::string atlas = temp_path("atlas.png");
  {
    std::FILE* f = std::fopen(atlas.c_str(), "wb");
    REQUIRE(f != nullptr);
    std::fputs("not really a png", f);
    std::fclose(f);
  }
  GltfOptions with;
  with.atlas_path = atlas;
  REQUIRE(export_gltf(c, temp_path("with_atlas.gltf"), with).ok());
  GltfOptions without;
  without.atlas_path = temp_path("missing-atlas.png");
  REQUIRE(export_gltf(c, temp_path("without_atlas.gltf"), without).ok());
  auto text = [](const std::string& p) {
    std::FILE* f = std::fopen(p.c_str(), "rb");
    std::string s;
    char buf[4096];
    size_t n;
    while (f && (n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
    if (f) std::fclose(f);
    return s;
  };
  CHECK(text(temp_path("with_atlas.gltf")).find("atlas.png") != std::string::npos);
  CHECK(text(temp_path("without_atlas.gltf")).find("atlas.png") == std::string::npos);
}

TEST_CASE("glTF export fails cleanly on an unwritable path", "[gltf]") {
  const Creature c = scenes::hand_built_creature();
  const Status st = export_gltf(c, "/nonexistent-dir/x/y.gltf");
  REQUIRE_FALSE(st.ok());
  CHECK(st.message().find("/nonexistent-dir/x/y") != std::string::npos);
}

TEST_CASE("glTF export writes its buffer next to it and replaces files atomically", "[gltf]") {
  const Creature c = scenes::hand_built_creature();
  const std::string path = temp_path("atomic.gltf");
  const std::string bin = temp_path("atomic.bin");
  std::filesystem::remove(path);
  std::filesystem::remove(bin);
  REQUIRE(export_gltf(c, path).ok());
  REQUIRE(std::filesystem::is_regular_file(bin));
  CHECK(read_file(path).value().find("\"atomic.bin\"") != std::string::npos);
  // A second export over the same files leaves no temporary files behind.
  REQUIRE(export_gltf(c, path).ok());
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path())) {
    files += e.path().filename().string().rfind("atomic", 0) == 0 ? 1 : 0;
  }
  CHECK(files == 2);
}

TEST_CASE("glTF export of generated examples re-imports with their skeletons", "[gltf]") {
  Result<Generator> gen = Generator::load(scenes::source_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  REQUIRE(gen.ok());
  for (const char* name : {"horse", "giraffe", "kangaroo", "pigeon", "frog", "blue whale"}) {
    Result<Genome> genome = gen->example(name, 1);
    if (!genome.ok()) continue;  // not every name need exist in the dataset
    Result<Creature> c = build_creature(*genome);
    REQUIRE(c.ok());
    const std::string path = temp_path(std::string(name) + ".gltf");
    REQUIRE(export_gltf(*c, path).ok());
    check_round_trip(*c, path);
  }
}

}  // namespace ossa

namespace ossa {

TEST_CASE("glTF export of a body: skinned, coloured, posable, its rest pose the body's", "[gltf][body]") {
  // --look body: one mesh, the body (vertex colours, weights summing to 1 over real bones);
  // loaded as a designer's character would be, its rest pose lies on the body as built.
  // --look xray: the sprites and the body; bones: the sprites alone (as before bodies).
  Result<Generator> gen = Generator::load(scenes::source_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  REQUIRE(gen.ok());
  for (const char* name : {"horse", "pigeon", "crocodile", "frog", "blue whale"}) {
    INFO(name);
    Result<Genome> genome = gen->example(name, 1);
    REQUIRE(genome.ok());
    Result<Creature> c = build_creature(*genome);
    REQUIRE(c.ok());
    const BodyMesh body = build_body(*c);
    for (CreatureLook look : {CreatureLook::kBody, CreatureLook::kXray, CreatureLook::kBones}) {
      INFO(creature_look_name(look));
      GltfOptions o;
      o.look = look;
      const std::string path = temp_path(std::string(name) + "_" + creature_look_name(look) + ".gltf");
      REQUIRE(export_gltf(*c, path, o).ok());
      Assimp::Importer importer;
      const aiScene* scene = importer.ReadFile(path, 0);
      REQUIRE(scene != nullptr);
      CHECK(scene->mNumMeshes == (look == CreatureLook::kXray ? 2u : 1u));
      const aiMesh* mesh = nullptr;
      // The body is the mesh with vertex colours (the sprites have a texture instead).
      for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        if (scene->mMeshes[m]->HasVertexColors(0)) mesh = scene->mMeshes[m];
      }
      if (look == CreatureLook::kBones) {
        CHECK(mesh == nullptr);
        continue;
      }
      REQUIRE(mesh != nullptr);
      // Assimp's exporter joins identical vertices; every body vertex is there.
      CHECK(mesh->mNumVertices <= body.vertices.size());
      CHECK(mesh->mNumVertices >= body.vertices.size() * 9 / 10);
      CHECK(mesh->mNumFaces == static_cast<unsigned>(body.triangle_count()));
      // The coat: more than one colour, the outline darker than the body.
      float lo = 1e9f, hi = -1e9f;
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const aiColor4D& col = mesh->mColors[0][v];
        lo = std::min(lo, col.r + col.g + col.b);
        hi = std::max(hi, col.r + col.g + col.b);
      }
      CHECK(hi - lo > 0.3f);
      std::vector<float> total(mesh->mNumVertices, 0.0f);
      for (unsigned b = 0; b < mesh->mNumBones; ++b) {
        for (unsigned w = 0; w < mesh->mBones[b]->mNumWeights; ++w) total[mesh->mBones[b]->mWeights[w].mVertexId] += mesh->mBones[b]->mWeights[w].mWeight;
      }
      for (float t : total) CHECK(t == Approx(1.0f).margin(1e-5));
      if (look != CreatureLook::kBody) continue;
      Result<RiggedMesh> loaded = load_rigged_mesh(path);
      INFO((loaded.ok() ? std::string() : loaded.message()));
      REQUIRE(loaded.ok());
      const std::vector<Mat2x3> palette = rigged_palette(*loaded, rest_locals(*loaded));
      for (size_t i = 0; i < loaded->vertices.size(); i += 5) {
        const glm::vec2 p = skin_position(loaded->vertices[i], palette);
        float nearest = 1e30f;
        for (const BodyVertex& q : body.vertices) nearest = std::min(nearest, glm::length(p - q.position_ms));
        CHECK(nearest < frame_tolerance(*c, 0.05f));
      }
    }
  }
}

}  // namespace ossa
