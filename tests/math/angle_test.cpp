#include "ossa/math/angle.h"

#include "ossa/math/rng.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace ossa;

TEST_CASE("fast_atan2 matches std::atan2", "[math][angle]") {
  Rng rng(61);
  float worst = 0.0f;
  for (int i = 0; i < 200000; ++i) {
    // Mixed scales, all quadrants, including points on the axes and diagonals.
    const float scale = static_cast<float>(std::pow(10.0, rng.uniform(-6, 6)));
    float x = static_cast<float>(rng.uniform(-1, 1)) * scale;
    float y = static_cast<float>(rng.uniform(-1, 1)) * scale;
    const int kind = rng.uniform_int(0, 9);
    if (kind == 0) x = 0.0f;
    if (kind == 1) y = 0.0f;
    if (kind == 2) y = x;
    if (kind == 3) y = -x;
    if (x == 0.0f && y == 0.0f) continue;
    const double exact = std::atan2(static_cast<double>(y), static_cast<double>(x));
    const float err = static_cast<float>(std::fabs(std::remainder(fast_atan2(y, x) - exact, 2.0 * M_PI)));
    worst = std::fmax(worst, err);
  }
  CHECK(worst <= 4e-7f);  // about 1.5 ulps of angles near pi
  CHECK(fast_atan2(0.0f, 0.0f) == 0.0f);
  CHECK(fast_atan2(0.0f, -0.0f) == 0.0f);
  CHECK(fast_atan2(0.0f, -1.0f) == Approx(kPi));
  CHECK(fast_atan2(1.0f, 0.0f) == Approx(0.5f * kPi));
  CHECK(fast_atan2(-1.0f, 0.0f) == Approx(-0.5f * kPi));
}

TEST_CASE("fast_atan2 is exactly odd in y and mirror-symmetric in x", "[math][angle]") {
  Rng rng(62);
  for (int i = 0; i < 10000; ++i) {
    const float x = static_cast<float>(rng.uniform(-3, 3));
    const float y = static_cast<float>(rng.uniform(-3, 3));
    REQUIRE(fast_atan2(-y, x) == -fast_atan2(y, x));
    REQUIRE(std::fabs(wrap_angle(fast_atan2(y, -x) - (kPi - fast_atan2(y, x)))) <= 4.8e-7f);
  }
}

TEST_CASE("wrap_angle maps into [-pi, pi] modulo 2 pi", "[math][angle]") {
  Rng rng(63);
  for (int i = 0; i < 10000; ++i) {
    const float a = static_cast<float>(rng.uniform(-50, 50));
    const float w = wrap_angle(a);
    REQUIRE(std::fabs(w) <= kPi + 1e-6f);
    REQUIRE(std::cos(w) == Approx(std::cos(a)).margin(1e-4));
    REQUIRE(std::sin(w) == Approx(std::sin(a)).margin(1e-4));
  }
}
