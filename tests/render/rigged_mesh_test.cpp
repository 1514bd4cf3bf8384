// Rigged sprite meshes through Assimp: the shipped character, skinning, the rig mapping, the
// tool's round trip, FBX/DAE round trips and malformed files (errors, never crashes).

#include "ossa/rig/rig_mapping.h"
#include "ossa/render/character_mesh.h"
#include "ossa/render/rigged_mesh.h"

#include "shared/scenes.h"

#include <catch2/catch.hpp>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <unistd.h>
#include <random>
#include <string>

#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "shared/scenes.h"

using namespace ossa;
namespace fs = std::filesystem;

namespace {

const char* const kBones[] = {"pelvis", "spine", "chest", "neck", "head",
                              "upper_arm_l", "lower_arm_l", "hand_l", "thigh_l", "shin_l", "foot_l",
                              "upper_arm_r", "lower_arm_r", "hand_r", "thigh_r", "shin_r", "foot_r"};

std::string character() { return scenes::source_path("assets/characters/humanoid.gltf"); }

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("ossa_rigged_" + name + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

void check_invariants(const RiggedMesh& m) {
  for (size_t i = 0; i < m.bones.size(); ++i) REQUIRE(m.bones[i].parent < static_cast<int>(i));
  for (const RiggedVertex& v : m.vertices) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      REQUIRE(v.weights[k] >= 0.0f);
      REQUIRE(v.bones[k] < m.bones.size());
      sum += v.weights[k];
    }
    REQUIRE(sum == Approx(1.0f).margin(1e-5));
  }
  REQUIRE(m.indices.size() % 3 == 0);
  for (uint32_t i : m.indices) REQUIRE(i < m.vertices.size());
}

// Bone name → parent name, for comparing hierarchies across files.
std::map<std::string, std::string> hierarchy(const RiggedMesh& m) {
  std::map<std::string, std::string> h;
  for (const RiggedBone& b : m.bones) h[b.name] = b.parent < 0 ? "" : m.bones[static_cast<size_t>(b.parent)].name;
  return h;
}

void require_error(const Result<RiggedMesh>& r, const std::string& name) {
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::Contains(name));
}

}  // namespace

TEST_CASE("the shipped character imports with its rig, weights, UVs and texture", "[render]") {
  Result<RiggedMesh> r = load_rigged_mesh(character());
  INFO((r.ok() ? std::string() : r.message()));
  REQUIRE(r.ok());
  const RiggedMesh& m = *r;
  REQUIRE(m.bones.size() == std::size(kBones));
  for (const char* name : kBones) CHECK(m.find_bone(name) >= 0);
  CHECK(m.bones[0].name == "pelvis");
  CHECK(m.bones[0].parent == -1);
  CHECK(m.bones[static_cast<size_t>(m.find_bone("shin_l"))].parent == m.find_bone("thigh_l"));
  CHECK(m.bones[static_cast<size_t>(m.find_bone("hand_r"))].parent == m.find_bone("lower_arm_r"));
  check_invariants(m);
  for (const RiggedVertex& v : m.vertices) {
    REQUIRE(v.uv.x >= 0.0f);
    REQUIRE(v.uv.x <= 1.0f);
    REQUIRE(v.uv.y >= 0.0f);
    REQUIRE(v.uv.y <= 1.0f);
  }
  // Knees blend thigh and shin.
  const int thigh = m.find_bone("thigh_l"), shin = m.find_bone("shin_l");
  bool knee_blend = false;
  for (const RiggedVertex& v : m.vertices) {
    bool t = false, s = false;
    for (int k = 0; k < 4; ++k) {
      t |= v.weights[k] > 0.2f && v.bones[k] == thigh;
      s |= v.weights[k] > 0.2f && v.bones[k] == shin;
    }
    knee_blend |= t && s;
  }
  CHECK(knee_blend);
  // Feet on the ground, head up: about 1.8 m tall.
  float lo = 1e9f, hi = -1e9f;
  for (const RiggedVertex& v : m.vertices) lo = std::min(lo, v.position.y), hi = std::max(hi, v.position.y);
  CHECK(lo == Approx(0.0f).margin(0.02));
  CHECK(hi == Approx(1.86f).margin(0.05));
  // The texture is a file next to the model and decodes.
  CHECK(fs::path(m.texture_path).filename() == "humanoid.png");
  RiggedMesh copy = m;
  Status t = load_rigged_texture(copy);
  INFO((t.ok() ? std::string() : t.message()));
  REQUIRE(t.ok());
  CHECK(copy.texture_width >= 256);
  CHECK(copy.texture_rgba.size() == static_cast<size_t>(copy.texture_width) * copy.texture_height * 4);
  // Every vertex samples inside the image; some texels are opaque.
  size_t opaque = 0;
  for (size_t i = 3; i < copy.texture_rgba.size(); i += 4) opaque += copy.texture_rgba[i] > 200;
  CHECK(opaque > copy.texture_rgba.size() / 4 / 10);
}

TEST_CASE("skinning with the rest pose reproduces the bind positions", "[render]") {
  Result<RiggedMesh> r = load_rigged_mesh(character());
  REQUIRE(r.ok());
  const std::vector<Mat2x3> palette = rigged_palette(*r, rest_locals(*r));
  for (const RiggedVertex& v : r->vertices) {
    const glm::vec2 p = skin_position(v, palette);
    REQUIRE(p.x == Approx(v.position.x).margin(1e-5));
    REQUIRE(p.y == Approx(v.position.y).margin(1e-5));
  }
  // Placement: the palette of a moved character moves every vertex by the same amount.
  Mat2x3 shift;
  shift.m[4] = 3.0f;
  shift.m[5] = -1.0f;
  const std::vector<Mat2x3> moved = rigged_palette(*r, rest_locals(*r), shift);
  for (const RiggedVertex& v : r->vertices) {
    const glm::vec2 p = skin_position(v, moved);
    REQUIRE(p.x == Approx(v.position.x + 3.0f).margin(1e-5));
    REQUIRE(p.y == Approx(v.position.y - 1.0f).margin(1e-5));
  }
}

TEST_CASE("bending a knee moves the shin and foot but not the other leg", "[render]") {
  Result<RiggedMesh> r = load_rigged_mesh(character());
  REQUIRE(r.ok());
  std::vector<Mat2x3> locals = rest_locals(*r);
  const int shin = r->find_bone("shin_l");
  locals[static_cast<size_t>(shin)] = rotated_local(locals[static_cast<size_t>(shin)], 1.2f);
  const std::vector<Mat2x3> palette = rigged_palette(*r, locals);
  int moved = 0;
  for (const RiggedVertex& v : r->vertices) {
    const glm::vec2 p = skin_position(v, palette);
    bool on_near_shin = false;
    for (int k = 0; k < 4; ++k) {
      const std::string& name = r->bones[v.bones[k]].name;
      on_near_shin |= v.weights[k] > 0.0f && (name == "shin_l" || name == "foot_l");
    }
    if (!on_near_shin) {
      REQUIRE(glm::length(p - v.position) < 1e-5f);
    } else if (glm::length(p - v.position) > 0.05f) {
      ++moved;
    }
  }
  CHECK(moved >= 6);
}

TEST_CASE("the rig mapping loads and names bones of its mesh", "[render]") {
  const std::string path = scenes::source_path("assets/characters/humanoid.rig.json");
  Result<RigMapping> rig = load_rig_mapping(path);
  INFO((rig.ok() ? std::string() : rig.message()));
  REQUIRE(rig.ok());
  CHECK(rig->root == "pelvis");
  CHECK(rig->head == "head");
  REQUIRE(rig->legs.size() == 2);
  REQUIRE(rig->arms.size() == 2);
  CHECK(rig->legs[0].side == Side::kNear);
  CHECK(rig->legs[1].side == Side::kFar);
  Result<RiggedMesh> mesh = load_rigged_mesh(rig->mesh_path);
  REQUIRE(mesh.ok());
  Result<Character> c = build_character(imported_skeleton(*mesh), *rig, path);
  INFO((c.ok() ? std::string() : c.message()));
  CHECK(c.ok());

  // Broken mappings name the file, the field and the bone.
  RigMapping bad = *rig;
  bad.legs[1].lower = "tail";
  Result<Character> e = build_character(imported_skeleton(*mesh), bad, "x.rig.json");
  REQUIRE_FALSE(e.ok());
  CHECK_THAT(e.message(), Catch::Contains("x.rig.json: legs[1].lower") && Catch::Contains("tail"));
  bad = *rig;
  std::swap(bad.arms[0].lower, bad.arms[0].end);
  CHECK_FALSE(build_character(imported_skeleton(*mesh), bad, "x.rig.json").ok());
}

TEST_CASE("the tool's export re-imports with the same hierarchy and mesh", "[render]") {
  const char* bin = std::getenv("OSSA_BIN_DIR");
  const fs::path tool = fs::path(bin ? bin : "") / "ossa-make-character";
  if (!bin || !fs::exists(tool)) {
    WARN("ossa-make-character not built; round trip through the tool skipped");
    return;
  }
  const fs::path dir = temp_dir("tool");
  const std::string cmd = tool.string() + " --out " + dir.string() + " > /dev/null";
  REQUIRE(std::system(cmd.c_str()) == 0);
  Result<RiggedMesh> fresh = load_rigged_mesh((dir / "humanoid.gltf").string());
  Result<RiggedMesh> shipped = load_rigged_mesh(character());
  REQUIRE(fresh.ok());
  REQUIRE(shipped.ok());
  check_invariants(*fresh);
  CHECK(hierarchy(*fresh) == hierarchy(*shipped));
  REQUIRE(fresh->vertices.size() == shipped->vertices.size());  // committed files are current
  CHECK(fresh->indices == shipped->indices);
  for (size_t i = 0; i < fresh->bones.size(); ++i) {
    for (int k = 0; k < 6; ++k) {
      REQUIRE(fresh->bones[i].rest_local.m[k] == Approx(shipped->bones[i].rest_local.m[k]).margin(1e-6));
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("the character survives FBX and DAE export and import", "[render]") {
  Result<RiggedMesh> original = load_rigged_mesh(character());
  REQUIRE(original.ok());
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(character(), 0);
  REQUIRE(scene);
  const fs::path dir = temp_dir("formats");
  for (const auto& [format, ext] : {std::pair{"fbxa", "fbx"}, {"collada", "dae"}}) {
    SECTION(format) {
      const std::string path = (dir / (std::string("humanoid.") + ext)).string();
      Assimp::Exporter exporter;
      REQUIRE(exporter.Export(scene, format, path) == aiReturn_SUCCESS);
      Result<RiggedMesh> back = load_rigged_mesh(path);
      INFO((back.ok() ? std::string() : back.message()));
      REQUIRE(back.ok());
      check_invariants(*back);
      CHECK(hierarchy(*back) == hierarchy(*original));
      // Same vertices (joined identically), same weights per bone name, same rest skinning.
      REQUIRE(back->vertices.size() == original->vertices.size());
      const std::vector<Mat2x3> palette = rigged_palette(*back, rest_locals(*back));
      for (const RiggedVertex& v : back->vertices) {
        const glm::vec2 p = skin_position(v, palette);
        REQUIRE(glm::length(p - v.position) < 1e-4f);
        // Find the original vertex at this position and UV; compare weights by bone name.
        const RiggedVertex* match = nullptr;
        for (const RiggedVertex& o : original->vertices) {
          if (glm::length(o.position - v.position) < 1e-5f && glm::length(o.uv - v.uv) < 1e-5f) match = &o;
        }
        REQUIRE(match);
        std::map<std::string, float> a, b;
        for (int k = 0; k < 4; ++k) {
          if (v.weights[k] > 0.0f) a[back->bones[v.bones[k]].name] += v.weights[k];
          if (match->weights[k] > 0.0f) b[original->bones[match->bones[k]].name] += match->weights[k];
        }
        REQUIRE(a.size() == b.size());
        for (const auto& [name, w] : b) REQUIRE(a[name] == Approx(w).margin(1e-4));
      }
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("malformed model files give errors naming the file", "[render]") {
  const fs::path dir = temp_dir("bad");
  const std::string text = *read_file(character());
  auto write = [&](const std::string& name, const std::string& bytes) {
    const std::string p = (dir / name).string();
    REQUIRE(write_file_atomic(p, bytes).ok());
    return p;
  };
  SECTION("missing file") { require_error(load_rigged_mesh((dir / "nope.gltf").string()), "nope.gltf"); }
  SECTION("empty file") { require_error(load_rigged_mesh(write("empty.gltf", "")), "empty.gltf"); }
  SECTION("truncated glTF") {
    for (size_t cut : {size_t{10}, text.size() / 3, text.size() / 2, text.size() - 5}) {
      require_error(load_rigged_mesh(write("truncated.gltf", text.substr(0, cut))), "truncated.gltf");
    }
  }
  SECTION("JSON that is not glTF") {
    require_error(load_rigged_mesh(write("other.gltf", R"({"format":"ossa.rig","version":1})")), "other.gltf");
  }
  SECTION("glTF referencing a missing .bin") {
    std::string t = text;
    const size_t at = t.find("humanoid.bin");
    REQUIRE(at != std::string::npos);
    t.replace(at, 12, "missing0.bin");
    require_error(load_rigged_mesh(write("nobin.gltf", t)), "nobin.gltf");
  }
  SECTION("a mesh without bones, and formats other than glTF, FBX, DAE") {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    require_error(load_rigged_mesh(write("plain.obj", obj)), "plain.obj");
  }
  SECTION("a text file and random bytes") {
    require_error(load_rigged_mesh(write("notes.gltf", "hello, world\n")), "notes.gltf");
    std::mt19937 rng(7);
    for (int i = 0; i < 20; ++i) {
      std::string bytes(static_cast<size_t>(1 + rng() % 400), '\0');
      for (char& c : bytes) c = static_cast<char>(rng());
      const std::vector<uint8_t> v(bytes.begin(), bytes.end());
      for (const char* hint : {"gltf", "glb", "fbx", "dae"}) {
        Result<RiggedMesh> m = load_rigged_mesh_from_memory(v, hint, "random.bin");
        require_error(m, "random.bin");
      }
    }
  }
  SECTION("random corruption of the character") {
    std::mt19937 rng(11);
    for (int i = 0; i < 60; ++i) {
      std::string t = text;
      for (int k = 0; k < 3; ++k) t[rng() % t.size()] = "{}[]\",:0-9e.aZ"[rng() % 14];
      Result<RiggedMesh> m = load_rigged_mesh(write("corrupt.gltf", t));
      if (m.ok()) {
        check_invariants(*m);
      } else {
        CHECK_THAT(m.message(), Catch::Contains("corrupt.gltf"));
      }
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("out-of-plane bones and too many bones are rejected", "[render]") {
  // A minimal glTF: one triangle skinned to joint 0 of a chain of `joints` nodes.
  auto gltf = [](const Json& rotation, int joints, bool inverse_binds = true) {
    Json doc = Json::parse(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0,"JOINTS_0":1,"WEIGHTS_0":2}}]}],
      "buffers":[{"byteLength":96,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAAAA"}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":12},{"buffer":0,"byteOffset":48,"byteLength":48}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"bufferView":1,"componentType":5121,"count":3,"type":"VEC4"},
                   {"bufferView":2,"componentType":5126,"count":3,"type":"VEC4"}]})");
    doc["nodes"] = Json::array();
    doc["skins"] = {{{"joints", Json::array()}}};
    for (int i = 0; i < joints; ++i) {
      Json node = {{"name", "bone" + std::to_string(i)}, {"translation", {0.0, 0.1, 0.0}}};
      if (i == 1) node["rotation"] = rotation;  // the root's rest = its bind (header)
      if (i + 1 < joints) node["children"] = {i + 1};
      doc["nodes"].push_back(node);
      doc["skins"][0]["joints"].push_back(i);
    }
    doc["nodes"].push_back({{"name", "mesh"}, {"mesh", 0}, {"skin", 0}});
    if (inverse_binds) {  // inverse binds of the chain (joint j at y = 0.1 (j + 1)) in a second buffer
      auto encode = [](const std::vector<uint8_t>& bytes) {
        static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        std::string out;
        for (size_t i = 0; i < bytes.size(); i += 3) {
          uint32_t n = static_cast<uint32_t>(bytes[i]) << 16;
          if (i + 1 < bytes.size()) n |= static_cast<uint32_t>(bytes[i + 1]) << 8;
          if (i + 2 < bytes.size()) n |= bytes[i + 2];
          out += t[(n >> 18) & 63];
          out += t[(n >> 12) & 63];
          out += i + 1 < bytes.size() ? t[(n >> 6) & 63] : '=';
          out += i + 2 < bytes.size() ? t[n & 63] : '=';
        }
        return out;
      };
      std::vector<uint8_t> bytes;
      for (int j = 0; j < joints; ++j) {
        for (int k = 0; k < 16; ++k) {
          float f = (k % 5 == 0) ? 1.0f : 0.0f;
          if (k == 13) f = -0.1f * static_cast<float>(j + 1);  // inverse of the chain's y offset
          const uint8_t* p = reinterpret_cast<const uint8_t*>(&f);
          bytes.insert(bytes.end(), p, p + 4);
        }
      }
      doc["buffers"].push_back({{"byteLength", bytes.size()},
                                {"uri", "data:application/octet-stream;base64," + encode(bytes)}});
      doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", bytes.size()}});
      doc["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", joints}, {"type", "MAT4"}});
      doc["skins"][0]["inverseBindMatrices"] = 3;
    }
    doc["scenes"][0]["nodes"].push_back(joints);
    const std::string text = doc.dump();
    return load_rigged_mesh_from_memory(std::vector<uint8_t>(text.begin(), text.end()), "gltf", "tiny.gltf");
  };
  Result<RiggedMesh> flat = gltf({0.0, 0.0, 0.3826834, 0.9238795}, 3);  // 45° about z
  INFO((flat.ok() ? std::string() : flat.message()));
  REQUIRE(flat.ok());
  CHECK(flat->bones.size() >= 1);
  check_invariants(*flat);
  REQUIRE(flat->bones.size() == 3);
  CHECK(flat->bones[1].rest_local.m[1] == Approx(std::sqrt(0.5f)).margin(1e-5));
  Result<RiggedMesh> tilted = gltf({0.3826834, 0.0, 0.0, 0.9238795}, 3);  // 45° about x
  REQUIRE_FALSE(tilted.ok());
  CHECK_THAT(tilted.message(), Catch::Contains("tiny.gltf") && Catch::Contains("x-y plane"));
  // Assimp 5.2 crashes on a skin without inverse bind matrices: we reject it first.
  Result<RiggedMesh> no_ibm = gltf({0.0, 0.0, 0.0, 1.0}, 3, false);
  REQUIRE_FALSE(no_ibm.ok());
  CHECK_THAT(no_ibm.message(), Catch::Contains("tiny.gltf: skins[0]") && Catch::Contains("inverseBindMatrices"));
  Result<RiggedMesh> many = gltf({0.0, 0.0, 0.0, 1.0}, 300);
  if (many.ok()) {
    CHECK(many->bones.size() <= 255);  // Assimp kept only the weighted joints
  } else {
    CHECK_THAT(many.message(), Catch::Contains("tiny.gltf") && Catch::Contains("255"));
  }
}

TEST_CASE("a DAE that crashes Assimp's COLLADA parser is reported, not fatal", "[render]") {
  // Found by tests/fuzz/mesh_fuzz.cpp: Assimp 5.2 dereferences a null pointer on this file.
  const std::string path = ossa::scenes::source_path("tests/fuzz/seeds/mesh/crash_collada_parser.dae");
  ossa::Result<ossa::RiggedMesh> mesh = ossa::load_rigged_mesh(path);
  REQUIRE_FALSE(mesh.ok());
  CHECK_THAT(mesh.message(), Catch::Contains("crash_collada_parser.dae"));
  CHECK_THAT(mesh.message(), Catch::Contains("malformed DAE"));
}
