#include "ossa/rig/rig_guess.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace ossa {

namespace {

// Lower-case words of a bone name: a namespace ("mixamorig:", "Armature|") dropped, split at
// separators, camel-case humps and digits; Rigify's "DEF" deform prefix dropped.
std::vector<std::string> words(const std::string& name) {
  std::string s = name;
  for (char sep : {':', '|'}) {
    if (const size_t at = s.rfind(sep); at != std::string::npos) s = s.substr(at + 1);
  }
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) out.push_back(cur);
    cur.clear();
  };
  for (size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (!std::isalnum(c)) {
      flush();
      continue;
    }
    const bool upper = std::isupper(c), digit = std::isdigit(c);
    if (!cur.empty()) {
      const unsigned char prev = static_cast<unsigned char>(s[i - 1]);
      const bool hump = upper && std::islower(prev);
      const bool to_digit = digit != static_cast<bool>(std::isdigit(prev));
      // "ABCDef": a new word starts at the last capital before a lower-case letter.
      const bool acronym_end = upper && std::isupper(prev) && i + 1 < s.size() && std::islower(static_cast<unsigned char>(s[i + 1]));
      if (hump || to_digit || acronym_end) flush();
    }
    cur += static_cast<char>(std::tolower(c));
  }
  flush();
  if (!out.empty() && (out[0] == "def" || out[0] == "bip01" || out[0] == "bip")) out.erase(out.begin());
  return out;
}

bool has(const std::vector<std::string>& w, const char* word) { return std::find(w.begin(), w.end(), word) != w.end(); }

}  // namespace

const char* bone_role_name(BoneRole role) {
  switch (role) {
    case BoneRole::kNone: return "none";
    case BoneRole::kRoot: return "root";
    case BoneRole::kSpine: return "spine";
    case BoneRole::kNeck: return "neck";
    case BoneRole::kHead: return "head";
    case BoneRole::kTail: return "tail";
    case BoneRole::kLegUpper: return "leg upper";
    case BoneRole::kLegLower: return "leg lower";
    case BoneRole::kFoot: return "foot";
    case BoneRole::kArmUpper: return "arm upper";
    case BoneRole::kArmLower: return "arm lower";
    case BoneRole::kHand: return "hand";
  }
  return "none";
}

NamedRole role_from_name(const std::string& bone_name) {
  std::vector<std::string> w = words(bone_name);
  NamedRole r;
  std::vector<std::string> rest;
  for (const std::string& t : w) {
    if (t == "l" || t == "left" || t == "lft") {
      r.side = -1;
    } else if (t == "r" || t == "right" || t == "rt") {
      r.side = 1;
    } else {
      rest.push_back(t);
    }
  }
  std::string j;
  for (const std::string& t : rest) j += t;
  auto in = [&](const char* s) { return j.find(s) != std::string::npos; };
  r.front = has(rest, "front") || (has(rest, "fore") && !in("forearm"));
  const bool twist = has(rest, "twist") || has(rest, "roll") || has(rest, "ik") || has(rest, "pole") || has(rest, "target");
  if (twist || rest.empty()) return r;
  if (in("tail")) {
    r.role = BoneRole::kTail;
  } else if (in("head") || in("skull")) {
    r.role = BoneRole::kHead;
  } else if (in("neck")) {
    r.role = BoneRole::kNeck;
  } else if (in("forearm") || in("lowerarm") || in("radius") || in("ulna") || (in("arm") && has(rest, "lower"))) {
    r.role = BoneRole::kArmLower;
  } else if (in("upperarm") || in("uparm") || in("humerus") || (in("arm") && !in("armature"))) {
    r.role = BoneRole::kArmUpper;
  } else if (in("hand") || in("wrist")) {
    r.role = BoneRole::kHand;
  } else if (in("thigh") || in("upleg") || in("upperleg") || in("femur") || (in("leg") && has(rest, "upper"))) {
    r.role = BoneRole::kLegUpper;
  } else if (in("shin") || in("calf") || in("lowerleg") || in("tibia") || in("crus") || in("leg")) {
    r.role = BoneRole::kLegLower;
  } else if (in("foot") || in("paw") || in("hoof") || in("ankle")) {
    r.role = BoneRole::kFoot;
  } else if ((in("hip") || in("pelvis")) && r.side == 0) {
    r.role = BoneRole::kRoot;
  } else if (in("hip")) {
    r.role = BoneRole::kLegUpper;
  } else if (in("spine") || in("chest") || in("torso") || in("back") || in("abdomen") || in("ribcage") || in("waist")) {
    r.role = BoneRole::kSpine;
  }
  return r;
}

namespace {

// A limb chain found by its names: upper, lower, foot or hand.
struct Found {
  std::array<int, 3> bones;
  int side;
  bool front, arm;
};

// guess_rig_mapping's state: the bones' roles from their names, the tree, the bones already
// given a part, and the guess so far. Its steps run in the order guess_rig_mapping calls them.
struct Guesser {
  const ImportedSkeleton& sk;
  RigGuess out;
  int n = 0;
  std::vector<NamedRole> role;
  std::vector<int> depth;
  std::vector<std::vector<int>> children;
  std::vector<int> order;           // the bones, shallowest first
  std::set<int> used;
  std::vector<Found> chains;
  int root = -1;

  Guesser(const ImportedSkeleton& skeleton, const std::string& mesh) : sk(skeleton) {
    out.mapping.mesh = mesh;
    n = static_cast<int>(sk.bones.size());
    role.resize(static_cast<size_t>(n));
    depth.assign(static_cast<size_t>(n), 0);
    children.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      role[static_cast<size_t>(i)] = role_from_name(sk.bones[static_cast<size_t>(i)].name);
      const int p = sk.bones[static_cast<size_t>(i)].parent;
      if (p >= 0 && p < i) {
        depth[static_cast<size_t>(i)] = depth[static_cast<size_t>(p)] + 1;
        children[static_cast<size_t>(p)].push_back(i);
      }
    }
    order.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) order[static_cast<size_t>(i)] = i;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth[static_cast<size_t>(a)] < depth[static_cast<size_t>(b)]; });
  }

  std::string name(int b) const { return sk.bones[static_cast<size_t>(b)].name; }
  float y_of(int b) const { return bone_start(sk.bones[static_cast<size_t>(b)].rest_mesh).y; }
  bool descends(int b, int a) const {
    for (int x = b; x >= 0; x = sk.bones[static_cast<size_t>(x)].parent) {
      if (x == a) return true;
    }
    return false;
  }
  // The child of `b` that plays `want` (by name), else its only child.
  int next_in_chain(int b, BoneRole want) const {
    const std::vector<int>& c = children[static_cast<size_t>(b)];
    for (int k : c) {
      if (role[static_cast<size_t>(k)].role == want && !used.count(k)) return k;
    }
    return c.size() == 1 && !used.count(c[0]) ? c[0] : -1;
  }

  // Limb chains from their upper bones, shallowest first.
  void find_chains() {
    for (int b : order) {
      const NamedRole& r = role[static_cast<size_t>(b)];
      const bool leg = r.role == BoneRole::kLegUpper, arm = r.role == BoneRole::kArmUpper;
      if ((!leg && !arm) || used.count(b)) continue;
      const int lower = next_in_chain(b, leg ? BoneRole::kLegLower : BoneRole::kArmLower);
      if (lower < 0) continue;
      used.insert(lower);
      const int end = next_in_chain(lower, leg ? BoneRole::kFoot : BoneRole::kHand);
      if (end < 0) {
        used.erase(lower);
        continue;
      }
      used.insert(b);
      used.insert(end);
      chains.push_back({{b, lower, end}, r.side, r.front, arm});
    }
  }

  // Arms whose hand reaches the ground are front legs.
  void arms_to_the_ground() {
    float ground = 1e30f, hip = -1e30f;
    for (const Found& f : chains) {
      if (f.arm) continue;
      ground = std::min(ground, y_of(f.bones[2]));
      hip = std::max(hip, y_of(f.bones[0]));
    }
    for (Found& f : chains) {
      if (!f.arm || ground > 1e29f) continue;
      if (y_of(f.bones[2]) <= ground + 0.3f * (hip - ground)) {
        f.arm = false;
        f.front = true;
        out.notes.push_back("arm " + name(f.bones[0]) + " reaches the ground: a front leg");
      }
    }
  }

  // Legs in pairs (hind, then front), near (left) first; arms near first.
  void write_limbs() {
    RigMapping& m = out.mapping;
    auto side_order = [](const Found& a, const Found& b) { return a.side < b.side; };
    std::vector<Found> hind, front, arms;
    for (const Found& f : chains) (f.arm ? arms : f.front ? front : hind).push_back(f);
    std::stable_sort(hind.begin(), hind.end(), side_order);
    std::stable_sort(front.begin(), front.end(), side_order);
    std::stable_sort(arms.begin(), arms.end(), side_order);
    auto chain = [&](const Found& f) {
      RigChain c;
      c.side = f.side > 0 ? Side::kFar : Side::kNear;
      c.upper = name(f.bones[0]);
      c.lower = name(f.bones[1]);
      c.end = name(f.bones[2]);
      return c;
    };
    int pair = 0;
    for (const std::vector<Found>* group : {&hind, &front}) {
      for (size_t k = 0; k < group->size(); ++k) {
        const Found& f = (*group)[k];
        RigChain c = chain(f);
        c.pair = pair + static_cast<int>(k / 2);
        const ImportedBone& foot = sk.bones[static_cast<size_t>(f.bones[2])];
        if (foot.has_extent()) c.contact = glm::vec2(foot.extent_max.x, foot.extent_min.y);
        m.legs.push_back(c);
      }
      pair += static_cast<int>((group->size() + 1) / 2);
    }
    // A mapping of pairs listed in order needs no explicit pair numbers.
    bool listed_in_pairs = true;
    for (size_t i = 0; i < m.legs.size(); ++i) listed_in_pairs = listed_in_pairs && m.legs[i].pair == static_cast<int>(i / 2);
    if (listed_in_pairs) {
      for (RigChain& c : m.legs) c.pair = -1;
    }
    for (const Found& f : arms) m.arms.push_back(chain(f));
    if (m.legs.empty()) out.notes.push_back("no leg found (a chain named thigh/upleg → shin/calf/leg → foot/paw): assign one");
  }

  // The root: the shallowest bone named pelvis / hips; else the bone every leg hangs from.
  // False when the skeleton has no bones.
  bool find_root() {
    for (int b : order) {
      if (role[static_cast<size_t>(b)].role == BoneRole::kRoot && !used.count(b)) {
        root = b;
        break;
      }
    }
    if (root < 0 && !chains.empty()) {
      root = sk.bones[static_cast<size_t>(chains[0].bones[0])].parent;
      for (const Found& f : chains) {
        while (root >= 0 && !descends(f.bones[0], root)) root = sk.bones[static_cast<size_t>(root)].parent;
      }
      if (root >= 0) out.notes.push_back("no bone named pelvis or hips: the root is " + name(root) + ", which every limb hangs from");
    }
    if (root < 0 && n > 0) root = order[0];
    if (root < 0) return false;
    out.mapping.root = name(root);
    used.insert(root);
    return true;
  }

  // Head, neck and spine: the path from the root to the head.
  void find_spine() {
    RigMapping& m = out.mapping;
    int head = -1;
    for (int b : order) {
      if (role[static_cast<size_t>(b)].role == BoneRole::kHead && !used.count(b) && descends(b, root) && b != root) {
        head = b;
        break;
      }
    }
    std::vector<int> path;
    if (head >= 0) {
      for (int b = sk.bones[static_cast<size_t>(head)].parent; b >= 0 && b != root; b = sk.bones[static_cast<size_t>(b)].parent) path.push_back(b);
      std::reverse(path.begin(), path.end());
      m.head = name(head);
      used.insert(head);
    } else {
      out.notes.push_back("no head found (a bone named head or skull): the head is not kept level");
      // The deepest spine bone under the root, and its path.
      int deepest = -1;
      for (int b : order) {
        if (role[static_cast<size_t>(b)].role == BoneRole::kSpine && descends(b, root) && b != root && !used.count(b)) deepest = b;
      }
      for (int b = deepest; b >= 0 && b != root; b = sk.bones[static_cast<size_t>(b)].parent) path.push_back(b);
      std::reverse(path.begin(), path.end());
    }
    for (int b : path) {
      if (used.count(b)) continue;
      used.insert(b);
      (role[static_cast<size_t>(b)].role == BoneRole::kNeck ? m.neck : m.spine).push_back(name(b));
    }
  }

  // Tail: the shallowest bone named tail under the root, and its tail-named children.
  void find_tail() {
    for (int b : order) {
      if (role[static_cast<size_t>(b)].role != BoneRole::kTail || used.count(b) || !descends(b, root)) continue;
      for (int t = b; t >= 0; t = next_in_chain(t, BoneRole::kTail)) {
        if (role[static_cast<size_t>(t)].role != BoneRole::kTail) break;
        out.mapping.tail.push_back(name(t));
        used.insert(t);
      }
      break;
    }
  }
};

}  // namespace

RigGuess guess_rig_mapping(const ImportedSkeleton& sk, const std::string& mesh) {
  Guesser g(sk, mesh);
  g.find_chains();
  g.arms_to_the_ground();
  g.write_limbs();
  if (!g.find_root()) return g.out;
  g.find_spine();
  g.find_tail();
  return g.out;
}

}  // namespace ossa
