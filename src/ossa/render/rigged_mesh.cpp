#include "ossa/render/rigged_mesh.h"

// The entry points of the rigged-mesh import and texture decoding (stb_image). The scene
// conversion is in rigged_mesh_convert.cpp, the checks before Assimp in
// rigged_mesh_precheck.cpp, skinning in rigged_skinning.cpp.

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/scene.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "ossa/draw/image.h"
#include "ossa/io/file.h"
#include "ossa/io/image_info.h"
#include "ossa/render/rigged_mesh_internal.h"

namespace ossa {

namespace rigged_detail {

Status decode_embedded(const aiTexture& t, const std::string& file, RiggedMesh& out) {
  if (!t.pcData) return Error::at(file, "embedded texture", "has no data");
  if (t.mHeight == 0) {  // compressed (PNG, JPEG, ...): mWidth bytes
    if (t.mWidth == 0 || t.mWidth > (1u << 30)) return Error::at(file, "embedded texture", "is empty");
    // Its size from the header before stb_image allocates it (draw/image.h).
    Result<Image> image = decode_image({reinterpret_cast<const char*>(t.pcData), t.mWidth}, file + ": embedded texture");
    if (!image) return image.error();
    out.texture_width = image->width;
    out.texture_height = image->height;
    out.texture_rgba = std::move(image->rgba);
    return {};
  }
  if (t.mWidth > kMaxImageSide || t.mHeight > kMaxImageSide ||
      static_cast<int64_t>(t.mWidth) * t.mHeight > kMaxImagePixels) {
    return Error::at(file, "embedded texture", "is " + std::to_string(t.mWidth) + " × " + std::to_string(t.mHeight) +
                                                   " pixels; images may be at most " + std::to_string(kMaxImageSide) +
                                                   " pixels on a side and " + std::to_string(kMaxImagePixels) + " in all");
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

void configure(Assimp::Importer& importer) {
  importer.SetPropertyInteger(AI_CONFIG_PP_LBW_MAX_WEIGHTS, kMaxRiggedWeights);
  // Keep lines and points out of the scene altogether.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
}

}  // namespace rigged_detail

namespace {

std::string assimp_error(const Assimp::Importer& importer) {
  const char* e = importer.GetErrorString();
  return std::string("cannot import: ") + (e && *e ? e : "unknown error");
}

// Every file Assimp opens goes through the input rule (io/file.h) here: a regular file of at
// most kMaxDataFileBytes, at most rigged_detail::kMaxMeshFilesBytes for the mesh and every file it names
// together, read whole into memory (so a file swapped for a pipe cannot block a read), never
// written. A glTF buffer that is a pipe made Assimp wait for ever; a 3 GB one was read whole.
class CheckedIOSystem : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override {
    struct stat st {};
    return file && ::stat(file, &st) == 0;  // (the default opens the file: a pipe blocks)
  }

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (!file || !mode || std::strpbrk(mode, "wa+")) return nullptr;
    Result<std::string> bytes = read_file(file);
    if (bytes && total_ + static_cast<long long>(bytes->size()) > rigged_detail::kMaxMeshFilesBytes) {
      bytes = Error::at(file, "", "would take the files of this mesh past " + std::to_string(rigged_detail::kMaxMeshFilesBytes) + " bytes in all");
    }
    if (!bytes) {
      if (refused.empty()) refused = bytes.message();
      return nullptr;
    }
    total_ += static_cast<long long>(bytes->size());
    files.push_back(file);
    auto* data = new uint8_t[std::max<size_t>(bytes->size(), 1)];
    std::memcpy(data, bytes->data(), bytes->size());
    return new Assimp::MemoryIOStream(data, bytes->size(), true);
  }

  std::string refused;              // the first file refused, and why
  std::vector<std::string> files;   // every file read

 private:
  long long total_ = 0;
};

}  // namespace

using namespace rigged_detail;

int RiggedMesh::find_bone(std::string_view name) const {
  for (size_t i = 0; i < bones.size(); ++i) {
    if (bones[i].name == name) return static_cast<int>(i);
  }
  return -1;
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
    auto* io = new CheckedIOSystem;  // owned by the importer
    importer.SetIOHandler(io);
    const aiScene* scene = importer.ReadFile(path, kImportFlags);
    if (!scene && !io->refused.empty()) return Error::at(path, "", "a file it refers to: " + io->refused);
    if (!scene) return Error::at(path, "", assimp_error(importer));
    Result<RiggedMesh> mesh = convert(scene, path, fs::path(path).parent_path().generic_string());
    if (mesh) mesh->files = io->files;
    return mesh;
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
    auto* io = new CheckedIOSystem;  // owned by the importer; no file should be opened
    importer.SetIOHandler(io);
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags,
                                                       hint.c_str());
    if (!scene && !io->refused.empty()) return Error::at(name, "", "a file it refers to: " + io->refused);
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
  // The size from the header before decoding (a 55 KB PNG may declare 16384 × 16384).
  Result<Image> image = decode_image_file(mesh.texture_path);
  if (!image) return image.error();
  mesh.texture_width = image->width;
  mesh.texture_height = image->height;
  mesh.texture_rgba = std::move(image->rgba);
  return {};
}

}  // namespace ossa
