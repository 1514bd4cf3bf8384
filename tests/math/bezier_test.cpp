#include "ossa/math/bezier.h"

#include "ossa/math/rng.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>

using namespace ossa;

namespace {

CubicBezier random_curve(Rng& rng) {
  CubicBezier c;
  for (glm::vec2& p : c.p)
    p = {static_cast<float>(rng.uniform(0.0, 1.0)), static_cast<float>(rng.uniform(0.0, 1.0))};
  return c;
}

// Arc length from 0 to t by a fine polyline in double precision (independent of the table).
double brute_arc_length(const CubicBezier& c, double t, int n = 20000) {
  auto at = [&](double u) {
    const double v = 1.0 - u;
    const double a = v * v * v, b = 3 * v * v * u, d = 3 * v * u * u, e = u * u * u;
    return glm::dvec2(a * c.p[0].x + b * c.p[1].x + d * c.p[2].x + e * c.p[3].x,
                      a * c.p[0].y + b * c.p[1].y + d * c.p[2].y + e * c.p[3].y);
  };
  double s = 0.0;
  glm::dvec2 prev = at(0.0);
  for (int i = 1; i <= n; ++i) {
    const glm::dvec2 q = at(t * i / n);
    s += glm::length(q - prev);
    prev = q;
  }
  return s;
}

}  // namespace

TEST_CASE("Bezier: endpoints and derivatives", "[math][bezier]") {
  Rng rng(31);
  for (int c = 0; c < 1000; ++c) {
    const CubicBezier b = random_curve(rng);
    REQUIRE(b.eval(0.0f) == b.p[0]);
    REQUIRE(glm::length(b.eval(1.0f) - b.p[3]) < 1e-6f);
    REQUIRE(glm::length(b.derivative(0.0f) - 3.0f * (b.p[1] - b.p[0])) < 1e-5f);
    REQUIRE(glm::length(b.derivative(1.0f) - 3.0f * (b.p[3] - b.p[2])) < 1e-5f);
    const float t = static_cast<float>(rng.uniform(0.05, 0.95));
    const float h = 1e-3f;
    const glm::vec2 fd = (b.eval(t + h) - b.eval(t - h)) / (2.0f * h);
    REQUIRE(glm::length(b.derivative(t) - fd) < 2e-3f);
    const glm::vec2 fd2 = (b.derivative(t + h) - b.derivative(t - h)) / (2.0f * h);
    REQUIRE(glm::length(b.second_derivative(t) - fd2) < 2e-2f);
  }
}

TEST_CASE("ArcLengthTable: a straight bezier is as long as the distance", "[math][bezier]") {
  Rng rng(32);
  for (int c = 0; c < 200; ++c) {
    const glm::vec2 a{static_cast<float>(rng.uniform(-5, 5)), static_cast<float>(rng.uniform(-5, 5))};
    const glm::vec2 d{static_cast<float>(rng.uniform(-5, 5)), static_cast<float>(rng.uniform(-5, 5))};
    // Control points on the segment at uneven fractions: the speed varies, the length does not.
    const float f1 = static_cast<float>(rng.uniform(0.0, 1.0));
    const float f2 = static_cast<float>(rng.uniform(f1, 1.0));
    const CubicBezier b{{a, a + f1 * d, a + f2 * d, a + d}};
    const ArcLengthTable table(b);
    REQUIRE(table.length() == Approx(glm::length(d)).epsilon(1e-5).margin(1e-6));
    // On a straight line the point at arc length s is exactly s along it.
    for (int i = 0; i <= 10; ++i) {
      const float s = table.length() * i / 10.0f;
      REQUIRE(glm::length(table.eval_at_length(s) - a) == Approx(s).margin(5e-4 * glm::length(d) + 1e-6));
    }
  }
}

TEST_CASE("ArcLengthTable: length matches a fine polyline", "[math][bezier]") {
  Rng rng(33);
  for (int c = 0; c < 100; ++c) {
    const CubicBezier b = random_curve(rng);
    const ArcLengthTable table(b);
    REQUIRE(table.length() == Approx(brute_arc_length(b, 1.0)).epsilon(1e-5));
  }
}

TEST_CASE("ArcLengthTable: t_at_length is monotone and exact at the ends", "[math][bezier]") {
  Rng rng(34);
  for (int c = 0; c < 200; ++c) {
    const CubicBezier b = random_curve(rng);
    const ArcLengthTable table(b, rng.uniform_int(1, 100));
    const float len = table.length();
    REQUIRE(table.t_at_length(0.0f) == 0.0f);
    REQUIRE(table.t_at_length(len) == 1.0f);
    REQUIRE(table.t_at_length(-1.0f) == 0.0f);
    REQUIRE(table.t_at_length(2.0f * len + 1.0f) == 1.0f);
    REQUIRE(table.t_at_fraction(0.0f) == 0.0f);
    REQUIRE(table.t_at_fraction(1.0f) == 1.0f);
    float prev = 0.0f;
    for (int i = 1; i <= 2000; ++i) {
      const float t = table.t_at_length(len * i / 2000.0f);
      REQUIRE(t >= prev);
      REQUIRE(t <= 1.0f);
      prev = t;
    }
  }
  // A curve collapsed to a point has length 0 and a defined parameter.
  const glm::vec2 q{1.0f, 2.0f};
  const ArcLengthTable point(CubicBezier{{q, q, q, q}});
  CHECK(point.length() == 0.0f);
  CHECK(point.t_at_length(0.5f) == 0.0f);
  CHECK(point.eval_at_length(0.5f) == q);
}

TEST_CASE("ArcLengthTable: re-parameterised points are equally spaced", "[math][bezier]") {
  Rng rng(35);
  for (int c = 0; c < 100; ++c) {
    const CubicBezier b = random_curve(rng);
    const ArcLengthTable table(b);
    const float len = table.length();
    // The arc length actually reached at t_at_length(s) is s.
    for (int i = 1; i < 16; ++i) {
      const float s = len * i / 16.0f;
      REQUIRE(brute_arc_length(b, table.t_at_length(s), 4000) == Approx(s).margin(5e-4 * len));
    }
  }
  // A curved spine-like arc: chords between consecutive re-parameterised points are equal.
  const CubicBezier arc{{{0.0f, 0.0f}, {0.1f, 0.6f}, {0.9f, 0.9f}, {1.0f, 0.2f}}};
  const ArcLengthTable table(arc);
  const int n = 24;
  const float step = table.length() / n;
  float min_chord = 1e9f, max_chord = 0.0f;
  for (int i = 0; i < n; ++i) {
    const float chord = glm::length(table.eval_at_length(step * (i + 1)) - table.eval_at_length(step * i));
    min_chord = std::fmin(min_chord, chord);
    max_chord = std::fmax(max_chord, chord);
  }
  CHECK(max_chord / min_chord < 1.005f);
  CHECK(max_chord <= step * 1.002f);  // a chord is never longer than its arc (+ table error)
  // Plain t = i/n spacing on the same curve is visibly uneven (the point of the table).
  float min_t = 1e9f, max_t = 0.0f;
  for (int i = 0; i < n; ++i) {
    const float chord = glm::length(arc.eval((i + 1.0f) / n) - arc.eval(float(i) / n));
    min_t = std::fmin(min_t, chord);
    max_t = std::fmax(max_t, chord);
  }
  CHECK(max_t / min_t > 1.2f);
}
