// The trunk's bob from the footfall timing (trunk_bob.h) on its own: how often a girdle rises
// per stride, where in the stance it is highest, how it grows with speed, and that a foot
// always down keeps it small.

#include "ossa/anim/trunk_bob.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace ossa;

namespace {

constexpr float kG = 9.81f, kH = 1.0f;

struct Timing {
  std::vector<float> starts;  // stance starts, cycles
  float duty = 0.5f, b = 0.0f, froude = 1.0f;
};

// The girdle's height over one cycle at 200 samples, for a creature of hip height kH moving at
// Froude number g.froude with Alexander's stride.
std::vector<float> heights(const Timing& g) {
  const float v = std::sqrt(g.froude * kG * kH), stride = 2.3f * kH * std::pow(g.froude, 0.3f);
  std::vector<float> y;
  for (int i = 0; i < 200; ++i) {
    y.push_back(anim::footfall_bob(g.starts, g.duty, g.b, static_cast<float>(i) / 200.0f, v / stride, stride, kH, kG));
  }
  return y;
}

float peak_to_peak(const std::vector<float>& y) { return *std::max_element(y.begin(), y.end()) - *std::min_element(y.begin(), y.end()); }

// Maxima over the cycle (circular).
int maxima(const std::vector<float>& y) {
  int n = 0;
  for (size_t i = 0; i < y.size(); ++i) {
    const float prev = y[(i + y.size() - 1) % y.size()], next = y[(i + 1) % y.size()];
    if (y[i] > prev && y[i] >= next) ++n;
  }
  return n;
}

float phase_of_max(const std::vector<float>& y) {
  return static_cast<float>(std::max_element(y.begin(), y.end()) - y.begin()) / static_cast<float>(y.size());
}

}  // namespace

TEST_CASE("trunk bob: alternating feet bob twice a stride, feet together once", "[anim][bob]") {
  const Timing walk{{0.0f, 0.5f}, 0.65f, anim::kWalkForceDip, 0.25f};
  const Timing trot{{0.0f, 0.5f}, 0.4f, 0.0f, 1.0f};
  const Timing hop{{0.0f, 0.0f}, 0.35f, 0.0f, 2.0f};
  const Timing gallop_pair{{0.0f, 0.1f}, 0.35f, 0.0f, 3.0f};  // a gallop's hind pair
  CHECK(maxima(heights(walk)) == 2);
  CHECK(maxima(heights(trot)) == 2);
  CHECK(maxima(heights(hop)) == 1);
  CHECK(maxima(heights(gallop_pair)) == 1);
  // Zero mean over the cycle: the bob moves the girdle about its standing height.
  for (const Timing* g : {&walk, &trot, &hop}) {
    const std::vector<float> y = heights(*g);
    float mean = 0.0f;
    for (float v : y) mean += v / static_cast<float>(y.size());
    CHECK(std::fabs(mean) < 1e-3f * peak_to_peak(y));
  }
}

TEST_CASE("trunk bob: a walk vaults over mid-stance, a run sinks into it", "[anim][bob]") {
  // One foot: stance from 0 to the duty; mid-stance at duty/2. A lone foot walking (with the
  // other half a cycle later) is highest near its mid-stance; running, lowest there.
  const Timing walk{{0.0f, 0.5f}, 0.6f, anim::kWalkForceDip, 0.3f};
  const Timing run{{0.0f, 0.5f}, 0.35f, 0.0f, 2.0f};
  const float walk_top = phase_of_max(heights(walk)), run_top = phase_of_max(heights(run));
  auto near = [](float phase, float target) { return std::fabs(std::remainder(phase - target, 0.5f)) < 0.08f; };
  CHECK(near(walk_top, 0.3f));                  // (each half cycle: mid-stance of its foot)
  CHECK(near(run_top, 0.35f + 0.5f * 0.15f));   // mid-flight between the two stances
}

TEST_CASE("trunk bob: grows with speed to a trot's few percent of the hip height, a foot always down keeps it small", "[anim][bob]") {
  const float creep = peak_to_peak(heights({{0.0f, 0.5f}, 0.65f, anim::kWalkForceDip, 0.02f}));
  const float walk = peak_to_peak(heights({{0.0f, 0.5f}, 0.65f, anim::kWalkForceDip, 0.3f}));
  const float trot = peak_to_peak(heights({{0.0f, 0.5f}, 0.4f, 0.0f, 1.0f}));
  const float amble = peak_to_peak(heights({{0.0f, 0.5f}, 0.55f, 0.0f, 1.0f}));
  INFO("creep " << creep << " walk " << walk << " trot " << trot << " amble " << amble);
  CHECK(creep < walk);
  CHECK(walk < trot);
  // The horse's trot: 4 % of the hip height (Buchner et al. 2000) for the centre of mass; the
  // girdles show kTrunkShare of the ballistic estimate.
  CHECK(trot > 0.015f * kH);
  CHECK(trot < 0.06f * kH);
  CHECK(amble < 0.5f * trot);
  // Nothing to bob without feet or time.
  CHECK(anim::footfall_bob({}, 0.5f, 0.0f, 0.3f, 1.0f, 1.0f, kH, kG) == 0.0f);
  const std::vector<float> one{0.0f};
  CHECK(anim::footfall_bob(one, 0.0f, 0.0f, 0.3f, 1.0f, 1.0f, kH, kG) == 0.0f);
  CHECK(std::isfinite(anim::footfall_bob(one, 0.5f, 0.0f, 0.3f, 0.0f, 1.0f, kH, kG)));  // a stopped clock
}
