#include "ossa/gen/pca_model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Eigenvalues>

namespace ossa {
namespace {

constexpr double kFrameSize = 1000.0;
// Relative cut-off below which an eigenvalue of Σ₂₂ counts as zero in the pseudo-inverse.
constexpr double kPinvRelTol = 1e-12;

double log_weight_scale() { return std::log10(PcaModel::kMaxWeightKg + 1.0); }

// Flips v so that its largest-magnitude entry is positive (eigenvectors are defined up to sign;
// this pins the sign so sigma coordinates mean the same in every build).
template <class V>
void fix_sign(V&& v) {
  Eigen::Index arg = 0;
  v.cwiseAbs().maxCoeff(&arg);
  if (v[arg] < 0.0) v = -v;
}

// Symmetric eigen-decomposition, eigenvalues descending and clamped to >= 0.
void sorted_eigen(const Eigen::MatrixXd& m, Eigen::VectorXd* values, Eigen::MatrixXd* vectors) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(m);
  OSSA_ASSERT(solver.info() == Eigen::Success, "eigen-decomposition failed");
  const Eigen::Index n = m.rows();
  values->resize(n);
  vectors->resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {  // Eigen sorts ascending
    (*values)[i] = std::max(0.0, solver.eigenvalues()[n - 1 - i]);
    vectors->col(i) = solver.eigenvectors().col(n - 1 - i);
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Preprocessing [Z 6.2]

double PcaModel::preprocess_dim(int dim, double raw) {
  switch (dim) {
    case kWings: return raw * kMinorFeatureScale;
    case kLegPairs: return raw / 2.0 * kMinorFeatureScale;
    case kWeightKg: return std::log10(raw + 1.0) / log_weight_scale() * kMinorFeatureScale;
    default: return raw / kFrameSize;
  }
}

double PcaModel::postprocess_dim(int dim, double pre) {
  switch (dim) {
    case kWings: return pre / kMinorFeatureScale;
    case kLegPairs: return pre / kMinorFeatureScale * 2.0;
    case kWeightKg: return std::pow(10.0, pre / kMinorFeatureScale * log_weight_scale()) - 1.0;
    default: return pre * kFrameSize;
  }
}

PcaVector PcaModel::preprocess(const PcaVector& raw) {
  PcaVector p;
  for (int d = 0; d < kPcaDims; ++d) p[d] = preprocess_dim(d, raw[d]);
  return p;
}

PcaVector PcaModel::postprocess(const PcaVector& pre) {
  PcaVector r;
  for (int d = 0; d < kPcaDims; ++d) r[d] = postprocess_dim(d, pre[d]);
  return r;
}

// ---------------------------------------------------------------------------------------
// Fit [Z 3.4]

PcaModel PcaModel::fit(const Dataset& data) {
  const int n = static_cast<int>(data.animals.size());
  OSSA_ASSERT(n >= 2, "PcaModel::fit needs at least two examples");
  Eigen::Matrix<double, Eigen::Dynamic, kPcaDims> x(n, kPcaDims);
  for (int i = 0; i < n; ++i) x.row(i) = preprocess(to_vector(data.animals[i])).transpose();

  PcaModel m;
  m.example_count_ = n;
  m.mean_ = x.colwise().mean().transpose();
  const auto centred = x.rowwise() - m.mean_.transpose();
  // Unbiased sample covariance (1 / (n - 1)): with 44 examples the difference from 1/n is 2 %,
  // and n - 1 is what the statistics packages the thesis compared against use.
  m.covariance_ = (centred.transpose() * centred) / static_cast<double>(n - 1);
  m.covariance_ = 0.5 * (m.covariance_ + m.covariance_.transpose()).eval();

  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  sorted_eigen(m.covariance_, &values, &vectors);
  m.eigenvalues_ = values;
  m.components_ = vectors;
  for (int i = 0; i < kPcaDims; ++i) fix_sign(m.components_.col(i));
  return m;
}

PcaVector PcaModel::component(int i) const {
  OSSA_ASSERT(i >= 0 && i < kPcaDims, "PcaModel::component: index out of range");
  return components_.col(i);
}

double PcaModel::explained_variance(int k) const {
  OSSA_ASSERT(k >= 0 && k <= kPcaDims, "PcaModel::explained_variance: k out of range");
  const double total = eigenvalues_.sum();
  return total > 0.0 ? eigenvalues_.head(k).sum() / total : 0.0;
}

// ---------------------------------------------------------------------------------------
// Projections

PcaVector PcaModel::to_components(const PcaVector& raw) const {
  return components_.transpose() * (preprocess(raw) - mean_);
}

PcaVector PcaModel::from_components(const PcaVector& coords) const {
  return postprocess(mean_ + components_ * coords);
}

PcaVector PcaModel::to_sigma(const PcaVector& raw) const {
  PcaVector c = to_components(raw);
  for (int i = 0; i < kPcaDims; ++i) {
    const double sigma = std::sqrt(eigenvalues_[i]);
    c[i] = sigma > kMinSigma ? c[i] / sigma : 0.0;
  }
  return c;
}

PcaVector PcaModel::from_sigma(const PcaVector& s) const {
  PcaVector c;
  for (int i = 0; i < kPcaDims; ++i) {
    const double sigma = std::sqrt(eigenvalues_[i]);
    c[i] = sigma > kMinSigma ? s[i] * sigma : 0.0;
  }
  return from_components(c);
}

double PcaModel::distance_preprocessed(const PcaVector& a, const PcaVector& b) {
  return (preprocess(a) - preprocess(b)).norm();
}

// ---------------------------------------------------------------------------------------
// Sampling [Z 3.4, 6.4]

PcaVector PcaModel::sample(Rng& rng) const {
  PcaVector pre = mean_;
  for (int i = 0; i < kPcaDims; ++i) {
    pre += (std::sqrt(eigenvalues_[i]) * rng.normal()) * components_.col(i);
  }
  return postprocess(pre);
}

Status PcaModel::check_conditions(const std::vector<Condition>& conditions) {
  bool used[kPcaDims] = {};
  for (size_t i = 0; i < conditions.size(); ++i) {
    const Condition& c = conditions[i];
    const std::string path = "conditions[" + std::to_string(i) + "]";
    if (c.dim < 0 || c.dim >= kPcaDims) {
      return Error::at("", path + ".dim", "expected a dimension in [0, 28], got " + std::to_string(c.dim));
    }
    if (used[c.dim]) {
      return Error::at("", path + ".dim", std::string("dimension ") + dim_name(c.dim) + " is conditioned twice");
    }
    used[c.dim] = true;
    if (!std::isfinite(c.value)) return Error::at("", path + ".value", "expected a finite number");
    // Jitter may lower the value by 0.5, so an integer weight condition needs a little margin.
    const double lowest = c.value - (c.integer ? 0.5 : 0.0);
    if (c.dim == kWeightKg && !(lowest > -1.0)) {
      return Error::at("", path + ".value", "expected a weight > -1 kg, got " + std::to_string(c.value));
    }
  }
  return {};
}

PcaVector PcaModel::sample_conditional(Rng& rng, const std::vector<Condition>& conditions) const {
  OSSA_ASSERT(check_conditions(conditions).ok(), "PcaModel::sample_conditional: invalid conditions");
  if (conditions.empty()) return sample(rng);

  // Split the dimensions: 2 = conditioned (in the order given), 1 = free (ascending).
  const int q = static_cast<int>(conditions.size());
  const int n1 = kPcaDims - q;
  std::vector<int> idx2(q), idx1;
  std::vector<double> b_raw(q);
  bool conditioned[kPcaDims] = {};
  for (int k = 0; k < q; ++k) {
    idx2[k] = conditions[k].dim;
    conditioned[idx2[k]] = true;
    b_raw[k] = conditions[k].value + (conditions[k].integer ? rng.uniform(-0.5, 0.5) : 0.0);
  }
  for (int d = 0; d < kPcaDims; ++d) {
    if (!conditioned[d]) idx1.push_back(d);
  }

  Eigen::VectorXd db(q);  // b - μ₂ in the preprocessed space
  Eigen::MatrixXd s22(q, q), s12(n1, q), s11(n1, n1);
  for (int k = 0; k < q; ++k) {
    db[k] = preprocess_dim(idx2[k], b_raw[k]) - mean_[idx2[k]];
    for (int l = 0; l < q; ++l) s22(k, l) = covariance_(idx2[k], idx2[l]);
    for (int i = 0; i < n1; ++i) s12(i, k) = covariance_(idx1[i], idx2[k]);
  }
  for (int i = 0; i < n1; ++i) {
    for (int j = 0; j < n1; ++j) s11(i, j) = covariance_(idx1[i], idx1[j]);
  }

  // Σ₂₂⁺ by eigen-decomposition: Σ₂₂ may be singular (a dimension without spread) or nearly so
  // (strongly correlated conditions); dropping its null space keeps the result finite and is
  // the least-squares answer when the conditions are inconsistent.
  Eigen::VectorXd ev;
  Eigen::MatrixXd evec;
  sorted_eigen(s22, &ev, &evec);
  Eigen::MatrixXd s22_pinv = Eigen::MatrixXd::Zero(q, q);
  const double cutoff = kPinvRelTol * std::max(ev[0], 0.0);
  for (int k = 0; k < q; ++k) {
    if (ev[k] > cutoff && ev[k] > 0.0) s22_pinv += (evec.col(k) / ev[k]) * evec.col(k).transpose();
  }

  const Eigen::MatrixXd gain = s12 * s22_pinv;  // Σ₁₂ Σ₂₂⁺
  const Eigen::VectorXd mu1 = [&] {
    Eigen::VectorXd m(n1);
    for (int i = 0; i < n1; ++i) m[i] = mean_[idx1[i]];
    return m;
  }();
  const Eigen::VectorXd mu_bar = mu1 + gain * db;
  Eigen::MatrixXd s_bar = s11 - gain * s12.transpose();
  s_bar = 0.5 * (s_bar + s_bar.transpose()).eval();

  Eigen::VectorXd x1 = mu_bar;
  if (n1 > 0) {
    Eigen::VectorXd lambda;
    Eigen::MatrixXd basis;
    sorted_eigen(s_bar, &lambda, &basis);  // negative eigenvalues clamped to 0
    for (int i = 0; i < n1; ++i) x1 += (std::sqrt(lambda[i]) * rng.normal()) * basis.col(i);
  }

  PcaVector pre = mean_;
  for (int i = 0; i < n1; ++i) pre[idx1[i]] = x1[i];
  PcaVector raw = postprocess(pre);
  for (int k = 0; k < q; ++k) raw[idx2[k]] = b_raw[k];  // exactly the (jittered) condition
  return raw;
}

PcaVector to_vector(const Animal& a) {
  PcaVector v;
  v[kWings] = a.wings;
  v[kLegPairs] = a.leg_pairs;
  v[kWeightKg] = a.weight_kg;
  for (int i = 0; i < kSpinePoints; ++i) {
    v[spine_x_dim(i)] = a.spine[i].x;
    v[spine_y_dim(i)] = a.spine[i].y;
  }
  v[kFrontUpper] = a.front.upper;
  v[kFrontLower] = a.front.lower;
  v[kFrontHand] = a.front.distal;
  v[kHindUpper] = a.hind.upper;
  v[kHindLower] = a.hind.lower;
  v[kHindFoot] = a.hind.distal;
  return v;
}

Animal from_vector(const PcaVector& v) {
  Animal a;
  auto round_to = [](double x, int lo, int hi) {
    if (!std::isfinite(x)) return lo;
    return static_cast<int>(std::lround(std::clamp(x, static_cast<double>(lo), static_cast<double>(hi))));
  };
  a.wings = round_to(v[kWings], 0, 1);
  a.leg_pairs = round_to(v[kLegPairs], 0, 2);
  a.weight_kg = v[kWeightKg];
  for (int i = 0; i < kSpinePoints; ++i) {
    a.spine[i] = glm::vec2(static_cast<float>(v[spine_x_dim(i)]), static_cast<float>(v[spine_y_dim(i)]));
  }
  a.front = {v[kFrontUpper], v[kFrontLower], v[kFrontHand]};
  a.hind = {v[kHindUpper], v[kHindLower], v[kHindFoot]};
  return a;
}

}  // namespace ossa
