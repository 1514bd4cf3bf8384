#include "ossa/gen/true_size.h"

#include <algorithm>
#include <cmath>

#include "ossa/gen/genome.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

namespace {

// Typical adults (≈). Hip heights are GAITS.md's (its sources there); lengths are total
// lengths, snout to tail tip. Where the example's weight ([Z C.3], often a maximum) belongs to
// a bigger or smaller animal than the measured one, the weight column lets the size follow
// by geometric similarity. Values marked "estimate" have no published mass; they are the
// nearest kind's build at that length.
constexpr PublishedSize kSizes[] = {
    {"blue whale", SizeMeasure::kLength, 26.0f, 120000.0f, "Jefferson, Webber & Pitman 2015, Marine Mammals of the World: 24-27 m"},
    {"horse", SizeMeasure::kHip, 1.3f, 550.0f, "GAITS.md: Griffin et al. 2004, J Exp Biol 207:4215"},
    {"african elephant", SizeMeasure::kHip, 1.8f, 4000.0f, "GAITS.md: 1.6-2.0 m (Hutchinson et al. 2006)"},
    {"yellow perch", SizeMeasure::kLength, 0.5f, 1.9f, "FishBase, Perca flavescens: max 50 cm, 1.9 kg"},
    {"archaeopteryx", SizeMeasure::kLength, 0.5f, 1.0f, "Wellnhofer 2009, Archaeopteryx: largest specimens ~0.5 m"},
    {"brachiosaurus", SizeMeasure::kHip, 4.0f, 33500.0f, "GAITS.md"},
    {"dimetrodon", SizeMeasure::kLength, 3.2f, 250.0f, "Romer & Price 1940: D. grandis ~3.2 m"},
    {"magpie", SizeMeasure::kLength, 0.45f, 0.22f, "Birkhead 1991, The Magpies: 44-46 cm, 200-250 g"},
    {"trout", SizeMeasure::kLength, 1.3f, 30.0f, "FishBase, Salvelinus namaycush: max 150 cm, 32.7 kg"},
    {"bowhead whale", SizeMeasure::kLength, 17.0f, 75000.0f, "Jefferson, Webber & Pitman 2015: 14-18 m"},
    {"ichthyornis", SizeMeasure::kLength, 0.3f, 0.3f, "Field et al. 2018, Nature 557:96 (estimate)"},
    {"ichthyosaurus", SizeMeasure::kLength, 2.0f, 90.0f, "McGowan & Motani 2003: I. communis to 3.3 m (estimate)"},
    {"ichthyostega", SizeMeasure::kLength, 1.5f, 80.0f, "Ahlberg, Clack & Blom 2005, Nature 437:137"},
    {"cape buffalo", SizeMeasure::kHip, 1.0f, 625.0f, "GAITS.md"},
    {"rabbit", SizeMeasure::kHip, 0.135f, 1.5f, "GAITS.md: 0.12-0.15 m (European rabbit, 1.2-2 kg)"},
    {"rock hyrax", SizeMeasure::kHip, 0.12f, 3.5f, "GAITS.md"},
    {"tarsier", SizeMeasure::kLength, 0.36f, 0.12f, "Nowak 1999, Walker's Mammals: head-body 9-16 cm, tail 20-26 cm"},
    {"tortoise", SizeMeasure::kHip, 0.2f, 50.0f, "GAITS.md (Zani et al. 2005)"},
    {"eared seal", SizeMeasure::kLength, 2.2f, 260.0f, "Jefferson, Webber & Pitman 2015: California sea lion"},
    {"armored shrew", SizeMeasure::kLength, 0.22f, 0.1f, "Nowak 1999: Scutisorex, head-body 12-15 cm, tail 7-10 cm"},
    {"parasaurolophus", SizeMeasure::kLength, 8.5f, 2600.0f, "Paul 2016, Princeton Field Guide to Dinosaurs"},
    {"peloneustes", SizeMeasure::kLength, 3.5f, 400.0f, "Ketchum & Benson 2011 (mass: estimate)"},
    {"sperm whale", SizeMeasure::kLength, 16.0f, 45000.0f, "Jefferson, Webber & Pitman 2015: males 16 m, 45 t"},
    {"red deer", SizeMeasure::kHip, 0.9f, 200.0f, "GAITS.md"},
    {"harbour seal", SizeMeasure::kLength, 1.8f, 125.0f, "Jefferson, Webber & Pitman 2015: to 1.9 m"},
    {"sinornis", SizeMeasure::kLength, 0.15f, 0.03f, "Sereno & Rao 1992, Science 255:845: sparrow-sized"},
    {"stegosaurus", SizeMeasure::kHip, 2.0f, 4500.0f, "GAITS.md"},
    {"pigeon", SizeMeasure::kHip, 0.09f, 0.35f, "GAITS.md (rock dove, 0.3-0.4 kg)"},
    {"thrinaxodon", SizeMeasure::kLength, 0.45f, 1.5f, "Kemp 2005, The Origin and Evolution of Mammals (mass: estimate)"},
    {"triceratops", SizeMeasure::kHip, 2.0f, 9000.0f, "GAITS.md"},
    {"propalaeotherium", SizeMeasure::kHip, 0.45f, 30.0f, "Franzen 2010, The Rise of Horses: shoulder 30-60 cm (estimate)"},
    {"swan", SizeMeasure::kHip, 0.25f, 11.0f, "GAITS.md (mute swan, 10-12 kg)"},
    {"chameleon", SizeMeasure::kLength, 0.6f, 0.7f, "Tilbury 2010, Chameleons of Africa: Parson's chameleon to 68 cm"},
    {"chamois", SizeMeasure::kHip, 0.5f, 35.0f, "GAITS.md"},
    {"wildebeest", SizeMeasure::kHip, 0.9f, 200.0f, "GAITS.md"},
    {"pig", SizeMeasure::kHip, 0.5f, 100.0f, "GAITS.md"},
    {"kangaroo", SizeMeasure::kHip, 0.5f, 45.0f, "GAITS.md"},
    {"tyrannosaurus", SizeMeasure::kHip, 2.5f, 8000.0f, "GAITS.md (Hutchinson et al. 2011: 6-8 t)"},
    {"dromedary", SizeMeasure::kHip, 1.3f, 500.0f, "GAITS.md"},
    {"ostrich", SizeMeasure::kHip, 1.1f, 120.0f, "GAITS.md: 1.0-1.2 m"},
    {"frog", SizeMeasure::kHip, 0.02f, 0.01f, "GAITS.md"},
    {"crocodile", SizeMeasure::kLength, 4.5f, 500.0f, "Grigg & Kirshner 2015: Nile crocodile males 3.5-5 m"},
    {"snake", SizeMeasure::kLength, 4.3f, 50.0f, "Burmese python, ~4-5 m at 40-60 kg (estimate)"},
    {"giraffe", SizeMeasure::kHip, 2.0f, 1200.0f, "GAITS.md"},
};

}  // namespace

const PublishedSize* published_size(std::string_view name) {
  for (const PublishedSize& s : kSizes) {
    if (s.example == name) return &s;
  }
  return nullptr;
}

namespace {

// The creature's rest pose, model space.
std::vector<Mat2x3> rest_matrices(const Creature& c) {
  const Skeleton& s = c.skeleton;
  const bool posed = c.rest_pose.locals.size() == static_cast<size_t>(s.bone_count());
  return model_matrices(s, posed ? c.rest_pose.locals : s.rest_locals());
}

// The highest joint above the ground of the legs `take` accepts, metres (0: none).
template <typename Take>
float legs_height(const Creature& c, const std::vector<Mat2x3>& m, Take take) {
  float height = 0.0f;
  for (const Limb& l : c.limbs) {
    if (l.kind != LimbKind::kLeg || !take(l)) continue;
    height = std::max(height, bone_start(m[static_cast<size_t>(l.bones[0])]).y - c.ground_y_ms);
  }
  return height;
}

bool hind(const Limb& l) { return l.girdle == GirdleKind::kHip; }

}  // namespace

float size_measure(const Creature& c, SizeMeasure measure) {
  const Skeleton& s = c.skeleton;
  const std::vector<Mat2x3> m = rest_matrices(c);
  if (measure == SizeMeasure::kHip) return legs_height(c, m, hind);
  float lo = 1e30f, hi = -1e30f;
  for (int b = 0; b < s.bone_count(); ++b) {
    const BoneKind k = s.kind(b);
    if (k != BoneKind::kSkull && k != BoneKind::kNeckVertebra && k != BoneKind::kBackVertebra &&
        k != BoneKind::kTailVertebra) {
      continue;
    }
    for (const glm::vec2 p : {bone_start(m[static_cast<size_t>(b)]), bone_end(m[static_cast<size_t>(b)], s.length(b))}) {
      lo = std::min(lo, p.x);
      hi = std::max(hi, p.x);
    }
  }
  return hi > lo ? hi - lo : 0.0f;
}

float leg_height(const Creature& c) {
  const std::vector<Mat2x3> m = rest_matrices(c);
  const float hip = legs_height(c, m, hind);
  return hip > 0.0f ? hip : legs_height(c, m, [](const Limb&) { return true; });
}

float true_size_scale(const Creature& c, double weight_kg, double body_volume_m3) {
  if (!(body_volume_m3 > 0.0) || !(weight_kg > 0.0) || !(c.scale > 0.0f)) return c.scale;
  const double size = std::cbrt(body_volume_m3);       // the body's own size at c.scale
  const double true_size = std::cbrt(weight_kg) * kSizeRuleMetres;
  // How leggy the body plan is: its leg height over its own size. Legless bodies and legs
  // too short to stand take the volume rule alone; the clamp keeps a stub of a leg from
  // ruling the size.
  const double h = leg_height(c);
  const double legginess = h > 0.0 ? std::clamp(h / size, 0.25, 4.0) : 1.0;
  const double scale = c.scale * true_size / size * std::pow(legginess, kSizeRuleBodyPlan - 1.0);
  return std::clamp(static_cast<float>(scale), kMinGenomeScale, kMaxGenomeScale);
}

std::optional<float> true_scale(const Creature& creature, const Genome& genome) {
  if (genome.options.true_size) return genome.scale;
  const PublishedSize* size = published_size(genome.name);
  if (!size) return std::nullopt;
  const float measured = size_measure(creature, size->measure);
  const double weight = genome.pca[kWeightKg];
  if (!(measured > 0.0f) || !(weight > 0.0)) return std::nullopt;
  const double true_metres = size->metres * std::cbrt(weight / size->at_kg);
  return static_cast<float>(genome.scale * true_metres / measured);
}

std::optional<float> expected_body_mass_kg(const Creature& creature, const Genome& genome) {
  const std::optional<float> t = true_scale(creature, genome);
  if (!t || !(*t > 0.0f)) return std::nullopt;
  const double ratio = genome.scale / *t;
  return static_cast<float>(genome.pca[kWeightKg] * ratio * ratio * ratio * genome.look.fatness);
}

}  // namespace ossa
