#include "ossa/render/gltf_export.h"

#include <assimp/Exporter.hpp>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/body/coat.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/skeleton/pose.h"

namespace ossa {
namespace {

aiMatrix4x4 to_ai(const Mat2x3& m) {
  // Mat2x3 is column-major (x' = m0 x + m2 y + m4); aiMatrix4x4 is row-major.
  return aiMatrix4x4(m.m[0], m.m[2], 0.0f, m.m[4],
                     m.m[1], m.m[3], 0.0f, m.m[5],
                     0.0f, 0.0f, 1.0f, 0.0f,
                     0.0f, 0.0f, 0.0f, 1.0f);
}

template <class T>
T* new_array(size_t n) {
  return n ? new T[n] : nullptr;
}

// Assimp writes through an IOSystem; this one keeps every file it is asked to write in memory
// (path → bytes), so that the files can be saved atomically once the export has succeeded.
using MemoryFiles = std::map<std::string, std::string>;

class MemoryStream : public Assimp::IOStream {
 public:
  MemoryStream(MemoryFiles& files, std::string path) : files_(&files), path_(std::move(path)) {}
  ~MemoryStream() override { (*files_)[path_] = std::move(bytes_); }
  size_t Read(void*, size_t, size_t) override { return 0; }
  size_t Write(const void* data, size_t size, size_t count) override {
    const size_t n = size * count;
    if (bytes_.size() < pos_ + n) bytes_.resize(pos_ + n);
    if (n) bytes_.replace(pos_, n, static_cast<const char*>(data), n);
    pos_ += n;
    return count;
  }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    const size_t base = origin == aiOrigin_CUR ? pos_ : origin == aiOrigin_END ? bytes_.size() : 0;
    pos_ = base + offset;
    return aiReturn_SUCCESS;
  }
  size_t Tell() const override { return pos_; }
  size_t FileSize() const override { return bytes_.size(); }
  void Flush() override {}

 private:
  MemoryFiles* files_;
  std::string path_;
  std::string bytes_;
  size_t pos_ = 0;
};

class MemoryIOSystem : public Assimp::IOSystem {
 public:
  explicit MemoryIOSystem(MemoryFiles& files) : files_(&files) {}
  bool Exists(const char* path) const override { return files_->count(path) > 0; }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* path, const char* mode) override {
    // Export only writes; anything else (a read of an existing file) is refused.
    if (!mode || (mode[0] != 'w' && mode[0] != 'a')) return nullptr;
    return new MemoryStream(*files_, path);
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

 private:
  MemoryFiles* files_;
};

// The mesh to write, in the rest pose (model space, metres): per vertex a position, a depth,
// Assimp UVs (v up) and its bones' weights (real bones only); triangles.
struct ExportMesh {
  struct Vertex {
    glm::vec2 position{0.0f};
    float z = 0.0f;
    glm::vec2 uv{0.0f};
    glm::vec4 colour{1.0f};                          // linear RGBA (bodies)
    std::array<std::pair<int, float>, 4> weights{};  // (bone, weight); weight 0: unused
  };
  std::vector<Vertex> vertices;
  std::vector<unsigned> indices;
};

// Depth: far side behind, near side in front (1 mm), plus a tiny per-bone step. Besides
// giving a draw order, it keeps the vertices of the near and far copies (which coincide in
// x, y) apart: Assimp's glTF exporter enforces JoinIdenticalVertices, which in 5.2 ignores
// bone weights and would merge them, dropping the near copy's weights.
float depth(const Skeleton& s, int bone) {
  return 0.001f * (static_cast<float>(s.layer(bone)) - 1.0f) + 1e-6f * static_cast<float>(bone);
}

// Rigid: a quad per bone spanning its length × width, weighted 1 to it.
ExportMesh rigid_quads(const Creature& creature, const std::vector<Mat2x3>& model) {
  const Skeleton& s = creature.skeleton;
  ExportMesh out;
  static constexpr float kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // A bone without a length or width gets a square 1 % of the creature's frame (2 cm in the
  // 2 m frame), in its own size: not at least 1 cm, a fifth of a 5 cm creature.
  const float unit = creature.scale > 0.0f && std::isfinite(creature.scale) ? creature.scale : 0.002f;
  const float fallback = 10.0f * unit;
  for (int i = 0; i < s.bone_count(); ++i) {
    const Mat2x3& m = model[static_cast<size_t>(i)];
    float length = s.length(i), width = s.width(i);
    if (!(length > 0.0f) || !std::isfinite(length)) length = std::max(width, fallback);
    if (!(width > 0.0f) || !std::isfinite(width)) width = std::max(0.15f * length, fallback);
    const auto v0 = static_cast<unsigned>(out.vertices.size());
    for (const auto& corner : kCorner) {
      ExportMesh::Vertex v;
      v.position = m.apply({corner[0] * length, (corner[1] - 0.5f) * width});
      v.z = depth(s, i);
      v.uv = {corner[0], corner[1]};
      v.weights[0] = {i, 1.0f};
      out.vertices.push_back(v);
    }
    out.indices.insert(out.indices.end(), {v0, v0 + 1, v0 + 2, v0, v0 + 2, v0 + 3});
  }
  return out;
}

// Smooth: the creature's sprite mesh (sprite_mesh.h) in its rest pose as drawn, with its
// weights. A mid-joint frame, which a glTF skin cannot compute, is folded into its two bones
// by its turn (a frame turned t of the way: 1 - t to the parent, t to the child); at rest
// every palette entry is the identity, so the rest pose is exact whatever the weights.
// Adds `w` of `bone` to a vertex's weights (merging a bone already there).
void add_weight(ExportMesh::Vertex& v, int& used, int bone, float w) {
  if (!(w > 0.0f)) return;
  for (int k = 0; k < used; ++k) {
    if (v.weights[static_cast<size_t>(k)].first == bone) {
      v.weights[static_cast<size_t>(k)].second += w;
      return;
    }
  }
  if (used < 4) v.weights[static_cast<size_t>(used++)] = {bone, w};
}

Result<ExportMesh> smooth_sprites(const Creature& creature, const SpriteSet& sprites) {
  Result<SpriteMesh> built = try_build_sprite_mesh(creature, sprites);
  if (!built.ok()) return built.error();
  const SpriteMesh& mesh = built.value();
  const Skeleton& s = creature.skeleton;
  const int n = s.bone_count();
  ExportMesh out;
  out.vertices.reserve(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const SpriteVertex& sv = mesh.vertices[i];
    ExportMesh::Vertex v;
    v.position = mesh.rest_positions.size() == mesh.vertices.size() ? mesh.rest_positions[i] : sv.position_ms;
    v.z = depth(s, sv.bones[0]);
    v.uv = sv.uv;  // t up in both (sprite_mesh.h SpriteInfo::uv_min, Assimp)
    int used = 0;
    const auto add = [&](int bone, float w) { add_weight(v, used, bone, w); };
    for (size_t k = 0; k < 4; ++k) {
      const int b = sv.bones[k];
      if (b < n) {
        add(b, sv.weights[k]);
      } else {
        const MidJoint& j = mesh.mid_joints[static_cast<size_t>(b - n)];
        add(j.parent, sv.weights[k] * (1.0f - j.turn));
        add(j.child, sv.weights[k] * j.turn);
      }
    }
    float total = 0.0f;
    for (const auto& [bone, w] : v.weights) total += w;
    for (auto& [bone, w] : v.weights) w = total > 0.0f ? w / total : 0.0f;
    out.vertices.push_back(v);
  }
  out.indices.assign(mesh.indices.begin(), mesh.indices.end());
  return out;
}


float linear(float srgb) { return srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f); }

// The body (body/body_mesh.h) in its rest pose: each part's outline stroke just behind its
// fill, the far limbs behind the body and the near ones in front (as its draw order); vertex
// colours the coat (countershading, the pattern at the vertex as body.frag draws it per
// pixel, far limbs darker); weights with every mid-joint frame folded into its two bones by
// its turn and a foot's level frame into the foot (exact at rest, as for the sprites).
ExportMesh body_geometry(const Creature& creature) {
  const BodyMesh body = build_body(creature);
  const int n = creature.skeleton.bone_count();
  ExportMesh out;
  out.vertices.resize(body.vertices.size());
  std::vector<bool> done(body.vertices.size(), false);
  for (size_t p = 0; p < body.parts.size(); ++p) {
    const BodyPart& part = body.parts[p];
    const float z = 0.001f * (static_cast<float>(part.layer) - 1.0f) + 2e-6f * static_cast<float>(p);
    const auto place = [&](uint32_t first, uint32_t count, float dz) {
      for (uint32_t i = first; i < first + count; ++i) {
        const uint32_t id = body.indices[i];
        out.indices.push_back(id);
        if (done[id]) continue;
        done[id] = true;
        const BodyVertex& bv = body.vertices[id];
        ExportMesh::Vertex& v = out.vertices[id];
        v.position = bv.position_ms;
        v.z = z + dz;
        v.uv = bv.coat_uv;
        const glm::vec3 base(bv.colour[0] / 255.0f, bv.colour[1] / 255.0f, bv.colour[2] / 255.0f);
        const glm::vec3 pattern(bv.pattern[0] / 255.0f, bv.pattern[1] / 255.0f, bv.pattern[2] / 255.0f);
        const float amount = bv.pattern[3] / 255.0f * coat_pattern(static_cast<CoatPattern>(bv.pattern_kind), bv.coat_uv);
        const glm::vec3 rgb = glm::mix(base, pattern, amount);
        v.colour = {linear(rgb.r), linear(rgb.g), linear(rgb.b), bv.colour[3] / 255.0f};
        int used = 0;
        for (size_t k = 0; k < 4; ++k) {
          const int b = bv.bones[k];
          const float w = bv.weights[k];
          if (b < n) {
            add_weight(v, used, b, w);
          } else if (b - n < static_cast<int>(body.mid_joints.size())) {
            const MidJoint& j = body.mid_joints[static_cast<size_t>(b - n)];
            if (j.level) {
              add_weight(v, used, j.child, w);
            } else {
              add_weight(v, used, j.parent, w * (1.0f - j.turn));
              add_weight(v, used, j.child, w * j.turn);
            }
          }
        }
        float total = 0.0f;
        for (const auto& [bone, wk] : v.weights) total += wk;
        for (auto& [bone, wk] : v.weights) wk = total > 0.0f ? wk / total : 0.0f;
      }
    };
    place(part.stroke_first_index, part.stroke_index_count, -1e-6f);
    place(part.first_index, part.index_count, 0.0f);
  }
  return out;
}

// An aiMesh of `geometry` skinned to the skeleton's bones (one mesh bone per skeleton bone,
// the inverse rest matrix as Assimp's offset), with vertex colours when `colours`.
aiMesh* skinned_mesh(const ExportMesh& geometry, const Skeleton& s, const std::vector<Mat2x3>& model,
                     const std::string& name, unsigned material, bool colours) {
  const int n = s.bone_count();
  aiMesh* mesh = new aiMesh;
  mesh->mName = name;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mMaterialIndex = material;
  mesh->mNumVertices = static_cast<unsigned>(geometry.vertices.size());
  mesh->mVertices = new_array<aiVector3D>(geometry.vertices.size());
  mesh->mNormals = new_array<aiVector3D>(geometry.vertices.size());
  mesh->mTextureCoords[0] = new_array<aiVector3D>(geometry.vertices.size());
  mesh->mNumUVComponents[0] = 2;
  if (colours) mesh->mColors[0] = new_array<aiColor4D>(geometry.vertices.size());
  std::vector<std::vector<aiVertexWeight>> weights(static_cast<size_t>(n));
  for (size_t i = 0; i < geometry.vertices.size(); ++i) {
    const ExportMesh::Vertex& v = geometry.vertices[i];
    mesh->mVertices[i] = aiVector3D(v.position.x, v.position.y, v.z);
    mesh->mNormals[i] = aiVector3D(0.0f, 0.0f, 1.0f);
    mesh->mTextureCoords[0][i] = aiVector3D(v.uv.x, v.uv.y, 0.0f);
    if (colours) mesh->mColors[0][i] = aiColor4D(v.colour.r, v.colour.g, v.colour.b, v.colour.a);
    for (const auto& [bone, w] : v.weights) {
      if (w > 0.0f) weights[static_cast<size_t>(bone)].emplace_back(static_cast<unsigned>(i), w);
    }
  }
  mesh->mNumFaces = static_cast<unsigned>(geometry.indices.size() / 3);
  mesh->mFaces = new_array<aiFace>(mesh->mNumFaces);
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    aiFace& face = mesh->mFaces[f];
    face.mNumIndices = 3;
    face.mIndices = new unsigned[3];
    for (unsigned k = 0; k < 3; ++k) face.mIndices[k] = geometry.indices[3 * f + k];
  }
  // One mesh bone per skeleton bone (a zero-length bone of a smooth mesh draws no sprite and
  // has no weights), the inverse rest (bind) matrix as Assimp's offset matrix.
  mesh->mNumBones = static_cast<unsigned>(n);
  mesh->mBones = new aiBone*[static_cast<size_t>(n)];
  for (int i = 0; i < n; ++i) {
    aiBone* bone = new aiBone;
    bone->mName = s.name(i);
    bone->mOffsetMatrix = to_ai(inverse(model[static_cast<size_t>(i)]));  // mesh (model) space → bone space
    const std::vector<aiVertexWeight>& w = weights[static_cast<size_t>(i)];
    bone->mNumWeights = static_cast<unsigned>(w.size());
    bone->mWeights = new_array<aiVertexWeight>(w.size());
    std::copy(w.begin(), w.end(), bone->mWeights);
    mesh->mBones[i] = bone;
  }
  return mesh;
}

// Assimp 5.2's glTF 2.0 exporter writes a node's matrix only when aiMatrix4x4::IsIdentity()
// is false, and IsIdentity allows 0.01 in every entry: a translation under 1 cm with a turn
// under 0.01 rad is taken for the identity and left out, so the node loads at its parent's
// frame. The 2 m frame mostly hid it (bones there are rarely under 1 cm apart); at true size
// a pigeon's vertebrae (5 mm apart, turning a few milliradians) all lost their transforms and
// its skinned rest pose came back up to 7 cm from the body as drawn. A bone at its parent's
// joint turning less than 0.01 rad was lost at any size.
// This puts back every matrix Assimp left out: it walks the written node tree alongside
// `node` (the exporter keeps the order of children) and gives each node without a transform
// its mTransformation, unless that is exactly the identity (glTF's default). Fails when the
// two trees differ (an exporter that reorders nodes).
Status restore_node_matrices(Json& gltf, size_t index, const aiNode& node, const std::string& path, int depth) {
  Json& nodes = gltf["nodes"];
  if (!nodes.is_array() || index >= nodes.size() || depth > kMaxJsonDepth) {
    return Error::at(path, "nodes", "the glTF exporter wrote an unexpected node tree");
  }
  Json& out = nodes[index];
  if (!out.is_object()) return Error::at(path, json_path("nodes", index), "the glTF exporter wrote an unexpected node");
  if (!out.contains("matrix") && !out.contains("translation") && !out.contains("rotation") &&
      !out.contains("scale") && !(node.mTransformation == aiMatrix4x4())) {
    const aiMatrix4x4& t = node.mTransformation;
    out["matrix"] = Json::array({json_float(t.a1), json_float(t.b1), json_float(t.c1), json_float(t.d1),
                                 json_float(t.a2), json_float(t.b2), json_float(t.c2), json_float(t.d2),
                                 json_float(t.a3), json_float(t.b3), json_float(t.c3), json_float(t.d3),
                                 json_float(t.a4), json_float(t.b4), json_float(t.c4), json_float(t.d4)});
  }
  const Json children = out.value("children", Json::array());
  if (!children.is_array() || children.size() != node.mNumChildren) {
    return Error::at(path, json_path("nodes", index), "the glTF exporter wrote an unexpected node tree");
  }
  for (unsigned k = 0; k < node.mNumChildren; ++k) {
    if (!children[k].is_number_unsigned()) {
      return Error::at(path, json_path("nodes", index), "the glTF exporter wrote an unexpected node tree");
    }
    if (Status s = restore_node_matrices(gltf, children[k].get<size_t>(), *node.mChildren[k], path, depth + 1); !s.ok()) return s;
  }
  return {};
}

// The .gltf text Assimp wrote, with the node matrices it left out (above).
Result<std::string> with_node_matrices(const std::string& text, const aiScene& scene, const std::string& path) {
  Result<Json> gltf = parse_json(text, path);
  if (!gltf.ok()) return gltf.error();
  Json& doc = gltf.value();
  const Json no_scene;
  const Json& index = doc.is_object() && doc.contains("scene") ? doc["scene"] : no_scene;
  const size_t scene_index = index.is_number_unsigned() ? index.get<size_t>() : 0;
  const Json& scenes = doc.is_object() && doc.contains("scenes") ? doc["scenes"] : no_scene;
  const Json& roots = scenes.is_array() && scene_index < scenes.size() && scenes[scene_index].is_object() &&
                              scenes[scene_index].contains("nodes") ? scenes[scene_index]["nodes"] : no_scene;
  if (!roots.is_array() || roots.size() != 1 || !roots[0].is_number_unsigned()) {
    return Error::at(path, "scenes", "the glTF exporter wrote an unexpected scene");
  }
  const size_t root = roots[0].get<size_t>();
  if (Status s = restore_node_matrices(doc, root, *scene.mRootNode, path, 0); !s.ok()) return s.error();
  return json_text(doc, 4);
}

}  // namespace

Status export_gltf(const Creature& creature, const std::string& path, const GltfOptions& options) {
  const Skeleton& s = creature.skeleton;
  const int n = s.bone_count();
  if (n == 0) return Error::at(path, "", "the creature has no bones");
  const std::vector<BoneLocal>& locals =
      creature.rest_pose.locals.size() == static_cast<size_t>(n) ? creature.rest_pose.locals
                                                                 : s.rest_locals();
  const std::vector<Mat2x3> model = model_matrices(s, locals);
  for (int i = 0; i < n; ++i) {
    for (float v : model[static_cast<size_t>(i)].m) {
      if (!std::isfinite(v)) return Error::at(path, s.name(i), "non-finite bone transform");
    }
  }

  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode(creature.name.empty() ? "creature" : creature.name);

  // Nodes: one per bone, children attached to their parents (parents precede children).
  std::vector<aiNode*> nodes(static_cast<size_t>(n));
  std::vector<std::vector<aiNode*>> children(static_cast<size_t>(n) + 1);  // last: scene root
  for (int i = 0; i < n; ++i) {
    aiNode* node = new aiNode(s.name(i));
    node->mTransformation = to_ai(local_matrix(locals[static_cast<size_t>(i)]));
    nodes[static_cast<size_t>(i)] = node;
    const int p = s.parent(i);
    children[p < 0 ? static_cast<size_t>(n) : static_cast<size_t>(p)].push_back(node);
  }
  // The meshes the look asks for: the bone sprites, the body, or both (x-ray).
  const std::string base = creature.name.empty() ? "creature" : creature.name;
  const bool sprites = options.look != CreatureLook::kBody, flesh = options.look != CreatureLook::kBones;
  const unsigned mesh_count = (sprites ? 1u : 0u) + (flesh ? 1u : 0u);
  aiNode* mesh_node = new aiNode(base + "_mesh");
  mesh_node->mNumMeshes = mesh_count;
  mesh_node->mMeshes = new unsigned[mesh_count];
  for (unsigned k = 0; k < mesh_count; ++k) mesh_node->mMeshes[k] = k;
  children[static_cast<size_t>(n)].push_back(mesh_node);
  for (size_t i = 0; i <= static_cast<size_t>(n); ++i) {
    aiNode* parent = i == static_cast<size_t>(n) ? scene->mRootNode : nodes[i];
    parent->mNumChildren = static_cast<unsigned>(children[i].size());
    parent->mChildren = new_array<aiNode*>(children[i].size());
    for (size_t k = 0; k < children[i].size(); ++k) {
      parent->mChildren[k] = children[i][k];
      children[i][k]->mParent = parent;
    }
  }

  // Sprite mesh: rigid quads, or the smooth sprite mesh, in the rest pose (= the bind pose).
  std::vector<aiMesh*> meshes;
  if (sprites) {
    ExportMesh geometry;
    if (creature.smooth_skinning) {
      Result<ExportMesh> smooth = smooth_sprites(creature, options.sprites ? *options.sprites : default_sprite_set());
      if (!smooth.ok()) return Error::at(path, "", smooth.message());
      geometry = std::move(smooth.value());
    } else {
      geometry = rigid_quads(creature, model);
    }
    meshes.push_back(skinned_mesh(geometry, s, model, base + "_sprites", 0, false));
  }
  if (flesh) {
    if (s.bone_count() > 255) return Error::at(path, "skeleton", "expected at most 255 bones for a body mesh");
    meshes.push_back(skinned_mesh(body_geometry(creature), s, model, base + "_body", sprites ? 1u : 0u, true));
  }
  scene->mNumMeshes = static_cast<unsigned>(meshes.size());
  scene->mMeshes = new aiMesh*[meshes.size()];
  std::copy(meshes.begin(), meshes.end(), scene->mMeshes);

  aiMaterial* material = new aiMaterial;
  const aiString material_name("bone");
  material->AddProperty(&material_name, AI_MATKEY_NAME);
  const aiColor4D ivory(0.91f, 0.86f, 0.75f, 1.0f);
  material->AddProperty(&ivory, 1, AI_MATKEY_COLOR_DIFFUSE);
  material->AddProperty(&ivory, 1, AI_MATKEY_BASE_COLOR);
  std::error_code ec;
  if (!options.atlas_path.empty() && std::filesystem::is_regular_file(options.atlas_path, ec)) {
    namespace fs = std::filesystem;
    const fs::path out_dir = fs::absolute(fs::path(path), ec).parent_path();
    fs::path rel = fs::relative(fs::absolute(options.atlas_path, ec), out_dir, ec);
    const std::string uri = (ec || rel.empty()) ? options.atlas_path : rel.generic_string();
    const aiString tex(uri);
    material->AddProperty(&tex, AI_MATKEY_TEXTURE_DIFFUSE(0));
    material->AddProperty(&tex, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
  }
  // The body's material: white, its colours from the vertices (glTF's COLOR_0 multiplies the
  // base colour).
  aiMaterial* coat = new aiMaterial;
  const aiString coat_name("coat");
  coat->AddProperty(&coat_name, AI_MATKEY_NAME);
  const aiColor4D white(1.0f, 1.0f, 1.0f, 1.0f);
  coat->AddProperty(&white, 1, AI_MATKEY_COLOR_DIFFUSE);
  coat->AddProperty(&white, 1, AI_MATKEY_BASE_COLOR);
  std::vector<aiMaterial*> materials;
  if (sprites) materials.push_back(material);
  else delete material;
  if (flesh) materials.push_back(coat);
  else delete coat;
  scene->mNumMaterials = static_cast<unsigned>(materials.size());
  scene->mMaterials = new aiMaterial*[materials.size()];
  std::copy(materials.begin(), materials.end(), scene->mMaterials);

  MemoryFiles files;
  {
    Assimp::Exporter exporter;
    exporter.SetIOHandler(new MemoryIOSystem(files));  // the exporter owns it
    if (exporter.Export(scene.get(), "gltf2", path) != aiReturn_SUCCESS) {
      return Error::at(path, "", std::string("glTF export failed: ") + exporter.GetErrorString());
    }
  }
  if (files.count(path) == 0) return Error::at(path, "", "glTF export wrote no file");
  Result<std::string> text = with_node_matrices(files[path], *scene, path);
  if (!text.ok()) return text.error();
  files[path] = std::move(text.value());
  // The buffers first, the .gltf that refers to them last.
  for (const auto& [file, bytes] : files) {
    if (file == path) continue;
    if (Status s = write_file_atomic(file, bytes); !s.ok()) return s;
  }
  return write_file_atomic(path, files[path]);
}

}  // namespace ossa
