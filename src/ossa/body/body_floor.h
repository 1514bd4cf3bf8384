#pragma once
// The floor a body rests on (issue 30): flesh yields to the ground rather than enter it. The
// animator keeps bones out of the level's boxes, but flesh lies around the bones — a knee
// on the ground, a belly or a tail in a landing's crouch, a heel as the shin turns over it —
// so where a skinned body vertex would lie below the top of a box under the creature it is
// lifted onto that top, as soft tissue flattens where it meets the ground. The floor is a few
// box tops (x-range and height) under the creature, found on the CPU every frame from the
// level and the pose, and sent with the creature's palette (kBodyFloorEntries entries after
// its bones and mid joints); the body shader (shaders/body.vert) and floor_point() apply it
// alike. Only tops lying below the bones over them count, so ceilings and walls higher than
// the creature never pull flesh up.

#include <array>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "ossa/level/level.h"
#include "ossa/math/transform2d.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

inline constexpr int kBodyFloorSegments = 8;
inline constexpr int kBodyFloorEntries = kBodyFloorSegments / 2;  // two segments per palette entry

struct BodyFloor {
  // Box tops under the creature, world metres: x from, x to, top y. Unused: x from > x to.
  std::array<glm::vec3, kBodyFloorSegments> segments;
  int count = 0;
  BodyFloor() { segments.fill(glm::vec3(1.0f, 0.0f, 0.0f)); }
};

// The floor under a creature posed by `world` (its bones' frames, bone → world): the tops of
// the boxes of `level` within `reach` metres (the flesh around its bones) of its bones' x-span
// that lie no higher than the highest bone over them (or, past the bones' ends, the nearest
// bone) plus half of `reach` (bones sunk into the ground) or 1 mm. Neighbouring tops of one height merge; while more than kBodyFloorSegments
// remain, the two neighbours whose merging lifts the least flesh merge at the higher top.
BodyFloor body_floor(const Level& level, const Skeleton& skeleton, std::span<const Mat2x3> world, float reach);

// A level ground at `top` under everything (pictures of a creature standing on a plain
// ground line: ossa-render without a level, creature images, contact sheets).
BodyFloor flat_floor(float top);

// `p` (world) lifted onto the highest floor top under it when it lies below that top; a top
// holds it up `overhang` metres past its ends too (BodyVertex::overhang): an outline edge no
// longer than that, between two floored vertices, then never cuts the top's corner.
glm::vec2 floor_point(glm::vec2 p, const BodyFloor& floor, float overhang = 0.0f);

// The floor as kBodyFloorEntries palette entries (segments 2k and 2k+1 in entry k: x from,
// x to, top of the first, then of the second), as the body shader reads them.
void encode_floor(const BodyFloor& floor, std::span<Mat2x3> entries);
BodyFloor decode_floor(std::span<const Mat2x3> entries);

}  // namespace ossa
