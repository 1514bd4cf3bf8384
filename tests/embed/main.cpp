// The smallest game that embeds ossa through find_package(ossa): load a level, stand a
// generated creature on it, walk it for two seconds, and solve an IK chain by hand.
#include <cstdio>
#include <memory>
#include <string>

#include <ossa/body/body_mesh.h>
#include <ossa/anim/animator.h>
#include <ossa/game/player.h>
#include <ossa/gen/generator.h>
#include <ossa/gen/skeleton_builder.h>
#include <ossa/level/level_io.h>
#include <ossa/math/two_bone_ik.h>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: embed_demo LEVEL EXAMPLES.json  (LEVEL: .json, .tmj, .tmx or project.ldtk#Level)\n");
    return 2;
  }
  ossa::Result<ossa::Level> level = ossa::load_level(argv[1]);
  if (!level) {
    std::fprintf(stderr, "%s\n", level.message().c_str());
    return 1;
  }
  const ossa::TwoBoneIkResult ik = ossa::solve_two_bone_ik({0.0f, 1.0f}, 0.5f, 0.5f, {0.3f, 0.2f}, 1.0f);
  if (!ik.reached) return 1;

  ossa::Result<ossa::Generator> gen = ossa::Generator::load(argv[2], ossa::body_volume_m3);
  if (!gen) {
    std::fprintf(stderr, "%s\n", gen.message().c_str());
    return 1;
  }
  auto creature = std::make_shared<const ossa::Creature>(ossa::build_creature(gen->example("horse").value()).value());
  ossa::Player player(creature, ossa::SplinePrototypes::defaults());
  player.animator().reset(level->spawn_ws + glm::vec2(0.0f, 1.0f), *level);
  for (int tick = 0; tick < 240; ++tick) player.step(1.0f / 120.0f, {0.5f, false}, *level);
  std::printf("level %s: %d colliders; ik upper %.3f lower %.3f; horse walked to x = %.2f (%s)\n",
              argv[1], level->size(), ik.upper_angle, ik.lower_angle, player.animator().x(),
              ossa::gait_name(player.animator().gait()));
  return player.animator().x() > level->spawn_ws.x + 1.0f ? 0 : 1;
}
