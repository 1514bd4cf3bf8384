#pragma once
// What ossa-make-character draws and exports, per character (humanoid.cpp, dog.cpp): bones in
// the rest pose, body parts (strips of quads over rectangles, drawn with signed distance
// shapes) and the rig mapping. main.cpp packs, draws and exports any CharacterDef.

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "ossa/io/json.h"
#include "ossa/math/transform2d.h"

namespace make_character {

using glm::vec2;
using glm::vec3;
using ossa::Json;
using ossa::Mat2x3;
constexpr float kPi = 3.14159265358979f;

// ---- Skeleton -------------------------------------------------------------------------------

struct BoneDef {
  std::string name;
  std::string parent;  // empty for the root
  vec2 head;           // joint position in model space, rest pose (metres)
  float angle;         // direction of the bone in model space, radians
};

// A rotation by `angle` about `pivot` (model space).
inline Mat2x3 rotation_about(vec2 pivot, float angle) {
  Mat2x3 m;
  const float c = std::cos(angle), s = std::sin(angle);
  m.m[0] = c, m.m[1] = s, m.m[2] = -s, m.m[3] = c;
  m.m[4] = pivot.x - (c * pivot.x - s * pivot.y);
  m.m[5] = pivot.y - (s * pivot.x + c * pivot.y);
  return m;
}
inline Mat2x3 translation(vec2 d) {
  Mat2x3 m;
  m.m[4] = d.x, m.m[5] = d.y;
  return m;
}
inline float rotation_of(const Mat2x3& m) { return std::atan2(m.m[1], m.m[0]); }
// A bone moved by a placement (a far limb turned about its hip).
inline BoneDef placed(BoneDef b, const Mat2x3& place) {
  b.head = place.apply(b.head);
  b.angle += rotation_of(place);
  return b;
}

// ---- Drawing: signed distance shapes in model space (metres; < 0 inside) ----------------------

using Sdf = std::function<float(vec2)>;

inline Sdf capsule(vec2 a, vec2 b, float ra, float rb) {
  return [=](vec2 p) {
    const vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab)) - (ra + (rb - ra) * t);
  };
}
inline Sdf circle(vec2 c, float r) { return [=](vec2 p) { return glm::length(p - c) - r; }; }
inline Sdf ellipse(vec2 c, float rx, float ry) {
  return [=](vec2 p) {
    const vec2 q = (p - c) / vec2(rx, ry);
    return (glm::length(q) - 1.0f) * std::min(rx, ry);
  };
}
// An ellipse turned by `angle` about its centre.
inline Sdf ellipse_turned(vec2 c, float rx, float ry, float angle) {
  const float co = std::cos(angle), si = std::sin(angle);
  return [=](vec2 p) {
    const vec2 d = p - c;
    const vec2 l(co * d.x + si * d.y, -si * d.x + co * d.y);
    const vec2 q = l / vec2(rx, ry);
    return (glm::length(q) - 1.0f) * std::min(rx, ry);
  };
}
inline Sdf rounded_box(vec2 lo, vec2 hi, float r) {
  return [=](vec2 p) {
    const vec2 c = 0.5f * (lo + hi), h = 0.5f * (hi - lo) - vec2(r);
    const vec2 d = glm::abs(p - c) - h;
    return glm::length(glm::max(d, vec2(0.0f))) + std::min(std::max(d.x, d.y), 0.0f) - r;
  };
}
// Keeps the part of `s` on the side of the line through p0 where n points away from.
inline Sdf clip(Sdf s, vec2 p0, vec2 n) {
  return [=](vec2 p) { return std::max(s(p), glm::dot(p - p0, glm::normalize(n))); };
}
inline Sdf unite(Sdf a, Sdf b) {
  return [=](vec2 p) { return std::min(a(p), b(p)); };
}
inline Sdf intersect(Sdf a, Sdf b) {
  return [=](vec2 p) { return std::max(a(p), b(p)); };
}

using Rgb = vec3;
inline Rgb rgb(int r, int g, int b) { return Rgb(r, g, b) / 255.0f; }
inline const Rgb kOutline = rgb(38, 30, 36);
inline const Rgb kWhite = rgb(250, 248, 240);

struct Layer {
  Sdf sdf;
  Rgb colour;
  float detail_line = 0.0f;  // metres; > 0 draws an inner outline along this shape's edge
  bool silhouette = true;    // part of the outer outline
};

// ---- Parts ------------------------------------------------------------------------------------

using W = std::vector<std::pair<std::string, float>>;

struct Row {
  float at;            // part-local y (vertical part) or x (horizontal)
  W weights;
};

struct Part {
  Part(std::string part_name, float depth, vec2 low, vec2 high, bool rows_along_x)
      : name(std::move(part_name)), z(depth), lo(low), hi(high), horizontal(rows_along_x) {}
  std::string name;
  float z;             // depth: draw order (far < body < near)
  vec2 lo, hi;         // rectangle in the part's own frame (the rest pose before `place`)
  bool horizontal;     // rows along x (a foot, a body) instead of y
  std::vector<Row> rows;
  std::vector<Layer> layers;  // drawn in the part's own frame
  bool far = false;    // drawn darker
  Mat2x3 place;        // part frame → model space (a far limb turned about its joint)
  int px = 0, py = 0, pw = 0, ph = 0;  // texture region (pixels), filled by the packer
};

struct CharacterDef {
  std::string name;              // file stem: NAME.gltf, NAME.bin, NAME.png, NAME.rig.json
  std::vector<BoneDef> bones;
  std::vector<Part> parts;
  Json rig;                      // the rig mapping (anim/rig_mapping.h), "mesh" filled in
  // Exported size: bones, vertices and contact points are multiplied by it (the drawing and
  // its texture stay as drawn).
  float scale = 1.0f;
};

CharacterDef humanoid();
CharacterDef dog();

}  // namespace make_character
