// Fuzzes the rig mapping loader and the character builder behind it (DESIGN.md §11: no input
// file, however malformed, may crash): any input gives an error naming the file, or a mapping
// that builds against a fixed skeleton (with the shipped humanoid's and dog's bone names) or
// fails with an error naming the file; a character that builds walks a second with finite poses.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "ossa/anim/animator.h"
#include "ossa/rig/character.h"
#include "ossa/rig/rig_mapping.h"

namespace {

// The humanoid's bones and the dog's (ossa-make-character), standing, frames along +x.
const ossa::ImportedSkeleton& skeleton() {
  static const ossa::ImportedSkeleton s = [] {
    ossa::ImportedSkeleton k;
    k.source = "fuzz.gltf";
    auto add = [&](const char* name, const char* parent, float x, float y, float angle) {
      ossa::ImportedBone b;
      b.name = name;
      b.parent = parent ? k.find(parent) : -1;
      b.rest_mesh.m[0] = std::cos(angle), b.rest_mesh.m[1] = std::sin(angle);
      b.rest_mesh.m[2] = -std::sin(angle), b.rest_mesh.m[3] = std::cos(angle);
      b.rest_mesh.m[4] = x, b.rest_mesh.m[5] = y;
      b.extent_min = {x - 0.05f, y - 0.1f};
      b.extent_max = {x + 0.1f, y + 0.05f};
      k.bones.push_back(b);
    };
    const float up = 1.5708f, down = -1.5708f;
    add("pelvis", nullptr, 0.0f, 0.95f, up);
    add("spine", "pelvis", 0.0f, 1.07f, up);
    add("chest", "spine", 0.0f, 1.27f, up);
    add("neck", "chest", 0.01f, 1.47f, up);
    add("head", "neck", 0.01f, 1.55f, up);
    add("tail_1", "pelvis", -0.1f, 0.95f, 2.6f);
    add("tail_2", "tail_1", -0.2f, 1.0f, 2.6f);
    add("tail_3", "tail_2", -0.3f, 1.05f, 2.6f);
    for (const char* s : {"_l", "_r"}) {
      auto n = [&](const char* stem) { static thread_local std::string t; t = std::string(stem) + s; return t; };
      const std::string thigh = n("thigh"), shin = n("shin"), foot = n("foot"), ua = n("upper_arm"), la = n("lower_arm"),
                        hand = n("hand"), hp = n("hind_paw"), fa = n("forearm"), fp = n("front_paw");
      add(thigh.c_str(), "pelvis", 0.0f, 0.95f, down);
      add(shin.c_str(), thigh.c_str(), 0.0f, 0.5f, down);
      add(foot.c_str(), shin.c_str(), 0.0f, 0.08f, 0.0f);
      add(ua.c_str(), "chest", 0.0f, 1.42f, down);
      add(la.c_str(), ua.c_str(), 0.0f, 1.15f, down);
      add(hand.c_str(), la.c_str(), 0.0f, 0.9f, down);
      add(hp.c_str(), shin.c_str(), 0.02f, 0.1f, -1.2f);
      add(fa.c_str(), ua.c_str(), 0.05f, 1.1f, down);
      add(fp.c_str(), fa.c_str(), 0.05f, 0.08f, -0.9f);
    }
    return k;
  }();
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ossa::Result<ossa::RigMapping> m = ossa::parse_rig_mapping(text, "fuzz.rig.json");
  if (!m.ok()) {
    if (m.message().rfind("fuzz.rig.json", 0) != 0) std::abort();
    return 0;
  }
  ossa::Result<ossa::Character> c = ossa::build_character(skeleton(), *m, "fuzz.rig.json");
  if (!c.ok()) {
    if (c.message().rfind("fuzz.rig.json", 0) != 0) std::abort();
    return 0;
  }
  if (!c->skeleton.is_valid()) std::abort();
  const ossa::Level flat({ossa::Box::from_corner(-50.0f, -1.0f, 100.0f, 1.0f)});
  ossa::Animator a(c->rig, ossa::SplinePrototypes::defaults());
  a.reset({0.0f, 1.0f}, flat);
  for (int i = 0; i < 120; ++i) a.update(1.0f / 120.0f, i < 60 ? 1.0f : -2.0f, flat);
  for (const ossa::Mat2x3& w : a.world_matrices()) {
    for (float v : w.m) {
      if (!std::isfinite(v)) std::abort();
    }
  }
  return 0;
}
