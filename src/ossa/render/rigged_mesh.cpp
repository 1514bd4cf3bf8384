#include "ossa/render/rigged_mesh.h"

// [SECTION] 3D → 2D projection
// [SECTION] Scene walk (bones, hierarchy)
// [SECTION] Vertices, weights, triangles
// [SECTION] Textures
// [SECTION] Entry points
// [SECTION] Skinning
// [SECTION] Rig mapping

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>
#include <map>
#include <memory>
#include <numeric>
#include <utility>

#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/skeleton/pose.h"

// stb_image, static so that it cannot clash with another translation unit of ossa::render (or
// Assimp) compiling its own copy.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace ossa {
namespace {

// ---------------------------------------------------------------------------------------------
// [SECTION] 3D → 2D projection

constexpr float kPlaneTolerance = 1e-3f;  // relative to the matrix's scale
constexpr int kMaxTextureSide = 16384;    // pixels; larger embedded textures are rejected

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

Status decode_embedded(const aiTexture& t, const std::string& file, RiggedMesh& out) {
  if (!t.pcData) return Error::at(file, "embedded texture", "has no data");
  if (t.mHeight == 0) {  // compressed (PNG, JPEG, ...): mWidth bytes
    if (t.mWidth == 0 || t.mWidth > (1u << 30)) return Error::at(file, "embedded texture", "is empty");
    int w = 0, h = 0, n = 0;
    stbi_uc* px = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(t.pcData),
                                        static_cast<int>(t.mWidth), &w, &h, &n, 4);
    if (!px) {
      return Error::at(file, "embedded texture",
                       std::string("cannot be decoded: ") + stbi_failure_reason());
    }
    out.texture_rgba.assign(px, px + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
    stbi_image_free(px);
    out.texture_width = w;
    out.texture_height = h;
    return {};
  }
  if (t.mWidth > kMaxTextureSide || t.mHeight > kMaxTextureSide) {
    return Error::at(file, "embedded texture", "is larger than 16384 pixels");
  }
  const size_t n = static_cast<size_t>(t.mWidth) * t.mHeight;
  out.texture_rgba.resize(n * 4);
  for (size_t i = 0; i < n; ++i) {  // aiTexel is BGRA
    out.texture_rgba[4 * i + 0] = t.pcData[i].r;
    out.texture_rgba[4 * i + 1] = t.pcData[i].g;
    out.texture_rgba[4 * i + 2] = t.pcData[i].b;
    out.texture_rgba[4 * i + 3] = t.pcData[i].a;
  }
  out.texture_width = static_cast<int>(t.mWidth);
  out.texture_height = static_cast<int>(t.mHeight);
  return {};
}

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

// ---------------------------------------------------------------------------------------------
// [SECTION] Entry points

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

// Guards against inputs that crash Assimp 5.2 itself (found by tests/fuzz/mesh_fuzz.cpp).
// - a glTF skin without "inverseBindMatrices" (optional in the spec, identity by default)
//   makes its importer dereference a null accessor;
// - inverse bind matrices reaching past their buffer view are read out of bounds.
// glTF (JSON) and GLB (JSON chunk) are pre-parsed for that; anything unparsable is left to
// Assimp, which reports it.
Status precheck(std::string_view bytes, const std::string& file) {
  // Only glTF, FBX and DAE reach Assimp: its other ~40 importers are not needed here and
  // some crash or allocate terabytes on garbage (e.g. a 27-byte "quick3ds..." file).
  const std::string_view head = bytes.substr(0, 4096);
  const bool fbx = bytes.substr(0, 18) == "Kaydara FBX Binary" ||
                   head.find("FBXHeaderExtension") != std::string_view::npos;
  const bool dae = head.find("<COLLADA") != std::string_view::npos;
  if (fbx || dae) return {};
  std::string_view json;
  if (bytes.size() >= 20 && bytes.substr(0, 4) == "glTF") {
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    if (bytes.substr(16, 4) != "JSON" || length > bytes.size() - 20) {
      return Error::at(file, "", "is a broken GLB file (no JSON chunk)");
    }
    json = bytes.substr(20, length);
  } else {
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos || bytes[first] != '{') {
      return Error::at(file, "", "is not a glTF 2.0, FBX or DAE (COLLADA) file");
    }
    json = bytes;
  }
  // glTF is UTF-8 JSON; Assimp's parser accepts some invalid input (e.g. bad UTF-8 in a key,
  // which hides "inverseBindMatrices" from it), so what nlohmann rejects is rejected here.
  Result<Json> parsed = parse_json(json, file);
  if (!parsed.ok()) return parsed.error();
  const Json& doc = *parsed;
  if (!doc.is_object()) return {};
  auto skins = doc.find("skins");
  if (skins == doc.end() || !skins->is_array()) return {};
  auto accessors = doc.find("accessors");
  for (size_t i = 0; i < skins->size(); ++i) {
    const Json& skin = (*skins)[i];
    const Json* ibm = skin.is_object() && skin.contains("inverseBindMatrices")
                          ? &skin["inverseBindMatrices"] : nullptr;
    const bool valid = ibm && ibm->is_number_unsigned() && accessors != doc.end() &&
                       accessors->is_array() && ibm->get<size_t>() < accessors->size() &&
                       (*accessors)[ibm->get<size_t>()].is_object() &&
                       (*accessors)[ibm->get<size_t>()].contains("type") &&
                       (*accessors)[ibm->get<size_t>()]["type"] == Json("MAT4");
    // Assimp 5.2 copies count · 64 bytes without checking the buffer view: check it here.
    bool in_bounds = false;
    if (valid) {
      const Json& acc = (*accessors)[ibm->get<size_t>()];
      auto views = doc.find("bufferViews");
      const Json* joints = skin.contains("joints") ? &skin["joints"] : nullptr;
      const Json* view_index = acc.contains("bufferView") ? &acc["bufferView"] : nullptr;
      if (joints && joints->is_array() && view_index && view_index->is_number_unsigned() &&
          views != doc.end() && views->is_array() && view_index->get<size_t>() < views->size() &&
          acc.contains("count") && acc["count"].is_number_unsigned() &&
          acc.contains("componentType") && acc["componentType"] == Json(5126)) {
        const Json& view = (*views)[view_index->get<size_t>()];
        const Json offset = acc.contains("byteOffset") ? acc["byteOffset"] : Json(uint64_t{0});
        const uint64_t count = acc["count"].get<uint64_t>();
        if (view.is_object() && view.contains("byteLength") && view["byteLength"].is_number_unsigned() &&
            offset.is_number_unsigned() && count >= joints->size() && count < (1u << 24) &&
            offset.get<uint64_t>() < (1ull << 40)) {
          in_bounds = offset.get<uint64_t>() + count * 64 <= view["byteLength"].get<uint64_t>();
        }
      }
    }
    if (valid && !in_bounds) {
      return Error::at(file, json_path(json_path("skins", i), "inverseBindMatrices"),
                       "expected a float MAT4 accessor with one matrix per joint inside its "
                       "buffer view");
    }
    if (!valid) {
      return Error::at(file, json_path("skins", i),
                       "expected \"inverseBindMatrices\" (the index of a MAT4 accessor); Assimp "
                       "5.2 cannot import a skin without them");
    }
  }
  return {};
}

constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_LimitBoneWeights | aiProcess_SortByPType |
                                  aiProcess_FlipUVs | aiProcess_ValidateDataStructure;

void configure(Assimp::Importer& importer) {
  importer.SetPropertyInteger(AI_CONFIG_PP_LBW_MAX_WEIGHTS, kMaxRiggedWeights);
  // Keep lines and points out of the scene altogether.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
}

std::string assimp_error(const Assimp::Importer& importer) {
  const char* e = importer.GetErrorString();
  return std::string("cannot import: ") + (e && *e ? e : "unknown error");
}

}  // namespace

int RiggedMesh::find_bone(std::string_view name) const {
  for (size_t i = 0; i < bones.size(); ++i) {
    if (bones[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

// FBX and DAE are parsed by Assimp alone, and its 5.2 COLLADA parser still crashes on some
// malformed files (tests/fuzz/mesh_fuzz.cpp finds them). Those formats are first imported in
// a forked child: if the child dies, the file is reported as unreadable instead of taking the
// tool (or the game, with unsaved work) down with it.
Status probe_import_in_child(std::span<const uint8_t> bytes, const std::string& hint, const std::string& name) {
  const std::string_view head(reinterpret_cast<const char*>(bytes.data()), std::min<size_t>(bytes.size(), 4096));
  const bool fbx = head.substr(0, 18) == "Kaydara FBX Binary" || head.find("FBXHeaderExtension") != std::string_view::npos;
  const bool dae = head.find("<COLLADA") != std::string_view::npos;
  if (!fbx && !dae) return {};
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return {};  // no probe possible; import directly
  if (pid == 0) {
    Assimp::Importer importer;
    configure(importer);
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags, hint.c_str());
    ::_exit(scene ? 0 : 1);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    return Error::at(name, "", std::string("is a malformed ") + (dae ? "DAE" : "FBX") +
                                   " file: the importer crashed reading it (signal " + std::to_string(WTERMSIG(status)) + ")");
  }
  return {};
}

Result<RiggedMesh> load_rigged_mesh(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    return Error::at(path, "", fs::exists(path, ec) ? "is not a regular file" : "no such file");
  }
  if (fs::file_size(path, ec) == 0) return Error::at(path, "", "is empty");
  try {
    Result<std::string> bytes = read_file(path);
    if (!bytes.ok()) return bytes.error();
    if (Status s = precheck(*bytes, path); !s.ok()) return s.error();
    const std::string ext = fs::path(path).extension().string();
    const std::span<const uint8_t> raw(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size());
    if (Status s = probe_import_in_child(raw, ext.empty() ? "" : ext.substr(1), path); !s.ok()) return s.error();
    Assimp::Importer importer;
    configure(importer);
    const aiScene* scene = importer.ReadFile(path, kImportFlags);
    if (!scene) return Error::at(path, "", assimp_error(importer));
    return convert(scene, path, fs::path(path).parent_path().generic_string());
  } catch (const std::exception& e) {
    return Error::at(path, "", std::string("cannot import: ") + e.what());
  } catch (...) {
    return Error::at(path, "", "cannot import: unknown exception");
  }
}

Result<RiggedMesh> load_rigged_mesh_from_memory(std::span<const uint8_t> bytes,
                                                const std::string& hint, const std::string& name) {
  if (bytes.empty()) return Error::at(name, "", "is empty");
  try {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (Status s = precheck(text, name); !s.ok()) return s.error();
    if (Status s = probe_import_in_child(bytes, hint, name); !s.ok()) return s.error();
    Assimp::Importer importer;
    configure(importer);
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags,
                                                       hint.c_str());
    if (!scene) return Error::at(name, "", assimp_error(importer));
    return convert(scene, name, "");
  } catch (const std::exception& e) {
    return Error::at(name, "", std::string("cannot import: ") + e.what());
  } catch (...) {
    return Error::at(name, "", "cannot import: unknown exception");
  }
}

Status load_rigged_texture(RiggedMesh& mesh) {
  if (!mesh.texture_rgba.empty()) return {};
  if (mesh.texture_path.empty()) return Error::at(mesh.source, "texture", "the mesh has none");
  Result<std::string> bytes = read_file(mesh.texture_path);
  if (!bytes.ok()) return bytes.error();
  int w = 0, h = 0, n = 0;
  stbi_uc* px = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes->data()),
                                      static_cast<int>(bytes->size()), &w, &h, &n, 4);
  if (!px) return Error::at(mesh.texture_path, "", std::string("cannot decode: ") + stbi_failure_reason());
  mesh.texture_rgba.assign(px, px + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  stbi_image_free(px);
  mesh.texture_width = w;
  mesh.texture_height = h;
  return {};
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Skinning

std::vector<Mat2x3> rest_locals(const RiggedMesh& mesh) {
  std::vector<Mat2x3> locals;
  locals.reserve(mesh.bones.size());
  for (const RiggedBone& b : mesh.bones) locals.push_back(b.rest_local);
  return locals;
}

Mat2x3 rotated_local(const Mat2x3& local, float angle) {
  Mat2x3 r;
  r.m[0] = std::cos(angle);
  r.m[1] = std::sin(angle);
  r.m[2] = -r.m[1];
  r.m[3] = r.m[0];
  return local * r;
}

bool RiggedPaletteJob::validate() const {
  if (!mesh) return false;
  const size_t n = mesh->bones.size();
  if (locals.size() != n || world.size() != n || palette.size() != n) return false;
  for (size_t i = 0; i < n; ++i) {
    if (mesh->bones[i].parent >= static_cast<int>(i)) return false;
  }
  return true;
}

bool RiggedPaletteJob::run() const {
  if (!validate()) return false;
  // Parents precede children, so one pass gives every world matrix (pose.h FK).
  for (size_t i = 0; i < mesh->bones.size(); ++i) {
    const int p = mesh->bones[i].parent;
    world[i] = (p < 0 ? model_to_world : world[static_cast<size_t>(p)]) * locals[i];
    palette[i] = world[i] * mesh->bones[i].inverse_bind;
  }
  return true;
}

std::vector<Mat2x3> rigged_palette(const RiggedMesh& mesh, std::span<const Mat2x3> locals,
                                   const Mat2x3& model_to_world) {
  std::vector<Mat2x3> world(mesh.bones.size()), palette(mesh.bones.size());
  RiggedPaletteJob job{&mesh, locals, model_to_world, world, palette};
  OSSA_ASSERT(job.run(), "rigged_palette: one local per bone expected");
  return palette;
}

glm::vec2 skin_position(const RiggedVertex& vertex, std::span<const Mat2x3> palette) {
  glm::vec2 p{0.0f};
  for (int k = 0; k < kMaxRiggedWeights; ++k) {
    if (vertex.weights[k] == 0.0f) continue;
    OSSA_ASSERT(vertex.bones[k] < palette.size(), "skin_position: bone index outside the palette");
    p += vertex.weights[k] * palette[vertex.bones[k]].apply(vertex.position);
  }
  return p;
}

}  // namespace ossa
