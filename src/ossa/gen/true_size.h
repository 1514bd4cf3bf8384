#pragma once
// True size — how big the creature's animal really is.
//
// The size rule (true_size_scale). Creatures are built at their true size by default (the
// genome's size choice, GenomeOptions::true_size; a fixed frame in metres is the other
// choice, for stylised games). The size comes from the genome's weight and body plan only:
//
//   leg height = c · weight^⅓ · (h / V^⅓)^α        c = 0.0975 m/kg^⅓, α = 0.69
//
// where h is the creature's leg height (the hip joint above the ground; the shoulder's for a
// body with forelegs only) and V the volume of its drawn body at girth 1 (the body layer
// measures it: body/body_mesh.h, body_volume_m3), both at any one scale — their ratio is the
// body plan's "legginess". With α = 1 this is the body's own volume made to weigh the
// weight at water's density (c = (1 / 1000 kg/m³)^⅓ = 0.1): exact if the drawn body had the
// animal's girth. It has not quite: slim-bodied bipeds and the big dinosaurs come out up to
// 1.6 times too big that way and long-legged ungulates somewhat small, so the body plan
// counts with α < 1. c and α are a least-squares fit (log ratio) over the 22 examples with a
// published hip height (kSizes below, tests/gen/true_size_test.cpp): 20 land within ±25 %,
// the frog (1.55: it stands tall where a real frog crouches) and the triceratops (1.29) do
// not; left out one at a time, the fit still places 17 of 22. Legless bodies (no leg
// height) take the volume rule itself (α = 1): the whales within 10 %.
//
// Published sizes (published_size). The examples also carry the size measured on their
// animal: the hip height of a legged animal (GAITS.md's table and its sources) or the total
// length of a legless one, on a typical adult of a stated weight. They check the rule (the
// test above) and, for a genome kept in a fixed frame, give the mass its body must weigh at
// that size (expected_body_mass_kg: the example's size at the frame, by geometric similarity,
// scaled by (weight / weight of the measured adult)^⅓).

#include <functional>
#include <optional>
#include <string_view>

#include "ossa/gen/creature.h"

namespace ossa {

struct Genome;

// What a published size measures, on the creature's rest pose.
enum class SizeMeasure : uint8_t {
  kHip,     // hip joint height above the ground (the hind legs' chain start), metres
  kLength,  // the spine and skull's horizontal extent, snout tip to tail tip, metres
};

struct PublishedSize {
  std::string_view example;  // Animal::name
  SizeMeasure measure;
  float metres;              // the measure on a typical adult …
  float at_kg;               // … of this weight
  std::string_view source;
};

// The published size of example `name`, or nullptr.
const PublishedSize* published_size(std::string_view name);

// `measure` on `creature`'s rest pose, metres (0 when the creature has no hind leg for kHip).
float size_measure(const Creature& creature, SizeMeasure measure);

// The leg height the size rule uses, metres on the rest pose: the hip's height when the
// creature has hind legs, else the highest shoulder (or neck) girdle with legs, else 0.
float leg_height(const Creature& creature);

// The volume (m³) of a creature's drawn body at girth 1, at the creature's own scale. The
// body layer measures it (body_volume_m3 in body/body_mesh.h); the Generator is handed it.
using BodyVolume = std::function<double(const Creature&)>;

inline constexpr double kSizeRuleMetres = 0.0975;  // c: metres per kg^⅓
inline constexpr double kSizeRuleBodyPlan = 0.69;  // α: how much the body plan counts

// Metres per frame unit at which `creature` (built at any scale, with body volume
// `body_volume_m3` at that scale) stands at its true size for `weight_kg` (the rule above),
// clamped into the genome's scale range.
float true_size_scale(const Creature& creature, double weight_kg, double body_volume_m3);

// Metres per frame unit at the animal's true size: the genome's own scale when it is built at
// true size (options.true_size), else from the example's published size when the genome is an
// example (its name) with a measurable body, else unknown.
std::optional<float> true_scale(const Creature& creature, const Genome& genome);

// The body mass the genome asks for at the creature's size: weight × (scale / true_scale)³ ×
// look.fatness; nullopt when the true size is unknown (random creatures: their weight sets
// how big they are at true size, not how heavy they look at this one — the body keeps its
// default girths, times fatness).
std::optional<float> expected_body_mass_kg(const Creature& creature, const Genome& genome);

}  // namespace ossa
