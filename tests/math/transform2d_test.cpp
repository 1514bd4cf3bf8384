#include "ossa/math/transform2d.h"

#include "ossa/math/rng.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

using namespace ossa;

namespace {

Transform2D random_transform(Rng& rng) {
  Transform2D t;
  t.translation = {static_cast<float>(rng.uniform(-10, 10)), static_cast<float>(rng.uniform(-10, 10))};
  t.rotation = static_cast<float>(rng.uniform(-7, 7));
  t.scale = static_cast<float>(rng.uniform(0.2, 3.0));
  t.mirror_x = rng.chance(0.5);
  return t;
}

glm::vec2 random_point(Rng& rng) {
  return {static_cast<float>(rng.uniform(-5, 5)), static_cast<float>(rng.uniform(-5, 5))};
}

bool near(glm::vec2 a, glm::vec2 b, float tol = 1e-3f) { return glm::length(a - b) <= tol; }

}  // namespace

TEST_CASE("Transform2D: the definition, mirror first", "[math][transform]") {
  Transform2D t;
  t.translation = {1.0f, 2.0f};
  t.rotation = 0.5f * 3.14159265f;
  t.scale = 2.0f;
  CHECK(near(t.apply_point({1.0f, 0.0f}), {1.0f, 4.0f}, 1e-5f));
  t.mirror_x = true;
  CHECK(near(t.apply_point({1.0f, 0.0f}), {1.0f, 0.0f}, 1e-5f));  // (-1,0) rotated 90° = (0,-1)
  CHECK(near(t.apply_vector({0.0f, 1.0f}), {-2.0f, 0.0f}, 1e-5f));
  CHECK(Transform2D::identity().apply_point({3.0f, -4.0f}) == glm::vec2(3.0f, -4.0f));
}

TEST_CASE("Transform2D: compose, inverse and apply agree over random transforms", "[math][transform]") {
  Rng rng(41);
  for (int c = 0; c < 10000; ++c) {
    const Transform2D a = random_transform(rng);
    const Transform2D b = random_transform(rng);
    const Transform2D d = random_transform(rng);
    const glm::vec2 p = random_point(rng);
    const glm::vec2 v = random_point(rng);
    // compose(a, b) applies b first.
    const Transform2D ab = compose(a, b);
    REQUIRE(near(ab.apply_point(p), a.apply_point(b.apply_point(p))));
    REQUIRE(near(ab.apply_vector(v), a.apply_vector(b.apply_vector(v))));
    REQUIRE(ab.mirror_x == (a.mirror_x != b.mirror_x));
    REQUIRE(std::fabs(ab.rotation) <= 3.1416f);
    // Associativity.
    REQUIRE(near(compose(compose(a, b), d).apply_point(p), compose(a, compose(b, d)).apply_point(p)));
    // Inverse on both sides.
    const Transform2D inv = a.inverse();
    REQUIRE(near(inv.apply_point(a.apply_point(p)), p));
    REQUIRE(near(a.apply_point(inv.apply_point(p)), p));
    REQUIRE(near(compose(a, inv).apply_point(p), p));
    REQUIRE(near(compose(inv, a).apply_point(p), p));
    REQUIRE(near(inv.inverse().apply_point(p), a.apply_point(p)));
    // The inverse of a composition is the reversed composition of inverses.
    REQUIRE(near(compose(a, b).inverse().apply_point(p), compose(b.inverse(), inv).apply_point(p)));
  }
}

TEST_CASE("Transform2D: Mat2x3 matches the transform and composes like it", "[math][transform]") {
  Rng rng(42);
  for (int c = 0; c < 10000; ++c) {
    const Transform2D a = random_transform(rng);
    const Transform2D b = random_transform(rng);
    const glm::vec2 p = random_point(rng);
    const Mat2x3 ma = a.to_mat2x3();
    const Mat2x3 mb = b.to_mat2x3();
    REQUIRE(near(ma.apply(p), a.apply_point(p)));
    REQUIRE(near(ma.apply_vector(p), a.apply_vector(p)));
    REQUIRE(near((ma * mb).apply(p), compose(a, b).apply_point(p)));
    REQUIRE(near(compose(a, b).to_mat2x3().apply(p), ma.apply(mb.apply(p))));
    REQUIRE(near((ma * a.inverse().to_mat2x3()).apply(p), p));
    // The determinant's sign tells a mirror.
    const float det = ma.m[0] * ma.m[3] - ma.m[1] * ma.m[2];
    REQUIRE((det < 0.0f) == a.mirror_x);
    REQUIRE(det == Approx((a.mirror_x ? -1.0f : 1.0f) * a.scale * a.scale).epsilon(1e-4));
    // glm form: same numbers, column-major.
    const glm::vec3 g = ma.to_glm() * glm::vec3(p, 1.0f);
    REQUIRE(near({g.x, g.y}, ma.apply(p), 1e-4f));
    REQUIRE(g.z == 1.0f);
  }
  const Mat2x3 id = Mat2x3::identity();
  CHECK(id.apply({3.0f, 4.0f}) == glm::vec2(3.0f, 4.0f));
  CHECK(Transform2D::identity().to_mat2x3().apply({3.0f, 4.0f}) == glm::vec2(3.0f, 4.0f));
}
