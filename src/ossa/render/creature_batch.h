#pragma once
// CreatureBatch — GPU skinning of many bone-sprite creatures with a constant number of draw
// calls (DESIGN.md §9, [T 4.3.1] RiggedShader generalised to a crowd):
//   * all creatures' SpriteMeshes live in ONE vertex buffer and ONE index buffer; the index
//     buffer is layer-major (every creature's far triangles, then body, then near), so
//   * one draw call per layer (3 per frame) draws every creature in the right order;
//   * each frame ONE upload sends all creatures' palettes (world · inverse_bind per bone,
//     PaletteJob, then the sprite mesh's smooth-skinning mid joints, mid_joint_palette) to a
//     texture buffer of RG32F texels, three per entry (Mat2x3 as stored);
//   * each vertex carries its creature's palette base, baked in when the geometry is built.
// draw_naive() is the per-bone reference path (one draw and one uniform upload per bone) for
// the benchmark. Needs a current GL context from construction on.
//
//   CreatureBatch batch;
//   int id = batch.add(build_sprite_mesh(creature, atlas.sprites), creature.skeleton);
//   batch.set_world(id, world_matrices);      // every frame, per creature
//   batch.upload_palettes();                  // once per frame
//   renderer.draw_batch(batch, atlas.texture);
// Rigged characters (character_mesh.h) bring their own textures: an instance added with
// texture slot s draws with the s-th texture given to draw(), in the same palette upload, one
// draw call per layer and slot in use (slot 0 first within each layer).
// Bodies (body/body_mesh.h) are instances of their own (add_body): their vertices live in a
// second vertex buffer drawn by the body program (draw_bodies: ONE draw for all of them,
// creature after creature, each its far limbs, body and near limbs, so overlapping creatures
// never interleave; draw_body_layer: a layer at a time for the x-ray look), their palettes in
// the same upload. A creature shown as body and bones (the x-ray look) is two
// instances with the same world matrices.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include "ossa/body/body_mesh.h"
#include "ossa/math/transform2d.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/render/vertex_array.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

class ShaderProgram;

// The skinned program's vertex: a SpriteVertex plus its creature's palette base.
struct BatchVertex {
  glm::vec2 position_ms{0.0f};
  glm::vec2 uv{0.0f};
  std::array<uint8_t, 4> bones{};
  std::array<float, 4> weights{};
  float shade = 1.0f;
  uint32_t palette_base = 0;
  static std::span<const VertexAttrib> layout();
};

// The body program's vertex: a BodyVertex plus its creature's palette base.
struct BodyBatchVertex {
  glm::vec2 position_ms{0.0f};
  glm::vec2 coat{0.0f};
  std::array<uint8_t, 4> bones{};
  std::array<float, 4> weights{};
  std::array<uint8_t, 4> colour{};
  std::array<uint8_t, 4> pattern{};
  uint32_t kind = 0;
  uint32_t palette_base = 0;
  uint32_t floor_base = 0;  // its creature's floor entries (body_floor.h) in the palette
  float overhang = 0.0f;    // BodyVertex::overhang
  uint8_t foot = kNoFoot;   // BodyVertex::foot
  static std::span<const VertexAttrib> layout();
};

// The bone program's vertex: a bone's start or end in bind-pose model space and its palette
// entry (creature base + bone).
struct BoneLineVertex {
  glm::vec2 position_ms{0.0f};
  uint32_t palette_index = 0;
  static std::span<const VertexAttrib> layout();
};

class CreatureBatch {
 public:
  CreatureBatch();
  ~CreatureBatch();
  CreatureBatch(const CreatureBatch&) = delete;
  CreatureBatch& operator=(const CreatureBatch&) = delete;

  // Adds a creature; returns its instance index. Its palette starts as the bind pose at the
  // origin (palette = identity). Geometry is (re)built on the next draw.
  int add(const SpriteMesh& mesh, const Skeleton& skeleton, int texture_slot = 0);
  // Adds a creature's body (creature_batch_body.cpp); set_world/set_pose take the same
  // matrices as for its sprites.
  int add_body(const BodyMesh& mesh, const Skeleton& skeleton);
  void clear();

  int creature_count() const { return static_cast<int>(creatures_.size()); }
  int bone_count() const { return bone_total_; }  // all creatures' skeleton bones
  int bone_count(int instance) const { return creatures_[instance].bone_count; }
  // Palette entries of all creatures: their bones and mid joints (SpriteMesh::palette_size).
  int palette_size() const { return static_cast<int>(palette_.size()); }
  int vertex_count() const { return static_cast<int>(vertices_.size()); }       // sprites
  int triangle_count() const { return static_cast<int>(mesh_indices_total_ / 3); }
  int body_vertex_count() const { return static_cast<int>(body_vertices_.size()); }
  int body_triangle_count() const { return static_cast<int>(body_indices_.size() / 3); }

  // CPU staging palette of one creature (its bones' matrices, then its mid joints', see
  // set_world): write it, then upload_palettes().
  std::span<Mat2x3> palette(int instance);
  std::span<const Mat2x3> palette() const { return palette_; }
  // palette(instance)[i] = world[i] · inverse_bind[i] (PaletteJob), then the mid joints from
  // their two bones (mid_joint_palette); world has one matrix per bone: bone frame → world.
  void set_world(int instance, std::span<const Mat2x3> world);
  // A body's floor (body/body_floor.h: the box tops its flesh rests on), into its palette;
  // a body starts without one. Ignored for sprite instances.
  void set_floor(int instance, const BodyFloor& floor);
  // Convenience: the creature's pose through forward kinematics placed by model_to_world.
  void set_pose(int instance, const Skeleton& skeleton, std::span<const BoneLocal> locals,
                const Mat2x3& model_to_world);

  // ONE glBufferSubData of every creature's palette into the texture buffer.
  void upload_palettes();
  // How many uploads so far (tests and benchmarks: one per frame, sprites and bodies alike).
  int palette_uploads() const { return palette_uploads_; }

  // Batched draw: binds the palette and atlas, one glDrawElements per non-empty layer.
  // The skinned program must be in use with u_view_proj set. Returns the draw calls issued.
  int draw(const ShaderProgram& skinned, unsigned atlas_texture);
  // The same with one texture per slot (textures[0] for slot 0, ...; a slot without one uses
  // textures[0]). Returns the draw calls issued.
  int draw(const ShaderProgram& skinned, std::span<const unsigned> textures);
  // Texture slots in use: 1 + the largest slot of any instance (1 when empty).
  int texture_slots() const;
  // Bodies: binds the palette, one glDrawElements for every body, creature by creature in the
  // order they were added, each far limbs, body, near limbs (the body program in use with
  // u_view_proj set; `alpha` multiplies the coat's: 1 opaque, < 1 translucent). Returns the
  // draw calls issued (0 or 1). draw_body_layer draws one layer of every body (for the x-ray
  // look's interleaving with the sprites' layers).
  int draw_bodies(const ShaderProgram& body, float alpha = 1.0f);
  int draw_body_layer(const ShaderProgram& body, int layer, float alpha = 1.0f);
  // The same for the sprites: one layer (draw() draws all three), one draw per texture slot.
  int draw_layer(const ShaderProgram& skinned, std::span<const unsigned> textures, int layer);
  // Per-bone reference: one draw and one u_bone upload per run of triangles of one bone
  // (the naive program must be in use). Returns the draw calls issued.
  int draw_naive(const ShaderProgram& naive, unsigned atlas_texture);
  // Skeleton lines of every creature, one draw (bone program in use).
  int draw_bones(const ShaderProgram& bone);

  // Index ranges of the layer-major index buffer (first index, count) per Layer.
  std::array<std::pair<uint32_t, uint32_t>, kLayerCount> layer_ranges();

 private:
  struct Instance {
    uint32_t vertex_base = 0, vertex_count = 0;
    uint32_t palette_base = 0;
    int bone_count = 0;
    int palette_count = 0;                  // bones + mid joints (+ a body's floor)
    std::array<uint32_t, 4> layer_begin{};  // into mesh_indices_ below (creature-local)
    uint32_t index_base = 0;                // where its indices start in mesh_indices_
    std::vector<Mat2x3> inverse_bind;
    int texture_slot = 0;
    std::vector<MidJoint> mid_joints;
    bool body = false;                      // a body: vertices in body_vertices_
  };
  struct NaiveRun {
    uint32_t first = 0, count = 0;  // indices in the layer-major buffer
    uint32_t palette_index = 0;
  };
  void rebuild_geometry();
  void rebuild_body_geometry();
  void ensure_palette_buffer();
  void bind_palette(const ShaderProgram& program);

  std::vector<Instance> creatures_;
  std::vector<BatchVertex> vertices_;
  std::vector<uint32_t> mesh_indices_;      // per creature, creature-local vertex numbers
  size_t mesh_indices_total_ = 0;
  std::vector<BoneLineVertex> bone_lines_;
  std::vector<Mat2x3> palette_;
  int bone_total_ = 0;
  std::array<std::pair<uint32_t, uint32_t>, kLayerCount> layer_ranges_{};
  // Per texture slot, per layer: its run of the layer-major index buffer.
  std::vector<std::array<std::pair<uint32_t, uint32_t>, kLayerCount>> slot_ranges_;
  std::vector<NaiveRun> naive_runs_;
  bool geometry_dirty_ = true;

  std::vector<BodyBatchVertex> body_vertices_;
  std::vector<uint32_t> body_mesh_indices_;  // per body, body-local vertex numbers
  std::vector<uint32_t> body_indices_;       // layer-major, uploaded
  std::array<std::pair<uint32_t, uint32_t>, kLayerCount> body_layer_ranges_{};
  std::pair<uint32_t, uint32_t> body_creature_range_{};  // every body, creature-major

  VertexArray<BatchVertex> mesh_va_;
  VertexArray<BodyBatchVertex> body_va_;
  VertexArray<BoneLineVertex> bone_va_;
  unsigned palette_buffer_ = 0, palette_texture_ = 0;
  int palette_uploads_ = 0;
  size_t palette_capacity_ = 0;   // matrices the GPU buffer holds
};

}  // namespace ossa
