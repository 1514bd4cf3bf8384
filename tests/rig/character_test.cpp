// Character (anim/character.h): an imported skeleton and a rig mapping become an ossa
// Skeleton, its standing pose and the same AnimRig a creature gets; what cannot work is an
// Error naming the file, the field and the bone. The skeleton here is built by hand the way
// Blender exports one (bones along their local +y, centimetres, a ground-level "root" above
// the hips, a bone beside the body), so nothing depends on Assimp.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

#include "ossa/anim/animator.h"
#include "ossa/rig/character.h"
#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "shared/level_scenes.h"

using namespace ossa;

namespace {

// A bone frame whose local +y runs from `head` towards `tail` (Blender's convention).
Mat2x3 blender_frame(glm::vec2 head, glm::vec2 tail) {
  const glm::vec2 d = glm::normalize(tail - head);
  Mat2x3 m;
  m.m[0] = d.y, m.m[1] = -d.x;  // local x: d turned clockwise
  m.m[2] = d.x, m.m[3] = d.y;   // local y: along the bone
  m.m[4] = head.x, m.m[5] = head.y;
  return m;
}

struct Biped {
  ImportedSkeleton skeleton;
  RigMapping mapping;
};

// A 1.6 m biped in centimetres, standing straight, facing +x.
Biped biped() {
  Biped b;
  ImportedSkeleton& s = b.skeleton;
  s.source = "biped.gltf";
  auto add = [&](const char* name, const char* parent, glm::vec2 head, glm::vec2 tail) {
    ImportedBone bone;
    bone.name = name;
    bone.parent = parent ? s.find(parent) : -1;
    bone.rest_ms = blender_frame(head, tail);
    s.bones.push_back(bone);
  };
  add("root", nullptr, {0, 0}, {0, 20});  // Rigify's root at the ground, above the hips
  add("hips", "root", {0, 90}, {0, 105});
  add("spine", "hips", {0, 105}, {0, 125});
  add("chest", "spine", {0, 125}, {0, 145});
  add("neck", "chest", {0, 145}, {2, 152});
  add("head", "neck", {2, 152}, {4, 175});
  add("prop", "root", {30, 50}, {40, 50});  // beside the body: hangs from the hips in ossa
  for (const char* side : {".L", ".R"}) {
    auto n = [&](const char* stem) { return std::string(stem) + side; };
    add(n("thigh").c_str(), "hips", {0, 90}, {0, 48});
    add(n("shin").c_str(), n("thigh").c_str(), {0, 48}, {0, 8});
    add(n("foot").c_str(), n("shin").c_str(), {0, 8}, {10, 2});
    add(n("toe").c_str(), n("foot").c_str(), {10, 2}, {16, 1});
    add(n("upper_arm").c_str(), "chest", {0, 140}, {0, 115});
    add(n("forearm").c_str(), n("upper_arm").c_str(), {0, 115}, {0, 90});
    add(n("hand").c_str(), n("forearm").c_str(), {0, 90}, {0, 80});
  }
  add("tail", "hips", {-10, 95}, {-25, 100});
  add("tail.001", "tail", {-25, 100}, {-35, 108});
  RigMapping& m = b.mapping;
  m.mesh = "biped.gltf";
  m.scale = 0.01f;
  m.root = "hips";
  m.spine = {"spine", "chest"};
  m.neck = {"neck"};
  m.head = "head";
  m.tail = {"tail", "tail.001"};
  for (const char* side : {".L", ".R"}) {
    RigChain leg;
    leg.side = side[1] == 'L' ? Side::kNear : Side::kFar;
    leg.upper = std::string("thigh") + side;
    leg.lower = std::string("shin") + side;
    leg.end = std::string("foot") + side;
    if (side[1] == 'L') leg.contact = glm::vec2(16.0f, 0.0f);  // the right foot: its toe's joint
    m.legs.push_back(leg);
    RigChain arm;
    arm.side = leg.side;
    arm.upper = std::string("upper_arm") + side;
    arm.lower = std::string("forearm") + side;
    arm.end = std::string("hand") + side;
    m.arms.push_back(arm);
  }
  return b;
}

std::string error_of(const Biped& b) {
  Result<Character> c = build_character(b.skeleton, b.mapping, "biped.rig.json");
  return c.ok() ? std::string("(built)") : c.message();
}

void check_near(const Mat2x3& a, const Mat2x3& b, float eps) {
  for (int k = 0; k < 6; ++k) REQUIRE(a.m[k] == Approx(b.m[k]).margin(eps));
}

}  // namespace

TEST_CASE("an imported skeleton and a mapping build an ossa skeleton re-rooted at the mapped root", "[anim][rig]") {
  const Biped b = biped();
  Result<Character> built = build_character(b.skeleton, b.mapping, "chars/biped.rig.json");
  INFO((built.ok() ? std::string() : built.message()));
  REQUIRE(built.ok());
  const Character& c = *built;
  CHECK(c.name == "biped");
  const Skeleton& sk = c.skeleton;
  REQUIRE(sk.bone_count() == static_cast<int>(b.skeleton.bones.size()));
  CHECK(sk.is_valid());
  CHECK(sk.name(0) == "hips");
  CHECK(sk.parent(0) == kNoParent);
  CHECK(sk.parent(sk.find("root")) == 0);  // above the mapped root: now hangs from it
  CHECK(sk.parent(sk.find("prop")) == 0);
  // Frames along the bones, in metres; the thigh ends at the shin's joint, the foot at its
  // ground contact; the ground (the lowest contact) at y = 0, the hips at x = 0.
  const std::vector<Mat2x3> rest = model_matrices(sk, sk.rest_locals());
  const int thigh = sk.find("thigh.L"), shin = sk.find("shin.L"), foot = sk.find("foot.L");
  CHECK(sk.length(thigh) == Approx(0.42f));
  CHECK(sk.rest(shin).offset_ls == glm::vec2(sk.length(thigh), 0.0f));  // exactly on the axis
  CHECK(bone_end(rest[static_cast<size_t>(foot)], sk.length(foot)).x == Approx(0.16f));
  CHECK(bone_end(rest[static_cast<size_t>(foot)], sk.length(foot)).y == Approx(0.0f).margin(1e-6));
  CHECK(c.contacts_ms[1].x == Approx(0.10f));  // the right toe's joint
  CHECK(c.contacts_ms[1].y == Approx(0.02f));
  CHECK(bone_start(rest[0]).x == Approx(0.0f).margin(1e-6));
  CHECK(bone_start(rest[0]).y == Approx(0.9f));
  // The binding: an ossa bone's rest frame times to_mesh is its mesh bone's, in model space.
  for (int k = 0; k < sk.bone_count(); ++k) {
    const ImportedBone& mb = b.skeleton.bones[static_cast<size_t>(c.mesh_bone[static_cast<size_t>(k)])];
    CHECK(mb.name == sk.name(k));
    check_near(rest[static_cast<size_t>(k)] * c.to_mesh[static_cast<size_t>(k)], c.mesh_to_model * mb.rest_ms, 1e-5f);
  }
  // The rig: one leg pair, knees forward (straight in the rest pose: the mapping's default),
  // arms, a head kept level, a tail; the straight legs stand a little bent.
  const AnimRig& rig = *c.rig;
  REQUIRE(rig.legs.size() == 2);
  REQUIRE(rig.girdles.size() == 1);
  CHECK(rig.legs[0].bend == 1.0f);
  CHECK(rig.arms.size() == 2);
  CHECK(rig.skull == sk.find("head"));
  CHECK(rig.tail.size() == 2);
  CHECK(rig.back == std::vector<int>{sk.find("chest"), sk.find("spine")});
  CHECK(rig.girdles[0].rest_height < 0.9f);
  CHECK(rig.girdles[0].rest_height > 0.85f);
  CHECK_FALSE(c.warnings.empty());
}

TEST_CASE("a built character walks, runs, stops and turns on flat ground like a creature", "[anim][rig]") {
  const Biped b = biped();
  auto c = std::make_shared<const Character>(build_character(b.skeleton, b.mapping, "biped.rig.json").value());
  const Level flat = scenes::flat_level(400.0f);
  Player player(c, SplinePrototypes::defaults());
  CHECK(player.is_character());
  CHECK(player.name() == "biped");
  CHECK_FALSE(player.animator().has_creature());
  player.animator().reset(flat.spawn_ws + glm::vec2(0.0f, 1.0f), flat);
  const SimResult r = run_script(player, flat, parse_script("walk:0.5:6,run:1:6,stop:1,walk:-0.5:6").value(), 120);
  CHECK(r.probe.max_stance_slip_m <= 0.001f);
  CHECK(r.probe.max_penetration_m <= 0.001f);
  CHECK(r.probe.nan_count == 0);
  for (const SegmentMetrics& s : r.segments) {
    INFO(s.command);
    CHECK(s.speed_error <= 0.02f);
  }
  CHECK(r.steps > 20);
}

TEST_CASE("a mapping that cannot work names the file, the field and the bone", "[anim][rig]") {
  {
    Biped b = biped();
    b.mapping.legs[1].lower = "calf.R";
    CHECK_THAT(error_of(b), Catch::StartsWith("biped.rig.json: legs[1].lower: bone \"calf.R\" is not in biped.gltf"));
  }
  {
    Biped b = biped();  // a leg that is not one chain
    b.mapping.legs[0].lower = "foot.L";
    b.mapping.legs[0].end = "toe.L";
    CHECK_THAT(error_of(b), Catch::Contains("legs[0].lower: bone \"foot.L\" is not a child of \"thigh.L\""));
  }
  {
    Biped b = biped();  // a leg of one bone: the shin starts where the thigh does
    b.skeleton.bones[static_cast<size_t>(b.skeleton.find("shin.R"))].rest_ms =
        blender_frame({0, 90}, {0, 8});
    CHECK_THAT(error_of(b), Catch::Contains("legs[1].upper: bone \"thigh.R\" has no length"));
  }
  {
    Biped b = biped();  // a foot above its hip
    b.mapping.legs[0].contact = glm::vec2(10.0f, 120.0f);
    CHECK_THAT(error_of(b), Catch::Contains("legs[0].foot: foot \"foot.L\" is not below its hip"));
  }
  {
    Biped b = biped();  // the contact at the ankle
    b.mapping.legs[0].contact = glm::vec2(0.0f, 8.0f);
    CHECK_THAT(error_of(b), Catch::Contains("legs[0].contact: the contact point of foot \"foot.L\" is at its ankle"));
  }
  {
    Biped b = biped();  // the spine must hang from the root
    b.mapping.spine = {"prop"};
    CHECK_THAT(error_of(b), Catch::Contains("spine[0]: bone \"prop\" does not hang from \"hips\""));
  }
  {
    Biped b = biped();  // so must every limb
    b.mapping.root = "chest";
    b.mapping.spine.clear();
    b.mapping.tail.clear();
    CHECK_THAT(error_of(b), Catch::Contains("legs[0].upper: bone \"thigh.L\" does not hang from \"chest\""));
  }
  {
    Biped b = biped();
    b.skeleton.bones[3].rest_ms.m[0] = NAN;
    CHECK_THAT(error_of(b), Catch::Contains("bone \"chest\": its rest transform is not finite"));
  }
  {
    Biped b = biped();  // a foot with no contact, no vertices and no child
    b.mapping.legs[1].end = "toe.R";
    b.mapping.legs[1].lower = "foot.R";
    b.mapping.legs[1].upper = "shin.R";
    CHECK_THAT(error_of(b), Catch::Contains("legs[1].contact: foot \"toe.R\" moves no vertex and has no child bone"));
  }
}

TEST_CASE("a contact point far from its foot is refused, a long foot reported", "[anim][rig]") {
  // [1e6, -1e6] grew the animator's ground profile until bad_alloc.
  {
    Biped b = biped();
    b.mapping.legs[0].contact = glm::vec2(1e6f, -1e6f);
    CHECK_THAT(error_of(b), Catch::StartsWith("biped.rig.json: legs[0].contact: the contact point of foot \"foot.L\" lies "));
    CHECK_THAT(error_of(b), Catch::Contains("m from its ankle, more than 2 times the leg's length (0.82 m): expected a point on the sole"));
  }
  {
    Biped b = biped();  // a leg's length in front of the ankle: builds, with a note
    b.mapping.legs[0].contact = glm::vec2(100.0f, 2.0f);
    Result<Character> c = build_character(b.skeleton, b.mapping, "biped.rig.json");
    REQUIRE(c.ok());
    // (Beside the standing-pose note every straight-legged biped gets.)
    const auto& w = c->warnings;
    CHECK(std::count(w.begin(), w.end(),
                     "legs[0]: the contact point of foot \"foot.L\" lies 1 m from its ankle, further than the leg is long (0.82 m)") == 1);
    CHECK(std::count_if(w.begin(), w.end(), [](const std::string& t) { return t.find("contact point") != std::string::npos; }) == 1);
  }
}

TEST_CASE("implausible sizes and leg counts are reported by the build", "[anim][rig]") {
  {
    Biped b = biped();  // centimetres read as metres: a 160 m biped
    b.mapping.scale = 1.0f;
    Result<Character> c = build_character(b.skeleton, b.mapping, "biped.rig.json");
    REQUIRE(c.ok());
    const auto& w = c->warnings;
    for (const char* leg : {"legs[0]", "legs[1]"}) {
      CHECK(std::count(w.begin(), w.end(), std::string(leg) + ": the leg is 82 m long (upper + lower), outside the 0.01 m to 20 m "
                                                              "of walking animals: is \"scale\" right? (a mesh in centimetres needs 0.01)") == 1);
    }
  }
  {
    Biped b = biped();  // 35 pairs of legs under the hips
    for (int i = 0; i < 68; ++i) {
      const std::string n = std::to_string(i);
      ImportedSkeleton& s = b.skeleton;
      auto add = [&](const std::string& name, int parent, glm::vec2 head, glm::vec2 tail) {
        ImportedBone bone;
        bone.name = name;
        bone.parent = parent;
        bone.rest_ms = blender_frame(head, tail);
        s.bones.push_back(bone);
        return static_cast<int>(s.bones.size()) - 1;
      };
      const int thigh = add("thigh" + n, s.find("hips"), {0, 90}, {0, 48});
      const int shin = add("shin" + n, thigh, {0, 48}, {0, 8});
      add("foot" + n, shin, {0, 8}, {10, 2});
      RigChain leg;
      leg.side = i % 2 ? Side::kFar : Side::kNear;
      leg.upper = "thigh" + n;
      leg.lower = "shin" + n;
      leg.end = "foot" + n;
      leg.contact = glm::vec2(10.0f, 0.0f);
      b.mapping.legs.push_back(leg);
    }
    Result<Character> c = build_character(b.skeleton, b.mapping, "biped.rig.json");
    REQUIRE(c.ok());
    bool warned = false;
    for (const std::string& w : c->warnings) {
      warned |= w == "legs: 35 leg pairs; the animator's gaits are made for 1 to 3 (bipeds, quadrupeds, six legs): more walk, "
                     "but their feet slide on steps";
    }
    CHECK(warned);
  }
}
