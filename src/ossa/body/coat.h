#pragma once
// Coat — the colours of a body (issue 30): a base colour with countershading (the back darker,
// the belly lighter), far-side limbs darker, and an optional pattern from seeded noise in body
// coordinates, so the pattern moves with the skin.
//
// The pattern is evaluated per pixel by shaders/body.frag; coat_pattern() here is the same
// function on the CPU (the SVG side view and the glTF export's vertex colours use it, and a
// test compares both). Keep the two in step: integer hash (Chris Wellons' lowbias32), value
// noise with a smoothstep fade, and Worley F1/F2 with one jittered point per unit cell.
// Coordinates are in pattern cells: a body vertex's coat_uv = (rest position − body origin) /
// (look.pattern_scale × back length) + an offset drawn from the seed.

#include <array>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "ossa/gen/look.h"

namespace ossa {

// The integer hash both sides use (lowbias32).
uint32_t coat_hash(uint32_t x);
// Value noise in [0, 1] at p (cells), smoothstep-interpolated lattice values.
float coat_value_noise(glm::vec2 p);
// Worley distances to the nearest and second-nearest jittered cell point (F1 ≤ F2), and the
// hash of the nearest point's cell (a per-spot random number).
struct Worley {
  float f1 = 0.0f, f2 = 0.0f;
  uint32_t cell = 0;
};
Worley coat_worley(glm::vec2 p);

// How much of the pattern colour shows at `p` (cells), 0 … 1, for `pattern`. `aa` is the
// width of the edges' smoothstep in cells (the shader uses the pixel footprint, fwidth).
//   stripes   bands across the body, their edges warped by value noise (tiger, zebra, perch)
//   spots     round spots of varying size (leopard cubs, trout, seals)
//   rosettes  rings of broken spots around a lighter centre (leopard, jaguar)
//   dapples   soft blotches (grey horses, whales)
//   patches   large polygonal patches separated by narrow lines of the base (giraffe, python)
float coat_pattern(CoatPattern pattern, glm::vec2 p, float aa = 0.08f);

// Countershading: the coat at fraction v across the body's depth (0 on the back line, 1 on
// the belly line; > 1 below it, the legs), before any pattern. sRGB.
glm::vec3 countershade(const Look& look, float v);

// The outline stroke's colour for a coat (a dark shade of its base).
glm::vec3 outline_colour(const Look& look);

// sRGB 0…1 (+ alpha) → bytes.
std::array<uint8_t, 4> to_rgba8(glm::vec4 c);

}  // namespace ossa
