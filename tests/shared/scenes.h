#pragma once
// Shared scenes (STYLE.md): the levels, chains and creatures that tests, benchmarks and tools
// all use, built in one place.

#include <string>

namespace ossa::scenes {

// Absolute path of a file in the source tree (levels/, assets/, tests/...): data_path()
// (ossa/io/data_dir.h), the OSSA_SOURCE_DIR environment variable when set (CTest sets it),
// else the compiled-in source tree.
std::string source_path(const std::string& relative);

}  // namespace ossa::scenes

#include "ossa/skeleton/skeleton.h"

namespace ossa::scenes {

// A straight chain of `bones` bones (the first is the root at the origin), each `length`
// metres long, each joint bent by `bend` radians.
Skeleton chain_skeleton(int bones, float length, float bend = 0.0f);

}  // namespace ossa::scenes

#include "ossa/gen/generator.h"

namespace ossa::scenes {

// The generator fitted on the shipped examples (loaded once per process).
const Generator& generator();

// Example `name` in a fixed frame of `frame_m` metres instead of its true size (the genome's
// other size choice): the 2 m frame the shipped levels' steps were laid out for, where a test
// is about how a creature meets steps rather than about its size.
Creature example_in_frame(std::string_view name, float frame_m = 2.0f);

}  // namespace ossa::scenes

namespace ossa::scenes {

// The walkers the animation tests, benchmarks and tools share: a biped (kangaroo), a
// quadruped (horse) and a creature with three leg pairs (two at the shoulder, one at the hip,
// built from a multi-limb genome).
Creature biped();     // the kangaroo's skeleton in the biped gait family (legs alternate)
Creature kangaroo();  // the kangaroo as it is (the hopper family)
Creature quadruped();
Creature three_leg_pairs();

// A small creature built bone by bone, independent of the generator, so the exporters can be
// tested on a known skeleton (tests/gen/export_test.cpp, tests/render/gltf_export_test.cpp): a
// four-legged animal (or, with `winged`, a two-legged one with wings) with root, neck, back and
// tail vertebrae, skull, ribs, scapulae, pelves and near/far limbs, posed so that the feet touch
// y = 0. Defined in shared/hand_creature.cpp.
Creature hand_built_creature(bool winged = false, ContactMode contact = ContactMode::kTip);

}  // namespace ossa::scenes
