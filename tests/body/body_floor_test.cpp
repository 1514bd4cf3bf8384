// The floor a body rests on (body_floor.h): which box tops count, how a point rests on them,
// and the palette entries the shader reads.

#include <catch2/catch.hpp>

#include <vector>

#include "ossa/body/body_floor.h"
#include "ossa/skeleton/pose.h"
#include "ossa/skeleton/skeleton.h"

using namespace ossa;

namespace {

// A two-bone creature lying along x from (x0, y) to (x0 + 2, y).
struct Stick {
  Skeleton skeleton;
  std::vector<Mat2x3> world;
  Stick(float x0, float y) {
    skeleton.add_bone("a", BoneKind::kNeckVertebra, -1, 1.0f, 0.1f, BoneLocal{}, Layer::kBody);
    skeleton.add_bone("b", BoneKind::kNeckVertebra, 0, 1.0f, 0.1f, BoneLocal{}, Layer::kBody);
    Mat2x3 a;
    a.m[4] = x0, a.m[5] = y;
    Mat2x3 b = a;
    b.m[4] = x0 + 1.0f;
    world = {a, b};
  }
};

Level level_of(std::vector<Box> boxes) {
  Level level;
  for (const Box& b : boxes) level.add_box(b);
  return level;
}

}  // namespace

TEST_CASE("a body's floor: the box tops under its bones, not ceilings or walls above them", "[body]") {
  const Stick s(0.0f, 0.5f);
  const Level level = level_of({
      Box::from_corner(-5.0f, -1.0f, 10.0f, 1.0f),  // ground, top 0
      Box::from_corner(1.2f, 0.0f, 0.3f, 0.2f),     // a step under the second bone, top 0.2
      Box::from_corner(-1.0f, 1.0f, 4.0f, 0.5f),    // a ceiling above, bottom 1
      Box::from_corner(2.05f, 0.0f, 1.0f, 3.0f),    // a wall just past the bones' end, top 3
      Box::from_corner(8.0f, -1.0f, 1.0f, 2.0f),    // far away
  });
  const BodyFloor floor = body_floor(level, s.skeleton, s.world, 0.3f, {});
  REQUIRE(floor.count == 2);
  CHECK(floor.segments[0].z == 0.0f);
  CHECK(floor.segments[0].x == Approx(-0.3f));  // clipped to the bones' reach
  CHECK(floor.segments[0].y == Approx(2.3f));
  CHECK(floor.segments[1].z == Approx(0.2f));
  // Resting on it: lifted onto the highest top under the point, left alone above it.
  CHECK(floor_point({1.0f, -0.1f}, floor).y == 0.0f);
  CHECK(floor_point({1.3f, 0.1f}, floor).y == Approx(0.2f));
  CHECK(floor_point({1.3f, 0.4f}, floor).y == Approx(0.4f));
  CHECK(floor_point({5.0f, -2.0f}, floor).y == -2.0f);  // past the floor's ends
}

TEST_CASE("a body's floor counts ground its bones sank into, and merges tops of one height", "[body]") {
  // A crawl wave may push bones below the ground's top: it is still the floor.
  const Stick s(0.0f, -0.04f);
  const Level level = level_of({Box::from_corner(-5.0f, -1.0f, 5.5f, 1.0f), Box::from_corner(0.5f, -1.0f, 5.0f, 1.0f)});
  const BodyFloor floor = body_floor(level, s.skeleton, s.world, 0.1f, {});
  REQUIRE(floor.count == 1);
  CHECK(floor.segments[0].x == Approx(-0.1f));
  CHECK(floor.segments[0].y == Approx(2.1f));
  CHECK(floor_point({1.0f, -0.04f}, floor).y == 0.0f);
  // No level, no floor.
  CHECK(body_floor(Level{}, s.skeleton, s.world, 0.1f, {}).count == 0);
}

TEST_CASE("a long body over more box tops than the floor holds rests on every one of them", "[body]") {
  // Sixteen treads of 0.125 m under a body 2 m long, a step of 1 or 3 cm between them (a
  // whale over stairs). Tops merge at the higher one until kBodyFloorSegments remain; no tread
  // is dropped, which would leave the flesh over it hanging inside its box. The merged tops
  // lift it by no more than one step.
  const Stick s(0.0f, 0.5f);
  std::vector<Box> treads;
  for (int k = 0; k < 16; ++k) treads.push_back(Box::from_corner(0.125f * k, -1.0f, 0.125f, 1.0f + (k % 2 ? 0.03f : 0.0f) + 0.01f * k));
  const BodyFloor floor = body_floor(level_of(treads), s.skeleton, s.world, 0.0f, {});
  CHECK(floor.count == kBodyFloorSegments);
  for (const Box& t : treads) {
    for (float x = t.min_ws.x; x <= t.max_ws.x; x += 0.01f) {
      const float y = floor_point({x, -1.0f}, floor).y;
      CHECK(y >= t.max_ws.y);
      CHECK(y <= t.max_ws.y + 0.04f);
    }
  }
  // Held up past a top's ends by a vertex's overhang: the outline edge between a vertex on a
  // tread and one short of it then stays above the tread's corner.
  CHECK(floor_point({2.05f, -1.0f}, floor, 0.1f).y == Approx(treads.back().max_ws.y));
  CHECK(floor_point({2.05f, -1.0f}, floor).y == -1.0f);
}

TEST_CASE("a body's floor round-trips through its palette entries", "[body]") {
  BodyFloor floor;
  floor.count = 3;
  floor.segments[0] = {-1.0f, 2.0f, 0.0f};
  floor.segments[1] = {2.0f, 3.0f, 0.5f};
  floor.segments[2] = {3.5f, 4.0f, -0.25f};
  floor.feet[1] = {0.5f, 1.5f, 0.25f};
  floor.feet[kBodyFloorFeet - 1] = {4.0f, 5.0f, -1.0f};
  std::vector<Mat2x3> entries(kBodyFloorEntries);
  encode_floor(floor, entries);
  const BodyFloor back = decode_floor(entries);
  CHECK(back.count == 3);
  for (int k = 0; k < kBodyFloorSegments; ++k) CHECK(back.segments[static_cast<size_t>(k)] == floor.segments[static_cast<size_t>(k)]);
  for (int k = 0; k < kBodyFloorFeet; ++k) CHECK(back.feet[static_cast<size_t>(k)] == floor.feet[static_cast<size_t>(k)]);
  // The default floor holds nothing: every point stays where it is.
  encode_floor(BodyFloor{}, entries);
  CHECK(decode_floor(entries).count == 0);
  CHECK(floor_point({0.0f, -10.0f}, decode_floor(entries)).y == -10.0f);
}

TEST_CASE("a leg's flesh rests level past the edge of the top its own foot stands on, and only there", "[body]") {
  // The stick's second bone ends at (2, 0), its "toe", on a tread of two tiles whose top y = 0
  // ends at x = 2.05; the ground below the edge is 0.3 lower. A third bone, another leg's foot,
  // hangs in the air.
  Stick s(0.0f, 0.0f);
  s.skeleton.add_bone("c", BoneKind::kNeckVertebra, 0, 0.5f, 0.1f, BoneLocal{}, Layer::kBody);
  Mat2x3 c = s.world[0];
  c.m[5] = 0.4f;
  s.world.push_back(c);
  const Level level = level_of({Box::from_corner(0.5f, -1.0f, 1.0f, 1.0f), Box::from_corner(1.5f, -1.0f, 0.55f, 1.0f),
                                Box::from_corner(2.05f, -1.0f, 2.0f, 0.7f)});
  const BodyFoot feet[2] = {{1, -1}, {2, -1}};
  const BodyFloor floor = body_floor(level, s.skeleton, s.world, 0.1f, feet);
  // The tiles are one top, ending at the tread's edge, and reach no further from the toe than
  // the foot bone's length.
  CHECK(floor.feet[0].x == Approx(1.0f));
  CHECK(floor.feet[0].y == Approx(2.05f));
  CHECK(floor.feet[0].z == 0.0f);
  CHECK(floor.feet[1].x > floor.feet[1].y);  // the foot in the air stands on nothing
  // A point of the standing foot's leg, past the edge and less than its overhang below the
  // top, rests level with it; deeper (a leg hanging down past the ledge) it keeps its place,
  // as does the flesh of the foot in the air and that of a part with no foot (its overhang
  // counts on every top alike).
  CHECK(floor_point({2.08f, -0.02f}, floor, 0.05f, 0).y == 0.0f);
  CHECK(floor_point({2.08f, -0.2f}, floor, 0.05f, 0).y == -0.2f);
  CHECK(floor_point({2.12f, -0.02f}, floor, 0.05f, 0).y == -0.02f);  // past its overhang
  CHECK(floor_point({2.08f, -0.02f}, floor, 0.05f, 1).y == -0.02f);
  CHECK(floor_point({2.08f, -0.02f}, floor, 0.05f).y == 0.0f);
  // A leg's overhang holds it up on no other top: beside the lower ground's end (x = 4.05).
  CHECK(floor_point({4.08f, -0.32f}, floor, 0.05f, 0).y == -0.32f);
  // Over the top the floor lifts every point, a leg's too.
  CHECK(floor_point({1.9f, -0.2f}, floor, 0.05f, 1).y == 0.0f);
  // A toe touching a top further than its foot bone's length from the top's edge (x = 2.5; a
  // swinging foot's toe, its knee out over the edge) holds nothing up past that edge.
  Stick back(-1.0f, 0.0f);
  back.skeleton.add_bone("c", BoneKind::kNeckVertebra, 0, 0.5f, 0.1f, BoneLocal{}, Layer::kBody);
  back.world.push_back(c);
  const BodyFloor far = body_floor(level_of({Box::from_corner(-5.0f, -1.0f, 7.5f, 1.0f)}), back.skeleton, back.world, 0.1f, feet);
  CHECK(far.feet[0].y == Approx(2.0f));
  CHECK(floor_point({2.04f, -0.02f}, far, 0.05f, 0).y == 0.0f);
  CHECK(floor_point({2.52f, -0.02f}, far, 0.05f, 0).y == -0.02f);
}
