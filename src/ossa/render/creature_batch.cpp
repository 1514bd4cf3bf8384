#include "ossa/render/creature_batch.h"

#include <algorithm>
#include <cstddef>

#include "ossa/assert.h"
#include "ossa/render/gl.h"
#include "ossa/render/shader.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

std::span<const VertexAttrib> BatchVertex::layout() {
  static const std::array<VertexAttrib, 6> kLayout{{
      {0, 2, GL_FLOAT, false, false, offsetof(BatchVertex, position_ms)},
      {1, 2, GL_FLOAT, false, false, offsetof(BatchVertex, uv)},
      {2, 4, GL_UNSIGNED_BYTE, false, true, offsetof(BatchVertex, bones)},
      {3, 4, GL_FLOAT, false, false, offsetof(BatchVertex, weights)},
      {4, 1, GL_FLOAT, false, false, offsetof(BatchVertex, shade)},
      {5, 1, GL_UNSIGNED_INT, false, true, offsetof(BatchVertex, palette_base)},
  }};
  return kLayout;
}

std::span<const VertexAttrib> BoneLineVertex::layout() {
  static const std::array<VertexAttrib, 2> kLayout{{
      {0, 2, GL_FLOAT, false, false, offsetof(BoneLineVertex, position_ms)},
      {1, 1, GL_UNSIGNED_INT, false, true, offsetof(BoneLineVertex, palette_index)},
  }};
  return kLayout;
}

CreatureBatch::CreatureBatch() {
  glGenBuffers(1, &palette_buffer_);
  glGenTextures(1, &palette_texture_);
}

CreatureBatch::~CreatureBatch() {
  if (palette_texture_) glDeleteTextures(1, &palette_texture_);
  if (palette_buffer_) glDeleteBuffers(1, &palette_buffer_);
}

int CreatureBatch::add(const SpriteMesh& mesh, const Skeleton& skeleton, int texture_slot) {
  OSSA_ASSERT(mesh.inverse_bind.empty() ||
                  static_cast<int>(mesh.inverse_bind.size()) == skeleton.bone_count(),
              "CreatureBatch::add: one inverse bind matrix per bone");
  Instance c;
  c.vertex_base = static_cast<uint32_t>(vertices_.size());
  c.vertex_count = static_cast<uint32_t>(mesh.vertices.size());
  c.palette_base = static_cast<uint32_t>(palette_.size());
  c.bone_count = skeleton.bone_count();
  c.palette_count = c.bone_count + static_cast<int>(mesh.mid_joints.size());
  c.layer_begin = mesh.layer_begin;
  c.index_base = static_cast<uint32_t>(mesh_indices_.size());
  c.inverse_bind = mesh.inverse_bind;
  c.texture_slot = std::max(texture_slot, 0);
  c.mid_joints = mesh.mid_joints;
  OSSA_ASSERT(c.mid_joints.empty() || !c.inverse_bind.empty(), "CreatureBatch::add: mid joints need a bind pose");

  for (const SpriteVertex& v : mesh.vertices) {
    BatchVertex b;
    b.position_ms = v.position_ms;
    b.uv = v.uv;
    b.bones = v.bones;
    b.weights = v.weights;
    b.shade = v.shade;
    b.palette_base = c.palette_base;
    vertices_.push_back(b);
  }
  mesh_indices_.insert(mesh_indices_.end(), mesh.indices.begin(), mesh.indices.end());
  mesh_indices_total_ += mesh.indices.size();

  // Bone lines: a bone's bind-pose frame is inverse(inverse_bind); its start and end in model
  // space are that frame's origin and (length, 0).
  const auto bind = model_matrices(skeleton, skeleton.rest_locals());
  for (int b = 0; b < skeleton.bone_count(); ++b) {
    const Mat2x3 frame = c.inverse_bind.empty() ? bind[b] : inverse(c.inverse_bind[b]);
    // Authored-in-bone-space meshes (empty inverse_bind) have palette = world: lines in the
    // bone frame itself.
    const Mat2x3 m = c.inverse_bind.empty() ? Mat2x3::identity() : frame;
    const uint32_t index = c.palette_base + static_cast<uint32_t>(b);
    bone_lines_.push_back({m.apply({0.0f, 0.0f}), index});
    bone_lines_.push_back({m.apply({skeleton.length(b), 0.0f}), index});
  }

  palette_.resize(palette_.size() + static_cast<size_t>(c.palette_count), Mat2x3::identity());
  bone_total_ += c.bone_count;
  creatures_.push_back(std::move(c));
  geometry_dirty_ = true;
  return static_cast<int>(creatures_.size()) - 1;
}

void CreatureBatch::clear() {
  creatures_.clear();
  vertices_.clear();
  body_vertices_.clear();
  body_mesh_indices_.clear();
  body_indices_.clear();
  mesh_indices_.clear();
  mesh_indices_total_ = 0;
  bone_lines_.clear();
  palette_.clear();
  bone_total_ = 0;
  naive_runs_.clear();
  geometry_dirty_ = true;
}

std::span<Mat2x3> CreatureBatch::palette(int instance) {
  const Instance& c = creatures_[instance];
  return std::span<Mat2x3>(palette_).subspan(c.palette_base, static_cast<size_t>(c.palette_count));
}

void CreatureBatch::set_world(int instance, std::span<const Mat2x3> world) {
  const Instance& c = creatures_[instance];
  OSSA_ASSERT(static_cast<int>(world.size()) == c.bone_count, "set_world: one matrix per bone");
  PaletteJob job;
  job.world = world;
  job.inverse_bind = c.inverse_bind;
  job.palette = palette(instance).first(static_cast<size_t>(c.bone_count));
  const bool ok = job.run();
  OSSA_ASSERT(ok, "set_world: palette job failed");
  (void)ok;
  if (!c.mid_joints.empty()) {
    mid_joint_palette(c.mid_joints, world, palette(instance).first(static_cast<size_t>(c.bone_count) + c.mid_joints.size()));
  }
}

void CreatureBatch::set_pose(int instance, const Skeleton& skeleton,
                             std::span<const BoneLocal> locals, const Mat2x3& model_to_world) {
  std::vector<Mat2x3> model(static_cast<size_t>(skeleton.bone_count()));
  std::vector<Mat2x3> world(model.size());
  ForwardKinematicsJob fk;
  fk.skeleton = &skeleton;
  fk.locals = locals;
  fk.model_to_world = model_to_world;
  fk.model = model;
  fk.world = world;
  const bool ok = fk.run();
  OSSA_ASSERT(ok, "set_pose: forward kinematics failed");
  (void)ok;
  set_world(instance, world);
}

void CreatureBatch::rebuild_geometry() {
  // Layer-major order: for each layer, every creature's triangles of that layer, so one
  // glDrawElements per layer draws all creatures and far < body < near holds across them.
  std::vector<uint32_t> indices;
  indices.reserve(mesh_indices_total_);
  naive_runs_.clear();
  const int slots = texture_slots();
  slot_ranges_.assign(static_cast<size_t>(slots), {});
  for (int l = 0; l < kLayerCount; ++l) {
    const uint32_t first = static_cast<uint32_t>(indices.size());
    for (int slot = 0; slot < slots; ++slot) {
    const uint32_t slot_first = static_cast<uint32_t>(indices.size());
    for (const Instance& c : creatures_) {
      if (c.texture_slot != slot || c.body) continue;
      const uint32_t begin = c.index_base + c.layer_begin[l];
      const uint32_t end = c.index_base + c.layer_begin[l + 1];
      for (uint32_t i = begin; i < end; ++i) {
        const uint32_t local = mesh_indices_[i];
        indices.push_back(c.vertex_base + local);
        // Naive runs: consecutive triangles of the same dominant bone, one draw each.
        if ((i - begin) % 3 == 0) {
          const BatchVertex& v = vertices_[c.vertex_base + local];
          int best = 0;
          for (int k = 1; k < 4; ++k) if (v.weights[k] > v.weights[best]) best = k;
          const uint32_t p = c.palette_base + v.bones[best];
          const uint32_t at = static_cast<uint32_t>(indices.size()) - 1;
          if (naive_runs_.empty() || naive_runs_.back().palette_index != p ||
              naive_runs_.back().first + naive_runs_.back().count != at) {
            naive_runs_.push_back({at, 0, p});
          }
          naive_runs_.back().count += 3;
        }
      }
    }
    slot_ranges_[static_cast<size_t>(slot)][static_cast<size_t>(l)] = {slot_first, static_cast<uint32_t>(indices.size()) - slot_first};
    }
    layer_ranges_[l] = {first, static_cast<uint32_t>(indices.size()) - first};
  }
  mesh_va_.upload(vertices_, indices, GL_STATIC_DRAW);
  bone_va_.upload(bone_lines_, {}, GL_STATIC_DRAW);
  rebuild_body_geometry();
  geometry_dirty_ = false;
}

std::array<std::pair<uint32_t, uint32_t>, kLayerCount> CreatureBatch::layer_ranges() {
  if (geometry_dirty_) rebuild_geometry();
  return layer_ranges_;
}

void CreatureBatch::ensure_palette_buffer() {
  if (palette_capacity_ >= palette_.size() && palette_capacity_ > 0) return;
  palette_capacity_ = std::max<size_t>(palette_.size(), 64);
  glBindBuffer(GL_TEXTURE_BUFFER, palette_buffer_);
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(palette_capacity_ * sizeof(Mat2x3)),
               nullptr, GL_STREAM_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, palette_texture_);
  // RG32F: three texels per Mat2x3 (x axis, y axis, translation) — the CPU layout as is.
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RG32F, palette_buffer_);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void CreatureBatch::upload_palettes() {
  static_assert(sizeof(Mat2x3) == 6 * sizeof(float), "Mat2x3 must be six packed floats");
  ensure_palette_buffer();
  if (palette_.empty()) return;
  glBindBuffer(GL_TEXTURE_BUFFER, palette_buffer_);
  glBufferSubData(GL_TEXTURE_BUFFER, 0, static_cast<GLsizeiptr>(palette_.size() * sizeof(Mat2x3)),
                  palette_.data());
  ++palette_uploads_;
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

int CreatureBatch::texture_slots() const {
  int slots = 1;
  for (const Instance& c : creatures_) slots = std::max(slots, c.texture_slot + 1);
  return slots;
}

int CreatureBatch::draw(const ShaderProgram& skinned, unsigned atlas_texture) {
  const unsigned textures[1] = {atlas_texture};
  return draw(skinned, textures);
}

void CreatureBatch::bind_palette(const ShaderProgram& program) {
  ensure_palette_buffer();
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_BUFFER, palette_texture_);
  program.set("u_palette", 1);
  glActiveTexture(GL_TEXTURE0);
}

int CreatureBatch::draw(const ShaderProgram& skinned, std::span<const unsigned> textures) {
  int calls = 0;
  for (int l = 0; l < kLayerCount; ++l) calls += draw_layer(skinned, textures, l);
  return calls;
}

int CreatureBatch::draw_layer(const ShaderProgram& skinned, std::span<const unsigned> textures, int l) {
  if (geometry_dirty_) rebuild_geometry();
  bind_palette(skinned);
  skinned.set("u_atlas", 0);
  int calls = 0;
  for (size_t slot = 0; slot < slot_ranges_.size(); ++slot) {
    const auto& [first, count] = slot_ranges_[slot][static_cast<size_t>(l)];
    if (count == 0) continue;
    const unsigned texture = slot < textures.size() ? textures[slot] : (textures.empty() ? 0u : textures[0]);
    glBindTexture(GL_TEXTURE_2D, texture);
    mesh_va_.draw_indices(GL_TRIANGLES, static_cast<int>(first), static_cast<int>(count));
    ++calls;
  }
  return calls;
}

int CreatureBatch::draw_naive(const ShaderProgram& naive, unsigned atlas_texture) {
  if (geometry_dirty_) rebuild_geometry();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, atlas_texture);
  naive.set("u_atlas", 0);
  const int bone_location = naive.location("u_bone");
  int calls = 0;
  for (const NaiveRun& run : naive_runs_) {
    const Mat2x3& m = palette_[run.palette_index];
    const float mat[9] = {m.m[0], m.m[1], 0.0f, m.m[2], m.m[3], 0.0f, m.m[4], m.m[5], 1.0f};
    glUniformMatrix3fv(bone_location, 1, GL_FALSE, mat);
    mesh_va_.draw_indices(GL_TRIANGLES, static_cast<int>(run.first), static_cast<int>(run.count));
    ++calls;
  }
  return calls;
}

int CreatureBatch::draw_bones(const ShaderProgram& bone) {
  if (geometry_dirty_) rebuild_geometry();
  if (bone_lines_.empty()) return 0;
  ensure_palette_buffer();
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_BUFFER, palette_texture_);
  bone.set("u_palette", 1);
  bone_va_.draw(GL_LINES);
  glActiveTexture(GL_TEXTURE0);
  return 1;
}

}  // namespace ossa
