#include "ossa/render/gltf_export.h"

#include <assimp/Exporter.hpp>
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ossa/io/file.h"
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
  aiNode* mesh_node = new aiNode((creature.name.empty() ? "creature" : creature.name) + "_mesh");
  mesh_node->mNumMeshes = 1;
  mesh_node->mMeshes = new unsigned[1]{0};
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

  // Sprite mesh: a quad per bone in the bind pose, weighted to its bone.
  aiMesh* mesh = new aiMesh;
  mesh->mName = (creature.name.empty() ? "creature" : creature.name) + "_sprites";
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mMaterialIndex = 0;
  mesh->mNumVertices = static_cast<unsigned>(4 * n);
  mesh->mVertices = new aiVector3D[mesh->mNumVertices];
  mesh->mNormals = new aiVector3D[mesh->mNumVertices];
  mesh->mTextureCoords[0] = new aiVector3D[mesh->mNumVertices];
  mesh->mNumUVComponents[0] = 2;
  mesh->mNumFaces = static_cast<unsigned>(2 * n);
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  mesh->mNumBones = static_cast<unsigned>(n);
  mesh->mBones = new aiBone*[static_cast<size_t>(n)];
  static constexpr float kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < n; ++i) {
    const Mat2x3& m = model[static_cast<size_t>(i)];
    const float fallback = 0.01f * std::max(1.0f, creature.scale * 1000.0f);
    float length = s.length(i), width = s.width(i);
    if (!(length > 0.0f) || !std::isfinite(length)) length = std::max(width, fallback);
    if (!(width > 0.0f) || !std::isfinite(width)) width = std::max(0.15f * length, fallback);
    const unsigned v0 = static_cast<unsigned>(4 * i);
    // Depth: far side behind, near side in front (1 mm), plus a tiny per-bone step. Besides
    // giving a draw order, it keeps the vertices of the near and far copies (which coincide in
    // x, y) apart: Assimp's glTF exporter enforces JoinIdenticalVertices, which in 5.2 ignores
    // bone weights and would merge them, dropping the near copy's weights.
    const float z = 0.001f * (static_cast<float>(s.layer(i)) - 1.0f) + 1e-6f * static_cast<float>(i);
    for (unsigned k = 0; k < 4; ++k) {
      const glm::vec2 p = m.apply({kCorner[k][0] * length, (kCorner[k][1] - 0.5f) * width});
      mesh->mVertices[v0 + k] = aiVector3D(p.x, p.y, z);
      mesh->mNormals[v0 + k] = aiVector3D(0.0f, 0.0f, 1.0f);
      mesh->mTextureCoords[0][v0 + k] = aiVector3D(kCorner[k][0], kCorner[k][1], 0.0f);
    }
    for (unsigned f = 0; f < 2; ++f) {
      aiFace& face = mesh->mFaces[2 * i + f];
      face.mNumIndices = 3;
      face.mIndices = new unsigned[3];
      face.mIndices[0] = v0;
      face.mIndices[1] = v0 + 1 + f;
      face.mIndices[2] = v0 + 2 + f;
    }
    aiBone* bone = new aiBone;
    bone->mName = s.name(i);
    bone->mOffsetMatrix = to_ai(inverse(m));  // mesh (model) space → bone space
    bone->mNumWeights = 4;
    bone->mWeights = new aiVertexWeight[4];
    for (unsigned k = 0; k < 4; ++k) bone->mWeights[k] = aiVertexWeight(v0 + k, 1.0f);
    mesh->mBones[i] = bone;
  }
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1]{mesh};

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
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{material};

  MemoryFiles files;
  {
    Assimp::Exporter exporter;
    exporter.SetIOHandler(new MemoryIOSystem(files));  // the exporter owns it
    if (exporter.Export(scene.get(), "gltf2", path) != aiReturn_SUCCESS) {
      return Error::at(path, "", std::string("glTF export failed: ") + exporter.GetErrorString());
    }
  }
  if (files.count(path) == 0) return Error::at(path, "", "glTF export wrote no file");
  // The buffers first, the .gltf that refers to them last.
  for (const auto& [file, bytes] : files) {
    if (file == path) continue;
    if (Status s = write_file_atomic(file, bytes); !s.ok()) return s;
  }
  return write_file_atomic(path, files[path]);
}

}  // namespace ossa
