#pragma once
// Creature draw data for any renderer (issue 31, "draw in any engine"): a creature and its
// pose as plain triangles, already skinned into world space on the CPU — no SDL, no GL.
//
//   SpriteAtlas atlas = load_sprite_atlas(default_sprite_dir());   // once: one RGBA image
//   CreatureDrawable horse = make_creature_drawable(creature, atlas.sprites);  // once per creature
//   DrawList list;                                                  // every frame:
//   list.clear();
//   for (each entity) append_creature(list, horse, entity.animator().world_matrices());
//   for (const DrawCommand& c : list.commands)                      // your renderer
//     draw_triangles(list.vertices, indices [c.first_index, + c.index_count),
//                    c.texture == DrawTexture::kAtlas ? atlas_texture : none);
//
// What a creature is drawn as (CreatureLook, body/body_mesh.h), the same meshes, palettes and
// order as ossa::render's CreatureBatch (GPU skinning) draws:
//   kBody   its body (flesh, skin and coat colour as vertex colours; body/body_mesh.h),
//           untextured: far limbs, the axial body, near limbs, each part's outline before it
//   kBones  its bone sprites (draw/sprite_mesh.h), textured from the atlas and tinted by the
//           vertex colour (far-side bones darker): far, body and near layer
//   kXray   per layer, that layer's bone sprites and then its body translucent over them
//           (alpha kXrayBodyAlpha)
// Creatures are drawn in the order they are appended, each whole (all its layers) before the
// next, so overlapping creatures never interleave; append the farthest first.
//
// Differences from the GL renderer, by design of plain vertex-coloured triangles: a body's coat
// pattern (stripes, spots: body.frag's per-pixel noise) is not drawn, only its countershaded
// colour; and a body's floor (body_floor.h: flesh lifted onto box tops under it) is applied
// when append_creature is given one, per vertex as the shader does.
//
// A renderer that skins on the GPU takes the bind-pose meshes instead: CreatureDrawable's
// sprites and body (vertices in model space with up to four bone indices and weights, indices
// by layer, SpriteMesh::layer_begin / BodyMesh::layer_begin) and their palettes each frame
// (sprite_palette, body_palette), as ossa::render's CreatureBatch does.
//
// Cost: one skinned vertex per mesh vertex per append — a horse's body 1 888 vertices and
// 2 274 triangles, its bone sprites 2 042 and 2 356 — about 50 µs (body) or 65 µs (bones) per
// horse on one core of the 2-core test machine while it was loaded; no allocation once the
// list's vectors have grown.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/body/body_floor.h"
#include "ossa/body/body_mesh.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/gen/creature.h"
#include "ossa/io/result.h"
#include "ossa/math/transform2d.h"

namespace ossa {

// One vertex of a DrawList.
struct DrawVertex {
  glm::vec2 position_ws{0.0f};        // world metres, +x right, +y up (DESIGN.md §3)
  glm::vec2 uv{0.0f};                 // into SpriteAtlas::image, (0, 0) its top-left corner,
                                      // (1, 1) its bottom-right (v DOWN the image, as SDL and
                                      // most image APIs count rows); (0, 0) when untextured
  std::array<uint8_t, 4> colour{255, 255, 255, 255};  // sRGB + straight alpha: the colour of an
                                      // untextured vertex, the tint a texel is multiplied by
};

enum class DrawTexture : uint8_t {
  kNone,   // vertex colours alone (bodies)
  kAtlas,  // the sprite atlas image (SpriteAtlas::image), times the vertex colour
};

// A run of triangles drawn with one texture: DrawList::indices [first_index, first_index +
// index_count), three per triangle. Triangles may wind either way: draw without culling, with
// ordinary alpha blending (src alpha, one minus src alpha), in the order given.
struct DrawCommand {
  DrawTexture texture = DrawTexture::kNone;
  Layer layer = Layer::kBody;         // the creature's layer these triangles belong to
  uint32_t creature = 0;              // which append_creature call made them (0, 1, 2, ...)
  uint32_t first_index = 0;
  uint32_t index_count = 0;
};

struct DrawList {
  std::vector<DrawVertex> vertices;
  std::vector<uint32_t> indices;      // into vertices
  std::vector<DrawCommand> commands;  // in draw order
  uint32_t creature_count = 0;        // append_creature calls since clear()
  std::vector<Mat2x3> palette;        // scratch: the palette of the creature being appended

  // Empties the list, keeping its memory.
  void clear();
  int triangle_count() const { return static_cast<int>(indices.size() / 3); }
};

struct CreatureDrawOptions {
  CreatureLook look = CreatureLook::kBody;
  SpriteMeshOptions sprites;          // bone sprites (kBones, kXray)
  BodyOptions body;                   // the body (kBody, kXray)
};

// A creature's meshes in its bind pose, built once and shared by every entity of it.
struct CreatureDrawable {
  CreatureLook look = CreatureLook::kBody;
  int bone_count = 0;                 // world matrices append_creature takes
  SpriteMesh sprites;                 // empty for kBody
  BodyMesh body;                      // empty for kBones

  // Triangles one append_creature adds.
  int triangle_count() const {
    return static_cast<int>((sprites.indices.size() + body.indices.size()) / 3);
  }
};

// Builds what `look` needs: the bone-sprite mesh (build_sprite_mesh, mapped into `sprites`:
// the SpriteSet of the atlas that will be drawn with, SpriteAtlas::sprites) and/or the body
// (build_body). Errors: a skeleton too large for a sprite mesh or a body's palette.
Result<CreatureDrawable> make_creature_drawable(const Creature& creature, const SpriteSet& sprites,
                                                const CreatureDrawOptions& options = {});

// Appends `drawable` posed by `world` (one matrix per bone, bone frame → world: what
// Animator::world_matrices() gives) to `list`: its vertices skinned into world space, its
// triangles and commands in draw order (see above); a command continues the previous one when
// texture, layer and creature agree. `floor` (body_floor(), flat_floor()): the box tops a body's
// flesh rests on; null: none. Precondition (asserted): world.size() == drawable.bone_count.
void append_creature(DrawList& list, const CreatureDrawable& drawable, std::span<const Mat2x3> world,
                     const BodyFloor* floor = nullptr);

// The world-space box around every vertex of `list` that creature `creature` added; a zero box
// at the origin when it added none.
Box creature_draw_bounds(const DrawList& list, uint32_t creature);

}  // namespace ossa
