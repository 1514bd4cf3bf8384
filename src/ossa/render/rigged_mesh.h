#pragma once
// RiggedMesh — a skinned 2D sprite character made in another tool (Blender, Spine-like
// editors, tools/ossa-make-character) and imported through Assimp: glTF 2.0, FBX or DAE
// (DESIGN.md §9, [T 4.2.4]: [T]'s character came as FBX). CPU side only, no OpenGL here: the
// renderer uploads `vertices`/`indices` once and draws them with the skinned program
// ([T 4.3.1] RiggedShader), reading the palette computed by RiggedPaletteJob.
//
// [SECTION] Mesh data      RiggedVertex, RiggedBone, RiggedMesh
// [SECTION] Import         load_rigged_mesh, load_rigged_mesh_from_memory, load_rigged_texture
// [SECTION] Skinning       rest_locals, RiggedPaletteJob, rigged_palette, skin_position
//
// Which bones play which part for the animator (the rig mapping, *.rig.json) is a core type:
// ossa/rig/rig_mapping.h; ossa/render/character_mesh.h loads a mapping with its mesh.
//
// How 3D becomes 2D
// -----------------
// Model space of a RiggedMesh is the mesh's bind space: the space its vertices were authored
// in, +x forward (the character faces +x), +y up, units as in the file (the shipped character
// is in metres). Vertex positions keep x and y; z is dropped but used once: triangles are
// sorted back to front by their mean z (stable), so a far arm (z < 0) is drawn before the
// torso and a near arm (z > 0) after it, with one draw call.
// Every 3D matrix (node transforms, inverse bind matrices) is projected to a Mat2x3 by keeping
// its upper-left 2×2 block and its x, y translation. That is exact when the matrix keeps the
// z axis: rotations about z, translations, uniform scale in x and y (also a mirror, e.g. a
// bone rolled 180° about its own axis; Mat2x3 holds it and palettes cancel it). The whole-scene
// placement (an FBX axis conversion, a mesh node's transform, a unit scale) is removed first:
// bone transforms are expressed relative to R = global(root bone) · inverse_bind(root bone),
// so at rest the root's palette entry is the identity whatever the exporter put above it. The
// root's rest transform therefore equals its bind transform (a file whose root rests away
// from its bind pose loads in its bind pose; the animator places the root anyway), and an
// out-of-plane placement above the root is removed rather than rejected.
// REJECTED, with an Error naming the file and the bone: a matrix that couples z with x or y
// (rotation about another axis, beyond 1e-3 of its scale), non-uniform x/y scale or shear
// (beyond 1e-3), a singular or non-finite matrix.
// Also rejected: any format but glTF 2.0 (.gltf/.glb), FBX and DAE (sniffed from the content,
// before Assimp sees it), a glTF skin without inverseBindMatrices (Assimp 5.2 crashes on
// those), a file Assimp cannot read, no mesh with bones, more than kMaxRiggedBones
// bones, two meshes that bind one bone differently, non-finite positions, UVs or weights,
// negative weights, and indices out of range. No input, however malformed, crashes.
// Before Assimp sees a glTF: its JSON is parsed with parse_json (nesting at most kMaxJsonDepth:
// Assimp's reader recurses), and its nodes must form trees at most 1 024 deep (Assimp's node
// import recurses). Every file Assimp opens — the mesh, glTF buffers — follows the input rule
// of io/file.h (regular files of at most 64 MiB, 256 MiB together; a pipe is refused, not
// waited on). Textures are sized from their header before decoding (io/image_info.h).

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/io/result.h"
#include "ossa/math/transform2d.h"

namespace ossa {

// ---------------------------------------------------------------------------------------------
// [SECTION] Mesh data

// Bone indices are stored as uint8, so a mesh holds at most 255 bones (0..254).
constexpr int kMaxRiggedBones = 255;
// Weights per vertex the skinned shader reads.
constexpr int kMaxRiggedWeights = 4;

// One vertex as the skinned shader reads it.
struct RiggedVertex {
  glm::vec2 position{0.0f};        // bind-pose model space (see above), file units
  glm::vec2 uv{0.0f};              // texture coordinates, (0,0) = top-left of the image, v
                                   // down (glTF's convention; Assimp's FlipUVs gives it for
                                   // every format), so image rows upload top row first
  std::array<uint8_t, 4> bones{};  // indices into RiggedMesh::bones; unused slots 0
  std::array<float, 4> weights{};  // >= 0, sorted descending, sum to 1 (±1e-6); unused 0.
                                   // More than four influences: the smallest are dropped and
                                   // the rest renormalised. A vertex with no influence gets
                                   // the root bone with weight 1.
};

struct RiggedBone {
  std::string name;          // node name in the file; unique within the mesh
  int parent = -1;           // index of the parent bone (< own index), -1 for a root
  Mat2x3 inverse_bind;       // model space → bone frame in the bind pose
  Mat2x3 rest_local;         // bone frame → parent bone frame (model space for a root) in the
                             // rest pose stored in the file's nodes; non-bone nodes between
                             // two bones are folded in
};

struct RiggedMesh {
  std::vector<RiggedVertex> vertices;
  std::vector<uint32_t> indices;   // triangles, back to front (see above)
  std::vector<RiggedBone> bones;   // parents first
  std::string source;              // the file (or name) it was loaded from, for messages
  std::vector<std::string> files;  // every file read for it (the mesh, its glTF buffers): a
                                   // tool never writes over one of them (io/file.h)
  // Texture of the first skinned mesh's material (diffuse / base colour), if any:
  std::string texture_path;        // a file: resolved against the model's folder; empty when
                                   // there is none or it is embedded
  std::vector<uint8_t> texture_rgba;  // an embedded texture, decoded: width·height·4 bytes,
                                      // rows top to bottom (or filled by load_rigged_texture)
  int texture_width = 0;
  int texture_height = 0;

  // Index of the bone named `name`, or -1.
  int find_bone(std::string_view name) const;
};

// ---------------------------------------------------------------------------------------------
// [SECTION] Import

// Loads a rigged mesh from a file (format by extension and content: .gltf/.glb, .fbx, .dae).
// Post-processing: Triangulate, JoinIdenticalVertices, LimitBoneWeights (4),
// SortByPType, FlipUVs, ValidateDataStructure (missing UVs are zeros). Meshes without bones
// and point/line primitives are ignored; all skinned meshes are merged into one.
// Errors name the file and what is wrong ("humanoid.gltf: bone \"thigh_l\": rotates out of
// the x-y plane ..."). A texture file is not read here (see load_rigged_texture).
Result<RiggedMesh> load_rigged_mesh(const std::string& path);

// The same from bytes in memory; `hint` is the format extension without the dot ("gltf",
// "glb", "fbx", "dae"), `name` names the data in errors. External files (a .bin, a texture)
// cannot be resolved from memory: use data URIs or embedded textures.
Result<RiggedMesh> load_rigged_mesh_from_memory(std::span<const uint8_t> bytes,
                                                const std::string& hint, const std::string& name);

// Decodes mesh.texture_path (PNG, JPEG, ... via stb_image) into texture_rgba / width / height.
// Does nothing when the texture is already embedded. Errors name the texture file; the
// renderer then falls back to its checker texture (DESIGN.md §11).
Status load_rigged_texture(RiggedMesh& mesh);

// ---------------------------------------------------------------------------------------------
// [SECTION] Skinning — consistent with skeleton/pose.h: world_i = world_parent(i) · local_i,
// palette_i = world_i · inverse_bind_i (PaletteJob), a vertex v ↦ Σ w_k · palette_{b_k} · v.

// The rest pose: one rest_local per bone.
std::vector<Mat2x3> rest_locals(const RiggedMesh& mesh);

// A local rotated by `angle` radians (counter-clockwise) about the bone's own origin, the
// joint: local · R(angle). Bending a knee is rotated_local(rest_local, -0.6f).
Mat2x3 rotated_local(const Mat2x3& local, float angle);

// Forward kinematics and palette for one rigged mesh (STYLE.md job: outputs passed in, no
// allocation in run()).
struct RiggedPaletteJob {
  const RiggedMesh* mesh = nullptr;  // input
  std::span<const Mat2x3> locals;    // input: one per bone, bone → parent frame
  Mat2x3 model_to_world;             // input: placement of the character (mirror for -x)
  std::span<Mat2x3> world;           // output: bone frame → world, one per bone
  std::span<Mat2x3> palette;         // output: world · inverse_bind, one per bone

  bool validate() const;
  bool run() const;
};

// Convenience (allocates; tools and tests): the palette of a pose.
std::vector<Mat2x3> rigged_palette(const RiggedMesh& mesh, std::span<const Mat2x3> locals,
                                   const Mat2x3& model_to_world = Mat2x3::identity());

// CPU skinning of one vertex (tests, tools; the renderer does this on the GPU).
glm::vec2 skin_position(const RiggedVertex& vertex, std::span<const Mat2x3> palette);

}  // namespace ossa
