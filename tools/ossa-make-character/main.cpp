// ossa-make-character — generates the shipped 2D rigged sprite characters (issue "Renderer",
// item 7, and issue "Rigged characters walk"; [T 4.3.1]: [T]'s player is one textured sprite
// mesh skinned to a humanoid skeleton).
//
//   <build>/bin/ossa-make-character [--out DIR]
//
// writes, for each character (humanoid.cpp, dog.cpp), DIR/NAME.gltf (+ NAME.bin, via Assimp's
// "gltf2" exporter), DIR/NAME.png (the texture, drawn procedurally) and DIR/NAME.rig.json (its
// rig mapping, anim/rig_mapping.h). DIR defaults to the source tree's assets/characters;
// commit the regenerated files.
//
// The characters stand in side view, facing +x, feet on y = 0, metres. Bones point along
// their local +x. Each body part is a strip of quads over a rectangle of the rest pose
// (turned or moved by its placement); its texture region holds the part drawn with signed
// distance shapes (flat fills, anti-aliased, dark outlines). Strips blend two bones at joints.
//
// [SECTION] Drawing   [SECTION] Export   [SECTION] main

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "character_def.h"
#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/skeleton/pose.h"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace {

using namespace make_character;
using ossa::inverse;

Mat2x3 frame(const BoneDef& b, float scale) {  // bone frame → model space
  Mat2x3 m;
  m.m[0] = std::cos(b.angle);
  m.m[1] = std::sin(b.angle);
  m.m[2] = -m.m[1];
  m.m[3] = m.m[0];
  m.m[4] = scale * b.head.x;
  m.m[5] = scale * b.head.y;
  return m;
}

aiMatrix4x4 to_ai(const Mat2x3& m) {
  return aiMatrix4x4(m.m[0], m.m[2], 0.0f, m.m[4], m.m[1], m.m[3], 0.0f, m.m[5],
                     0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f);
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Drawing

// Packs the parts' regions in shelves; returns the texture size.
constexpr float kPixelsPerMetre = 400.0f;
constexpr int kPad = 4;

glm::ivec2 pack(std::vector<Part>& ps, int width) {
  int x = kPad, y = kPad, shelf = 0;
  std::vector<Part*> order;
  for (Part& p : ps) order.push_back(&p);
  std::stable_sort(order.begin(), order.end(),
                   [](const Part* a, const Part* b) { return a->hi.y - a->lo.y > b->hi.y - b->lo.y; });
  for (Part* p : order) {
    p->pw = static_cast<int>(std::ceil((p->hi.x - p->lo.x) * kPixelsPerMetre));
    p->ph = static_cast<int>(std::ceil((p->hi.y - p->lo.y) * kPixelsPerMetre));
    if (x + p->pw + kPad > width) {
      x = kPad;
      y += shelf + kPad;
      shelf = 0;
    }
    p->px = x;
    p->py = y;
    x += p->pw + kPad;
    shelf = std::max(shelf, p->ph);
  }
  int height = 64;
  while (height < y + shelf + kPad) height *= 2;
  return {width, height};
}

// Model-space point of a texel centre of part p, and the texture coordinate (top-left origin)
// of a model-space point.
vec2 texel_to_model(const Part& p, int ix, int iy) {
  return {p.lo.x + (static_cast<float>(ix - p.px) + 0.5f) / kPixelsPerMetre,
          p.hi.y - (static_cast<float>(iy - p.py) + 0.5f) / kPixelsPerMetre};
}
vec2 model_to_uv(const Part& p, vec2 q, glm::ivec2 size) {
  return {(static_cast<float>(p.px) + (q.x - p.lo.x) * kPixelsPerMetre) / static_cast<float>(size.x),
          (static_cast<float>(p.py) + (p.hi.y - q.y) * kPixelsPerMetre) / static_cast<float>(size.y)};
}

void draw(const Part& p, glm::ivec2 size, std::vector<uint8_t>& rgba) {
  const float px = 1.0f / kPixelsPerMetre, outline = 0.016f;
  const float shade = p.far ? 0.68f : 1.0f;
  for (int iy = p.py; iy < p.py + p.ph; ++iy) {
    for (int ix = p.px; ix < p.px + p.pw; ++ix) {
      const vec2 q = texel_to_model(p, ix, iy);
      Rgb c = kOutline;
      float alpha = 0.0f, silhouette = 1e9f;
      for (const Layer& l : p.layers) {
        const float d = l.sdf(q);
        const float cover = std::clamp(0.5f - d / px, 0.0f, 1.0f);
        c = glm::mix(c, l.colour * shade, alpha == 0.0f ? 1.0f : cover);
        alpha = std::max(alpha, cover);
        if (l.detail_line > 0.0f) {
          const float line = std::clamp(0.5f - (std::fabs(d + 0.5f * l.detail_line) - 0.5f * l.detail_line) / px, 0.0f, 1.0f);
          c = glm::mix(c, kOutline, line);
        }
        if (l.silhouette) silhouette = std::min(silhouette, d);
      }
      // The outer outline lies just inside the silhouette.
      const float edge = std::clamp(0.5f - (silhouette + outline) / px, 0.0f, 1.0f);
      c = glm::mix(kOutline, c, silhouette < 1e8f ? edge : 1.0f);
      uint8_t* o = &rgba[(static_cast<size_t>(iy) * size.x + ix) * 4];
      for (int k = 0; k < 3; ++k) o[k] = static_cast<uint8_t>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
      o[3] = static_cast<uint8_t>(std::lround(alpha * 255.0f));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Export

template <class T>
T* new_array(size_t n) { return n ? new T[n] : nullptr; }

int export_character(CharacterDef def, const std::filesystem::path& dir) {
  const std::vector<BoneDef>& bones = def.bones;
  const std::string& name = def.name;
  std::map<std::string, int> index;
  for (size_t i = 0; i < bones.size(); ++i) index[bones[i].name] = static_cast<int>(i);
  std::vector<Part>& ps = def.parts;
  const glm::ivec2 size = pack(ps, 1024);

  // Texture.
  std::vector<uint8_t> rgba(static_cast<size_t>(size.x) * size.y * 4, 0);
  for (size_t i = 0; i < rgba.size(); i += 4) {  // transparent, outline-coloured (no bright fringe)
    rgba[i] = 38, rgba[i + 1] = 30, rgba[i + 2] = 36;
  }
  for (const Part& p : ps) draw(p, size, rgba);
  const std::string png = (dir / (name + ".png")).string();
  if (!stbi_write_png(png.c_str(), size.x, size.y, 4, rgba.data(), size.x * 4)) {
    std::fprintf(stderr, "ossa-make-character: %s: cannot write the PNG\n", png.c_str());
    return 1;
  }

  // Mesh: two vertices per row, quads between rows, parts in depth order.
  std::stable_sort(ps.begin(), ps.end(), [](const Part& a, const Part& b) { return a.z < b.z; });
  std::vector<vec3> positions;
  std::vector<vec2> uvs;
  std::vector<std::vector<std::pair<int, float>>> weights;  // per vertex
  std::vector<unsigned> tris;
  for (const Part& p : ps) {
    const unsigned base = static_cast<unsigned>(positions.size());
    for (const Row& r : p.rows) {
      for (int k = 0; k < 2; ++k) {
        const vec2 q = p.horizontal ? vec2(r.at, k ? p.hi.y : p.lo.y) : vec2(k ? p.hi.x : p.lo.x, r.at);
        const vec2 m = def.scale * p.place.apply(q);
        positions.push_back({m.x, m.y, p.z});
        uvs.push_back(model_to_uv(p, q, size));
        std::vector<std::pair<int, float>> w;
        for (const auto& [bone, wt] : r.weights) w.push_back({index.at(bone), wt});
        weights.push_back(w);
      }
    }
    for (unsigned i = 0; i + 1 < p.rows.size(); ++i) {
      unsigned a = base + 2 * i, b = a + 1, c = a + 3, d = a + 2;  // a,b this row; d,c next
      const vec3 e1 = positions[b] - positions[a], e2 = positions[c] - positions[a];
      if (e1.x * e2.y - e1.y * e2.x < 0.0f) std::swap(b, d);  // counter-clockwise, facing +z
      tris.insert(tris.end(), {a, b, c, a, c, d});
    }
  }

  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode(name);
  std::vector<aiNode*> nodes;
  std::vector<std::vector<aiNode*>> children(bones.size() + 1);
  for (const BoneDef& b : bones) {
    aiNode* node = new aiNode(b.name);
    const Mat2x3 local = b.parent.empty() ? frame(b, def.scale) : inverse(frame(bones[index.at(b.parent)], def.scale)) * frame(b, def.scale);
    node->mTransformation = to_ai(local);
    nodes.push_back(node);
    children[b.parent.empty() ? bones.size() : static_cast<size_t>(index.at(b.parent))].push_back(node);
  }
  aiNode* mesh_node = new aiNode(name + "_mesh");
  mesh_node->mNumMeshes = 1;
  mesh_node->mMeshes = new unsigned[1]{0};
  children[bones.size()].push_back(mesh_node);
  for (size_t i = 0; i <= bones.size(); ++i) {
    aiNode* parent = i == bones.size() ? scene->mRootNode : nodes[i];
    parent->mNumChildren = static_cast<unsigned>(children[i].size());
    parent->mChildren = new_array<aiNode*>(children[i].size());
    for (size_t k = 0; k < children[i].size(); ++k) {
      parent->mChildren[k] = children[i][k];
      children[i][k]->mParent = parent;
    }
  }

  aiMesh* mesh = new aiMesh;
  mesh->mName = name + "_sprites";
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = static_cast<unsigned>(positions.size());
  mesh->mVertices = new aiVector3D[positions.size()];
  mesh->mNormals = new aiVector3D[positions.size()];
  mesh->mTextureCoords[0] = new aiVector3D[positions.size()];
  mesh->mNumUVComponents[0] = 2;
  for (size_t i = 0; i < positions.size(); ++i) {
    mesh->mVertices[i] = aiVector3D(positions[i].x, positions[i].y, positions[i].z);
    mesh->mNormals[i] = aiVector3D(0.0f, 0.0f, 1.0f);
    // Assimp's scene convention has v up; its glTF exporter flips to glTF's top-left origin.
    mesh->mTextureCoords[0][i] = aiVector3D(uvs[i].x, 1.0f - uvs[i].y, 0.0f);
  }
  mesh->mNumFaces = static_cast<unsigned>(tris.size() / 3);
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    mesh->mFaces[f].mNumIndices = 3;
    mesh->mFaces[f].mIndices = new unsigned[3]{tris[3 * f], tris[3 * f + 1], tris[3 * f + 2]};
  }
  mesh->mNumBones = static_cast<unsigned>(bones.size());
  mesh->mBones = new aiBone*[bones.size()];
  for (size_t bi = 0; bi < bones.size(); ++bi) {
    aiBone* bone = new aiBone;
    bone->mName = bones[bi].name;
    bone->mOffsetMatrix = to_ai(inverse(frame(bones[bi], def.scale)));  // model space → bone frame
    std::vector<aiVertexWeight> ws;
    for (size_t v = 0; v < weights.size(); ++v) {
      for (const auto& [b, w] : weights[v]) {
        if (b == static_cast<int>(bi)) ws.push_back(aiVertexWeight(static_cast<unsigned>(v), w));
      }
    }
    bone->mNumWeights = static_cast<unsigned>(ws.size());
    bone->mWeights = new_array<aiVertexWeight>(ws.size());
    std::copy(ws.begin(), ws.end(), bone->mWeights);
    mesh->mBones[bi] = bone;
  }
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1]{mesh};

  aiMaterial* material = new aiMaterial;
  const aiString material_name(name);
  material->AddProperty(&material_name, AI_MATKEY_NAME);
  const aiColor4D white(1.0f, 1.0f, 1.0f, 1.0f);
  material->AddProperty(&white, 1, AI_MATKEY_COLOR_DIFFUSE);
  material->AddProperty(&white, 1, AI_MATKEY_BASE_COLOR);
  const aiString tex(name + ".png");
  material->AddProperty(&tex, AI_MATKEY_TEXTURE_DIFFUSE(0));
  material->AddProperty(&tex, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{material};

  const std::string gltf = (dir / (name + ".gltf")).string();
  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), "gltf2", gltf) != aiReturn_SUCCESS) {
    std::fprintf(stderr, "ossa-make-character: %s: glTF export failed: %s\n", gltf.c_str(),
                 exporter.GetErrorString());
    return 1;
  }

  // The rig mapping (anim/rig_mapping.h).
  Json rig = def.rig;
  for (Json& leg : rig["legs"]) {
    if (leg.contains("contact")) {
      leg["contact"] = {ossa::json_float(def.scale * leg["contact"][0].get<float>()),
                        ossa::json_float(def.scale * leg["contact"][1].get<float>())};
    }
  }
  rig["format"] = "ossa.rig";
  rig["version"] = 1;
  rig["mesh"] = name + ".gltf";
  const std::string rig_path = (dir / (name + ".rig.json")).string();
  if (ossa::Status s = ossa::write_json_atomic(rig_path, rig); !s.ok()) {
    std::fprintf(stderr, "ossa-make-character: %s\n", s.message().c_str());
    return 1;
  }
  std::printf("wrote %s, %s (%dx%d), %s: %zu bones, %zu vertices, %zu triangles\n", gltf.c_str(),
              png.c_str(), size.x, size.y, rig_path.c_str(), bones.size(), positions.size(),
              tris.size() / 3);
  return 0;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// [SECTION] main

int main(int argc, char** argv) {
  std::filesystem::path out = ossa::data_path("assets/characters");
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: ossa-make-character [--out DIR]  (default: %s)\n", out.string().c_str());
      return 0;
    } else {
      std::fprintf(stderr, "ossa-make-character: unknown argument \"%s\"; usage: "
                   "ossa-make-character [--out DIR]\n", a.c_str());
      return 2;
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  for (const CharacterDef& def : {humanoid(), dog()}) {
    if (const int rc = export_character(def, out); rc != 0) return rc;
  }
  return 0;
}
