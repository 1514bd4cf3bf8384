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
#include <cstdint>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "ossa/level/level.h"
#include "ossa/math/transform2d.h"
#include "ossa/skeleton/skeleton.h"

namespace ossa {

inline constexpr int kBodyFloorSegments = 8;
// A leg's foot standing on a top holds that leg's flesh up past the top's ends (floor_point):
// up to this many feet per creature (BodyVertex::foot; later legs keep their flesh as skinned).
inline constexpr int kBodyFloorFeet = 8;
inline constexpr uint8_t kNoFoot = 255;
// Two segments or two feet per palette entry: the segments first, then the feet.
inline constexpr int kBodyFloorEntries = (kBodyFloorSegments + kBodyFloorFeet) / 2;

// A leg's foot as the floor sees it (BodyMesh::feet): the ends of its bones that bear on the
// ground — its foot bone's (the toe's), and for a flat foot its shin's too (the heel's).
struct BodyFoot {
  int toe_bone = -1;
  int heel_bone = -1;  // -1: a foot standing on its tip
};

struct BodyFloor {
  // Box tops under the creature, world metres: x from, x to, top y. Unused: x from > x to.
  std::array<glm::vec3, kBodyFloorSegments> segments;
  int count = 0;
  // Per foot (BodyVertex::foot), the top it stands on, as a segment (unused: not standing).
  std::array<glm::vec3, kBodyFloorFeet> feet;
  BodyFloor() {
    segments.fill(glm::vec3(1.0f, 0.0f, 0.0f));
    feet.fill(glm::vec3(1.0f, 0.0f, 0.0f));
  }
};

// The floor under a creature posed by `world` (its bones' frames, bone → world): the tops of
// the boxes of `level` within `reach` metres (the flesh around its bones) of its bones' x-span
// that lie no higher than the highest bone over them (or, past the bones' ends, the nearest
// bone) plus half of `reach` (bones sunk into the ground) or 1 mm. Neighbouring tops of one
// height merge; while more than kBodyFloorSegments remain, the two neighbours whose merging
// lifts the least flesh merge at the higher top.
// And for each of `feet` (BodyMesh::feet) whose toe or heel lies on a box's top (within
// kFootOnTop), that top with the tops of one height joining it, within its foot bone's length
// of the toe and heel.
BodyFloor body_floor(const Level& level, const Skeleton& skeleton, std::span<const Mat2x3> world, float reach,
                     std::span<const BodyFoot> feet);
inline constexpr float kFootOnTop = 0.002f;  // metres

// A level ground at `top` under everything (pictures of a creature standing on a plain
// ground line: ossa-render without a level, creature images, contact sheets).
BodyFloor flat_floor(float top);

// `p` (world) lifted onto the highest floor top under it when it lies below that top; a top
// holds it up `overhang` metres past its ends too (BodyVertex::overhang): an outline edge no
// longer than that, between two floored vertices, then never cuts the top's corner.
// A leg's point (`foot` < kBodyFloorFeet) is held up past a top's ends only by the top its own
// foot stands on, and only where it lies less than `overhang` below it: the flesh of a foot
// standing at a tread's edge, its sole or its shin's underside out over the edge, stays level
// with the tread rather than cut its corner, while a hoof beside a riser (another top) keeps
// its shape, as does a leg hanging down past a ledge.
glm::vec2 floor_point(glm::vec2 p, const BodyFloor& floor, float overhang = 0.0f, uint8_t foot = kNoFoot);

// The floor as kBodyFloorEntries palette entries (segments 2k and 2k+1 in entry k: x from,
// x to, top of the first, then of the second; then the feet's tops alike), as the body shader
// reads them.
void encode_floor(const BodyFloor& floor, std::span<Mat2x3> entries);
BodyFloor decode_floor(std::span<const Mat2x3> entries);

}  // namespace ossa
