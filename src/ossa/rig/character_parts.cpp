// build_character's phases (1) to (3): the mapped parts, the joints in ossa model space, each
// bone's direction, length and width (character_internal.h).

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "ossa/io/json.h"
#include "ossa/rig/character_internal.h"

namespace ossa::character_build {

namespace {

// A bone shorter than this fraction of the character's size has no length.
constexpr float kMinBoneOfSize = 1e-4f;

bool finite(const Mat2x3& m) {
  for (float v : m.m) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

float det(const Mat2x3& m) { return m.m[0] * m.m[3] - m.m[1] * m.m[2]; }

Result<int> find_bone(const Builder& b, const std::string& field, const std::string& name) {
  const int i = b.in.find(name);
  if (i < 0) return b.err(field, "bone " + quoted(name) + " is not in " + b.in.source);
  return i;
}

}  // namespace

Status check_bones(const Builder& b) {
  if (b.n == 0) return b.err("", b.in.source + " has no bones");
  if (b.n > 255) return b.err("", b.in.source + " has " + std::to_string(b.n) + " bones; at most 255 animate");
  for (int i = 0; i < b.n; ++i) {
    const ImportedBone& bone = b.in.bones[static_cast<size_t>(i)];
    if (bone.parent >= i || bone.parent < -1) return b.err("", b.in.source + ": bone " + quoted(bone.name) + ": its parent comes after it");
    if (!finite(bone.rest_mesh) || std::fabs(det(bone.rest_mesh)) < 1e-12f) {
      return b.err("", b.in.source + ": bone " + quoted(bone.name) + ": its rest transform is not finite or not invertible");
    }
    if (b.in.find(bone.name) != i) return b.err("", b.in.source + ": two bones are named " + quoted(bone.name));
  }
  return {};
}

Status find_parts(Builder& b) {
  // (1) Every mapped bone, and the chains.
  auto look = [&](const std::string& field, const std::string& name, int* out) -> Status {
    Result<int> r = find_bone(b, field, name);
    if (!r.ok()) return r.error();
    *out = *r;
    return {};
  };
  if (Status s = look("root", b.map.root, &b.root); !s.ok()) return s;
  if (!b.map.head.empty()) {
    if (Status s = look("head", b.map.head, &b.head); !s.ok()) return s;
  }
  auto list = [&](const char* key, const std::vector<std::string>& names, std::vector<int>* out) -> Status {
    for (size_t i = 0; i < names.size(); ++i) {
      int v = -1;
      if (Status s = look(json_path(key, i), names[i], &v); !s.ok()) return s;
      out->push_back(v);
    }
    return {};
  };
  if (Status s = list("spine", b.map.spine, &b.spine); !s.ok()) return s;
  if (Status s = list("neck", b.map.neck, &b.neck); !s.ok()) return s;
  if (Status s = list("tail", b.map.tail, &b.tail); !s.ok()) return s;
  for (int kind = 0; kind < 2; ++kind) {
    const std::vector<RigChain>& chains = kind == 0 ? b.map.legs : b.map.arms;
    const char* key = kind == 0 ? "legs" : "arms";
    const char* end_key = kind == 0 ? "foot" : "hand";
    for (size_t i = 0; i < chains.size(); ++i) {
      Chain c{{}, json_path(key, i), end_key};
      const RigChain& rc = chains[i];
      if (Status s = look(json_path(c.path, "upper"), rc.upper, &c.bones[0]); !s.ok()) return s;
      if (Status s = look(json_path(c.path, "lower"), rc.lower, &c.bones[1]); !s.ok()) return s;
      if (Status s = look(json_path(c.path, end_key), rc.end, &c.bones[2]); !s.ok()) return s;
      if (b.in.bones[static_cast<size_t>(c.bones[1])].parent != c.bones[0]) {
        return b.err(json_path(c.path, "lower"), "bone " + quoted(rc.lower) + " is not a child of " + quoted(rc.upper) +
                                                     " (a limb is a chain upper → lower → " + end_key + ")");
      }
      if (b.in.bones[static_cast<size_t>(c.bones[2])].parent != c.bones[1]) {
        return b.err(json_path(c.path, end_key), "bone " + quoted(rc.end) + " is not a child of " + quoted(rc.lower) +
                                                     " (a limb is a chain upper → lower → " + end_key + ")");
      }
      if (b.in.bones[static_cast<size_t>(c.bones[0])].parent < 0) {
        return b.err(json_path(c.path, "upper"), "bone " + quoted(rc.upper) + " hangs from nothing (a limb hangs from the body)");
      }
      (kind == 0 ? b.legs : b.arms).push_back(c);
    }
  }
  // Everything hangs from the root, and the spine parts follow each other.
  auto hangs = [&](const std::string& field, int bone, int from, const std::string& from_name) -> Status {
    if (bone == from || !b.descends(bone, from)) {
      return b.err(field, "bone " + quoted(b.in.bones[static_cast<size_t>(bone)].name) + " does not hang from " + quoted(from_name));
    }
    return {};
  };
  {
    int prev = b.root;
    std::string prev_name = b.map.root;
    auto follow = [&](const char* key, const std::vector<int>& bones, const std::vector<std::string>& names) -> Status {
      for (size_t i = 0; i < bones.size(); ++i) {
        if (Status s = hangs(json_path(key, i), bones[i], prev, prev_name); !s.ok()) return s;
        prev = bones[i];
        prev_name = names[i];
      }
      return {};
    };
    if (Status s = follow("spine", b.spine, b.map.spine); !s.ok()) return s;
    if (Status s = follow("neck", b.neck, b.map.neck); !s.ok()) return s;
    if (b.head >= 0) {
      if (Status s = hangs("head", b.head, prev, prev_name); !s.ok()) return s;
    }
    if (!b.tail.empty()) {
      if (Status s = hangs(json_path("tail", 0), b.tail[0], b.root, b.map.root); !s.ok()) return s;
      for (size_t i = 1; i < b.tail.size(); ++i) {
        if (Status s = hangs(json_path("tail", i), b.tail[i], b.tail[i - 1], b.map.tail[i - 1]); !s.ok()) return s;
      }
    }
    for (const std::vector<Chain>* chains : {&b.legs, &b.arms}) {
      for (const Chain& c : *chains) {
        if (Status s = hangs(json_path(c.path, "upper"), c.bones[0], b.root, b.map.root); !s.ok()) return s;
      }
    }
  }
  return {};
}

Status place_joints(Builder& b) {
  // (2) Joints in ossa model space: scaled, the root at x = 0, the lowest contact at y = 0.
  std::vector<glm::vec2> raw(static_cast<size_t>(b.n));
  for (int i = 0; i < b.n; ++i) raw[static_cast<size_t>(i)] = b.map.scale * bone_start(b.in.bones[static_cast<size_t>(i)].rest_mesh);
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (glm::vec2 p : raw) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  b.size = std::max(std::max(hi.x - lo.x, hi.y - lo.y), 1e-3f);
  b.min_len = kMinBoneOfSize * b.size;
  std::vector<glm::vec2> contact_raw;
  for (size_t i = 0; i < b.legs.size(); ++i) {
    const Chain& c = b.legs[i];
    const RigChain& rc = b.map.legs[i];
    const ImportedBone& foot = b.in.bones[static_cast<size_t>(c.bones[2])];
    glm::vec2 p;
    if (rc.contact) {
      p = b.map.scale * *rc.contact;
    } else if (foot.has_extent()) {
      p = b.map.scale * glm::vec2(foot.extent_max.x, foot.extent_min.y);  // the lowest front point
    } else {
      int child = -1;
      for (int j = c.bones[2] + 1; j < b.n && child < 0; ++j) {
        if (b.in.bones[static_cast<size_t>(j)].parent == c.bones[2]) child = j;
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
  const glm::vec2 shift(-raw[static_cast<size_t>(b.root)].x, -ground);
  b.s = Mat2x3{};
  b.s.m[0] = b.s.m[3] = b.map.scale;
  b.s.m[4] = shift.x;
  b.s.m[5] = shift.y;
  b.joint.resize(static_cast<size_t>(b.n));
  for (int i = 0; i < b.n; ++i) b.joint[static_cast<size_t>(i)] = raw[static_cast<size_t>(i)] + shift;
  for (glm::vec2 p : contact_raw) b.contacts.push_back(p + shift);
  return {};
}

Status aim_bones(Builder& b) {
  // (3) Directions and lengths. Chains first; a foot points at its contact point.
  b.next.assign(static_cast<size_t>(b.n), -1);
  b.dir.assign(static_cast<size_t>(b.n), glm::vec2(0.0f));
  b.length.assign(static_cast<size_t>(b.n), 0.0f);
  auto aim = [&](int bone, glm::vec2 to) {
    const glm::vec2 d = to - b.joint[static_cast<size_t>(bone)];
    const float len = glm::length(d);
    if (len < b.min_len) return false;
    b.dir[static_cast<size_t>(bone)] = d / len;
    b.length[static_cast<size_t>(bone)] = len;
    return true;
  };
  auto link = [&](int bone, int to) {
    if (aim(bone, b.joint[static_cast<size_t>(to)])) b.next[static_cast<size_t>(bone)] = to;
  };
  {
    std::vector<int> body = {b.root};
    body.insert(body.end(), b.spine.begin(), b.spine.end());
    body.insert(body.end(), b.neck.begin(), b.neck.end());
    if (b.head >= 0) body.push_back(b.head);
    for (size_t i = 0; i + 1 < body.size(); ++i) link(body[i], body[i + 1]);
    for (size_t i = 0; i + 1 < b.tail.size(); ++i) link(b.tail[i], b.tail[i + 1]);
  }
  for (int kind = 0; kind < 2; ++kind) {
    const std::vector<Chain>& chains = kind == 0 ? b.legs : b.arms;
    for (size_t i = 0; i < chains.size(); ++i) {
      const Chain& c = chains[i];
      const std::array<const char*, 3> keys = {"upper", "lower", c.end_key};
      for (int k = 0; k < 2; ++k) {
        if (!aim(c.bones[k], b.joint[static_cast<size_t>(c.bones[k + 1])])) {
          return b.err(json_path(c.path, keys[static_cast<size_t>(k)]),
                       "bone " + quoted(b.in.bones[static_cast<size_t>(c.bones[k])].name) + " has no length: " +
                           quoted(b.in.bones[static_cast<size_t>(c.bones[k + 1])].name) +
                           " starts where it starts (a limb needs an upper and a lower bone of some length)");
        }
        b.next[static_cast<size_t>(c.bones[k])] = c.bones[k + 1];
      }
      if (kind == 0 && !aim(c.bones[2], b.contacts[i])) {
        return b.err(json_path(c.path, "contact"), "the contact point of foot " + quoted(b.map.legs[i].end) +
                                                       " is at its ankle: expected a point on the sole, away from the ankle");
      }
    }
  }
  // Any other bone: its first child with some length, a leaf along its parent.
  for (int i = 0; i < b.n; ++i) {
    if (b.length[static_cast<size_t>(i)] > 0.0f) continue;
    for (int j = i + 1; j < b.n; ++j) {
      if (b.in.bones[static_cast<size_t>(j)].parent == i && aim(i, b.joint[static_cast<size_t>(j)])) break;
    }
  }
  for (int i = 0; i < b.n; ++i) {
    const size_t u = static_cast<size_t>(i);
    if (b.length[u] > 0.0f) continue;
    const int p = b.in.bones[u].parent;
    glm::vec2 d = p >= 0 && b.length[static_cast<size_t>(p)] > 0.0f ? b.dir[static_cast<size_t>(p)] : glm::vec2(0.0f, 1.0f);
    float len = p >= 0 ? 0.1f * b.length[static_cast<size_t>(p)] : 0.0f;
    const ImportedBone& bone = b.in.bones[u];
    if (bone.has_extent()) {
      // Towards the middle of what it moves (a dog's head points at its snout, a hand down).
      const glm::vec2 to_middle = b.s.apply(0.5f * (bone.extent_min + bone.extent_max)) - b.joint[u];
      if (glm::length(to_middle) > b.min_len) d = glm::normalize(to_middle);
      float reach = 0.0f;
      for (glm::vec2 c : {bone.extent_min, bone.extent_max, glm::vec2(bone.extent_min.x, bone.extent_max.y),
                          glm::vec2(bone.extent_max.x, bone.extent_min.y)}) {
        reach = std::max(reach, glm::dot(b.s.apply(c) - b.joint[u], d));
      }
      if (reach > b.min_len) len = reach;
    }
    b.dir[u] = d;
    b.length[u] = std::max(len, b.min_len);
  }
  // Widths (the strobe's strokes): the vertices' extent across the bone.
  b.width.assign(static_cast<size_t>(b.n), 0.0f);
  for (int i = 0; i < b.n; ++i) {
    const size_t u = static_cast<size_t>(i);
    const ImportedBone& bone = b.in.bones[u];
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
    b.width[u] = std::max(w, b.min_len);
  }
  return {};
}

}  // namespace ossa::character_build
