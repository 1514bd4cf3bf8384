#include "ossa/math/two_bone_ik.h"

#include "ossa/math/angle.h"
#include "ossa/math/rng.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

using namespace ossa;

namespace {

constexpr int kCases = 10000;

float uni(Rng& rng, double lo, double hi) { return static_cast<float>(rng.uniform(lo, hi)); }

glm::vec2 unit(float angle) { return {std::cos(angle), std::sin(angle)}; }

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

bool all_finite(const TwoBoneIkResult& r) {
  return std::isfinite(r.upper_angle) && std::isfinite(r.lower_angle) && finite(r.upper_dir) &&
         finite(r.lower_dir) && finite(r.middle) && finite(r.end);
}

struct Chain {
  glm::vec2 root;
  float l1, l2;
  float bend;
};

// Creature-sized chains: root within a metre of the origin, bones 5 cm to 1.5 m.
Chain random_chain(Rng& rng) {
  return {{uni(rng, -1, 1), uni(rng, -1, 1)}, uni(rng, 0.05, 1.5), uni(rng, 0.05, 1.5),
          rng.chance(0.5) ? 1.0f : -1.0f};
}

glm::vec2 target_at(Rng& rng, const Chain& c, float dist) {
  return c.root + dist * unit(uni(rng, -3.2, 3.2));
}

// Forward kinematics from the output angles, the way skeleton FK will use them.
glm::vec2 fk_end(const Chain& c, const TwoBoneIkResult& r) {
  return c.root + c.l1 * unit(r.upper_angle) + c.l2 * unit(r.upper_angle + r.lower_angle);
}

float angle_distance(float a, float b) { return std::fabs(wrap_angle(a - b)); }

}  // namespace

TEST_CASE("IK: reachable targets are reached, by positions and by FK of the angles", "[math][ik]") {
  Rng rng(51);
  for (int i = 0; i < kCases; ++i) {
    const Chain c = random_chain(rng);
    const float chain = c.l1 + c.l2;
    const glm::vec2 target = target_at(rng, c, uni(rng, std::fabs(c.l1 - c.l2), chain));
    const TwoBoneIkResult r = solve_two_bone_ik(c.root, c.l1, c.l2, target, c.bend);
    const float tol = 1e-5f * chain;
    REQUIRE(r.reached);
    REQUIRE(glm::length(r.end - target) <= tol);
    REQUIRE(glm::length(fk_end(c, r) - target) <= tol);
    REQUIRE(glm::length(r.middle + c.l2 * r.lower_dir - target) <= tol);
    REQUIRE(glm::distance(r.middle, c.root) == Approx(c.l1).epsilon(1e-5));
    REQUIRE(glm::distance(r.end, r.middle) == Approx(c.l2).epsilon(1e-4).margin(tol));
    REQUIRE(glm::length(r.upper_dir - unit(r.upper_angle)) <= 1e-6f);
    REQUIRE(glm::length(r.lower_dir - unit(r.upper_angle + r.lower_angle)) <= 2e-6f);
    REQUIRE(glm::length(r.lower_dir) == Approx(1.0f).epsilon(1e-6));
  }
}

TEST_CASE("IK: beyond reach the chain is fully extended towards the target", "[math][ik]") {
  Rng rng(52);
  for (int i = 0; i < kCases; ++i) {
    const Chain c = random_chain(rng);
    const float chain = c.l1 + c.l2;
    const glm::vec2 target = target_at(rng, c, chain * uni(rng, 1.001, 4.0));
    const TwoBoneIkResult r = solve_two_bone_ik(c.root, c.l1, c.l2, target, c.bend);
    const glm::vec2 dir = glm::normalize(target - c.root);
    REQUIRE_FALSE(r.reached);
    REQUIRE(glm::length(r.end - (c.root + chain * dir)) <= 1e-5f * chain);
    REQUIRE(glm::length(r.middle - (c.root + c.l1 * dir)) <= 1e-3f * chain);
    REQUIRE(glm::dot(r.upper_dir, dir) >= 1.0f - 1e-5f);
    REQUIRE(glm::dot(r.lower_dir, dir) >= 1.0f - 1e-5f);
    REQUIRE(std::fabs(r.lower_angle) <= 5e-3f);
  }
}

TEST_CASE("IK: closer than |upper - lower| the chain folds with its end towards the target", "[math][ik]") {
  Rng rng(53);
  int tested = 0;
  for (int i = 0; i < kCases; ++i) {
    const Chain c = random_chain(rng);
    const float min_reach = std::fabs(c.l1 - c.l2);
    if (min_reach < 0.01f) continue;
    ++tested;
    const glm::vec2 target = target_at(rng, c, min_reach * uni(rng, 0.01, 0.999));
    const TwoBoneIkResult r = solve_two_bone_ik(c.root, c.l1, c.l2, target, c.bend);
    const glm::vec2 dir = glm::normalize(target - c.root);
    const float tol = 1e-5f * (c.l1 + c.l2);
    const float d = glm::distance(target, c.root);
    if (min_reach - d > 2e-5f * (c.l1 + c.l2)) REQUIRE_FALSE(r.reached);
    REQUIRE(glm::length(r.end - (c.root + min_reach * dir)) <= tol);
    REQUIRE(glm::dot(r.upper_dir, r.lower_dir) <= -1.0f + 1e-5f);  // folded back on itself
    REQUIRE(std::fabs(cross(dir, r.middle - c.root)) <= 2e-3f * (c.l1 + c.l2));  // on the line
    REQUIRE(angle_distance(std::fabs(r.lower_angle), kPi) <= 5e-3f);
    REQUIRE(glm::length(fk_end(c, r) - r.end) <= 1e-4f * (c.l1 + c.l2));
  }
  CHECK(tested > kCases / 2);
}

TEST_CASE("IK: the middle joint lies on the bend_sign side", "[math][ik]") {
  Rng rng(54);
  for (int i = 0; i < kCases; ++i) {
    const Chain c = random_chain(rng);
    const float lo = std::fabs(c.l1 - c.l2), hi = c.l1 + c.l2;
    // Strictly inside the reachable annulus, where the knee is really bent.
    const glm::vec2 target = target_at(rng, c, uni(rng, lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo)));
    const TwoBoneIkResult r = solve_two_bone_ik(c.root, c.l1, c.l2, target, c.bend);
    const float side = cross(target - c.root, r.middle - c.root);
    REQUIRE(side * c.bend > 0.0f);
    // The knee turns back towards the target: lower_angle has the opposite sign of bend_sign.
    REQUIRE(r.lower_angle * c.bend < 0.0f);
  }
}

TEST_CASE("IK: a mirrored chain with the flipped bend sign gives the mirrored pose", "[math][ik]") {
  Rng rng(55);
  auto mirror = [](glm::vec2 v) { return glm::vec2(-v.x, v.y); };
  for (int i = 0; i < kCases; ++i) {
    const Chain c = random_chain(rng);
    const float chain = c.l1 + c.l2;
    const glm::vec2 target = target_at(rng, c, chain * uni(rng, 0.0, 1.3));
    const float soft = rng.chance(0.3) ? uni(rng, 0.0, 0.1) : 0.0f;
    const TwoBoneIkResult r = solve_two_bone_ik(c.root, c.l1, c.l2, target, c.bend, soft);
    const TwoBoneIkResult m =
        solve_two_bone_ik(mirror(c.root), c.l1, c.l2, mirror(target), -c.bend, soft);
    REQUIRE(angle_distance(m.upper_angle, kPi - r.upper_angle) <= 1e-6f);
    REQUIRE(angle_distance(m.lower_angle, -r.lower_angle) == 0.0f);
    REQUIRE(m.middle == mirror(r.middle));
    REQUIRE(m.end == mirror(r.end));
    REQUIRE(m.upper_dir == mirror(r.upper_dir));
    REQUIRE(m.lower_dir == mirror(r.lower_dir));
    REQUIRE(m.reached == r.reached);
  }
}

TEST_CASE("IK: never NaN, also for zero lengths and coincident points", "[math][ik]") {
  Rng rng(56);
  for (int i = 0; i < kCases; ++i) {
    Chain c = random_chain(rng);
    // Mix in every degenerate case: zero bones, target on the root, everything at one point,
    // equal bones (min reach 0), tiny and large scales.
    const int kind = rng.uniform_int(0, 7);
    if (kind == 0) c.l1 = 0.0f;
    if (kind == 1) c.l2 = 0.0f;
    if (kind == 2) c.l1 = c.l2 = 0.0f;
    if (kind == 3) c.l2 = c.l1;
    if (kind == 4) { c.l1 *= 1e-20f; c.l2 *= 1e-20f; }
    if (kind == 5) { c.l1 *= 1e12f; c.l2 *= 1e12f; }
    glm::vec2 target = target_at(rng, c, (c.l1 + c.l2) * uni(rng, 0.0, 2.0));
    if (rng.chance(0.3)) target = c.root;
    if (kind == 6) { c.root = {0.0f, 0.0f}; target = c.root; c.l1 = c.l2 = 0.0f; }
    if (kind == 7) target = c.root + glm::vec2(1e-30f, -1e-30f);
    const float soft = rng.chance(0.5) ? uni(rng, 0.0, 0.5) : 0.0f;
    TwoBoneIkJob job;
    job.root = c.root;
    job.upper_length = c.l1;
    job.lower_length = c.l2;
    job.target = target;
    job.bend_sign = c.bend;
    job.soft_reach = soft;
    REQUIRE(job.run());
    const TwoBoneIkResult& r = job.result;
    REQUIRE(all_finite(r));
    REQUIRE(glm::length(r.upper_dir) == Approx(1.0f).epsilon(1e-5));
    REQUIRE(glm::length(r.lower_dir) == Approx(1.0f).epsilon(1e-5));
  }
  // The documented pose for a target on the root: the chain points along +x.
  const TwoBoneIkResult r = solve_two_bone_ik({1.0f, 1.0f}, 0.5f, 0.2f, {1.0f, 1.0f}, 1.0f);
  CHECK(r.upper_dir.x == Approx(1.0f));
  CHECK(r.end.x == Approx(1.3f));
  CHECK(r.end.y == Approx(1.0f));
  const TwoBoneIkResult z = solve_two_bone_ik({2.0f, 3.0f}, 0.0f, 0.0f, {2.0f, 3.0f}, -1.0f);
  CHECK(z.reached);
  CHECK(z.end == glm::vec2(2.0f, 3.0f));
  CHECK(z.upper_angle == 0.0f);
  CHECK(z.lower_angle == 0.0f);
}

TEST_CASE("IK: soft reach is continuous, never overshoots, and is off below its band", "[math][ik]") {
  Rng rng(57);
  for (int i = 0; i < kCases; ++i) {
    const Chain c = random_chain(rng);
    const float chain = c.l1 + c.l2;
    const float soft = uni(rng, 0.005, 0.2);
    const float angle = uni(rng, -3.2, 3.2);
    const float d = chain * uni(rng, 0.5, 1.5);
    const float step = chain * 1e-3f;
    const TwoBoneIkResult a = solve_two_bone_ik(c.root, c.l1, c.l2, c.root + d * unit(angle), c.bend, soft);
    const TwoBoneIkResult b =
        solve_two_bone_ik(c.root, c.l1, c.l2, c.root + (d + step) * unit(angle), c.bend, soft);
    const float tol = 1e-5f * chain;
    // Never beyond the target (unless it is inside the folded reach), never beyond full reach.
    if (d >= std::fabs(c.l1 - c.l2)) REQUIRE(glm::distance(a.end, c.root) <= d + tol);
    REQUIRE(glm::distance(a.end, c.root) <= chain + tol);
    // Continuous: moving the target by `step` moves the end by at most `step`, the knee by a
    // bounded amount (no snap into the straight pose).
    REQUIRE(glm::distance(a.end, b.end) <= step + tol);
    REQUIRE(glm::distance(a.middle, b.middle) <= 0.1f * chain);
    const float start = (1.0f - soft) * chain;
    if (d < start * 0.999f && d > std::fabs(c.l1 - c.l2)) {
      const TwoBoneIkResult hard = solve_two_bone_ik(c.root, c.l1, c.l2, c.root + d * unit(angle), c.bend);
      REQUIRE(a.reached);
      REQUIRE(glm::distance(a.end, hard.end) <= tol);
    }
    // Inside the band the end lags the target by about soft·y²/2, y = (d - start) / soft.
    if (d > start + 0.1f * soft * chain) REQUIRE_FALSE(a.reached);
    if (d > start * 1.001f && d <= chain) {
      REQUIRE(std::fabs(a.lower_angle) > 0.0f);  // still bent: eased, not snapped straight
    }
  }
  // Far beyond reach the soft chain converges on the straight one.
  const TwoBoneIkResult far = solve_two_bone_ik({0.0f, 0.0f}, 0.6f, 0.4f, {50.0f, 0.0f}, 1.0f, 0.05f);
  CHECK(far.end.x == Approx(1.0f).epsilon(1e-5));
}

TEST_CASE("IK: validate rejects bad inputs and run leaves the result alone", "[math][ik]") {
  TwoBoneIkJob job;
  job.upper_length = 1.0f;
  job.lower_length = 1.0f;
  job.target = {1.0f, 0.5f};
  REQUIRE(job.validate());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  auto rejected = [](TwoBoneIkJob j) {
    j.result.upper_angle = 123.0f;
    const bool ok = j.run();
    return !ok && !j.validate() && j.result.upper_angle == 123.0f;
  };
  { TwoBoneIkJob j = job; j.target.x = nan; CHECK(rejected(j)); }
  { TwoBoneIkJob j = job; j.root.y = inf; CHECK(rejected(j)); }
  { TwoBoneIkJob j = job; j.upper_length = -0.1f; CHECK(rejected(j)); }
  { TwoBoneIkJob j = job; j.lower_length = nan; CHECK(rejected(j)); }
  { TwoBoneIkJob j = job; j.bend_sign = 0.0f; CHECK(rejected(j)); }
  { TwoBoneIkJob j = job; j.bend_sign = 0.5f; CHECK(rejected(j)); }
  { TwoBoneIkJob j = job; j.soft_reach = 1.0f; CHECK(rejected(j)); }
  { TwoBoneIkJob j = job; j.soft_reach = -0.1f; CHECK(rejected(j)); }
  // compute_angles = false writes positions and directions, not angles.
  TwoBoneIkJob j = job;
  j.compute_angles = false;
  j.result.upper_angle = 7.0f;
  j.result.lower_angle = 8.0f;
  REQUIRE(j.run());
  CHECK(j.result.upper_angle == 7.0f);
  CHECK(j.result.lower_angle == 8.0f);
  CHECK(j.result.reached);
  CHECK(glm::distance(j.result.end, job.target) <= 1e-5f);
}
