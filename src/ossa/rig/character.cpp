#include "ossa/rig/character.h"

// build_character runs its phases in order (character_internal.h): (1) every mapped bone and
// the chains, (2) the joints in ossa model space, (3) each ossa bone's direction and length
// (those three in character_parts.cpp), (4) the rest pose can walk, (5) the ossa skeleton
// re-rooted at the mapped root, its rest pose and binding, (6) the roles and the AnimRig.

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>

#include "ossa/anim/anim_math.h"
#include "ossa/io/json.h"
#include "ossa/math/angle.h"
#include "ossa/math/two_bone_ik.h"
#include "ossa/rig/character_checks.h"
#include "ossa/rig/character_internal.h"

namespace ossa {

using namespace character_build;

namespace {

// A straight rest leg: the knee within this fraction of the leg's reach of the hip-ankle line.
constexpr float kStraightOfReach = 1e-3f;
// A foot whose contact point stands this fraction of its hip's height above the ground is
// reported (not refused).
constexpr float kFloatingOfHip = 0.05f;
// The standing pose keeps every leg's hip within this fraction of its reach of its ankle.
constexpr float kStandOfReach = 0.97f;

// (4) The rest pose must be able to walk: feet below hips, each knee's bend, sizes.
Status check_legs(Builder& b, Character& ch) {
  // (4) The rest pose must be able to walk.
  b.bend.assign(b.legs.size(), 1);
  for (size_t i = 0; i < b.legs.size(); ++i) {
    const Chain& c = b.legs[i];
    const glm::vec2 hip = b.joint[static_cast<size_t>(c.bones[0])];
    const glm::vec2 knee = b.joint[static_cast<size_t>(c.bones[1])];
    const glm::vec2 ankle = b.joint[static_cast<size_t>(c.bones[2])];
    const float reach = b.length[static_cast<size_t>(c.bones[0])] + b.length[static_cast<size_t>(c.bones[1])];
    if (!(b.contacts[i].y < hip.y - b.min_len) || !(ankle.y < hip.y)) {
      char what[200];
      std::snprintf(what, sizeof what, "foot %s is not below its hip in the rest pose (contact y %.3f m, ankle y %.3f m, hip y %.3f m): a leg must hang down",
                    quoted(b.map.legs[i].end).c_str(), b.contacts[i].y, ankle.y, hip.y);
      return b.err(json_path(c.path, "foot"), what);
    }
    const glm::vec2 u = ankle - hip, v = knee - hip;
    const float cross = u.x * v.y - u.y * v.x;
    if (std::fabs(cross) <= kStraightOfReach * reach * glm::length(u)) {
      b.bend[i] = b.map.legs[i].knee;
    } else {
      b.bend[i] = cross > 0.0f ? 1 : -1;
    }
    if (Status st = check_leg_size(c.path, b.map.legs[i].end, ankle, b.contacts[i], reach, b.file, ch.warnings); !st.ok()) {
      return st;
    }
    const float hip_h = hip.y;
    if (b.contacts[i].y > kFloatingOfHip * hip_h) {
      char what[160];
      std::snprintf(what, sizeof what, "%s: foot %s stands %.3f m above the ground in the rest pose", c.path.c_str(),
                    quoted(b.map.legs[i].end).c_str(), b.contacts[i].y);
      ch.warnings.push_back(what);
    }
  }

  check_leg_pairs(b.map, ch.warnings);
  return {};
}

// (5) The ossa skeleton, its bone kinds and layers, and the binding to the mesh.
void build_skeleton(Builder& b, Character& ch) {
  // (5) The ossa skeleton: root first, then the mesh order; a bone outside the root's subtree
  // (or above it) hangs from the root.
  b.order = {b.root};
  for (int i = 0; i < b.n; ++i) {
    if (i != b.root) b.order.push_back(i);
  }
  b.ossa_of.assign(static_cast<size_t>(b.n), -1);
  for (size_t k = 0; k < b.order.size(); ++k) b.ossa_of[static_cast<size_t>(b.order[k])] = static_cast<int>(k);
  std::vector<BoneKind> kind(static_cast<size_t>(b.n), BoneKind::kRib);
  std::vector<Layer> layer(static_cast<size_t>(b.n), Layer::kBody);
  kind[static_cast<size_t>(b.root)] = BoneKind::kRoot;
  for (int v : b.spine) kind[static_cast<size_t>(v)] = BoneKind::kBackVertebra;
  for (int v : b.neck) kind[static_cast<size_t>(v)] = BoneKind::kNeckVertebra;
  for (int v : b.tail) kind[static_cast<size_t>(v)] = BoneKind::kTailVertebra;
  if (b.head >= 0) kind[static_cast<size_t>(b.head)] = BoneKind::kSkull;
  for (int k = 0; k < 2; ++k) {
    const std::vector<Chain>& chains = k == 0 ? b.legs : b.arms;
    const std::vector<RigChain>& rcs = k == 0 ? b.map.legs : b.map.arms;
    for (size_t i = 0; i < chains.size(); ++i) {
      const int girdle = b.in.bones[static_cast<size_t>(chains[i].bones[0])].parent;
      if (kind[static_cast<size_t>(girdle)] == BoneKind::kRib) kind[static_cast<size_t>(girdle)] = k == 0 ? BoneKind::kPelvis : BoneKind::kScapula;
      const BoneKind kinds[3] = {BoneKind::kUpperLimb, BoneKind::kLowerLimb, BoneKind::kHand};
      for (int j = 0; j < 3; ++j) {
        kind[static_cast<size_t>(chains[i].bones[static_cast<size_t>(j)])] = kinds[j];
        layer[static_cast<size_t>(chains[i].bones[static_cast<size_t>(j)])] = rcs[i].side == Side::kNear ? Layer::kNear : Layer::kFar;
      }
    }
  }
  std::vector<Mat2x3> model(static_cast<size_t>(b.n));
  for (int i = 0; i < b.n; ++i) model[static_cast<size_t>(i)] = frame_matrix(b.dir[static_cast<size_t>(i)], b.joint[static_cast<size_t>(i)]);
  for (int m : b.order) {
    const size_t u = static_cast<size_t>(m);
    const int mp = b.in.bones[u].parent;
    const int parent = m == b.root ? -1 : (mp >= 0 && b.descends(mp, b.root) ? mp : b.root);
    BoneLocal local;
    if (parent < 0) {
      local.offset_ls = b.joint[u];
      local.angle_ls = std::atan2(b.dir[u].y, b.dir[u].x);
    } else {
      const size_t pu = static_cast<size_t>(parent);
      const Mat2x3 rel = inverse(model[pu]) * model[u];
      local.offset_ls = bone_start(rel);
      // A chain's next joint lies on the parent's axis at its end, exactly (the IK needs it).
      if (b.next[pu] == m) local.offset_ls = {b.length[pu], 0.0f};
      local.angle_ls = anim::bone_angle(rel);
    }
    ch.skeleton.add_bone(b.in.bones[u].name, kind[u], parent < 0 ? kNoParent : b.ossa(parent), b.length[u],
                         b.width[u], local, layer[u]);
  }
  // The binding, from the rest pose as FK gives it (so palettes are the identity at rest).
  const std::vector<Mat2x3> ossa_rest = model_matrices(ch.skeleton, ch.skeleton.rest_locals());
  for (size_t k = 0; k < b.order.size(); ++k) {
    const int m = b.order[k];
    ch.mesh_bone.push_back(m);
    ch.to_mesh.push_back(inverse(ossa_rest[k]) * b.s * b.in.bones[static_cast<size_t>(m)].rest_mesh);
  }
  ch.mesh_to_model = b.s;
  ch.contacts_ms = b.contacts;
}

// (5b) The standing pose.
void stand(const Builder& b, Character& ch) {
  // (5b) The standing pose: legs straight in the rest pose (a character modelled standing
  // tall) could not stand there, as stance legs stop short of full reach (kReachLimit); the
  // body lowers until every leg's hip is within kStandOfReach of its reach of its ankle, the
  // knees bend their way, ankles and feet stay.
  ch.rest_pose = Pose::rest(ch.skeleton);
  float lower = 0.0f;
  for (const Chain& c : b.legs) {
    const float reach = b.length[static_cast<size_t>(c.bones[0])] + b.length[static_cast<size_t>(c.bones[1])];
    const glm::vec2 hip = b.joint[static_cast<size_t>(c.bones[0])], ankle = b.joint[static_cast<size_t>(c.bones[2])];
    const float h = hip.y - ankle.y, want = kStandOfReach * reach;
    const float dx = hip.x - ankle.x;
    if (want > std::fabs(dx)) lower = std::max(lower, h - std::sqrt(want * want - dx * dx));
  }
  if (lower > 0.0f) {
    ch.rest_pose.locals[0].offset_ls.y -= lower;
    const std::vector<Mat2x3> body = model_matrices(ch.skeleton, ch.rest_pose.locals);
    for (size_t i = 0; i < b.legs.size(); ++i) {
      const Chain& c = b.legs[i];
      const int up = b.ossa(c.bones[0]), lo = b.ossa(c.bones[1]), ft = b.ossa(c.bones[2]);
      const int girdle = ch.skeleton.parent(up);
      const glm::vec2 hip = bone_start(body[static_cast<size_t>(up)]);
      const glm::vec2 ankle = b.joint[static_cast<size_t>(c.bones[2])];
      const TwoBoneIkResult ik = solve_two_bone_ik(hip, ch.skeleton.length(up), ch.skeleton.length(lo), ankle, static_cast<float>(b.bend[i]));
      const float girdle_angle = anim::bone_angle(body[static_cast<size_t>(girdle)]);
      const float foot_angle = std::atan2(b.dir[static_cast<size_t>(c.bones[2])].y, b.dir[static_cast<size_t>(c.bones[2])].x);
      ch.rest_pose.locals[static_cast<size_t>(up)].angle_ls = wrap_angle(ik.upper_angle - girdle_angle);
      ch.rest_pose.locals[static_cast<size_t>(lo)].angle_ls = ik.lower_angle;
      ch.rest_pose.locals[static_cast<size_t>(ft)].angle_ls = wrap_angle(foot_angle - ik.upper_angle - ik.lower_angle);
    }
    char what[160];
    std::snprintf(what, sizeof what, "the legs are straight in the rest pose: the standing pose lowers the body %.3f m and bends the knees", lower);
    ch.warnings.push_back(what);
  }
}

// (6) The roles and the rig.
void assign_roles(const Builder& b, Character& ch) {
  // (6) Roles and the rig.
  RigRoles& roles = ch.roles;
  roles.root = 0;
  roles.skull = b.head >= 0 ? b.ossa(b.head) : -1;
  for (auto it = b.spine.rbegin(); it != b.spine.rend(); ++it) roles.back.push_back(b.ossa(*it));
  for (auto it = b.neck.rbegin(); it != b.neck.rend(); ++it) roles.neck.push_back(b.ossa(*it));
  for (int v : b.tail) roles.tail.push_back(b.ossa(v));
  roles.flat_contact = false;
  for (size_t i = 0; i < b.legs.size(); ++i) {
    const Chain& c = b.legs[i];
    roles.limbs.push_back({LimbKind::kLeg, b.ossa(b.in.bones[static_cast<size_t>(c.bones[0])].parent),
                           {b.ossa(c.bones[0]), b.ossa(c.bones[1]), b.ossa(c.bones[2])}, b.map.legs[i].side, b.bend[i], b.map.leg_pair(i)});
  }
  for (size_t i = 0; i < b.arms.size(); ++i) {
    const Chain& c = b.arms[i];
    const int girdle_mesh = b.in.bones[static_cast<size_t>(c.bones[0])].parent;
    roles.limbs.push_back({LimbKind::kArm, b.ossa(girdle_mesh), {b.ossa(c.bones[0]), b.ossa(c.bones[1]), b.ossa(c.bones[2])}, b.map.arms[i].side, 1, 0});
  }
  ch.rig = build_anim_rig(ch.skeleton, ch.rest_pose, roles);
  ch.name = character_name(b.file);
  ch.rig_path = b.file;
  ch.mapping = b.map;
}

}  // namespace

int ImportedSkeleton::find(const std::string& name) const {
  for (size_t i = 0; i < bones.size(); ++i) {
    if (bones[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string character_name(const std::string& rig_file) {
  std::string name = std::filesystem::path(rig_file).filename().string();
  for (const char* ext : {".rig.json", ".json"}) {
    const std::string e = ext;
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0) {
      name.resize(name.size() - e.size());
      break;
    }
  }
  return name;
}

Result<Character> build_character(const ImportedSkeleton& sk, const RigMapping& map, const std::string& file) {
  Builder b(sk, map, file);
  b.n = static_cast<int>(sk.bones.size());
  Character ch;
  if (Status s = check_bones(b); !s.ok()) return s.error();
  if (Status s = find_parts(b); !s.ok()) return s.error();
  if (Status s = place_joints(b); !s.ok()) return s.error();
  if (Status s = aim_bones(b); !s.ok()) return s.error();
  if (Status s = check_legs(b, ch); !s.ok()) return s.error();
  build_skeleton(b, ch);
  stand(b, ch);
  assign_roles(b, ch);
  return ch;
}

}  // namespace ossa
