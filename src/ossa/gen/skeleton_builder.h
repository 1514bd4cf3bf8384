#pragma once
// SkeletonBuilder — turns a Genome into a Creature, deterministically (no random numbers)
// [Z ch. 7, DESIGN.md §5.3–5.8]:
//   1. post-process the PCA point: spine made C1 at shoulder and hip by rotating the two
//      neighbouring control points by equal and opposite angles [Z 9.6.2]; lengths ≥ 0;
//   2. apply one rule per non-terminal until only bones remain [Z 5.2]:
//      Skeleton → Spine + Girdles + Skull; Spine → Neck + Back + Tail; Neck/Back/Tail →
//      vertebrae placed by arc length (or t = i/n); Back → ribs on [0, rib_interval];
//      Girdle → girdle bone + Limbs; Limb → upper + lower + hand, near and far copies;
//   3. pose limbs with the genome's rest angles and place the model on its ground (y = 0).

#include "ossa/gen/creature.h"
#include "ossa/gen/genome.h"
#include "ossa/io/result.h"

namespace ossa {

// Builds the creature. Errors name the genome field that cannot be built (e.g. a limb on a
// girdle it is not allowed on).
Result<Creature> build_creature(const Genome& genome);

}  // namespace ossa
