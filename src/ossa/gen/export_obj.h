#pragma once
// OBJ export — the box proxies of [Z 7.4]: every bone of a Creature (in its rest pose) as one
// box, length × width × depth, in model space (metres, +x forward, +y up, +z towards the
// viewer). Near-side bones sit at +z, far-side bones at -z, body bones (spine, skull) at z = 0,
// so the proxies of a four-legged creature stand like a 3D skeleton. Real bone meshes can later
// replace the boxes (the thesis's unit-box convention).
//
// Per bone: "o <name>" and "g <name>", 8 vertices ("v x y z") and 6 quad faces ("f a b c d",
// 1-based, counter-clockwise seen from outside). Bones of zero length (the root) or with
// non-finite transforms get no box. Names are written with whitespace replaced by '_'.

#include <string>

#include "ossa/gen/creature.h"

namespace ossa {

struct ObjOptions {
  float depth_ratio = 1.0f;  // box depth (z) as a multiple of the bone's width, > 0
  // Distance in z of the near/far copies from the body plane, metres. < 0: half the longest
  // rib, or 1.5 × the widest back vertebra when there are no ribs (the rib cage's half width).
  float side_offset = -1.0f;
};

std::string creature_obj(const Creature& creature, const ObjOptions& options = {});

// Number of boxes creature_obj writes (bones with length > 0 and finite transforms).
int creature_obj_box_count(const Creature& creature);

}  // namespace ossa
