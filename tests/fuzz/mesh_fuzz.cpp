// Fuzzes the rigged-mesh importer (Assimp + our 3D → 2D conversion) through
// load_rigged_mesh_from_memory (DESIGN.md §11: no input file, however malformed, may crash).
// Any input must give an error naming the data, or a mesh whose invariants hold: parents
// first, bone indices in range, weights >= 0 summing to 1, indices in range, finite values.
// Needs ossa::render (Assimp): tests/fuzz/CMakeLists.txt must link fuzz_mesh with it.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

#include "ossa/render/rigged_mesh.h"

namespace {

// The format hint from the content (Assimp also sniffs signatures, the hint only orders them).
const char* hint_for(std::string_view s) {
  if (s.substr(0, 4) == "glTF") return "glb";
  if (s.find("COLLADA") != std::string_view::npos) return "dae";
  if (s.find("FBX") != std::string_view::npos || s.find("Kaydara") != std::string_view::npos) return "fbx";
  return "gltf";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ossa::Result<ossa::RiggedMesh> r =
      ossa::load_rigged_mesh_from_memory(std::span<const uint8_t>(data, size), hint_for(text), "fuzz.mesh");
  if (!r.ok()) {
    if (r.message().rfind("fuzz.mesh", 0) != 0) std::abort();
    return 0;
  }
  const ossa::RiggedMesh& m = *r;
  if (m.bones.empty() || m.bones.size() > ossa::kMaxRiggedBones) std::abort();
  for (size_t i = 0; i < m.bones.size(); ++i) {
    if (m.bones[i].parent >= static_cast<int>(i)) std::abort();
    for (float v : m.bones[i].inverse_bind.m) if (!std::isfinite(v)) std::abort();
    for (float v : m.bones[i].rest_local.m) if (!std::isfinite(v)) std::abort();
  }
  for (const ossa::RiggedVertex& v : m.vertices) {
    if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y)) std::abort();
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      if (v.bones[k] >= m.bones.size() || !(v.weights[k] >= 0.0f)) std::abort();
      sum += v.weights[k];
    }
    if (std::fabs(sum - 1.0f) > 1e-4f) std::abort();
  }
  if (m.indices.size() % 3 != 0) std::abort();
  for (uint32_t i : m.indices) if (i >= m.vertices.size()) std::abort();
  if (!m.texture_rgba.empty() &&
      m.texture_rgba.size() != static_cast<size_t>(m.texture_width) * m.texture_height * 4) {
    std::abort();
  }
  return 0;
}
