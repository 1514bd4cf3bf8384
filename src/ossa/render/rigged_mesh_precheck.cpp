// The checks before Assimp sees a file (rigged_mesh.h): which formats reach it, the glTF
// inputs it crashes on, and a trial import of FBX and DAE in a child process.

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

#include "ossa/io/json.h"
#include "ossa/render/rigged_mesh_internal.h"

namespace ossa::rigged_detail {

namespace {

// Deepest node hierarchy a glTF may have. Assimp 5.2 walks the hierarchy recursively (import,
// validation, destruction): a 20 000-node chain overflowed its stack. A skeleton is a few
// dozen nodes deep; long tails or hair chains a few hundred.
constexpr uint32_t kMaxNodeDepth = 1024;

// The glTF node graph must be trees (one parent per node, no cycles) at most kMaxNodeDepth
// deep; checked iteratively before Assimp sees it. Children out of range are Assimp's to
// report.
Status check_node_tree(const Json& doc, const std::string& file) {
  auto nodes = doc.find("nodes");
  if (nodes == doc.end() || !nodes->is_array()) return {};
  const size_t n = nodes->size();
  const auto children = [&](size_t i) -> const Json* {
    const Json& node = (*nodes)[i];
    if (!node.is_object()) return nullptr;
    auto c = node.find("children");
    return c != node.end() && c->is_array() ? &*c : nullptr;
  };
  const auto child_index = [&](const Json& c) -> std::optional<size_t> {
    if (!c.is_number_unsigned() || c.get<uint64_t>() >= n) return std::nullopt;
    return static_cast<size_t>(c.get<uint64_t>());
  };
  std::vector<int64_t> parent(n, -1);
  for (size_t i = 0; i < n; ++i) {
    const Json* list = children(i);
    if (!list) continue;
    for (const Json& c : *list) {
      const std::optional<size_t> k = child_index(c);
      if (!k) continue;
      const std::string field = json_path(json_path("nodes", i), "children");
      if (*k == i) return Error::at(file, field, "node " + std::to_string(i) + " is its own ancestor");
      if (parent[*k] >= 0) {
        return Error::at(file, field, "node " + std::to_string(*k) + " already has a parent (node " +
                                          std::to_string(parent[*k]) + "); glTF nodes form trees");
      }
      parent[*k] = static_cast<int64_t>(i);
    }
  }
  std::vector<uint32_t> depth(n, 0);
  std::vector<size_t> stack;
  for (size_t root = 0; root < n; ++root) {
    if (parent[root] >= 0) continue;
    depth[root] = 1;
    stack.push_back(root);
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      if (depth[i] > kMaxNodeDepth) {
        return Error::at(file, "nodes", "the node hierarchy is more than " + std::to_string(kMaxNodeDepth) +
                                            " nodes deep (at node " + std::to_string(i) + "); a skeleton needs far fewer");
      }
      if (const Json* list = children(i)) {
        for (const Json& c : *list) {
          if (const std::optional<size_t> k = child_index(c)) {
            depth[*k] = depth[i] + 1;
            stack.push_back(*k);
          }
        }
      }
    }
  }
  // Every node reached from a root; the others hang in a cycle.
  for (size_t i = 0; i < n; ++i) {
    if (depth[i] == 0) {
      return Error::at(file, json_path(json_path("nodes", static_cast<size_t>(parent[i])), "children"),
                       "node " + std::to_string(i) + " is its own ancestor");
    }
  }
  return {};
}

}  // namespace

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
  if (Status s = check_node_tree(doc, file); !s.ok()) return s;
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

}  // namespace ossa::rigged_detail
