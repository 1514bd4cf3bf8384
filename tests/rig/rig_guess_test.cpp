// The starting rig mapping guessed from bone names (anim/rig_guess.h): Rigify, Mixamo,
// Unreal and plain names, case and separators not mattering, and a quadruped whose front legs
// are named as arms.

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "ossa/rig/rig_guess.h"

using namespace ossa;

namespace {

struct Names {
  std::string root, spine1, spine2, neck, head;
  std::string thigh, shin, foot, upper_arm, forearm, hand;  // with {s} for the side
  std::string left, right;                                  // what {s} becomes
};

std::string side(std::string s, const std::string& token) {
  const size_t at = s.find("{s}");
  return at == std::string::npos ? s : s.replace(at, 3, token);
}

// A standing biped skeleton (metres, frames along +x) with the given names.
ImportedSkeleton skeleton(const Names& n) {
  ImportedSkeleton s;
  s.source = "test.gltf";
  auto add = [&](const std::string& name, const std::string& parent, glm::vec2 head) {
    ImportedBone b;
    b.name = name;
    b.parent = parent.empty() ? -1 : s.find(parent);
    b.rest_mesh.m[4] = head.x, b.rest_mesh.m[5] = head.y;
    s.bones.push_back(b);
  };
  add(n.root, "", {0.0f, 0.95f});
  add(n.spine1, n.root, {0.0f, 1.1f});
  add(n.spine2, n.spine1, {0.0f, 1.3f});
  add(n.neck, n.spine2, {0.0f, 1.45f});
  add(n.head, n.neck, {0.0f, 1.55f});
  for (const std::string& t : {n.left, n.right}) {
    add(side(n.thigh, t), n.root, {0.0f, 0.95f});
    add(side(n.shin, t), side(n.thigh, t), {0.0f, 0.5f});
    add(side(n.foot, t), side(n.shin, t), {0.0f, 0.08f});
    add(side(n.upper_arm, t), n.spine2, {0.0f, 1.42f});
    add(side(n.forearm, t), side(n.upper_arm, t), {0.0f, 1.15f});
    add(side(n.hand, t), side(n.forearm, t), {0.0f, 0.9f});
  }
  return s;
}

void check_biped(const Names& n) {
  INFO("root " << n.root << ", thigh " << n.thigh);
  const RigGuess g = guess_rig_mapping(skeleton(n), "test.gltf");
  const RigMapping& m = g.mapping;
  CHECK(m.mesh == "test.gltf");
  CHECK(m.root == n.root);
  CHECK(m.spine == std::vector<std::string>{n.spine1, n.spine2});
  CHECK(m.neck == std::vector<std::string>{n.neck});
  CHECK(m.head == n.head);
  REQUIRE(m.legs.size() == 2);
  CHECK(m.legs[0].upper == side(n.thigh, n.left));  // left: the near side
  CHECK(m.legs[0].side == Side::kNear);
  CHECK(m.legs[0].lower == side(n.shin, n.left));
  CHECK(m.legs[0].end == side(n.foot, n.left));
  CHECK(m.legs[1].upper == side(n.thigh, n.right));
  CHECK(m.legs[1].side == Side::kFar);
  REQUIRE(m.arms.size() == 2);
  CHECK(m.arms[0].upper == side(n.upper_arm, n.left));
  CHECK(m.arms[0].lower == side(n.forearm, n.left));
  CHECK(m.arms[1].end == side(n.hand, n.right));
  CHECK(g.notes.empty());
}

}  // namespace

TEST_CASE("bone names say the part and the side whatever the convention", "[anim][rig]") {
  CHECK(role_from_name("mixamorig:LeftUpLeg").role == BoneRole::kLegUpper);
  CHECK(role_from_name("mixamorig:LeftUpLeg").side == -1);
  CHECK(role_from_name("mixamorig:RightLeg").role == BoneRole::kLegLower);
  CHECK(role_from_name("mixamorig:RightLeg").side == 1);
  CHECK(role_from_name("mixamorig:LeftForeArm").role == BoneRole::kArmLower);
  CHECK_FALSE(role_from_name("mixamorig:LeftForeArm").front);
  CHECK(role_from_name("mixamorig:Hips").role == BoneRole::kRoot);
  CHECK(role_from_name("DEF-thigh.L").role == BoneRole::kLegUpper);
  CHECK(role_from_name("DEF-thigh.L").side == -1);
  CHECK(role_from_name("upper_arm.R").role == BoneRole::kArmUpper);
  CHECK(role_from_name("calf_l").role == BoneRole::kLegLower);
  CHECK(role_from_name("thigh_twist_01_l").role == BoneRole::kNone);  // helpers are not parts
  CHECK(role_from_name("LEFT-LEG-UPPER").role == BoneRole::kLegUpper);
  CHECK(role_from_name("left leg lower").role == BoneRole::kLegLower);
  CHECK(role_from_name("FrontPaw_R").role == BoneRole::kFoot);
  CHECK(role_from_name("FrontPaw_R").front);
  CHECK(role_from_name("tail_03").role == BoneRole::kTail);
  CHECK(role_from_name("Spine2").role == BoneRole::kSpine);
  CHECK(role_from_name("HeadTop_End").role == BoneRole::kHead);
  CHECK(role_from_name("Armature").role == BoneRole::kNone);
}

TEST_CASE("a mapping is guessed from Rigify, Mixamo, Unreal and plain bone names", "[anim][rig]") {
  check_biped({"hips", "spine", "chest", "neck", "head", "thigh.{s}", "shin.{s}", "foot.{s}", "upper_arm.{s}", "forearm.{s}",
               "hand.{s}", "L", "R"});
  check_biped({"mixamorig:Hips", "mixamorig:Spine", "mixamorig:Spine1", "mixamorig:Neck", "mixamorig:Head",
               "mixamorig:{s}UpLeg", "mixamorig:{s}Leg", "mixamorig:{s}Foot", "mixamorig:{s}Arm", "mixamorig:{s}ForeArm",
               "mixamorig:{s}Hand", "Left", "Right"});
  check_biped({"pelvis", "spine_01", "spine_02", "neck_01", "head", "thigh_{s}", "calf_{s}", "foot_{s}", "upperarm_{s}",
               "lowerarm_{s}", "hand_{s}", "l", "r"});
  check_biped({"Pelvis", "Spine-Lower", "Spine-Upper", "Neck", "Head", "{s}_leg_upper", "{s}_leg_lower", "{s}_foot",
               "{s}_arm_upper", "{s}_arm_lower", "{s}_hand", "left", "right"});
}

TEST_CASE("a quadruped's front legs named as arms are guessed as legs: arms that reach the ground", "[anim][rig]") {
  ImportedSkeleton s;
  s.source = "dog.gltf";
  auto add = [&](const std::string& name, const std::string& parent, glm::vec2 head) {
    ImportedBone b;
    b.name = name;
    b.parent = parent.empty() ? -1 : s.find(parent);
    b.rest_mesh.m[4] = head.x, b.rest_mesh.m[5] = head.y;
    s.bones.push_back(b);
  };
  add("pelvis", "", {-0.3f, 0.5f});
  add("spine", "pelvis", {0.0f, 0.52f});
  add("chest", "spine", {0.2f, 0.52f});
  add("neck", "chest", {0.3f, 0.6f});
  add("head", "neck", {0.4f, 0.7f});
  add("tail_1", "pelvis", {-0.35f, 0.55f});
  add("tail_2", "tail_1", {-0.45f, 0.6f});
  for (const char* t : {"L", "R"}) {
    const std::string x = std::string(".") + t;
    add("thigh" + x, "pelvis", {-0.3f, 0.45f});
    add("shin" + x, "thigh" + x, {-0.25f, 0.27f});
    add("hind_paw" + x, "shin" + x, {-0.32f, 0.12f});
    add("upper_arm" + x, "chest", {0.2f, 0.42f});
    add("forearm" + x, "upper_arm" + x, {0.15f, 0.27f});
    add("front_paw" + x, "forearm" + x, {0.18f, 0.08f});
  }
  const RigGuess g = guess_rig_mapping(s, "dog.gltf");
  const RigMapping& m = g.mapping;
  REQUIRE(m.legs.size() == 4);
  CHECK(m.arms.empty());
  CHECK(m.legs[0].upper == "thigh.L");
  CHECK(m.legs[1].upper == "thigh.R");
  CHECK(m.legs[2].upper == "upper_arm.L");
  CHECK(m.legs[3].end == "front_paw.R");
  CHECK(m.leg_pair(2) == 1);
  CHECK(m.tail == std::vector<std::string>{"tail_1", "tail_2"});
  CHECK(m.head == "head");
  CHECK(m.spine == std::vector<std::string>{"spine", "chest"});
  CHECK_FALSE(g.notes.empty());  // says the arms became legs

  // No legs at all: said, not guessed.
  ImportedSkeleton snake;
  snake.bones = {s.bones[0], s.bones[1]};
  const RigGuess none = guess_rig_mapping(snake, "snake.gltf");
  CHECK(none.mapping.legs.empty());
  CHECK_FALSE(none.notes.empty());
}
