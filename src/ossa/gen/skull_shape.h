#pragma once
// SkullShape — a skull's proportions, a gene of the Genome (genome.h) and an optional field of
// an example animal (dataset.h).

namespace ossa {

// The skull's proportions (issue 30: skull proportions follow the genome, so the horse, the pig
// and the deer do not share one skull): its length as a fraction of the back length, its
// height as a fraction of its length, and the share of its length in front of the eye (muzzle,
// beak or snout). Version 1 files get their variant's default (the skulls they were built with).
struct SkullShape {
  float length = 0.30f;  // skull length / back length, 0.08 … 0.8
  float height = 0.42f;  // skull height / skull length, 0.15 … 1.2
  float snout = 0.5f;    // muzzle length / skull length, 0.1 … 0.85
  bool operator==(const SkullShape&) const = default;
};
inline constexpr float kMinSkullLength = 0.08f, kMaxSkullLength = 0.8f;
inline constexpr float kMinSkullHeight = 0.15f, kMaxSkullHeight = 1.2f;
inline constexpr float kMinSnout = 0.1f, kMaxSnout = 0.85f;
// The proportions every skull of a variant had before they were genes (0 mammal, 1 bird,
// 2 reptile, 3 fish).
SkullShape default_skull_shape(int variant);

}  // namespace ossa
