#include "ossa/rig/character.h"

// build_character: (1) look every mapped bone up and check the chains, (2) place the joints in
// ossa model space, (3) pick each ossa bone's direction and length, (4) check the rest pose can
// walk, (5) the ossa skeleton re-rooted at the mapped root, its rest pose and binding, (6) the
// roles and the AnimRig.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include <glm/geometric.hpp>

#include "ossa/anim/anim_math.h"
#include "ossa/rig/character_checks.h"
#include "ossa/math/angle.h"
#include "ossa/math/two_bone_ik.h"

namespace ossa {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// A bone shorter than this fraction of the character's size has no length.
constexpr float kMinBoneOfSize = 1e-4f;
// A straight rest leg: the knee within this fraction of the leg's reach of the hip-ankle line.
constexpr float kStraightOfReach = 1e-3f;
// A foot whose contact point stands this fraction of its hip's height above the ground is
// reported (not refused).
constexpr float kFloatingOfHip = 0.05f;
// The standing pose keeps every leg's hip within this fraction of its reach of its ankle.
constexpr float kStandOfReach = 0.97f;

bool finite(const Mat2x3& m) {
  for (float v : m.m) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

float det(const Mat2x3& m) { return m.m[0] * m.m[3] - m.m[1] * m.m[2]; }

struct Builder {
  Builder(const ImportedSkeleton& skeleton, const RigMapping& mapping, const std::string& rig_file)
      : in(skeleton), map(mapping), file(rig_file) {}
  const ImportedSkeleton& in;
  const RigMapping& map;
  const std::string& file;
  int n = 0;
  std::vector<glm::vec2> joint;    // per mesh bone: its joint, ossa model space
  std::vector<glm::vec2> dir;      // per mesh bone: ossa direction (unit)
  std::vector<float> length;       // per mesh bone
  std::vector<int> next;           // per mesh bone: the joint it points at (-1: none)
  std::vector<float> width;
  Mat2x3 s;                        // mesh model → ossa model
  float size = 1.0f;               // metres: the skeleton's extent, for tolerances

  Error err(const std::string& field, const std::string& what) const { return Error::at(file, field, what); }

  bool descends(int bone, int ancestor) const {
    for (int b = bone; b >= 0; b = in.bones[static_cast<size_t>(b)].parent) {
      if (b == ancestor) return true;
    }
    return false;
  }
};

Result<int> find_bone(const Builder& b, const std::string& field, const std::string& name) {
  const int i = b.in.find(name);
  if (i < 0) return b.err(field, "bone " + quoted(name) + " is not in " + b.in.source);
  return i;
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
  if (b.n == 0) return b.err("", sk.source + " has no bones");
  if (b.n > 255) return b.err("", sk.source + " has " + std::to_string(b.n) + " bones; at most 255 animate");
  for (int i = 0; i < b.n; ++i) {
    const ImportedBone& bone = sk.bones[static_cast<size_t>(i)];
    if (bone.parent >= i || bone.parent < -1) return b.err("", sk.source + ": bone " + quoted(bone.name) + ": its parent comes after it");
    if (!finite(bone.rest_ms) || std::fabs(det(bone.rest_ms)) < 1e-12f) {
      return b.err("", sk.source + ": bone " + quoted(bone.name) + ": its rest transform is not finite or not invertible");
    }
    if (sk.find(bone.name) != i) return b.err("", sk.source + ": two bones are named " + quoted(bone.name));
  }

  // (1) Every mapped bone, and the chains.
  auto look = [&](const std::string& field, const std::string& name, int* out) -> Status {
    Result<int> r = find_bone(b, field, name);
    if (!r.ok()) return r.error();
    *out = *r;
    return {};
  };
  int root = -1, head = -1;
  if (Status s = look("root", map.root, &root); !s.ok()) return s.error();
  if (!map.head.empty()) {
    if (Status s = look("head", map.head, &head); !s.ok()) return s.error();
  }
  auto list = [&](const char* key, const std::vector<std::string>& names, std::vector<int>* out) -> Status {
    for (size_t i = 0; i < names.size(); ++i) {
      int v = -1;
      if (Status s = look(json_path(key, i), names[i], &v); !s.ok()) return s;
      out->push_back(v);
    }
    return {};
  };
  std::vector<int> spine, neck, tail;
  if (Status s = list("spine", map.spine, &spine); !s.ok()) return s.error();
  if (Status s = list("neck", map.neck, &neck); !s.ok()) return s.error();
  if (Status s = list("tail", map.tail, &tail); !s.ok()) return s.error();
  struct Chain {
    std::array<int, 3> bones{};
    std::string path;
    const char* end_key;
  };
  std::vector<Chain> legs, arms;
  for (int kind = 0; kind < 2; ++kind) {
    const std::vector<RigChain>& chains = kind == 0 ? map.legs : map.arms;
    const char* key = kind == 0 ? "legs" : "arms";
    const char* end_key = kind == 0 ? "foot" : "hand";
    for (size_t i = 0; i < chains.size(); ++i) {
      Chain c{{}, json_path(key, i), end_key};
      const RigChain& rc = chains[i];
      if (Status s = look(json_path(c.path, "upper"), rc.upper, &c.bones[0]); !s.ok()) return s.error();
      if (Status s = look(json_path(c.path, "lower"), rc.lower, &c.bones[1]); !s.ok()) return s.error();
      if (Status s = look(json_path(c.path, end_key), rc.end, &c.bones[2]); !s.ok()) return s.error();
      if (sk.bones[static_cast<size_t>(c.bones[1])].parent != c.bones[0]) {
        return b.err(json_path(c.path, "lower"), "bone " + quoted(rc.lower) + " is not a child of " + quoted(rc.upper) +
                                                     " (a limb is a chain upper → lower → " + end_key + ")");
      }
      if (sk.bones[static_cast<size_t>(c.bones[2])].parent != c.bones[1]) {
        return b.err(json_path(c.path, end_key), "bone " + quoted(rc.end) + " is not a child of " + quoted(rc.lower) +
                                                     " (a limb is a chain upper → lower → " + end_key + ")");
      }
      if (sk.bones[static_cast<size_t>(c.bones[0])].parent < 0) {
        return b.err(json_path(c.path, "upper"), "bone " + quoted(rc.upper) + " hangs from nothing (a limb hangs from the body)");
      }
      (kind == 0 ? legs : arms).push_back(c);
    }
  }
  // Everything hangs from the root, and the spine parts follow each other.
  auto hangs = [&](const std::string& field, int bone, int from, const std::string& from_name) -> Status {
    if (bone == from || !b.descends(bone, from)) {
      return b.err(field, "bone " + quoted(sk.bones[static_cast<size_t>(bone)].name) + " does not hang from " + quoted(from_name));
    }
    return {};
  };
  {
    int prev = root;
    std::string prev_name = map.root;
    auto follow = [&](const char* key, const std::vector<int>& bones, const std::vector<std::string>& names) -> Status {
      for (size_t i = 0; i < bones.size(); ++i) {
        if (Status s = hangs(json_path(key, i), bones[i], prev, prev_name); !s.ok()) return s;
        prev = bones[i];
        prev_name = names[i];
      }
      return {};
    };
    if (Status s = follow("spine", spine, map.spine); !s.ok()) return s.error();
    if (Status s = follow("neck", neck, map.neck); !s.ok()) return s.error();
    if (head >= 0) {
      if (Status s = hangs("head", head, prev, prev_name); !s.ok()) return s.error();
    }
    if (!tail.empty()) {
      if (Status s = hangs(json_path("tail", 0), tail[0], root, map.root); !s.ok()) return s.error();
      for (size_t i = 1; i < tail.size(); ++i) {
        if (Status s = hangs(json_path("tail", i), tail[i], tail[i - 1], map.tail[i - 1]); !s.ok()) return s.error();
      }
    }
    for (const std::vector<Chain>* chains : {&legs, &arms}) {
      for (const Chain& c : *chains) {
        if (Status s = hangs(json_path(c.path, "upper"), c.bones[0], root, map.root); !s.ok()) return s.error();
      }
    }
  }

  // (2) Joints in ossa model space: scaled, the root at x = 0, the lowest contact at y = 0.
  std::vector<glm::vec2> raw(static_cast<size_t>(b.n));
  for (int i = 0; i < b.n; ++i) raw[static_cast<size_t>(i)] = map.scale * bone_start(sk.bones[static_cast<size_t>(i)].rest_ms);
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (glm::vec2 p : raw) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  b.size = std::max(std::max(hi.x - lo.x, hi.y - lo.y), 1e-3f);
  const float min_len = kMinBoneOfSize * b.size;
  std::vector<glm::vec2> contact_raw;
  for (size_t i = 0; i < legs.size(); ++i) {
    const Chain& c = legs[i];
    const RigChain& rc = map.legs[i];
    const ImportedBone& foot = sk.bones[static_cast<size_t>(c.bones[2])];
    glm::vec2 p;
    if (rc.contact) {
      p = map.scale * *rc.contact;
    } else if (foot.has_extent()) {
      p = map.scale * glm::vec2(foot.extent_max.x, foot.extent_min.y);  // the lowest front point
    } else {
      int child = -1;
      for (int j = c.bones[2] + 1; j < b.n && child < 0; ++j) {
        if (sk.bones[static_cast<size_t>(j)].parent == c.bones[2]) child = j;
      }
      if (child < 0) {
        return b.err(json_path(c.path, "contact"), "foot " + quoted(rc.end) +
                                                       " moves no vertex and has no child bone: give the contact point [x, y]");
      }
      p = raw[static_cast<size_t>(child)];
    }
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return b.err(json_path(c.path, "contact"), "expected finite numbers");
    contact_raw.push_back(p);
  }
  float ground = 1e30f;
  for (glm::vec2 p : contact_raw) ground = std::min(ground, p.y);
  const glm::vec2 shift(-raw[static_cast<size_t>(root)].x, -ground);
  b.s = Mat2x3{};
  b.s.m[0] = b.s.m[3] = map.scale;
  b.s.m[4] = shift.x;
  b.s.m[5] = shift.y;
  b.joint.resize(static_cast<size_t>(b.n));
  for (int i = 0; i < b.n; ++i) b.joint[static_cast<size_t>(i)] = raw[static_cast<size_t>(i)] + shift;
  std::vector<glm::vec2> contacts;
  for (glm::vec2 p : contact_raw) contacts.push_back(p + shift);

  // (3) Directions and lengths. Chains first; a foot points at its contact point.
  b.next.assign(static_cast<size_t>(b.n), -1);
  b.dir.assign(static_cast<size_t>(b.n), glm::vec2(0.0f));
  b.length.assign(static_cast<size_t>(b.n), 0.0f);
  auto aim = [&](int bone, glm::vec2 to) {
    const glm::vec2 d = to - b.joint[static_cast<size_t>(bone)];
    const float len = glm::length(d);
    if (len < min_len) return false;
    b.dir[static_cast<size_t>(bone)] = d / len;
    b.length[static_cast<size_t>(bone)] = len;
    return true;
  };
  auto link = [&](int bone, int to) {
    if (aim(bone, b.joint[static_cast<size_t>(to)])) b.next[static_cast<size_t>(bone)] = to;
  };
  {
    std::vector<int> body = {root};
    body.insert(body.end(), spine.begin(), spine.end());
    body.insert(body.end(), neck.begin(), neck.end());
    if (head >= 0) body.push_back(head);
    for (size_t i = 0; i + 1 < body.size(); ++i) link(body[i], body[i + 1]);
    for (size_t i = 0; i + 1 < tail.size(); ++i) link(tail[i], tail[i + 1]);
  }
  for (int kind = 0; kind < 2; ++kind) {
    const std::vector<Chain>& chains = kind == 0 ? legs : arms;
    for (size_t i = 0; i < chains.size(); ++i) {
      const Chain& c = chains[i];
      const std::array<const char*, 3> keys = {"upper", "lower", c.end_key};
      for (int k = 0; k < 2; ++k) {
        if (!aim(c.bones[k], b.joint[static_cast<size_t>(c.bones[k + 1])])) {
          return b.err(json_path(c.path, keys[static_cast<size_t>(k)]),
                       "bone " + quoted(sk.bones[static_cast<size_t>(c.bones[k])].name) + " has no length: " +
                           quoted(sk.bones[static_cast<size_t>(c.bones[k + 1])].name) +
                           " starts where it starts (a limb needs an upper and a lower bone of some length)");
        }
        b.next[static_cast<size_t>(c.bones[k])] = c.bones[k + 1];
      }
      if (kind == 0 && !aim(c.bones[2], contacts[i])) {
        return b.err(json_path(c.path, "contact"), "the contact point of foot " + quoted(map.legs[i].end) +
                                                       " is at its ankle: expected a point on the sole, away from the ankle");
      }
    }
  }
  // Any other bone: its first child with some length, a leaf along its parent.
  for (int i = 0; i < b.n; ++i) {
    if (b.length[static_cast<size_t>(i)] > 0.0f) continue;
    for (int j = i + 1; j < b.n; ++j) {
      if (sk.bones[static_cast<size_t>(j)].parent == i && aim(i, b.joint[static_cast<size_t>(j)])) break;
    }
  }
  for (int i = 0; i < b.n; ++i) {
    const size_t u = static_cast<size_t>(i);
    if (b.length[u] > 0.0f) continue;
    const int p = sk.bones[u].parent;
    glm::vec2 d = p >= 0 && b.length[static_cast<size_t>(p)] > 0.0f ? b.dir[static_cast<size_t>(p)] : glm::vec2(0.0f, 1.0f);
    float len = p >= 0 ? 0.1f * b.length[static_cast<size_t>(p)] : 0.0f;
    const ImportedBone& bone = sk.bones[u];
    if (bone.has_extent()) {
      // Towards the middle of what it moves (a dog's head points at its snout, a hand down).
      const glm::vec2 to_middle = b.s.apply(0.5f * (bone.extent_min + bone.extent_max)) - b.joint[u];
      if (glm::length(to_middle) > min_len) d = glm::normalize(to_middle);
      float reach = 0.0f;
      for (glm::vec2 c : {bone.extent_min, bone.extent_max, glm::vec2(bone.extent_min.x, bone.extent_max.y),
                          glm::vec2(bone.extent_max.x, bone.extent_min.y)}) {
        reach = std::max(reach, glm::dot(b.s.apply(c) - b.joint[u], d));
      }
      if (reach > min_len) len = reach;
    }
    b.dir[u] = d;
    b.length[u] = std::max(len, min_len);
  }
  // Widths (the strobe's strokes): the vertices' extent across the bone.
  b.width.assign(static_cast<size_t>(b.n), 0.0f);
  for (int i = 0; i < b.n; ++i) {
    const size_t u = static_cast<size_t>(i);
    const ImportedBone& bone = sk.bones[u];
    float w = 0.2f * b.length[u];
    if (bone.has_extent()) {
      const glm::vec2 across(-b.dir[u].y, b.dir[u].x);
      float a = 1e30f, z = -1e30f;
      for (glm::vec2 c : {bone.extent_min, bone.extent_max, glm::vec2(bone.extent_min.x, bone.extent_max.y),
                          glm::vec2(bone.extent_max.x, bone.extent_min.y)}) {
        const float t = glm::dot(b.s.apply(c) - b.joint[u], across);
        a = std::min(a, t);
        z = std::max(z, t);
      }
      w = std::clamp(z - a, 0.05f * b.length[u], 2.0f * b.length[u]);
    }
    b.width[u] = std::max(w, min_len);
  }

  // (4) The rest pose must be able to walk.
  Character ch;
  std::vector<int> bend(legs.size(), 1);
  for (size_t i = 0; i < legs.size(); ++i) {
    const Chain& c = legs[i];
    const glm::vec2 hip = b.joint[static_cast<size_t>(c.bones[0])];
    const glm::vec2 knee = b.joint[static_cast<size_t>(c.bones[1])];
    const glm::vec2 ankle = b.joint[static_cast<size_t>(c.bones[2])];
    const float reach = b.length[static_cast<size_t>(c.bones[0])] + b.length[static_cast<size_t>(c.bones[1])];
    if (!(contacts[i].y < hip.y - min_len) || !(ankle.y < hip.y)) {
      char what[200];
      std::snprintf(what, sizeof what, "foot %s is not below its hip in the rest pose (contact y %.3f m, ankle y %.3f m, hip y %.3f m): a leg must hang down",
                    quoted(map.legs[i].end).c_str(), contacts[i].y, ankle.y, hip.y);
      return b.err(json_path(c.path, "foot"), what);
    }
    const glm::vec2 u = ankle - hip, v = knee - hip;
    const float cross = u.x * v.y - u.y * v.x;
    if (std::fabs(cross) <= kStraightOfReach * reach * glm::length(u)) {
      bend[i] = map.legs[i].knee;
    } else {
      bend[i] = cross > 0.0f ? 1 : -1;
    }
    if (Status st = check_leg_size(c.path, map.legs[i].end, ankle, contacts[i], reach, file, ch.warnings); !st.ok()) {
      return st.error();
    }
    const float hip_h = hip.y;
    if (contacts[i].y > kFloatingOfHip * hip_h) {
      char what[160];
      std::snprintf(what, sizeof what, "%s: foot %s stands %.3f m above the ground in the rest pose", c.path.c_str(),
                    quoted(map.legs[i].end).c_str(), contacts[i].y);
      ch.warnings.push_back(what);
    }
  }

  check_leg_pairs(map, ch.warnings);

  // (5) The ossa skeleton: root first, then the mesh order; a bone outside the root's subtree
  // (or above it) hangs from the root.
  std::vector<int> order = {root};
  for (int i = 0; i < b.n; ++i) {
    if (i != root) order.push_back(i);
  }
  std::vector<int> ossa_of(static_cast<size_t>(b.n), -1);
  for (size_t k = 0; k < order.size(); ++k) ossa_of[static_cast<size_t>(order[k])] = static_cast<int>(k);
  std::vector<BoneKind> kind(static_cast<size_t>(b.n), BoneKind::kRib);
  std::vector<Layer> layer(static_cast<size_t>(b.n), Layer::kBody);
  kind[static_cast<size_t>(root)] = BoneKind::kRoot;
  for (int v : spine) kind[static_cast<size_t>(v)] = BoneKind::kBackVertebra;
  for (int v : neck) kind[static_cast<size_t>(v)] = BoneKind::kNeckVertebra;
  for (int v : tail) kind[static_cast<size_t>(v)] = BoneKind::kTailVertebra;
  if (head >= 0) kind[static_cast<size_t>(head)] = BoneKind::kSkull;
  for (int k = 0; k < 2; ++k) {
    const std::vector<Chain>& chains = k == 0 ? legs : arms;
    const std::vector<RigChain>& rcs = k == 0 ? map.legs : map.arms;
    for (size_t i = 0; i < chains.size(); ++i) {
      const int girdle = sk.bones[static_cast<size_t>(chains[i].bones[0])].parent;
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
  for (int m : order) {
    const size_t u = static_cast<size_t>(m);
    const int mp = sk.bones[u].parent;
    const int parent = m == root ? -1 : (mp >= 0 && b.descends(mp, root) ? mp : root);
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
    ch.skeleton.add_bone(sk.bones[u].name, kind[u], parent < 0 ? kNoParent : ossa_of[static_cast<size_t>(parent)], b.length[u],
                         b.width[u], local, layer[u]);
  }
  // The binding, from the rest pose as FK gives it (so palettes are the identity at rest).
  const std::vector<Mat2x3> ossa_rest = model_matrices(ch.skeleton, ch.skeleton.rest_locals());
  for (size_t k = 0; k < order.size(); ++k) {
    const int m = order[k];
    ch.mesh_bone.push_back(m);
    ch.to_mesh.push_back(inverse(ossa_rest[k]) * b.s * sk.bones[static_cast<size_t>(m)].rest_ms);
  }
  ch.mesh_to_model = b.s;
  ch.contacts_ms = contacts;

  // (5b) The standing pose: legs straight in the rest pose (a character modelled standing
  // tall) could not stand there, as stance legs stop short of full reach (kReachLimit); the
  // body lowers until every leg's hip is within kStandOfReach of its reach of its ankle, the
  // knees bend their way, ankles and feet stay.
  auto o = [&](int mesh) { return ossa_of[static_cast<size_t>(mesh)]; };
  ch.rest_pose = Pose::rest(ch.skeleton);
  float lower = 0.0f;
  for (const Chain& c : legs) {
    const float reach = b.length[static_cast<size_t>(c.bones[0])] + b.length[static_cast<size_t>(c.bones[1])];
    const glm::vec2 hip = b.joint[static_cast<size_t>(c.bones[0])], ankle = b.joint[static_cast<size_t>(c.bones[2])];
    const float h = hip.y - ankle.y, want = kStandOfReach * reach;
    const float dx = hip.x - ankle.x;
    if (want > std::fabs(dx)) lower = std::max(lower, h - std::sqrt(want * want - dx * dx));
  }
  if (lower > 0.0f) {
    ch.rest_pose.locals[0].offset_ls.y -= lower;
    const std::vector<Mat2x3> body = model_matrices(ch.skeleton, ch.rest_pose.locals);
    for (size_t i = 0; i < legs.size(); ++i) {
      const Chain& c = legs[i];
      const int up = o(c.bones[0]), lo = o(c.bones[1]), ft = o(c.bones[2]);
      const int girdle = ch.skeleton.parent(up);
      const glm::vec2 hip = bone_start(body[static_cast<size_t>(up)]);
      const glm::vec2 ankle = b.joint[static_cast<size_t>(c.bones[2])];
      const TwoBoneIkResult ik = solve_two_bone_ik(hip, ch.skeleton.length(up), ch.skeleton.length(lo), ankle, static_cast<float>(bend[i]));
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

  // (6) Roles and the rig.
  RigRoles& roles = ch.roles;
  roles.root = 0;
  roles.skull = head >= 0 ? o(head) : -1;
  for (auto it = spine.rbegin(); it != spine.rend(); ++it) roles.back.push_back(o(*it));
  for (auto it = neck.rbegin(); it != neck.rend(); ++it) roles.neck.push_back(o(*it));
  for (int v : tail) roles.tail.push_back(o(v));
  roles.flat_contact = false;
  for (size_t i = 0; i < legs.size(); ++i) {
    const Chain& c = legs[i];
    roles.limbs.push_back({LimbKind::kLeg, o(sk.bones[static_cast<size_t>(c.bones[0])].parent),
                           {o(c.bones[0]), o(c.bones[1]), o(c.bones[2])}, map.legs[i].side, bend[i], map.leg_pair(i)});
  }
  for (size_t i = 0; i < arms.size(); ++i) {
    const Chain& c = arms[i];
    const int girdle_mesh = sk.bones[static_cast<size_t>(c.bones[0])].parent;
    roles.limbs.push_back({LimbKind::kArm, o(girdle_mesh), {o(c.bones[0]), o(c.bones[1]), o(c.bones[2])}, map.arms[i].side, 1, 0});
  }
  ch.rig = build_anim_rig(ch.skeleton, ch.rest_pose, roles);
  ch.name = character_name(file);
  ch.rig_path = file;
  ch.mapping = map;
  return ch;
}

}  // namespace ossa
