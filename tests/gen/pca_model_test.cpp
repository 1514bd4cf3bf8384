#include "ossa/gen/pca_model.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "shared/scenes.h"

using namespace ossa;

namespace {

const Dataset& examples() {
  static const Dataset d = [] {
    Result<Dataset> r = load_dataset(scenes::source_path("assets/creatures/examples.json"));
    OSSA_ASSERT(r.ok(), "examples.json must load");
    return std::move(r).value();
  }();
  return d;
}

const PcaModel& model() {
  static const PcaModel m = PcaModel::fit(examples());
  return m;
}

// Mean of `count` samples of `draw` in raw units.
template <class Draw>
PcaVector sample_mean(int count, Draw draw) {
  PcaVector sum = PcaVector::Zero();
  for (int i = 0; i < count; ++i) sum += draw();
  return sum / count;
}

}  // namespace

TEST_CASE("preprocessing follows [Z 6.2] and inverts exactly", "[gen]") {
  CHECK(PcaModel::preprocess_dim(kWings, 1.0) == Approx(0.01));
  CHECK(PcaModel::preprocess_dim(kLegPairs, 2.0) == Approx(0.01));
  CHECK(PcaModel::preprocess_dim(kWeightKg, 120000.0) == Approx(0.01));
  CHECK(PcaModel::preprocess_dim(kWeightKg, 0.0) == 0.0);
  CHECK(PcaModel::preprocess_dim(spine_y_dim(4), 500.0) == Approx(0.5));
  CHECK(PcaModel::preprocess_dim(kHindFoot, 1000.0) == Approx(1.0));
  for (const Animal& a : examples().animals) {
    const PcaVector raw = to_vector(a);
    const PcaVector back = PcaModel::postprocess(PcaModel::preprocess(raw));
    for (int d = 0; d < kPcaDims; ++d) CHECK(back[d] == Approx(raw[d]).epsilon(1e-12).margin(1e-9));
  }
}

TEST_CASE("eigenvalues are descending and non-negative, components orthonormal", "[gen]") {
  const PcaModel& m = model();
  CHECK(m.example_count() == 44);
  for (int i = 0; i < kPcaDims; ++i) {
    CHECK(m.eigenvalues()[i] >= 0.0);
    if (i > 0) CHECK(m.eigenvalues()[i] <= m.eigenvalues()[i - 1]);
  }
  CHECK(m.eigenvalues()[kPcaDims - 1] > 0.0);  // 44 examples span all 29 dimensions [Z 6.3]
  const PcaMatrix gram = m.components().transpose() * m.components();
  CHECK((gram - PcaMatrix::Identity()).cwiseAbs().maxCoeff() < 1e-10);
  // V Λ Vᵀ reproduces the covariance.
  const PcaMatrix rebuilt = m.components() * m.eigenvalues().asDiagonal() * m.components().transpose();
  CHECK((rebuilt - m.covariance()).cwiseAbs().maxCoeff() < 1e-12);
  CHECK(m.explained_variance(kPcaDims) == Approx(1.0));
  CHECK(m.explained_variance(0) == 0.0);
  // The minor features are scaled down so they do not dominate the first component [Z 6.2].
  for (int d : {int(kWings), int(kLegPairs), int(kWeightKg)}) {
    CHECK(std::abs(m.component(0)[d]) < 0.05);
  }
}

TEST_CASE("all components reproduce every example through sigma coordinates", "[gen]") {
  const PcaModel& m = model();
  for (const Animal& a : examples().animals) {
    INFO(a.name);
    const PcaVector raw = to_vector(a);
    const PcaVector back = m.from_sigma(m.to_sigma(raw));
    for (int d = 0; d < kPcaDims; ++d) {
      INFO(dim_name(d));
      CHECK(back[d] == Approx(raw[d]).epsilon(1e-9).margin(1e-7));
    }
    const PcaVector via_components = m.from_components(m.to_components(raw));
    CHECK((via_components - raw).cwiseAbs().maxCoeff() < 1e-7);
  }
  // The mean sits at the origin of the component space.
  CHECK(m.to_sigma(m.mean_raw()).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("samples have the model's mean and are reproducible by seed", "[gen]") {
  const PcaModel& m = model();
  Rng rng(20240611);
  const PcaVector mean = sample_mean(20000, [&] { return PcaModel::preprocess(m.sample(rng)); });
  const PcaVector error = mean - m.mean_preprocessed();
  for (int d = 0; d < kPcaDims; ++d) {
    INFO(dim_name(d));
    // 5 standard errors of the mean.
    CHECK(std::abs(error[d]) < 5.0 * std::sqrt(m.covariance()(d, d) / 20000.0));
  }
  Rng a(7), b(7), c(8);
  for (int i = 0; i < 10; ++i) {
    const PcaVector sa = m.sample(a);
    CHECK(sa == m.sample(b));
    CHECK(sa != m.sample(c));
  }
  Rng ca(11), cb(11);
  const std::vector<Condition> cond = {{kWings, 1.0, true}, {kWeightKg, 500.0, false}};
  for (int i = 0; i < 10; ++i) CHECK(m.sample_conditional(ca, cond) == m.sample_conditional(cb, cond));
}

TEST_CASE("conditional sampling honours the conditions", "[gen]") {
  const PcaModel& m = model();
  Rng rng(99);
  for (int i = 0; i < 500; ++i) {
    const PcaVector s = m.sample_conditional(rng, {{kWings, 1.0, true}, {kLegPairs, 0.0, true},
                                                   {kWeightKg, 500.0, false}});
    CHECK(s[kWings] >= 0.5);
    CHECK(s[kWings] < 1.5);
    CHECK(std::lround(s[kWings]) == 1);
    CHECK(s[kLegPairs] >= -0.5);
    CHECK(s[kLegPairs] < 0.5);
    CHECK(s[kWeightKg] == 500.0);  // exactly the condition
    CHECK(s.allFinite());
  }
  // Without jitter the conditioned value is exact.
  const PcaVector s = m.sample_conditional(rng, {{spine_y_dim(kSpineHip), 420.0, false}});
  CHECK(s[spine_y_dim(kSpineHip)] == 420.0);
}

TEST_CASE("conditioning shifts correlated dimensions plausibly", "[gen]") {
  const PcaModel& m = model();
  Rng rng(5);
  const int n = 4000;
  const PcaVector free_mean = sample_mean(n, [&] { return m.sample(rng); });
  const PcaVector winged = sample_mean(n, [&] { return m.sample_conditional(rng, {{kWings, 1.0, true}}); });
  const PcaVector legless = sample_mean(n, [&] { return m.sample_conditional(rng, {{kLegPairs, 0.0, true}}); });
  const PcaVector heavy = sample_mean(n, [&] { return m.sample_conditional(rng, {{kWeightKg, 50000.0, false}}); });
  // In the examples the winged animals are birds: long wings (front limbs) and a high hip.
  CHECK(winged[kFrontUpper] + winged[kFrontLower] + winged[kFrontHand] >
        free_mean[kFrontUpper] + free_mean[kFrontLower] + free_mean[kFrontHand] + 50.0);
  CHECK(winged[spine_y_dim(kSpineHip)] > free_mean[spine_y_dim(kSpineHip)] + 50.0);
  // Legless animals (whales, fish, marine reptiles, the snake) have short hind limbs and a low spine.
  CHECK(legless[kHindUpper] + legless[kHindLower] + legless[kHindFoot] <
        free_mean[kHindUpper] + free_mean[kHindLower] + free_mean[kHindFoot] - 100.0);
  CHECK(legless[spine_y_dim(kSpineHip)] < free_mean[spine_y_dim(kSpineHip)] - 100.0);
  // Heavy animals (whales, sauropods) are rarely winged.
  CHECK(heavy[kWings] < free_mean[kWings]);
}

TEST_CASE("conditions are validated", "[gen]") {
  CHECK(PcaModel::check_conditions({}).ok());
  CHECK(PcaModel::check_conditions({{kWings, 1.0, true}, {kHindFoot, 100.0, false}}).ok());
  CHECK_THAT(PcaModel::check_conditions({{29, 1.0, false}}).message(),
             Catch::Contains("conditions[0].dim"));
  CHECK_THAT(PcaModel::check_conditions({{kWings, 1.0, true}, {kWings, 0.0, true}}).message(),
             Catch::Contains("conditions[1].dim: dimension wings is conditioned twice"));
  CHECK_THAT(PcaModel::check_conditions({{kWeightKg, -3.0, false}}).message(),
             Catch::Contains("weight > -1 kg"));
  CHECK_FALSE(PcaModel::check_conditions({{kFrontUpper, NAN, false}}).ok());
}

TEST_CASE("conditioning on many dimensions, even redundant ones, stays finite", "[gen]") {
  const PcaModel& m = model();
  Rng rng(3);
  // Condition on every spine point of the horse: the legs follow, the spine is exact.
  const Animal& horse = *examples().find("horse");
  std::vector<Condition> cond;
  for (int p = 0; p < kSpinePoints; ++p) {
    cond.push_back({spine_x_dim(p), horse.spine[p].x, false});
    cond.push_back({spine_y_dim(p), horse.spine[p].y, false});
  }
  for (int i = 0; i < 50; ++i) {
    const PcaVector s = m.sample_conditional(rng, cond);
    CHECK(s.allFinite());
    CHECK(s[spine_x_dim(0)] == double(horse.spine[0].x));
  }
  // All 29 dimensions conditioned: the result is the condition.
  std::vector<Condition> all;
  const PcaVector pig = to_vector(*examples().find("pig"));
  for (int d = 0; d < kPcaDims; ++d) all.push_back({d, pig[d], false});
  CHECK(m.sample_conditional(rng, all) == pig);
}

TEST_CASE("model statistics", "[.][stats]") {
  const PcaModel& m = model();
  std::printf("eigenvalues (descending):\n");
  for (int i = 0; i < kPcaDims; ++i) std::printf("  %2d  %.6g\n", i, m.eigenvalues()[i]);
  std::printf("variance in the first 5 components: %.3f, first 6: %.3f\n", m.explained_variance(5),
              m.explained_variance(6));
  const Animal* nearest = nullptr;
  const Animal* farthest = nullptr;
  double dmin = 1e300, dmax = -1.0;
  for (const Animal& a : examples().animals) {
    const double dist = PcaModel::distance_preprocessed(to_vector(a), m.mean_raw());
    if (dist < dmin) { dmin = dist; nearest = &a; }
    if (dist > dmax) { dmax = dist; farthest = &a; }
  }
  std::printf("nearest to the mean: %s (%.4f), farthest: %s (%.4f)\n", nearest->name.c_str(), dmin,
              farthest->name.c_str(), dmax);
  const PcaVector mean = m.mean_raw();
  std::printf("mean: wings %.3f, leg pairs %.3f, weight %.1f kg\n", mean[kWings], mean[kLegPairs],
              mean[kWeightKg]);
  SUCCEED();
}
