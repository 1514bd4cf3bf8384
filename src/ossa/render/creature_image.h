#pragma once
// Creature images — one creature drawn in its rest pose into an offscreen framebuffer, framed
// on its sprites, as an Image or a PNG file: the creature panel's PNG export (DESIGN.md §10).
// Drawn by the same Renderer, bone-sprite Atlas, SpriteMesh and CreatureBatch as the game and
// ossa-render, so the picture is what the game shows.
//
//   CreatureImageOptions o;
//   o.width = 800;
//   o.height = 600;                                     // transparent background by default
//   Status s = write_creature_png("out/horse.png", creature, o);   // needs a current GL context
//
// Space: world +y up is up in the image; the creature as drawn in its rest pose (its body's and
// its sprites' vertices, as the look shows them) is centred and fills the image up to the
// margin on the tighter axis.

#include <string>

#include <glm/vec4.hpp>

#include "ossa/gen/creature.h"
#include "ossa/io/result.h"
#include "ossa/platform/image.h"
#include "ossa/render/renderer.h"
#include "ossa/render/texture.h"

namespace ossa {

struct CreatureImageOptions {
  int width = 800;             // pixels, 1 to RenderTarget::kMaxSize
  int height = 600;            // pixels, 1 to RenderTarget::kMaxSize
  glm::vec4 background{0.0f};  // straight RGBA in [0, 1]; alpha 0 = transparent
  float margin = 0.05f;        // free space around the creature, as a fraction of its size
                               // on the tighter axis, >= 0
  CreatureLook look = CreatureLook::kBody;  // body, x-ray (body over bones) or bone sprites
  bool ground = false;         // a ground strip under y = 0 (the creature stands on it)
  float frame_height = 0.0f;   // metres of world the image's height shows (0: fit the creature)
};

// Draws `creature` with `renderer` and `atlas` into an offscreen target and reads it back
// (rows top to bottom, straight alpha). The caller's framebuffer, viewport and blending
// (GlFrameState) and the renderer's camera and stats are kept, so this may run in the middle
// of the game's frame. Errors (no file names here): no current GL context, a size out of range,
// a creature with too many bones or a non-finite rest pose, GL errors.
Result<Image> render_creature_image(Renderer& renderer, const Atlas& atlas, const Creature& creature,
                                    const CreatureImageOptions& options = {});

// Loads the programs from `shader_dir` and the bone atlas from `sprite_dir` (a missing sprite
// is logged and drawn as a checker tile), renders as above and writes `path` as PNG atomically.
// Errors name `path` and what went wrong; an existing file at `path` is then left untouched.
Status write_creature_png(const std::string& path, const Creature& creature,
                          const CreatureImageOptions& options = {},
                          const std::string& shader_dir = default_shader_dir(),
                          const std::string& sprite_dir = default_sprite_dir());

}  // namespace ossa
