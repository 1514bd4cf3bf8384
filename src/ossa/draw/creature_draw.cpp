#include "ossa/draw/creature_draw.h"

// A creature's draw data on the CPU: the palette as CreatureBatch::set_world builds it
// (sprite_palette: PaletteJob, then the mid joints; for bodies body_palette), every
// vertex skinned as the skinned and body shaders skin it, the triangles layer by layer.

#include "ossa/assert.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ossa {
namespace {

uint8_t to_byte(float x) { return static_cast<uint8_t>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); }

// Adds indices [begin, end) of a mesh whose vertices start at `base` in the list, as one
// command (or the continuation of the last one).
void push_triangles(DrawList& list, std::span<const uint32_t> mesh_indices, uint32_t begin, uint32_t end,
                    uint32_t base, DrawTexture texture, Layer layer) {
  if (end <= begin) return;
  const auto first = static_cast<uint32_t>(list.indices.size());
  for (uint32_t i = begin; i < end; ++i) list.indices.push_back(base + mesh_indices[i]);
  const uint32_t creature = list.creature_count;
  if (!list.commands.empty()) {
    DrawCommand& last = list.commands.back();
    if (last.texture == texture && last.layer == layer && last.creature == creature &&
        last.first_index + last.index_count == first) {
      last.index_count += end - begin;
      return;
    }
  }
  list.commands.push_back({texture, layer, creature, first, end - begin});
}

// The bone sprites' vertices skinned by `palette`; returns the first one's index in the list.
uint32_t append_sprite_vertices(DrawList& list, const SpriteMesh& mesh, std::span<const Mat2x3> palette) {
  const auto base = static_cast<uint32_t>(list.vertices.size());
  for (const SpriteVertex& v : mesh.vertices) {
    DrawVertex d;
    d.position_ws = skin_vertex(v, palette);
    d.uv = {v.uv.x, 1.0f - v.uv.y};  // the atlas's t grows up the image; rows grow down
    const uint8_t shade = to_byte(v.shade);
    d.colour = {shade, shade, shade, 255};
    list.vertices.push_back(d);
  }
  return base;
}

uint32_t append_body_vertices(DrawList& list, const BodyMesh& mesh, std::span<const Mat2x3> palette,
                              const BodyFloor* floor, float alpha) {
  const auto base = static_cast<uint32_t>(list.vertices.size());
  for (const BodyVertex& v : mesh.vertices) {
    DrawVertex d;
    d.position_ws = floor ? drawn_body_vertex(v, palette, *floor) : skin_body_vertex(v, palette);
    d.colour = v.colour;
    d.colour[3] = to_byte(alpha * static_cast<float>(v.colour[3]) / 255.0f);
    list.vertices.push_back(d);
  }
  return base;
}

}  // namespace

void DrawList::clear() {
  vertices.clear();
  indices.clear();
  commands.clear();
  creature_count = 0;
}

Result<CreatureDrawable> make_creature_drawable(const Creature& creature, const SpriteSet& sprites,
                                                const CreatureDrawOptions& options) {
  CreatureDrawable d;
  d.look = options.look;
  d.bone_count = creature.skeleton.bone_count();
  if (options.look != CreatureLook::kBody) {
    Result<SpriteMesh> mesh = try_build_sprite_mesh(creature, sprites, options.sprites);
    if (!mesh) return mesh.error();
    d.sprites = std::move(*mesh);
  }
  if (options.look != CreatureLook::kBones) {
    Result<BodyMesh> body = try_build_body(creature, options.body);
    if (!body) return body.error();
    d.body = std::move(*body);
  }
  return d;
}

void append_creature(DrawList& list, const CreatureDrawable& drawable, std::span<const Mat2x3> world,
                     const BodyFloor* floor) {
  OSSA_ASSERT(static_cast<int>(world.size()) == drawable.bone_count,
              "append_creature: one world matrix per bone");
  const bool sprites = !drawable.sprites.vertices.empty();
  const bool body = !drawable.body.vertices.empty();

  uint32_t sprite_base = 0, body_base = 0;
  if (sprites) {
    const SpriteMesh& mesh = drawable.sprites;
    list.palette.assign(static_cast<size_t>(mesh.palette_size()), Mat2x3::identity());
    sprite_palette(mesh, world, list.palette);
    sprite_base = append_sprite_vertices(list, mesh, list.palette);
  }
  if (body) {
    const BodyMesh& mesh = drawable.body;
    list.palette.assign(static_cast<size_t>(mesh.palette_size()), Mat2x3::identity());
    body_palette(mesh, world, list.palette);
    const float alpha = drawable.look == CreatureLook::kXray ? kXrayBodyAlpha : 1.0f;
    body_base = append_body_vertices(list, mesh, list.palette, floor, alpha);
  }

  for (int l = 0; l < kLayerCount; ++l) {
    const auto layer = static_cast<Layer>(l);
    const auto li = static_cast<size_t>(l);
    if (sprites) {
      const SpriteMesh& m = drawable.sprites;
      push_triangles(list, m.indices, m.layer_begin[li], m.layer_begin[li + 1], sprite_base, DrawTexture::kAtlas, layer);
    }
    if (body) {
      const BodyMesh& m = drawable.body;
      push_triangles(list, m.indices, m.layer_begin[li], m.layer_begin[li + 1], body_base, DrawTexture::kNone, layer);
    }
  }
  ++list.creature_count;
}

Box creature_draw_bounds(const DrawList& list, uint32_t creature) {
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const DrawCommand& c : list.commands) {
    if (c.creature != creature) continue;
    for (uint32_t i = c.first_index; i < c.first_index + c.index_count; ++i) {
      const glm::vec2 p = list.vertices[list.indices[i]].position_ws;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (lo.x > hi.x) return {};
  return {lo, hi};
}

}  // namespace ossa
