#include "shared/scenes.h"

#include "ossa/body/body_mesh.h"
#include "ossa/io/data_dir.h"

namespace ossa::scenes {

std::string source_path(const std::string& relative) { return data_path(relative); }

}  // namespace ossa::scenes

namespace ossa::scenes {

Skeleton chain_skeleton(int bones, float length, float bend) {
  Skeleton s;
  for (int i = 0; i < bones; ++i) {
    BoneLocal rest;
    rest.offset_ls = i == 0 ? glm::vec2(0.0f) : glm::vec2(length, 0.0f);
    rest.angle_ls = i == 0 ? 0.0f : bend;
    s.add_bone("bone" + std::to_string(i), i == 0 ? BoneKind::kRoot : BoneKind::kBackVertebra,
               i == 0 ? kNoParent : i - 1, length, 0.1f * length, rest, Layer::kBody);
  }
  return s;
}

}  // namespace ossa::scenes

namespace ossa::scenes {

const Generator& generator() {
  static const Generator g = [] {
    Result<Generator> r = Generator::load(source_path("assets/creatures/examples.json"), ossa::body_volume_m3);
    OSSA_ASSERT(r.ok(), "assets/creatures/examples.json must load");
    return std::move(r.value());
  }();
  return g;
}

}  // namespace ossa::scenes

#include "ossa/gen/skeleton_builder.h"

namespace ossa::scenes {

Creature biped() {
  // The kangaroo's skeleton moving as a plain biped (its own family hops: kangaroo()).
  Genome g = generator().example("kangaroo").value();
  g.gait_family = GaitFamily::kBiped;
  return build_creature(g).value();
}

Creature example_in_frame(std::string_view name, float frame_m) {
  GenerateOptions o;
  o.genome.true_size = false;
  o.genome.frame_m = frame_m;
  return build_creature(generator().example(name, 1, o).value()).value();
}

Creature kangaroo() { return build_creature(generator().example("kangaroo").value()).value(); }

Creature quadruped() { return build_creature(generator().example("horse").value()).value(); }

Creature three_leg_pairs() {
  GenerateOptions o;
  o.genome.multi_limb = true;
  Genome g = generator().example("dromedary", 1, o).value();
  g.name = "three-leg-pairs";
  g.limbs = {LimbGene{LimbKind::kLeg, GirdleKind::kShoulder, 0, {}},
             LimbGene{LimbKind::kLeg, GirdleKind::kShoulder, 1, {}},
             LimbGene{LimbKind::kLeg, GirdleKind::kHip, 0, {}}};
  recompute_rest_angles(g);
  generator().apply_size(g);  // the body changed: its true size with it
  return build_creature(g).value();
}

}  // namespace ossa::scenes
