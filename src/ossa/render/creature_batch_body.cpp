// CreatureBatch's bodies (creature_batch.h): body instances, their layer-major index buffer
// and their draws. Their palettes share the sprites' buffer and its one upload per frame.

#include <cstddef>

#include "ossa/assert.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/gl.h"
#include "ossa/render/shader.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

std::span<const VertexAttrib> BodyBatchVertex::layout() {
  static const std::array<VertexAttrib, 11> kLayout{{
      {0, 2, GL_FLOAT, false, false, offsetof(BodyBatchVertex, position_ms)},
      {1, 2, GL_FLOAT, false, false, offsetof(BodyBatchVertex, coat)},
      {2, 4, GL_UNSIGNED_BYTE, false, true, offsetof(BodyBatchVertex, bones)},
      {3, 4, GL_FLOAT, false, false, offsetof(BodyBatchVertex, weights)},
      {4, 4, GL_UNSIGNED_BYTE, true, false, offsetof(BodyBatchVertex, colour)},
      {5, 4, GL_UNSIGNED_BYTE, true, false, offsetof(BodyBatchVertex, pattern)},
      {6, 1, GL_UNSIGNED_INT, false, true, offsetof(BodyBatchVertex, kind)},
      {7, 1, GL_UNSIGNED_INT, false, true, offsetof(BodyBatchVertex, palette_base)},
      {8, 1, GL_UNSIGNED_INT, false, true, offsetof(BodyBatchVertex, floor_base)},
      {9, 1, GL_FLOAT, false, false, offsetof(BodyBatchVertex, overhang)},
      {10, 1, GL_UNSIGNED_BYTE, false, true, offsetof(BodyBatchVertex, foot)},
  }};
  return kLayout;
}

int CreatureBatch::add_body(const BodyMesh& mesh, const Skeleton& skeleton) {
  OSSA_ASSERT(static_cast<int>(mesh.inverse_bind.size()) == skeleton.bone_count(),
              "CreatureBatch::add_body: one inverse bind matrix per bone");
  Instance c;
  c.body = true;
  c.vertex_base = static_cast<uint32_t>(body_vertices_.size());
  c.vertex_count = static_cast<uint32_t>(mesh.vertices.size());
  c.palette_base = static_cast<uint32_t>(palette_.size());
  c.bone_count = skeleton.bone_count();
  c.palette_count = mesh.palette_size();
  c.layer_begin = mesh.layer_begin;
  c.index_base = static_cast<uint32_t>(body_mesh_indices_.size());
  c.inverse_bind = mesh.inverse_bind;
  c.mid_joints = mesh.mid_joints;
  body_vertices_.reserve(body_vertices_.size() + mesh.vertices.size());
  for (const BodyVertex& v : mesh.vertices) {
    BodyBatchVertex b;
    b.position_ms = v.position_ms;
    b.coat = v.coat_uv;
    b.bones = v.bones;
    b.weights = v.weights;
    b.colour = v.colour;
    b.pattern = v.pattern;
    b.kind = v.pattern_kind;
    b.palette_base = c.palette_base;
    b.floor_base = c.palette_base + static_cast<uint32_t>(mesh.floor_entry());
    b.overhang = v.overhang;
    b.foot = v.foot;
    body_vertices_.push_back(b);
  }
  body_mesh_indices_.insert(body_mesh_indices_.end(), mesh.indices.begin(), mesh.indices.end());
  // Its skeleton's lines (draw_bones), from the bind pose, as for sprites.
  for (int b = 0; b < skeleton.bone_count(); ++b) {
    const Mat2x3 frame = inverse(c.inverse_bind[static_cast<size_t>(b)]);
    const uint32_t index = c.palette_base + static_cast<uint32_t>(b);
    bone_lines_.push_back({frame.apply({0.0f, 0.0f}), index});
    bone_lines_.push_back({frame.apply({skeleton.length(b), 0.0f}), index});
  }
  bone_total_ += c.bone_count;
  palette_.resize(palette_.size() + static_cast<size_t>(c.palette_count), Mat2x3::identity());
  creatures_.push_back(std::move(c));
  geometry_dirty_ = true;
  const int instance = static_cast<int>(creatures_.size()) - 1;
  set_floor(instance, BodyFloor{});
  return instance;
}

void CreatureBatch::set_floor(int instance, const BodyFloor& floor) {
  const Instance& c = creatures_[static_cast<size_t>(instance)];
  if (!c.body) return;
  const size_t first = static_cast<size_t>(c.bone_count) + c.mid_joints.size();
  encode_floor(floor, palette(instance).subspan(first, static_cast<size_t>(kBodyFloorEntries)));
}

void CreatureBatch::rebuild_body_geometry() {
  body_indices_.clear();
  body_indices_.reserve(2 * body_mesh_indices_.size());
  for (int l = 0; l < kLayerCount; ++l) {
    const auto first = static_cast<uint32_t>(body_indices_.size());
    for (const Instance& c : creatures_) {
      if (!c.body) continue;
      for (uint32_t i = c.index_base + c.layer_begin[static_cast<size_t>(l)]; i < c.index_base + c.layer_begin[static_cast<size_t>(l) + 1]; ++i) {
        body_indices_.push_back(c.vertex_base + body_mesh_indices_[i]);
      }
    }
    body_layer_ranges_[static_cast<size_t>(l)] = {first, static_cast<uint32_t>(body_indices_.size()) - first};
  }
  // The same triangles creature-major (each body's own order: far, body, near), after them in
  // the same buffer: one draw draws every body without interleaving overlapping creatures.
  const auto first = static_cast<uint32_t>(body_indices_.size());
  for (const Instance& c : creatures_) {
    if (!c.body) continue;
    for (uint32_t i = c.index_base + c.layer_begin[0]; i < c.index_base + c.layer_begin[kLayerCount]; ++i) {
      body_indices_.push_back(c.vertex_base + body_mesh_indices_[i]);
    }
  }
  body_creature_range_ = {first, static_cast<uint32_t>(body_indices_.size()) - first};
  body_va_.upload(body_vertices_, body_indices_, GL_STATIC_DRAW);
}

int CreatureBatch::draw_body_layer(const ShaderProgram& body, int layer, float alpha) {
  if (geometry_dirty_) rebuild_geometry();
  const auto& [first, count] = body_layer_ranges_[static_cast<size_t>(layer)];
  if (count == 0) return 0;
  bind_palette(body);
  body.set("u_alpha", alpha);
  body_va_.draw_indices(GL_TRIANGLES, static_cast<int>(first), static_cast<int>(count));
  return 1;
}

int CreatureBatch::draw_bodies(const ShaderProgram& body, float alpha) {
  if (geometry_dirty_) rebuild_geometry();
  const auto& [first, count] = body_creature_range_;
  if (count == 0) return 0;
  bind_palette(body);
  body.set("u_alpha", alpha);
  body_va_.draw_indices(GL_TRIANGLES, static_cast<int>(first), static_cast<int>(count));
  return 1;
}

}  // namespace ossa
