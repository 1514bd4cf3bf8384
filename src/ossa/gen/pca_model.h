#pragma once
// PcaModel — the Gaussian model of the example animals ([Z 3.4, 6.2–6.4], DESIGN.md §5.2).
//
// Two spaces appear below:
//   raw           a PcaVector in original units (dataset.h: counts, kg, frame units); what
//                 callers pass in and get back.
//   preprocessed  the space the statistics live in ([Z 6.2]): coordinates and lengths / 1000;
//                 wings / 1 and leg pairs / 2, then × 0.01; weight log10(w + 1) / log10(120001),
//                 then × 0.01. The factor 0.01 keeps the three non-geometric features out of the
//                 largest components. preprocess / postprocess are exact inverses (up to
//                 rounding) for weights > -1 kg.
// Component coordinates are coordinates along the (unit) eigenvectors in the preprocessed space;
// sigma coordinates are those divided by the standard deviation √λ of each component — the
// units of the creature panel's sliders.
//
// Typical use:
//   PcaModel model = PcaModel::fit(load_dataset(path).value());
//   Rng rng(seed);
//   PcaVector raw = model.sample_conditional(rng, {{kWings, 1.0, true}});
//   Animal shape = from_vector(raw);
//
// A fitted model is immutable; all methods are const and thread-compatible (the Rng is the
// caller's).

#include <vector>

#include <Eigen/Core>

#include "ossa/gen/dataset.h"
#include "ossa/io/result.h"
#include "ossa/math/rng.h"

namespace ossa {

// The raw vector of an animal (layout in dataset.h's `Dim`) and the model's matrices.
using PcaVector = Eigen::Matrix<double, kPcaDims, 1>;
using PcaMatrix = Eigen::Matrix<double, kPcaDims, kPcaDims>;

PcaVector to_vector(const Animal& animal);
// The animal a raw vector describes; names and class are empty. wings and leg_pairs are rounded
// to the nearest valid value (0..1, 0..2); use the raw vector itself where the continuous value
// matters (limb lotteries, DESIGN.md §5.4). Nothing else is clamped.
Animal from_vector(const PcaVector& raw);

// Fixes one raw dimension to a value for conditional sampling [Z 6.4].
struct Condition {
  int dim = 0;           // a Dim, 0 <= dim < kPcaDims
  double value = 0.0;    // raw units (wings 0/1, leg pairs 0..2, kg, frame units)
  bool integer = false;  // add uniform jitter in [-0.5, 0.5] to `value` before use [Z 6.4]
};

class PcaModel {
 public:
  // Maximum weight of the weight normalisation: the blue whale, 120 t [Z 6.2].
  static constexpr double kMaxWeightKg = 120000.0;
  // Scale of wings, leg pairs and weight after their [0, 1] normalisation [Z 6.2].
  static constexpr double kMinorFeatureScale = 0.01;

  // Mean, covariance (sample covariance, divided by n - 1) and eigen-decomposition of the
  // preprocessed examples. Requires at least two animals.
  static PcaModel fit(const Dataset& data);

  // Raw → preprocessed and back, whole vectors or one dimension.
  static PcaVector preprocess(const PcaVector& raw);
  static PcaVector postprocess(const PcaVector& preprocessed);
  static double preprocess_dim(int dim, double raw);
  static double postprocess_dim(int dim, double preprocessed);

  int example_count() const { return example_count_; }
  // Mean of the preprocessed examples, and the same point in raw units. (Because the weight is
  // averaged as a logarithm, mean_raw()[kWeightKg] is a geometric-style mean, not the
  // arithmetic mean of the weights.)
  const PcaVector& mean_preprocessed() const { return mean_; }
  PcaVector mean_raw() const { return postprocess(mean_); }
  // Covariance of the preprocessed examples.
  const PcaMatrix& covariance() const { return covariance_; }
  // Variances along the components, descending, >= 0 (tiny negative round-off clamped to 0).
  const PcaVector& eigenvalues() const { return eigenvalues_; }
  // Unit eigenvector i (0 = largest variance) in the preprocessed space. Its sign is fixed so
  // that its largest-magnitude entry is positive, which makes it reproducible across builds.
  PcaVector component(int i) const;
  // All eigenvectors as columns, in the order of eigenvalues().
  const PcaMatrix& components() const { return components_; }
  // Fraction of the total variance in the first k components (k in 0..kPcaDims).
  double explained_variance(int k) const;

  // Coordinates of a raw point along the components: Vᵀ (preprocess(raw) - mean).
  PcaVector to_components(const PcaVector& raw) const;
  PcaVector from_components(const PcaVector& coords) const;
  // Component coordinates divided by √λ. A component with λ below kMinSigma² has no spread:
  // its sigma coordinate is 0 and from_sigma puts the point at the mean along it.
  PcaVector to_sigma(const PcaVector& raw) const;
  PcaVector from_sigma(const PcaVector& sigma_coords) const;
  static constexpr double kMinSigma = 1e-12;

  // Euclidean distance of two raw points after preprocessing.
  static double distance_preprocessed(const PcaVector& raw_a, const PcaVector& raw_b);

  // A random raw point: mean + Σ zᵢ vᵢ with zᵢ ~ N(0, λᵢ) [Z 3.4]. Draws kPcaDims normals.
  PcaVector sample(Rng& rng) const;

  // A random raw point from the conditional Gaussian given the conditions [Z 6.4]:
  //   μ̄ = μ₁ + Σ₁₂ Σ₂₂⁺ (b − μ₂),   Σ̄ = Σ₁₁ − Σ₁₂ Σ₂₂⁺ Σ₂₁
  // (the seed prints Σ₁₂⁻¹ in the second formula, a typo), in the preprocessed space, where
  // index 2 are the conditioned dimensions and b their (jittered, preprocessed) values.
  // Σ₂₂⁺ is the pseudo-inverse from Σ₂₂'s eigen-decomposition, dropping eigenvalues below
  // 1e-12 × the largest, so redundant or near-singular conditions stay finite. Σ̄ is sampled
  // through its eigen-decomposition with negative eigenvalues clamped to 0. Integer
  // conditions first get uniform jitter in [-0.5, 0.5] (one uniform draw each, in order).
  // The conditioned dimensions of the result are exactly the (jittered) raw values.
  // An empty list is the same distribution as sample(). Requires check_conditions() to pass.
  PcaVector sample_conditional(Rng& rng, const std::vector<Condition>& conditions) const;

  // Checks user-supplied conditions: dims in range and distinct, values finite, a weight
  // condition > -1 kg. Errors name the condition ("conditions[1].dim: ...").
  static Status check_conditions(const std::vector<Condition>& conditions);

 private:
  PcaModel() = default;

  int example_count_ = 0;
  PcaVector mean_ = PcaVector::Zero();
  PcaMatrix covariance_ = PcaMatrix::Zero();
  PcaVector eigenvalues_ = PcaVector::Zero();
  PcaMatrix components_ = PcaMatrix::Identity();
};

}  // namespace ossa
