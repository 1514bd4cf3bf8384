#include "ossa/gen/generator.h"

#include <algorithm>
#include <cmath>

#include "ossa/gen/body_plan.h"
#include "ossa/gen/pca_model.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/math/rng.h"

namespace ossa {

namespace {

struct Slot {
  GirdleKind girdle;
  int slot;
};

int skull_for_class(const std::string& animal_class) {
  if (animal_class == "bird") return 1;
  if (animal_class == "fish") return 3;
  if (animal_class == "reptile" || animal_class == "dinosaur" || animal_class == "amphibian") return 2;
  return 0;
}

// [Z 7.2.4]: a limb takes a random free slot it is allowed on; with none free, another limb
// that may move to a free slot makes room; else the limb is dropped.
bool place_limb(LimbKind kind, std::vector<LimbGene>& placed, const std::vector<Slot>& slots, Rng& rng,
                const Slot* preferred = nullptr) {
  auto is_free = [&](const Slot& s) {
    for (const LimbGene& l : placed) {
      if (l.girdle == s.girdle && l.slot == s.slot) return false;
    }
    return true;
  };
  std::vector<Slot> free;
  for (const Slot& s : slots) {
    if (is_free(s) && limb_allowed(kind, s.girdle)) free.push_back(s);
  }
  if (!free.empty()) {
    Slot chosen = free[static_cast<size_t>(rng.uniform_int(0, static_cast<int>(free.size()) - 1))];
    for (const Slot& s : free) {
      if (preferred && s.girdle == preferred->girdle && s.slot == preferred->slot) chosen = s;
    }
    placed.push_back({kind, chosen.girdle, chosen.slot, {}});
    return true;
  }
  auto in_slots = [&](GirdleKind girdle, int slot) {
    return std::any_of(slots.begin(), slots.end(), [&](const Slot& s) { return s.girdle == girdle && s.slot == slot; });
  };
  for (LimbGene& other : placed) {
    if (!limb_allowed(kind, other.girdle) || !in_slots(other.girdle, other.slot)) continue;
    for (const Slot& s : slots) {
      if (is_free(s) && limb_allowed(other.kind, s.girdle)) {
        const LimbGene moved_from = other;
        other.girdle = s.girdle;
        other.slot = s.slot;
        placed.push_back({kind, moved_from.girdle, moved_from.slot, {}});
        return true;
      }
    }
  }
  return false;
}

// A foot at least this long against the leg above it (upper + lower) stands on its tip, as
// hooved and toe-walking animals do on their long metapodials; at most this long, flat (the
// examples: horse, deer, camel 0.58–0.79 against tortoise, crocodile, lizards 0.32–0.35).
constexpr double kTipFootOfLeg = 0.55;
constexpr double kFlatFootOfLeg = 0.36;

// A random creature's contact mode from its legs' mean foot proportion; between the two bounds
// the heel draw decides.
ContactMode contact_from_proportions(const BodyPlan& plan, const Genome& g, bool heel_draw) {
  double sum = 0.0;
  int count = 0;
  for (const LimbGene& limb : g.limbs) {
    if (limb.kind != LimbKind::kLeg) continue;
    const LimbLengths l = limb_lengths(plan, g, limb.kind, limb.girdle);
    if (l.upper + l.lower <= 0.0) continue;
    sum += l.distal / (l.upper + l.lower);
    ++count;
  }
  if (count == 0) return ContactMode::kTip;
  const double foot = sum / count;
  if (foot >= kTipFootOfLeg) return ContactMode::kTip;
  if (foot <= kFlatFootOfLeg) return ContactMode::kFlat;
  return heel_draw ? ContactMode::kFlat : ContactMode::kTip;
}

// The frame's scale: its metres over the skeleton's 1000 frame units.
void use_frame(Genome& g) {
  g.options.frame_m = std::clamp(g.options.frame_m, kMinFrameMetres, kMaxFrameMetres);
  g.scale = g.options.frame_m / 1000.0f;
}

}  // namespace

SkullShape random_skull_shape(int variant, uint64_t seed) {
  Rng rng(seed ^ 0x736b756c6c2d7631ull);  // "skull-v1": its own stream of the seed
  SkullShape s = default_skull_shape(variant);
  s.length *= static_cast<float>(rng.uniform(0.85, 1.2));
  s.height *= static_cast<float>(rng.uniform(0.85, 1.2));
  s.snout = std::clamp(s.snout * static_cast<float>(rng.uniform(0.85, 1.15)), kMinSnout, kMaxSnout);
  return s;
}

std::vector<Appendage> random_appendages(const Genome& g, uint64_t seed) {
  Rng rng(seed ^ 0x617070656e646167ull);  // "appendag": its own stream of the seed
  int legs = 0, wings = 0, fins = 0, leg_pairs_hip = 0;
  for (const LimbGene& l : g.limbs) {
    legs += l.kind == LimbKind::kLeg;
    wings += l.kind == LimbKind::kWing;
    fins += l.kind == LimbKind::kFin;
    leg_pairs_hip += l.kind == LimbKind::kLeg && l.girdle == GirdleKind::kHip;
  }
  std::vector<Appendage> out;
  const auto add = [&](AppendageKind kind, double lo, double hi) {
    out.push_back({kind, static_cast<float>(rng.uniform(lo, hi))});
  };
  const bool swims = legs == 0 && wings == 0 && fins > 0;
  if (swims) {
    // Fish and whales: a caudal fin or fluke, usually a dorsal fin.
    add(AppendageKind::kTailFin, 0.8, 1.2);
    if (rng.chance(g.skull_variant == 3 ? 0.9 : 0.5)) add(AppendageKind::kDorsalFin, 0.6, 1.2);
    return out;
  }
  switch (g.skull_variant) {
    case 0:  // mammals: ears; hoofed quadrupeds sometimes horns or antlers
      if (legs > 0) add(AppendageKind::kEars, 0.7, 1.4);
      if (legs >= 2 && g.contact == ContactMode::kTip) {
        const double u = rng.uniform();
        if (u < 0.2) add(AppendageKind::kHorns, 0.6, 1.3);
        else if (u < 0.3) add(AppendageKind::kAntlers, 0.6, 1.2);
      }
      if (legs >= 2 && rng.chance(0.15)) add(AppendageKind::kMane, 0.6, 1.2);
      if (legs >= 2 && rng.chance(0.05)) add(AppendageKind::kHump, 0.6, 1.2);
      if (legs >= 2 && g.pca[kWeightKg] > 1000.0 && rng.chance(0.1)) add(AppendageKind::kTrunk, 0.7, 1.2);
      break;
    case 1:  // birds: sometimes a crest
      if (rng.chance(0.2)) add(AppendageKind::kCrest, 0.6, 1.3);
      break;
    case 2: {  // reptiles: crests, frills, sails, plates, shells — now and then
      const double u = rng.uniform();
      if (legs > 0 && u < 0.08) add(AppendageKind::kFrill, 0.6, 1.2);
      else if (legs > 0 && u < 0.16) add(AppendageKind::kSail, 0.6, 1.2);
      else if (legs > 0 && u < 0.22) add(AppendageKind::kPlates, 0.6, 1.2);
      else if (legs >= 2 && leg_pairs_hip > 0 && u < 0.26) add(AppendageKind::kShell, 0.8, 1.1);
      else if (u < 0.38) add(AppendageKind::kCrest, 0.5, 1.2);
      break;
    }
    default: break;
  }
  return out;
}

Generator::Generator(Dataset dataset, PcaModel model, BodyVolume body_volume)
    : dataset_(std::move(dataset)),
      model_(std::make_shared<const PcaModel>(std::move(model))),
      body_volume_(std::move(body_volume)) {}

Result<Generator> Generator::load(const std::string& dataset_path, BodyVolume body_volume) {
  Result<Dataset> data = load_dataset(dataset_path);
  if (!data) return data.error();
  if (data->animals.size() < 2) return Error::at(dataset_path, "animals", "expected at least 2 animals");
  PcaModel model = PcaModel::fit(*data);
  return Generator(std::move(*data), std::move(model), std::move(body_volume));
}

void recompute_rest_angles(Genome& g) {
  const BodyPlan plan = plan_body(g);
  for (LimbGene& limb : g.limbs) {
    switch (limb.kind) {
      case LimbKind::kLeg: {
        const GirdlePlan& gp = plan.girdles[static_cast<int>(limb.girdle)];
        if (!gp.exists) break;
        limb.angles = place_leg(plan, gp.joint_fu[limb.slot], limb_lengths(plan, g, limb.kind, limb.girdle),
                                limb.girdle, g.contact);
        break;
      }
      case LimbKind::kArm: limb.angles = arm_rest_angles(); break;
      case LimbKind::kFin: limb.angles = fin_rest_angles(); break;
      case LimbKind::kWing: break;
    }
  }
}

Genome Generator::complete(std::array<double, kPcaDims> pca, Rng& rng, const GenerateOptions& options,
                           std::string name, uint64_t seed) const {
  Genome g;
  g.name = std::move(name);
  g.seed = seed;
  g.pca = pca;
  g.options = options.genome;
  g.pca[kWeightKg] = std::max(0.01, g.pca[kWeightKg]);
  clamp_to_genome_limits(g);  // a far draw stays within what the loader reads back

  // Girdles this body offers (the neck girdle needs a long enough neck) [Z 7.2.3].
  const BodyPlan bare = plan_body(g);
  std::vector<Slot> slots;
  const int per_girdle = g.options.multi_limb ? 2 : 1;
  for (GirdleKind k : {GirdleKind::kShoulder, GirdleKind::kHip, GirdleKind::kNeck}) {
    if (!bare.girdles[static_cast<int>(k)].exists) continue;
    for (int s = 0; s < per_girdle; ++s) slots.push_back({k, s});
  }
  if (g.options.neck_girdle && !bare.girdles[static_cast<int>(GirdleKind::kNeck)].exists) {
    g.options.neck_girdle = false;  // the neck is too short after all: no neck girdle
  }

  // Counts [Z 7.2.4]: user input first, else lotteries on the PCA point.
  const double wing_p = std::clamp(g.pca[kWings], 0.0, 1.0);
  const double leg_v = std::clamp(g.pca[kLegPairs], 0.0, 2.0);
  const int wings = options.wings ? *options.wings : (rng.chance(wing_p) ? 1 : 0);
  const int legs = options.leg_pairs ? *options.leg_pairs
                                     : (leg_v <= 1.0 ? (rng.chance(leg_v) ? 1 : 0) : (rng.chance(leg_v - 1.0) ? 2 : 1));
  const int arms = options.arm_pairs ? *options.arm_pairs : (rng.chance(wing_p) ? 1 : 0);
  const double front_total = std::max(0.0, g.pca[kFrontUpper]) + std::max(0.0, g.pca[kFrontLower]) +
                             std::max(0.0, g.pca[kFrontHand]);
  const bool front_limb = front_total > 0.15 * bare.body_size;
  // Fins: legless, wingless bodies swim; with a front limb it becomes the fin, else a coin
  // decides between a fish and a snake-like body.
  int fins = 0;
  if (options.fin_pairs) {
    fins = *options.fin_pairs;
  } else if (legs == 0 && wings == 0) {
    fins = front_total > 0.02 * bare.body_size || rng.chance(0.5) ? 1 : 0;
  }

  std::vector<LimbGene> placed;
  for (int i = 0; i < wings; ++i) place_limb(LimbKind::kWing, placed, slots, rng);
  // A lone leg pair stands on the hip when the hind limb can carry the body: bipeds carry
  // their weight behind [Z 7.2.3]; the seed's random girdle puts a kangaroo on its front legs
  // half of the time.
  const Slot hip_slot = Slot{GirdleKind::kHip, 0};
  // A leg must be able to carry the body: girdles whose limb is shorter than 10% of the back
  // get no legs (random points near the legless examples have stubs there).
  std::vector<Slot> leg_slots;
  for (const Slot& s : slots) {
    if (limb_lengths(bare, g, LimbKind::kLeg, s.girdle).total() >= 0.1 * bare.body_size) leg_slots.push_back(s);
  }
  for (int i = 0; i < legs; ++i) {
    // At most one leg pair per girdle [Z 7.2.4], even with several slots per girdle.
    std::vector<Slot> usable;
    for (const Slot& s : leg_slots) {
      if (std::none_of(placed.begin(), placed.end(), [&](const LimbGene& l) {
            return l.kind == LimbKind::kLeg && l.girdle == s.girdle;
          })) {
        usable.push_back(s);
      }
    }
    place_limb(LimbKind::kLeg, placed, usable, rng, legs == 1 ? &hip_slot : nullptr);
  }
  for (int i = 0; i < arms; ++i) place_limb(LimbKind::kArm, placed, slots, rng);
  // Arms come with the wing probability [Z 7.2.4]; a walker with a free shoulder and a
  // substantial front limb keeps it as arms (kangaroo, T. rex, human), else it would vanish.
  if (!options.arm_pairs && arms == 0 && legs >= 1 && front_limb) {
    bool shoulder_free = true;
    for (const LimbGene& l : placed) shoulder_free &= !(l.girdle == GirdleKind::kShoulder && l.slot == 0);
    if (shoulder_free) placed.push_back({LimbKind::kArm, GirdleKind::kShoulder, 0, {}});
  }
  for (int i = 0; i < fins; ++i) place_limb(LimbKind::kFin, placed, slots, rng);
  // Stable order: by girdle (neck, shoulder, hip), then slot.
  std::stable_sort(placed.begin(), placed.end(), [](const LimbGene& a, const LimbGene& b) {
    return std::make_pair(static_cast<int>(a.girdle), a.slot) < std::make_pair(static_cast<int>(b.girdle), b.slot);
  });
  g.limbs = placed;

  // Vertebrae and ribs [Z 7.3].
  g.neck_vertebrae = wings > 0 ? rng.uniform_int(10, 30) : 7;
  g.back_vertebrae = 25;
  g.tail_vertebrae = rng.uniform_int(5, 20);
  g.rib_interval = static_cast<float>(rng.uniform(0.35, 1.0));

  // Skull: by the body's features (examples override it by their class).
  if (wings > 0) {
    g.skull_variant = 1;
  } else if (legs == 0) {
    g.skull_variant = fins > 0 ? 3 : 2;
  } else {
    g.skull_variant = rng.chance(0.25) ? 2 : 0;
  }
  g.skull_shape = random_skull_shape(g.skull_variant, seed);

  // Size: the frame for now; apply_size sets the true size once the body is complete.
  use_frame(g);

  // Contact mode: as given (an example's posture), else from the legs' proportions, then the
  // rest pose. The heel draw [Z 7.2.1] is made either way, so that a given contact leaves the
  // rest of the genome as the seed makes it.
  const BodyPlan plan = plan_body(g);
  const bool heel_draw = rng.chance(plan.heel_probability);
  g.contact = options.contact ? *options.contact : contact_from_proportions(plan, g, heel_draw);
  // Winged bodies stand on their toes: flat would lay a bird's tarsometatarsus on the ground.
  if (wings > 0) g.contact = ContactMode::kTip;
  if (g.contact == ContactMode::kFlat) {
    // Standing flat shortens the reach to the heel; a girdle that would then sit too low to
    // stand (under 30% of its reach above the ground) keeps to its toes.
    const BodyPlan flat = plan_body(g);
    for (const LimbGene& limb : g.limbs) {
      if (limb.kind != LimbKind::kLeg) continue;
      const LimbLengths l = limb_lengths(flat, g, limb.kind, limb.girdle);
      const float height = flat.girdles[static_cast<int>(limb.girdle)].joint_fu[limb.slot].y - flat.ground_y;
      if (height < 0.3f * static_cast<float>(l.upper + l.lower)) g.contact = ContactMode::kTip;
    }
  }
  for (LimbGene& limb : g.limbs) {
    if (limb.kind == LimbKind::kWing) {
      // Folded wing: random angles in fixed intervals [Z 7.2].
      limb.angles = {static_cast<float>(rng.uniform(-2.9, -2.6)), static_cast<float>(rng.uniform(-3.0, -2.7)),
                     static_cast<float>(rng.uniform(2.6, 3.0))};
    }
  }
  recompute_rest_angles(g);
  // The body: a coat and appendages from their own streams of the seed (no other draw moves).
  g.look = random_look(seed, g.skull_variant, wings > 0);
  g.appendages = random_appendages(g, seed);
  clamp_to_genome_limits(g);
  return g;
}

Genome Generator::random(uint64_t seed, const GenerateOptions& options) const {
  Rng rng(seed);
  std::vector<Condition> conditions;
  if (options.wings) conditions.push_back({kWings, static_cast<double>(*options.wings), true});
  if (options.leg_pairs) conditions.push_back({kLegPairs, static_cast<double>(*options.leg_pairs), true});
  if (options.weight_kg) conditions.push_back({kWeightKg, *options.weight_kg, false});
  if (options.genome.neck_girdle) {
    // Forcing a neck girdle is a condition on the neck [Z 7.2.3]: the head end as high as
    // the long-necked examples carry it.
    double high = 0.0;
    for (const Animal& a : dataset_.animals) high = std::max<double>(high, a.spine[kSpineHead].y);
    conditions.push_back({spine_y_dim(kSpineHead), 0.9 * high, false});
  }
  PcaVector raw = model_->sample_conditional(rng, conditions);
  // Reject the rare degenerate draw (a back shorter than 5% of the frame).
  for (int attempt = 0; attempt < 8; ++attempt) {
    const glm::vec2 d = glm::vec2(raw[spine_x_dim(kSpineHip)] - raw[spine_x_dim(kSpineShoulder)],
                                  raw[spine_y_dim(kSpineHip)] - raw[spine_y_dim(kSpineShoulder)]);
    if (std::sqrt(d.x * d.x + d.y * d.y) > 50.0f) break;
    raw = model_->sample_conditional(rng, conditions);
  }
  std::array<double, kPcaDims> pca;
  for (int d = 0; d < kPcaDims; ++d) pca[d] = raw[d];
  Genome g = complete(pca, rng, options, "random-" + std::to_string(seed), seed);
  apply_size(g);
  return g;
}

Result<Genome> Generator::example(std::string_view name, uint64_t seed, const GenerateOptions& options) const {
  const Animal* animal = dataset_.find(name);
  if (!animal) return Error::at("", "example", "no example animal named \"" + std::string(name) + "\"");
  const PcaVector raw = to_vector(*animal);
  std::array<double, kPcaDims> pca;
  for (int d = 0; d < kPcaDims; ++d) pca[d] = raw[d];
  GenerateOptions o = options;
  // The example's own counts decide (they are exact 0/1/2 values).
  if (!o.wings) o.wings = animal->wings;
  if (!o.leg_pairs) o.leg_pairs = animal->leg_pairs;
  if (!o.contact && animal->posture) {
    o.contact = *animal->posture == LimbPosture::kPlantigrade ? ContactMode::kFlat : ContactMode::kTip;
  }
  if (!o.fin_pairs) {
    // Fish and whales swim with fins; a snake has none.
    const bool swims = animal->animal_class == "fish" || (animal->leg_pairs == 0 && animal->wings == 0 &&
                                                          animal->front.total() > 0.0);
    o.fin_pairs = swims ? 1 : 0;
  }
  Rng rng(seed);
  Genome g = complete(pca, rng, o, animal->name, seed);
  g.skull_variant = skull_for_class(animal->animal_class);
  g.skull_shape = animal->skull ? *animal->skull : default_skull_shape(g.skull_variant);
  // The example's own coat and appendages where the dataset gives them.
  const bool winged = std::any_of(g.limbs.begin(), g.limbs.end(), [](const LimbGene& l) { return l.kind == LimbKind::kWing; });
  g.look = animal->look ? *animal->look : random_look(seed, g.skull_variant, winged);
  g.appendages = animal->look || !animal->appendages.empty() ? animal->appendages : random_appendages(g, seed);
  clamp_to_genome_limits(g);
  apply_size(g);
  return g;
}

Genome Generator::variation(const Genome& parent, uint64_t seed, double sigma) const {
  Rng rng(seed);
  Genome g = parent;
  g.seed = seed;
  PcaVector raw;
  for (int d = 0; d < kPcaDims; ++d) raw[d] = parent.pca[d];
  PcaVector s = model_->to_sigma(raw);
  for (int i = 0; i < kPcaDims; ++i) s[i] += rng.normal(0.0, sigma);
  raw = model_->from_sigma(s);
  for (int d = 0; d < kPcaDims; ++d) g.pca[d] = raw[d];
  // The discrete features the body was built with stay put; they are not PCA dimensions.
  g.pca[kWings] = parent.pca[kWings];
  g.pca[kLegPairs] = parent.pca[kLegPairs];
  g.pca[kWeightKg] = std::max(0.01, g.pca[kWeightKg]);
  // Occasional discrete mutations [Z 8.2].
  if (g.tail_vertebrae > 0 && rng.chance(0.2)) g.tail_vertebrae = std::clamp(g.tail_vertebrae + rng.uniform_int(-3, 3), 5, 20);
  if (rng.chance(0.2)) g.rib_interval = static_cast<float>(std::clamp(g.rib_interval + rng.normal(0.0, 0.1), 0.2, 1.0));
  if (g.neck_vertebrae > 7 && rng.chance(0.2)) g.neck_vertebrae = std::clamp(g.neck_vertebrae + rng.uniform_int(-2, 2), 10, 30);
  if (rng.chance(0.05)) {
    g.skull_variant = rng.uniform_int(0, kSkullVariants - 1);
    g.skull_shape = default_skull_shape(g.skull_variant);
  }
  // A neck girdle needs a long neck; drop limbs whose girdle the new body no longer has.
  clamp_to_genome_limits(g);
  const BodyPlan plan = plan_body(g);
  std::erase_if(g.limbs, [&](const LimbGene& l) { return !plan.girdles[static_cast<int>(l.girdle)].exists; });
  recompute_rest_angles(g);
  apply_size(g);
  return g;
}

void Generator::apply_size(Genome& g) const {
  use_frame(g);
  if (!g.options.true_size || !body_volume_) return;
  // The rule measures the body at the frame's scale; the true scale follows from it.
  Result<Creature> built = build_creature(g);
  if (!built) return;  // a genome the builder refuses keeps its frame (the builder says why)
  g.scale = true_size_scale(*built, g.pca[kWeightKg], body_volume_(*built));
}

}  // namespace ossa
