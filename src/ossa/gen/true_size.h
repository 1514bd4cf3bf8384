#pragma once
// True size — how big the creature's animal really is, for the body's mass (issue 30: a body's
// volume × 1000 kg/m³ matches the genome's weight at the creature's size, weight ×
// (size / true size)³).
//
// Until creatures are built at their true size (the issue "True size and true legs"), every
// example fills the same 2 m frame (scale 0.002 m per frame unit), so its body must weigh what
// its animal would weigh at that size. The genome's weight alone cannot say how big the animal
// is: any rule "size ∝ weight^⅓" (the genome option true_size's 2 m frame for 500 kg among
// them) gives every creature the same mass per frame size whatever its shape — a 2 m whale
// as heavy as a 2 m horse. So the examples carry a published size: the hip height of a
// legged animal (GAITS.md's table and its sources) or the total length of a legless one,
// measured on a typical adult of a stated weight (true_size.cpp). Its true scale follows
// by geometric similarity: the example's own hip height (or length) in frame units at the
// published size, scaled by (weight / weight of the measured adult)^⅓.
//
// When the true-size issue lands, true_scale() is where its rule goes; the mass check
// (expected_body_mass_kg) stays as it is.

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
