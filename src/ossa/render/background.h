#pragma once
// Background — what the level is seen against (DESIGN.md §8, §9): a vertical sky gradient
// fixed to the screen, two ranges of procedural hills scrolling with parallax, and an image
// when the level names one. Plus the level itself drawn as scenery: every collider a filled,
// earth-coloured box with a lighter top edge, so boxes read as ground, not as debug lines.
// Everything is built as flat-coloured triangles into a DebugDraw (world space, metres).

#include <glm/vec3.hpp>

#include "ossa/level/box.h"
#include "ossa/render/renderer.h"
#include "ossa/render/texture.h"

namespace ossa {

class DebugDraw;
class Level;

struct BackgroundStyle {
  glm::vec3 sky_top{0.32f, 0.52f, 0.80f};     // linear RGB at the top of the screen
  glm::vec3 sky_bottom{0.55f, 0.70f, 0.85f};  // at the bottom (the level's colour when set)
  float parallax = 0.5f;                      // the near hills' scroll factor in [0, 1]
  float horizon_ws = 0.0f;                    // world height the hills stand on, metres
};

// Sky bands covering `camera`'s view and the hills (far range scrolls at parallax/3, near at
// `parallax`); hills are a sum of sines of the scrolled x, so they never repeat visibly.
void add_background(DebugDraw& draw, const Camera2D& camera, const BackgroundStyle& style);

// A level's background image over the camera's view, scrolled by `parallax` in [0, 1] and
// repeated horizontally (tiles as tall as the view, each image's aspect kept): one draw,
// whatever the image's shape and however far the camera is from the origin (a 1 px wide strip
// used to cost one draw per tile, and a loop counting tiles in a float never ended past 2^24).
// `texture` should be made with Texture::Wrap::kRepeat; an invalid one draws nothing.
void draw_background_image(Renderer& renderer, const Texture& texture, float parallax);

// The colliders overlapping `visible` as ground: fill, a lighter top band (grass) and a
// darker outline. Boxes whose top is covered by another box get no grass band.
void add_level_scenery(DebugDraw& draw, const Level& level, const Box& visible);

}  // namespace ossa
