#pragma once
// The whole of ossa::core in one include (DESIGN.md §1): math, io, skeleton, gen, body, level,
// anim, rig and game. No SDL, OpenGL or ImGui: link ossa::core (find_package(ossa)). The
// drawing side is <ossa/render.h> (ossa::render). Every public header of those modules is
// here (the CTest "install: ossa.h and render.h include every installed header" checks it);
// the headers of a module's internals are neither here nor installed.

#include "ossa/assert.h"

// math: splines, transforms, two-bone IK, seeded random numbers
#include "ossa/math/angle.h"
#include "ossa/math/bezier.h"
#include "ossa/math/hermite.h"
#include "ossa/math/rng.h"
#include "ossa/math/transform2d.h"
#include "ossa/math/two_bone_ik.h"

// io: Result/Error, JSON, files, the data folder
#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/io/image_info.h"
#include "ossa/io/json.h"
#include "ossa/io/json_fwd.h"
#include "ossa/io/parse_arg.h"
#include "ossa/io/result.h"

// skeleton: Skeleton, Pose, forward kinematics
#include "ossa/skeleton/mid_joint.h"
#include "ossa/skeleton/pose.h"
#include "ossa/skeleton/skeleton.h"

// gen: examples, PCA model, Genome, SkeletonBuilder, exports
#include "ossa/gen/body_plan.h"
#include "ossa/gen/creature.h"
#include "ossa/gen/dataset.h"
#include "ossa/gen/export_obj.h"
#include "ossa/gen/export_svg.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/gait_family.h"
#include "ossa/gen/genome.h"
#include "ossa/gen/look.h"
#include "ossa/gen/pca_model.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/gen/skull_shape.h"
#include "ossa/gen/true_size.h"

// body: bodies: flesh, skin and coat built from the skeleton
#include "ossa/body/body_floor.h"
#include "ossa/body/body_mass.h"
#include "ossa/body/body_mesh.h"
#include "ossa/body/body_svg.h"
#include "ossa/body/coat.h"

// level: Level, its spatial index and queries, level files, Tiled and LDtk
#include "ossa/level/box.h"
#include "ossa/level/box_tree.h"
#include "ossa/level/ldtk.h"
#include "ossa/level/ldtk_art.h"
#include "ossa/level/level.h"
#include "ossa/level/level_art.h"
#include "ossa/level/level_io.h"
#include "ossa/level/level_load.h"
#include "ossa/level/tile_merge.h"
#include "ossa/level/tiled.h"

// anim: AnimRig, the animator's stages, Animator, SplinePrototypes, AnimatorParams
#include "ossa/anim/anim_math.h"
#include "ossa/anim/anim_rig.h"
#include "ossa/anim/anim_state.h"
#include "ossa/anim/animator.h"
#include "ossa/anim/animator_params.h"
#include "ossa/anim/body_motion.h"
#include "ossa/anim/body_placement.h"
#include "ossa/anim/foothold.h"
#include "ossa/anim/gait_clock.h"
#include "ossa/anim/gait_family.h"
#include "ossa/anim/ground_profile.h"
#include "ossa/anim/leg_geometry.h"
#include "ossa/anim/leg_ik.h"
#include "ossa/anim/level_probe.h"
#include "ossa/anim/limb_clearance.h"
#include "ossa/anim/locomotion.h"
#include "ossa/anim/pentapedal.h"
#include "ossa/anim/pose_stage.h"
#include "ossa/anim/rig_scale.h"
#include "ossa/anim/secondary_motion.h"
#include "ossa/anim/spline_prototypes.h"
#include "ossa/anim/step.h"
#include "ossa/anim/swing.h"
#include "ossa/anim/trunk_bob.h"
#include "ossa/anim/turn.h"

// rig: rigged characters: mappings, guessing, building a Character
#include "ossa/rig/character.h"
#include "ossa/rig/character_checks.h"
#include "ossa/rig/rig_guess.h"
#include "ossa/rig/rig_mapping.h"

// game: Controls, Player, World, Replay, headless simulation, its gait measurement and the
// drawn body's outline against the level
#include "ossa/game/controls.h"
#include "ossa/game/gait_metrics.h"
#include "ossa/game/herd.h"
#include "ossa/game/outline_probe.h"
#include "ossa/game/player.h"
#include "ossa/game/replay.h"
#include "ossa/game/sim.h"
#include "ossa/game/world.h"
