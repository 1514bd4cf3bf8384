#pragma once
// Internals of the rigged-mesh import (rigged_mesh.h), shared by its files: rigged_mesh.cpp
// (the entry points and texture decoding), rigged_mesh_convert.cpp (an Assimp scene to a
// RiggedMesh), rigged_mesh_precheck.cpp (the checks before Assimp sees a file) and
// rigged_skinning.cpp. Not a public interface.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include <assimp/postprocess.h>

#include "ossa/io/result.h"
#include "ossa/render/rigged_mesh.h"

struct aiScene;
struct aiTexture;
namespace Assimp {
class Importer;
}

namespace ossa::rigged_detail {

// The mesh file and every file it names (glTF buffers) together, bytes.
constexpr long long kMaxMeshFilesBytes = 256LL * 1024 * 1024;

constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_LimitBoneWeights | aiProcess_SortByPType |
                                  aiProcess_FlipUVs | aiProcess_ValidateDataStructure;

// The importer's properties (at most kMaxRiggedWeights weights, no points or lines).
void configure(Assimp::Importer& importer);

// rigged_mesh_convert.cpp: the skinned meshes of an imported scene as one RiggedMesh (the
// header's rules); `folder` resolves a texture file named by the material.
Result<RiggedMesh> convert(const aiScene* scene, const std::string& file, const std::string& folder);

// rigged_mesh.cpp: an embedded texture decoded into out.texture_rgba.
Status decode_embedded(const aiTexture& t, const std::string& file, RiggedMesh& out);

// rigged_mesh_precheck.cpp: refuses what Assimp 5.2 cannot read safely, before it sees it.
Status precheck(std::string_view bytes, const std::string& file);
// FBX and DAE: a trial import in a forked child (see the definition).
Status probe_import_in_child(std::span<const uint8_t> bytes, const std::string& hint, const std::string& name);

}  // namespace ossa::rigged_detail
