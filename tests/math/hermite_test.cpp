#include "ossa/math/hermite.h"

#include "ossa/math/rng.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace ossa;

namespace {

// A random valid spline with n keys spread over [t0, t0 + span].
HermiteSpline random_spline(Rng& rng, int n) {
  HermiteSpline s;
  float t = static_cast<float>(rng.uniform(-1.0, 1.0));
  for (int i = 0; i < n; ++i) {
    s.keys.push_back({t, static_cast<float>(rng.uniform(-2.0, 2.0)),
                      static_cast<float>(rng.uniform(-5.0, 5.0))});
    t += static_cast<float>(rng.uniform(0.05, 0.5));
  }
  return s;
}

// Reference evaluation with a linear scan and the textbook Hermite basis.
float reference_position(const HermiteSpline& s, float t) {
  const auto& k = s.keys;
  if (k.size() == 1) return k[0].p;
  t = std::fmin(std::fmax(t, k.front().t), k.back().t);
  std::size_t i = 0;
  while (i + 2 < k.size() && k[i + 1].t <= t) ++i;
  const float dt = k[i + 1].t - k[i].t;
  const float u = (t - k[i].t) / dt;
  const float u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * k[i].p + (u3 - 2 * u2 + u) * dt * k[i].m +
         (-2 * u3 + 3 * u2) * k[i + 1].p + (u3 - u2) * dt * k[i + 1].m;
}

}  // namespace

TEST_CASE("Hermite: passes through every key with its tangent", "[math][hermite]") {
  Rng rng(11);
  for (int c = 0; c < 1000; ++c) {
    const HermiteSpline s = random_spline(rng, rng.uniform_int(2, 12));
    REQUIRE(s.is_valid());
    for (const HermiteKey& k : s.keys) {
      REQUIRE(s.position(k.t) == Approx(k.p).margin(1e-5));
      REQUIRE(s.velocity(k.t) == Approx(k.m).margin(1e-3));
    }
  }
}

TEST_CASE("Hermite: matches a linear-scan reference everywhere", "[math][hermite]") {
  Rng rng(12);
  for (int c = 0; c < 500; ++c) {
    const HermiteSpline s = random_spline(rng, rng.uniform_int(1, 20));
    const float lo = s.keys.front().t - 0.5f;
    const float hi = s.keys.back().t + 0.5f;
    for (int i = 0; i < 50; ++i) {
      const float t = static_cast<float>(rng.uniform(lo, hi));
      REQUIRE(s.position(t) == Approx(reference_position(s, t)).margin(1e-4));
    }
  }
}

TEST_CASE("Hermite: short (scanned) and long (binary-searched) splines pick the same segment", "[math][hermite]") {
  // Up to 16 keys the segment search is a forward scan, beyond it a binary search: either way
  // the value at t equals, bit for bit, the two-key spline of the segment that holds t, on the
  // keys themselves, between them, at both ends and for NaN.
  Rng rng(14);
  for (int c = 0; c < 300; ++c) {
    const HermiteSpline s = random_spline(rng, rng.uniform_int(2, 60));
    const auto& k = s.keys;
    const std::size_t n = k.size();
    auto segment_value = [&](std::size_t i, float t, bool velocity) {
      const HermiteSpline two({k[i], k[i + 1]});
      return velocity ? two.velocity(t) : two.position(t);
    };
    for (std::size_t i = 0; i + 1 < n; ++i) {
      INFO(n << " keys, segment " << i);
      const float inside = static_cast<float>(rng.uniform(k[i].t, k[i + 1].t));
      for (float t : {k[i].t, inside}) {
        if (!(t < k[i + 1].t)) continue;
        REQUIRE(s.position(t) == segment_value(i, t, false));
        REQUIRE(s.velocity(t) == segment_value(i, t, true));
      }
    }
    CHECK(s.position(k.back().t + 1.0f) == segment_value(n - 2, k.back().t, false));
    CHECK(s.position(k.front().t - 1.0f) == segment_value(0, k.front().t, false));
    CHECK(s.position(std::numeric_limits<float>::quiet_NaN()) == k.front().p);
  }
}

TEST_CASE("Hermite: C1 across interior keys, velocity is dp/dt", "[math][hermite]") {
  Rng rng(13);
  for (int c = 0; c < 500; ++c) {
    const HermiteSpline s = random_spline(rng, rng.uniform_int(3, 8));
    for (std::size_t i = 1; i + 1 < s.keys.size(); ++i) {
      const float t = s.keys[i].t;
      const float e = 1e-4f;
      // Position: continuous; velocity: both one-sided limits (Richardson-extrapolated from
      // two points on each side, exact for the linear part) equal the key's tangent.
      CHECK(s.position(t - e) == Approx(s.position(t + e)).margin(0.01));
      const float left = 2.0f * s.velocity(t - e) - s.velocity(t - 2.0f * e);
      const float right = 2.0f * s.velocity(t + e) - s.velocity(t + 2.0f * e);
      CHECK(left == Approx(s.keys[i].m).margin(0.02));
      CHECK(right == Approx(s.keys[i].m).margin(0.02));
    }
    // Central differences inside segments (a key inside [t - h, t + h] would add the jump
    // of the second derivative to the difference).
    const float h = 2e-4f;
    for (std::size_t i = 0; i + 1 < s.keys.size(); ++i) {
      for (int k = 0; k < 5; ++k) {
        const float t = static_cast<float>(rng.uniform(s.keys[i].t + 2 * h, s.keys[i + 1].t - 2 * h));
        const float fd = (s.position(t + h) - s.position(t - h)) / (2.0f * h);
        CHECK(s.velocity(t) == Approx(fd).epsilon(1e-3).margin(0.01));
      }
    }
  }
}

TEST_CASE("Hermite: reproduces a cubic polynomial exactly", "[math][hermite]") {
  // p(t) = 1 - 2t + 3t² - t³: keys sampled from it must give it back between the keys.
  auto p = [](float t) { return 1.0f - 2.0f * t + 3.0f * t * t - t * t * t; };
  auto dp = [](float t) { return -2.0f + 6.0f * t - 3.0f * t * t; };
  HermiteSpline s;
  for (float t : {0.0f, 0.2f, 0.5f, 0.9f, 1.0f}) s.keys.push_back({t, p(t), dp(t)});
  for (int i = 0; i <= 100; ++i) {
    const float t = i / 100.0f;
    CHECK(s.position(t) == Approx(p(t)).margin(1e-5));
    CHECK(s.velocity(t) == Approx(dp(t)).margin(1e-4));
  }
}

TEST_CASE("Hermite: clamps t and handles a single key", "[math][hermite]") {
  HermiteSpline s({{0.0f, 1.0f, 2.0f}, {0.5f, -1.0f, 0.0f}, {1.0f, 3.0f, -4.0f}});
  CHECK(s.position(-3.0f) == 1.0f);
  CHECK(s.position(7.0f) == 3.0f);
  CHECK(s.velocity(-3.0f) == Approx(2.0f));
  CHECK(s.velocity(7.0f) == Approx(-4.0f));
  CHECK(s.position(std::numeric_limits<float>::quiet_NaN()) == 1.0f);

  HermiteSpline one({{0.3f, 5.0f, 9.0f}});
  REQUIRE(one.is_valid());
  CHECK(one.position(-1.0f) == 5.0f);
  CHECK(one.position(0.3f) == 5.0f);
  CHECK(one.position(2.0f) == 5.0f);
  CHECK(one.velocity(0.3f) == 0.0f);

  float p = 0.0f, v = 0.0f;
  s.evaluate(0.25f, &p, &v);
  CHECK(p == s.position(0.25f));
  CHECK(v == s.velocity(0.25f));
}

TEST_CASE("Hermite: is_valid rejects bad key lists", "[math][hermite]") {
  CHECK_FALSE(HermiteSpline().is_valid());
  CHECK_FALSE(HermiteSpline({{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}).is_valid());
  CHECK_FALSE(HermiteSpline({{0.5f, 0.0f, 0.0f}, {0.2f, 1.0f, 0.0f}}).is_valid());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  CHECK_FALSE(HermiteSpline({{0.0f, nan, 0.0f}, {1.0f, 1.0f, 0.0f}}).is_valid());
  CHECK_FALSE(HermiteSpline({{0.0f, 0.0f, inf}, {1.0f, 1.0f, 0.0f}}).is_valid());
  CHECK(HermiteSpline({{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}}).is_valid());
}

TEST_CASE("Hermite: blend interpolates keys and stays valid", "[math][hermite]") {
  Rng rng(14);
  for (int c = 0; c < 500; ++c) {
    const int n = rng.uniform_int(1, 10);
    const HermiteSpline a = random_spline(rng, n);
    const HermiteSpline b = random_spline(rng, n);
    const HermiteSpline at0 = HermiteSpline::blend(a, b, 0.0f);
    const HermiteSpline at1 = HermiteSpline::blend(a, b, 1.0f);
    for (int i = 0; i < n; ++i) {
      REQUIRE(at0.keys[i].t == a.keys[i].t);
      REQUIRE(at0.keys[i].p == a.keys[i].p);
      REQUIRE(at1.keys[i].m == b.keys[i].m);
    }
    const float w = static_cast<float>(rng.uniform());
    const HermiteSpline mid = HermiteSpline::blend(a, b, w);
    REQUIRE(mid.is_valid());
    for (int i = 0; i < n; ++i) {
      REQUIRE(mid.keys[i].t == Approx(a.keys[i].t + w * (b.keys[i].t - a.keys[i].t)).margin(1e-5));
      REQUIRE(mid.keys[i].p == Approx(a.keys[i].p + w * (b.keys[i].p - a.keys[i].p)).margin(1e-5));
      REQUIRE(mid.keys[i].m == Approx(a.keys[i].m + w * (b.keys[i].m - a.keys[i].m)).margin(1e-5));
    }
  }
  // Blending two splines with the same times blends their values.
  HermiteSpline a({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}});
  HermiteSpline b({{0.0f, 2.0f, 0.0f}, {1.0f, 2.0f, 0.0f}});
  CHECK(HermiteSpline::blend(a, b, 0.25f).position(0.6f) == Approx(0.5f));
}
