// An Assimp scene to a RiggedMesh (rigged_mesh.h: how 3D becomes 2D, what is rejected).
//
// [SECTION] 3D → 2D projection
// [SECTION] Scene walk (bones, hierarchy)
// [SECTION] Vertices, weights, triangles
// [SECTION] Textures
// [SECTION] The conversion

#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "ossa/render/rigged_mesh_internal.h"

namespace ossa::rigged_detail {
namespace {

// ---------------------------------------------------------------------------------------------
// [SECTION] 3D → 2D projection

constexpr float kPlaneTolerance = 1e-3f;  // relative to the matrix's scale

bool finite(const aiMatrix4x4& m) {
  const float* p = &m.a1;
  for (int i = 0; i < 16; ++i) {
    if (!std::isfinite(p[i])) return false;
  }
  return true;
}

// Projects an affine 3D matrix to 2D (see the header): keeps the x-y block and the x-y
// translation when the matrix keeps the z axis and is a similarity in x-y. Returns an empty
// string and fills `out`, or says what is wrong.
std::string project(const aiMatrix4x4& a, Mat2x3& out) {
  if (!finite(a)) return "is not finite";
  const float s = std::sqrt(std::fabs(a.a1 * a.b2 - a.a2 * a.b1));  // uniform x-y scale
  if (!(s > 1e-12f) || !std::isfinite(s)) return "is singular in the x-y plane (zero scale)";
  const float tol = kPlaneTolerance * s;
  if (std::fabs(a.a3) > tol || std::fabs(a.b3) > tol || std::fabs(a.c1) > tol ||
      std::fabs(a.c2) > tol) {
    return "rotates out of the x-y plane (a 2D rig may only rotate about z)";
  }
  if (std::fabs(a.d1) > 1e-6f || std::fabs(a.d2) > 1e-6f || std::fabs(a.d3) > 1e-6f ||
      std::fabs(a.d4 - 1.0f) > 1e-6f) {
    return "is projective, not affine";
  }
  const float len0 = std::hypot(a.a1, a.b1), len1 = std::hypot(a.a2, a.b2);
  const float dot = a.a1 * a.a2 + a.b1 * a.b2;
  if (std::fabs(len0 - len1) > tol || std::fabs(dot) > tol * s) {
    return "scales x and y differently or shears (only uniform scale is supported)";
  }
  // Mat2x3 is column-major (x' = m0 x + m2 y + m4); aiMatrix4x4 is row-major.
  out.m[0] = a.a1;
  out.m[1] = a.b1;
  out.m[2] = a.a2;
  out.m[3] = a.b2;
  out.m[4] = a.a4;
  out.m[5] = a.b4;
  return {};
}

bool same_matrix(const aiMatrix4x4& a, const aiMatrix4x4& b) {
  const float* p = &a.a1;
  const float* q = &b.a1;
  for (int i = 0; i < 16; ++i) {
    if (std::fabs(p[i] - q[i]) > 1e-4f * (1.0f + std::fabs(p[i]))) return false;
  }
  return true;
}

std::string in_quotes(const std::string& s) { return "\"" + s + "\""; }

// ---------------------------------------------------------------------------------------------
// [SECTION] Scene walk (bones, hierarchy)

struct BoneSource {
  const aiNode* node = nullptr;
  aiMatrix4x4 offset;    // aiBone::mOffsetMatrix (mesh space → bone space)
  aiMatrix4x4 global;    // node transform → scene root
};

// Guards against hostile node graphs (Assimp validates, but a cycle or a deep chain must not
// overflow our stack either).
constexpr size_t kMaxNodes = 1u << 20;
constexpr int kMaxDepth = 4096;

struct Walker {
  const std::map<std::string, size_t>& wanted;  // bone name → slot in `found`
  std::vector<BoneSource>& found;
  std::vector<int> order;          // slots in depth-first pre-order (parents first)
  std::vector<int> parent_slot;    // per slot
  size_t visited = 0;
  std::string error;

  void walk(const aiNode* node, const aiMatrix4x4& parent_global, int bone_above, int depth) {
    if (!node || !error.empty()) return;
    if (++visited > kMaxNodes || depth > kMaxDepth) {
      error = "the node hierarchy is too large or cyclic";
      return;
    }
    const aiMatrix4x4 global = parent_global * node->mTransformation;
    int here = bone_above;
    auto it = wanted.find(node->mName.C_Str());
    if (it != wanted.end() && found[it->second].node == nullptr) {
      const int slot = static_cast<int>(it->second);
      found[it->second].node = node;
      found[it->second].global = global;
      parent_slot[static_cast<size_t>(slot)] = bone_above;
      order.push_back(slot);
      here = slot;
    }
    if (node->mNumChildren > 0 && !node->mChildren) return;
    for (unsigned i = 0; i < node->mNumChildren; ++i) {
      walk(node->mChildren[i], global, here, depth + 1);
    }
  }
};

// ---------------------------------------------------------------------------------------------
// [SECTION] Vertices, weights, triangles

struct Influence {
  int bone = 0;
  float weight = 0.0f;
};

// Keeps the four largest influences and renormalises them (header: RiggedVertex::weights).
void set_weights(RiggedVertex& v, std::vector<Influence>& in) {
  std::stable_sort(in.begin(), in.end(),
                   [](const Influence& a, const Influence& b) { return a.weight > b.weight; });
  if (in.size() > kMaxRiggedWeights) in.resize(kMaxRiggedWeights);
  float sum = 0.0f;
  for (const Influence& i : in) sum += i.weight;
  if (!(sum > 0.0f) || !std::isfinite(sum)) {
    v.bones = {0, 0, 0, 0};
    v.weights = {1.0f, 0.0f, 0.0f, 0.0f};
    return;
  }
  for (size_t k = 0; k < kMaxRiggedWeights; ++k) {
    v.bones[k] = k < in.size() ? static_cast<uint8_t>(in[k].bone) : 0;
    v.weights[k] = k < in.size() ? in[k].weight / sum : 0.0f;
  }
}

struct Triangle {
  uint32_t i[3];
  float depth;  // mean z; back (small z) first
};

// ---------------------------------------------------------------------------------------------
// [SECTION] Textures

Status read_texture(const aiScene& scene, const aiMesh& mesh, const std::string& file,
                    const std::string& folder, RiggedMesh& out) {
  if (!scene.mMaterials || mesh.mMaterialIndex >= scene.mNumMaterials) return {};
  const aiMaterial* material = scene.mMaterials[mesh.mMaterialIndex];
  if (!material) return {};
  aiString path;
  if (material->GetTexture(aiTextureType_DIFFUSE, 0, &path) != AI_SUCCESS &&
      material->GetTexture(aiTextureType_BASE_COLOR, 0, &path) != AI_SUCCESS) {
    return {};
  }
  if (path.length == 0) return {};
  if (const aiTexture* t = scene.GetEmbeddedTexture(path.C_Str())) {
    return decode_embedded(*t, file, out);
  }
  if (path.C_Str()[0] == '*') {
    return Error::at(file, "texture " + in_quotes(path.C_Str()), "refers to a missing embedded texture");
  }
  namespace fs = std::filesystem;
  fs::path p(std::string(path.C_Str()));
  if (p.is_relative() && !folder.empty()) p = fs::path(folder) / p;
  out.texture_path = p.lexically_normal().generic_string();
  return {};
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// [SECTION] The conversion

Result<RiggedMesh> convert(const aiScene* scene, const std::string& file, const std::string& folder) {
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    return Error::at(file, "", "incomplete scene (no mesh data)");
  }
  // Skinned triangle meshes.
  std::vector<const aiMesh*> meshes;
  for (unsigned i = 0; i < scene->mNumMeshes && scene->mMeshes; ++i) {
    const aiMesh* m = scene->mMeshes[i];
    if (m && m->mNumBones > 0 && m->mBones && m->mNumFaces > 0 && m->mVertices &&
        (m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
      meshes.push_back(m);
    }
  }
  if (meshes.empty()) {
    return Error::at(file, "", scene->mNumMeshes == 0 ? "contains no mesh"
                                                      : "contains no triangle mesh with bones");
  }

  // Bones: the union over all skinned meshes, each with one inverse bind matrix.
  std::map<std::string, size_t> slot_of;
  std::vector<BoneSource> sources;
  for (const aiMesh* m : meshes) {
    for (unsigned b = 0; b < m->mNumBones; ++b) {
      const aiBone* bone = m->mBones[b];
      if (!bone) return Error::at(file, "", "a mesh has a null bone");
      const std::string name = bone->mName.C_Str();
      auto [it, inserted] = slot_of.emplace(name, sources.size());
      if (inserted) {
        if (sources.size() >= static_cast<size_t>(kMaxRiggedBones)) {
          return Error::at(file, "", "has more than 255 bones (the skinned shader's limit)");
        }
        sources.push_back({nullptr, bone->mOffsetMatrix, aiMatrix4x4()});
      } else if (!same_matrix(sources[it->second].offset, bone->mOffsetMatrix)) {
        return Error::at(file, "bone " + in_quotes(name),
                         "is bound differently by two meshes (merge them into one skin)");
      }
    }
  }
  Walker walker{slot_of, sources, {}, std::vector<int>(sources.size(), -1), 0, {}};
  walker.walk(scene->mRootNode, aiMatrix4x4(), -1, 0);
  if (!walker.error.empty()) return Error::at(file, "", walker.error);
  for (const auto& [name, slot] : slot_of) {
    if (!sources[slot].node) return Error::at(file, "bone " + in_quotes(name), "has no node in the scene");
  }

  // Scene placement R = global(root) · offset(root), removed from every bone (header).
  RiggedMesh out;
  out.source = file;
  const BoneSource& root = sources[static_cast<size_t>(walker.order.front())];
  aiMatrix4x4 r = root.global * root.offset;
  const float det = r.Determinant();
  if (!std::isfinite(det) || std::fabs(det) < 1e-30f || !finite(r)) {
    return Error::at(file, "bone " + in_quotes(root.node->mName.C_Str()),
                     "has a singular bind matrix");
  }
  const aiMatrix4x4 r_inv = aiMatrix4x4(r).Inverse();
  std::vector<int> index_of_slot(sources.size(), -1);
  for (int slot : walker.order) {
    const BoneSource& s = sources[static_cast<size_t>(slot)];
    RiggedBone b;
    b.name = s.node->mName.C_Str();
    const int parent_slot = walker.parent_slot[static_cast<size_t>(slot)];
    b.parent = parent_slot < 0 ? -1 : index_of_slot[static_cast<size_t>(parent_slot)];
    aiMatrix4x4 local;
    if (b.parent < 0) {
      local = r_inv * s.global;
    } else {
      aiMatrix4x4 pg = sources[static_cast<size_t>(parent_slot)].global;
      if (!finite(pg) || std::fabs(pg.Determinant()) < 1e-30f) {
        return Error::at(file, "bone " + in_quotes(b.name), "has a singular parent transform");
      }
      local = pg.Inverse() * s.global;
    }
    std::string what = project(local, b.rest_local);
    if (what.empty()) what = project(s.offset, b.inverse_bind);
    if (!what.empty()) return Error::at(file, "bone " + in_quotes(b.name), what);
    index_of_slot[static_cast<size_t>(slot)] = static_cast<int>(out.bones.size());
    out.bones.push_back(std::move(b));
  }

  // Vertices, weights, triangles of all skinned meshes.
  std::vector<Triangle> triangles;
  std::vector<float> depth;
  for (size_t mi = 0; mi < meshes.size(); ++mi) {
    const aiMesh& m = *meshes[mi];
    const std::string where = meshes.size() == 1 ? std::string("mesh") : "mesh " + std::to_string(mi);
    const uint32_t base = static_cast<uint32_t>(out.vertices.size());
    if (out.vertices.size() + m.mNumVertices > (1u << 26)) {
      return Error::at(file, where, "has too many vertices");
    }
    std::vector<std::vector<Influence>> influences(m.mNumVertices);
    for (unsigned b = 0; b < m.mNumBones; ++b) {
      const aiBone& bone = *m.mBones[b];
      const int index = index_of_slot[slot_of.at(bone.mName.C_Str())];
      if (bone.mNumWeights > 0 && !bone.mWeights) return Error::at(file, where, "a bone has no weights array");
      for (unsigned w = 0; w < bone.mNumWeights; ++w) {
        const aiVertexWeight& vw = bone.mWeights[w];
        if (vw.mVertexId >= m.mNumVertices) {
          return Error::at(file, "bone " + in_quotes(bone.mName.C_Str()), "weights a vertex out of range");
        }
        if (!std::isfinite(vw.mWeight) || vw.mWeight < 0.0f) {
          return Error::at(file, "bone " + in_quotes(bone.mName.C_Str()),
                           "has a weight that is negative or not a number");
        }
        if (vw.mWeight > 0.0f) influences[vw.mVertexId].push_back({index, vw.mWeight});
      }
    }
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D& p = m.mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        return Error::at(file, where, "vertex " + std::to_string(v) + " is not finite (NaN or inf)");
      }
      RiggedVertex rv;
      rv.position = {p.x, p.y};
      if (m.mTextureCoords[0]) {
        const aiVector3D& t = m.mTextureCoords[0][v];
        if (!std::isfinite(t.x) || !std::isfinite(t.y)) {
          return Error::at(file, where, "UV " + std::to_string(v) + " is not finite (NaN or inf)");
        }
        rv.uv = {t.x, t.y};
      }
      set_weights(rv, influences[v]);
      out.vertices.push_back(rv);
      depth.push_back(p.z);
    }
    if (!m.mFaces) return Error::at(file, where, "has no faces array");
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines (SortByPType splits them off)
      if (!face.mIndices) return Error::at(file, where, "a face has no indices");
      Triangle t{};
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= m.mNumVertices) {
          return Error::at(file, where, "face " + std::to_string(f) + " has an index out of range");
        }
        t.i[k] = base + face.mIndices[k];
        t.depth += depth[t.i[k]] / 3.0f;
      }
      triangles.push_back(t);
    }
  }
  if (triangles.empty()) return Error::at(file, "", "the skinned meshes have no triangles");
  // Draw order from depth, back to front; stable, so the file's order breaks ties.
  std::stable_sort(triangles.begin(), triangles.end(),
                   [](const Triangle& a, const Triangle& b) { return a.depth < b.depth; });
  out.indices.reserve(triangles.size() * 3);
  for (const Triangle& t : triangles) out.indices.insert(out.indices.end(), t.i, t.i + 3);

  if (Status s = read_texture(*scene, *meshes.front(), file, folder, out); !s.ok()) return s.error();
  return out;
}

}  // namespace ossa::rigged_detail
