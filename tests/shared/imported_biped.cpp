#include "shared/imported_biped.h"

#include <string>

#include <glm/geometric.hpp>

namespace ossa::scenes {

Mat2x3 blender_frame(glm::vec2 head, glm::vec2 tail) {
  const glm::vec2 d = glm::normalize(tail - head);
  Mat2x3 m;
  m.m[0] = d.y, m.m[1] = -d.x;  // local x: d turned clockwise
  m.m[2] = d.x, m.m[3] = d.y;   // local y: along the bone
  m.m[4] = head.x, m.m[5] = head.y;
  return m;
}

ImportedBiped imported_biped() {
  ImportedBiped b;
  ImportedSkeleton& s = b.skeleton;
  s.source = "biped.gltf";
  auto add = [&](const char* name, const char* parent, glm::vec2 head, glm::vec2 tail) {
    ImportedBone bone;
    bone.name = name;
    bone.parent = parent ? s.find(parent) : -1;
    bone.rest_mesh = blender_frame(head, tail);
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

}  // namespace ossa::scenes
