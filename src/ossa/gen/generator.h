#pragma once
// Generator — draws Genomes: random creatures from the PCA model with optional conditions,
// the 44 examples, and variations of a genome [Z 6–8]. All randomness happens here; the
// SkeletonBuilder (skeleton_builder.h) turns a Genome into a Creature deterministically.

#include <memory>
#include <optional>
#include <string_view>

#include "ossa/gen/dataset.h"
#include "ossa/gen/genome.h"
#include "ossa/gen/true_size.h"
#include "ossa/io/result.h"

namespace ossa {

// The largest variation step (σ units): beyond it a step leaves the space the 44 examples
// span so far that every value ends clamped at a limit.
inline constexpr double kMaxVariationSigma = 10.0;

class PcaModel;  // ossa/gen/pca_model.h
class Rng;

// User input for a random creature. Unset conditions come from the PCA point.
struct GenerateOptions {
  std::optional<int> wings;          // 0 or 1: condition on the PCA and the wing count
  std::optional<int> leg_pairs;      // 0, 1 or 2 ground-contact leg pairs
  std::optional<double> weight_kg;   // > 0
  std::optional<int> arm_pairs;      // else drawn with the wing probability [Z 7.2.4]
  std::optional<int> fin_pairs;      // else 1 for legless wingless bodies with a tail, else 0
  std::optional<ContactMode> contact;// tip or flat feet; else from the legs' proportions
  GenomeOptions genome;              // neck girdle, several limbs per girdle, spacing, size
};

class Generator {
 public:
  // `body_volume` measures a drawn body for the size rule (pass ossa::body_volume_m3 from
  // body/body_mesh.h; the body layer sits above this one). Without it a genome that asks for
  // its true size keeps the 2 m frame's scale.
  Generator(Dataset dataset, PcaModel model, BodyVolume body_volume);

  // Loads assets/creatures/examples.json (or `path`) and fits the model.
  static Result<Generator> load(const std::string& dataset_path, BodyVolume body_volume);

  const Dataset& dataset() const { return dataset_; }
  const PcaModel& model() const { return *model_; }

  // A random creature; the same seed and options give a byte-identical genome.
  Genome random(uint64_t seed, const GenerateOptions& options = {}) const;
  // One of the 44 examples (English or German name), with its own PCA values; the discrete
  // choices (vertebrae, ribs, limb slots) are drawn from `seed`.
  Result<Genome> example(std::string_view name, uint64_t seed = 1,
                         const GenerateOptions& options = {}) const;
  // A variation [Z 8.2]: a Gaussian step of `sigma` (in σ units of every principal component)
  // in PCA space, plus occasional discrete mutations (vertebra counts, rib interval, skull).
  // sigma in [0, kMaxVariationSigma]; the result is clamped into the genome limits.
  Genome variation(const Genome& parent, uint64_t seed, double sigma) const;

  // Sets genome.scale from its size choice (options.true_size: the size rule of
  // gen/true_size.h, else options.frame_m). random, example and variation call it; call it
  // again after changing the weight, the body or the choice.
  void apply_size(Genome& genome) const;

  // Completes a genome whose PCA point and options are set: draws limb layout, vertebrae,
  // ribs, contact mode and skull from rng, then computes the rest-pose angles.
  Genome complete(std::array<double, kPcaDims> pca, Rng& rng, const GenerateOptions& options,
                  std::string name, uint64_t seed) const;

 private:
  Dataset dataset_;
  // Shared between copies: a fitted model is immutable (and its header, Eigen, stays out of
  // every file that only draws genomes).
  std::shared_ptr<const PcaModel> model_;
  BodyVolume body_volume_;
};

// A skull of `variant` with its proportions varied around the variant's default (length and
// height by 0.85 … 1.2, snout by 0.85 … 1.15), drawn from `seed` (a stream of its own).
SkullShape random_skull_shape(int variant, uint64_t seed);

// Appendages drawn from `seed` (a stream of its own) for a body like `genome`'s: swimmers a
// tail fin and usually a dorsal fin; mammals ears, hoofed ones now and then horns or antlers,
// a mane, a hump, heavy ones rarely a trunk; birds sometimes a crest; reptiles now and then a
// frill, sail, plates, shell or crest.
std::vector<Appendage> random_appendages(const Genome& genome, uint64_t seed);

// Recomputes the rest angles of every leg, arm and fin of `genome` from its current PCA point
// and layout ([Z 7.2.2] leg placement); wing angles (drawn at random) are kept.
void recompute_rest_angles(Genome& genome);

}  // namespace ossa
