#include "ossa/game/gait_metrics.h"

#include <algorithm>
#include <numbers>

namespace ossa {

namespace {

constexpr int kMaxLegs = 64;  // bits of GaitSample::stance

bool in_stance(const GaitSample& s, int leg) { return ((s.stance >> leg) & 1u) != 0; }

// Ticks of leg's touch-downs (swing → stance); the first tick has no tick before it to say.
std::vector<int> touchdowns(const std::vector<GaitSample>& samples, int leg) {
  std::vector<int> out;
  for (size_t t = 1; t < samples.size(); ++t) {
    if (in_stance(samples[t], leg) && !in_stance(samples[t - 1], leg)) out.push_back(static_cast<int>(t));
  }
  return out;
}

// Circular mean of phases (cycles), kept as a sum of unit vectors so several leg pairs add up.
struct PhaseSum {
  double c = 0.0, s = 0.0;
  int n = 0;
  void add(double phase) {
    c += std::cos(2.0 * std::numbers::pi * phase);
    s += std::sin(2.0 * std::numbers::pi * phase);
    ++n;
  }
  float mean() const {
    if (n == 0 || std::hypot(c, s) < 1e-9 * n) return NAN;  // none, or phases that cancel out
    double p = std::atan2(s, c) / (2.0 * std::numbers::pi);
    if (p < 0.0) p += 1.0;
    return p >= 1.0 ? 0.0f : static_cast<float>(p);
  }
};

// For each stride of `lead` (touch-down to touch-down), the phase at which `follow` first
// touches down in it: (t_follow - t_lead) / stride.
void add_phases(const std::vector<int>& lead, const std::vector<int>& follow, PhaseSum& sum) {
  size_t f = 0;
  for (size_t k = 0; k + 1 < lead.size(); ++k) {
    while (f < follow.size() && follow[f] < lead[k]) ++f;
    if (f < follow.size() && follow[f] < lead[k + 1]) {
      sum.add(static_cast<double>(follow[f] - lead[k]) / static_cast<double>(lead[k + 1] - lead[k]));
    }
  }
}

// Maxima of one stride's detrended heights, read as a loop from its lowest point (the stride
// starts and ends at the same detrended height, 0), counting a maximum once it has risen
// `threshold` above the last minimum and fallen `threshold` below its peak.
int count_bobs(const std::vector<float>& s, float threshold) {
  const size_t m = s.size();
  if (m < 2) return 0;
  const size_t start = static_cast<size_t>(std::min_element(s.begin(), s.end()) - s.begin());
  bool rising = true;
  float lo = s[start], hi = s[start];
  int peaks = 0;
  for (size_t i = 1; i <= m; ++i) {
    const float v = s[(start + i) % m];
    if (rising) {
      hi = std::max(hi, v);
      if (hi - lo < threshold && v < lo) lo = hi = v;  // no rise yet: a lower start
      if (hi - lo >= threshold && hi - v >= threshold) {
        ++peaks;
        rising = false;
        lo = v;
      }
    } else {
      lo = std::min(lo, v);
      if (v - lo >= threshold) {
        rising = true;
        hi = v;
      }
    }
  }
  return peaks;
}

}  // namespace

GaitMeasure measure_gait(const std::vector<GaitSample>& samples, const std::vector<GaitLeg>& legs, float dt,
                         float hip_height) {
  GaitMeasure m;
  const int leg_count = std::min(static_cast<int>(legs.size()), kMaxLegs);
  if (leg_count == 0 || samples.size() < 2) return m;
  int girdles = 0;
  for (int i = 0; i < leg_count; ++i) girdles = std::max(girdles, legs[i].girdle + 1);
  const int hind = girdles - 1;
  auto leg_at = [&](int girdle, Side side) {
    for (int i = 0; i < leg_count; ++i) {
      if (legs[i].girdle == girdle && legs[i].side == side) return i;
    }
    return -1;
  };
  std::vector<std::vector<int>> down(static_cast<size_t>(leg_count));
  for (int i = 0; i < leg_count; ++i) down[i] = touchdowns(samples, i);

  // The reference leg: the first leg of the hind pair. Its whole strides are the window.
  int ref = -1;
  for (int i = 0; i < leg_count && ref < 0; ++i) ref = legs[i].girdle == hind ? i : -1;
  const std::vector<int>& ref_down = down[static_cast<size_t>(ref)];
  if (ref_down.size() < 2) return m;
  const int t0 = ref_down.front(), t1 = ref_down.back();
  const int strides = static_cast<int>(ref_down.size()) - 1;
  m.strides = static_cast<float>(strides);
  m.stride_period_s = static_cast<float>(t1 - t0) * dt / static_cast<float>(strides);

  // Hildebrand's limb phase: the same side's fore foot after the hind foot, both sides.
  if (girdles == 2) {
    PhaseSum limb;
    for (Side side : {Side::kNear, Side::kFar}) {
      const int h = leg_at(1, side), f = leg_at(0, side);
      if (h >= 0 && f >= 0) add_phases(down[h], down[f], limb);
    }
    m.limb_phase = limb.mean();
  }
  auto pair_phase = [&](int girdle) {
    const int near = leg_at(girdle, Side::kNear), far = leg_at(girdle, Side::kFar);
    PhaseSum sum;
    if (near >= 0 && far >= 0) add_phases(down[near], down[far], sum);
    return sum.mean();
  };
  m.hind_pair_phase = pair_phase(hind);
  if (girdles >= 2) m.fore_pair_phase = pair_phase(0);
  // The sequence of a symmetric gait (NaN compares false throughout).
  const bool symmetric = std::fabs(m.hind_pair_phase - 0.5f) <= GaitMeasure::kSymmetricPairTolerance &&
                         std::fabs(m.fore_pair_phase - 0.5f) <= GaitMeasure::kSymmetricPairTolerance;
  const float couplet = std::fmin(pair_phase_gap(m.limb_phase), std::fabs(m.limb_phase - 0.5f));
  if (symmetric && couplet > GaitMeasure::kCoupletTolerance) {
    m.footfall_sequence = m.limb_phase < 0.5f ? "lateral" : "diagonal";
  }

  // Duty factor per leg over its whole cycles.
  double duty = 0.0;
  int duty_legs = 0;
  for (int i = 0; i < leg_count; ++i) {
    const std::vector<int>& d = down[i];
    if (d.size() < 2) continue;
    int stance = 0;
    for (int t = d.front(); t < d.back(); ++t) stance += in_stance(samples[t], i) ? 1 : 0;
    duty += static_cast<double>(stance) / static_cast<double>(d.back() - d.front());
    ++duty_legs;
  }
  if (duty_legs > 0) m.duty_factor = static_cast<float>(duty / duty_legs);

  // Suspensions: runs of ticks with every foot up that begin within the strides.
  const uint64_t mask = leg_count >= kMaxLegs ? ~uint64_t{0} : (uint64_t{1} << leg_count) - 1u;
  int suspensions = 0, flight_ticks = 0;
  for (int t = t0; t < t1; ++t) {
    const bool flight = (samples[t].stance & mask) == 0;
    const bool flight_before = (samples[t - 1].stance & mask) == 0;  // t0 >= 1
    suspensions += flight && !flight_before ? 1 : 0;
    flight_ticks += flight ? 1 : 0;
  }
  m.suspensions_per_stride = static_cast<float>(suspensions) / static_cast<float>(strides);
  m.suspension_fraction = static_cast<float>(flight_ticks) / static_cast<float>(t1 - t0);

  // The root's bob per stride, detrended by the line through its touch-down heights.
  std::vector<std::vector<float>> bob(static_cast<size_t>(strides));
  double excursion = 0.0;
  for (int k = 0; k < strides; ++k) {
    const int a = ref_down[k], b = ref_down[k + 1];
    const float ya = samples[a].root_y, yb = samples[b].root_y;
    std::vector<float>& s = bob[k];
    for (int t = a; t < b; ++t) {
      s.push_back(samples[t].root_y - (ya + (yb - ya) * static_cast<float>(t - a) / static_cast<float>(b - a)));
    }
    const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
    excursion += static_cast<double>(std::max(*hi, 0.0f) - std::min(*lo, 0.0f));  // the end: 0 as well
  }
  const float mean_excursion = static_cast<float>(excursion / strides);
  if (hip_height > 0.0f) m.vertical_excursion = mean_excursion / hip_height;
  if (mean_excursion >= 1e-4f) {
    int bobs = 0;
    for (const std::vector<float>& s : bob) bobs += count_bobs(s, 0.1f * mean_excursion);
    m.bobs_per_stride = static_cast<float>(bobs) / static_cast<float>(strides);
  }
  return m;
}

}  // namespace ossa
