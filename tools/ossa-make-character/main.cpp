// ossa-make-character — generates the shipped 2D rigged sprite character (issue "Renderer",
// item 7; [T 4.3.1]: [T]'s player is one textured sprite mesh skinned to a humanoid skeleton).
//
//   <build>/bin/ossa-make-character [--out DIR]
//
// writes DIR/humanoid.gltf (+ humanoid.bin, via Assimp's "gltf2" exporter), DIR/humanoid.png
// (the texture, drawn procedurally) and DIR/humanoid.rig.json (limb roles for the animator).
// DIR defaults to the source tree's assets/characters; commit the regenerated files.
//
// The character stands in side view, facing +x, feet on y = 0, metres. Bones point along
// their local +x. "_l" is the near side (in front of the body, z > 0), "_r" the far side
// (behind, z < 0, drawn darker). Each body part is a strip of quads over a rectangle of the
// rest pose; its texture region holds the part drawn with signed distance shapes (flat fills,
// anti-aliased, dark outlines). Limb strips blend the two bones at knees and elbows.
//
// [SECTION] Skeleton   [SECTION] Drawing   [SECTION] Parts   [SECTION] Export   [SECTION] main

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/math/transform2d.h"
#include "ossa/skeleton/pose.h"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace {

using namespace ossa;
using glm::vec2;
using glm::vec3;
constexpr float kPi = 3.14159265358979f;

// ---------------------------------------------------------------------------------------------
// [SECTION] Skeleton

struct BoneDef {
  std::string name;
  std::string parent;  // empty for the root
  vec2 head;           // joint position in model space, rest pose (metres)
  float angle;         // direction of the bone in model space, radians
};

const float kFarLegDx = -0.05f;  // far leg a little behind, far arm a little ahead, so that
const float kFarArmDx = 0.035f;  // both sides show in the rest pose

std::vector<BoneDef> skeleton() {
  const float up = kPi / 2, down = -kPi / 2;
  std::vector<BoneDef> b = {
      {"pelvis", "", {0.0f, 0.95f}, up},
      {"spine", "pelvis", {0.0f, 1.07f}, up},
      {"chest", "spine", {0.0f, 1.27f}, up},
      {"neck", "chest", {0.01f, 1.47f}, up},
      {"head", "neck", {0.01f, 1.55f}, up},
  };
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const float ax = side == 0 ? 0.0f : kFarArmDx, lx = side == 0 ? 0.0f : kFarLegDx;
    b.push_back({"upper_arm" + s, "chest", {ax, 1.42f}, down});
    b.push_back({"lower_arm" + s, "upper_arm" + s, {ax, 1.15f}, down});
    b.push_back({"hand" + s, "lower_arm" + s, {ax, 0.90f}, down});
    b.push_back({"thigh" + s, "pelvis", {lx, 0.95f}, down});
    b.push_back({"shin" + s, "thigh" + s, {lx, 0.50f}, down});
    b.push_back({"foot" + s, "shin" + s, {lx, 0.08f}, 0.0f});
  }
  return b;
}

Mat2x3 frame(const BoneDef& b) {  // bone frame → model space
  Mat2x3 m;
  m.m[0] = std::cos(b.angle);
  m.m[1] = std::sin(b.angle);
  m.m[2] = -m.m[1];
  m.m[3] = m.m[0];
  m.m[4] = b.head.x;
  m.m[5] = b.head.y;
  return m;
}

aiMatrix4x4 to_ai(const Mat2x3& m) {
  return aiMatrix4x4(m.m[0], m.m[2], 0.0f, m.m[4], m.m[1], m.m[3], 0.0f, m.m[5],
                     0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f);
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Drawing — signed distance shapes in model space (metres; < 0 inside)

using Sdf = std::function<float(vec2)>;

Sdf capsule(vec2 a, vec2 b, float ra, float rb) {
  return [=](vec2 p) {
    const vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab)) - (ra + (rb - ra) * t);
  };
}
Sdf circle(vec2 c, float r) { return [=](vec2 p) { return glm::length(p - c) - r; }; }
Sdf ellipse(vec2 c, float rx, float ry) {
  return [=](vec2 p) {
    const vec2 q = (p - c) / vec2(rx, ry);
    return (glm::length(q) - 1.0f) * std::min(rx, ry);
  };
}
Sdf rounded_box(vec2 lo, vec2 hi, float r) {
  return [=](vec2 p) {
    const vec2 c = 0.5f * (lo + hi), h = 0.5f * (hi - lo) - vec2(r);
    const vec2 d = glm::abs(p - c) - h;
    return glm::length(glm::max(d, vec2(0.0f))) + std::min(std::max(d.x, d.y), 0.0f) - r;
  };
}
// Keeps the part of `s` on the side of the line through p0 where n points away from.
Sdf clip(Sdf s, vec2 p0, vec2 n) {
  return [=](vec2 p) { return std::max(s(p), glm::dot(p - p0, glm::normalize(n))); };
}

using Rgb = vec3;
Rgb rgb(int r, int g, int b) { return Rgb(r, g, b) / 255.0f; }
const Rgb kOutline = rgb(38, 30, 36);
const Rgb kSkin = rgb(241, 194, 155), kShirt = rgb(212, 74, 62), kPants = rgb(60, 92, 158),
          kBelt = rgb(82, 54, 36), kShoe = rgb(74, 58, 50), kSole = rgb(44, 36, 34),
          kHair = rgb(112, 68, 38), kWhite = rgb(250, 248, 240), kMouth = rgb(150, 60, 60);

struct Layer {
  Sdf sdf;
  Rgb colour;
  float detail_line = 0.0f;  // metres; > 0 draws an inner outline along this shape's edge
  bool silhouette = true;    // part of the outer outline
};

// ---------------------------------------------------------------------------------------------
// [SECTION] Parts

struct Row {
  float at;                                    // model y (vertical part) or x (horizontal)
  std::vector<std::pair<std::string, float>> weights;
};

struct Part {
  std::string name;
  float z;             // depth: draw order (far < body < near)
  vec2 lo, hi;         // rectangle in the rest pose, model space
  bool horizontal;     // rows along x (the foot) instead of y
  std::vector<Row> rows;
  std::vector<Layer> layers;
  bool far = false;    // drawn darker
  int px = 0, py = 0, pw = 0, ph = 0;  // texture region (pixels), filled by the packer
};

using W = std::vector<std::pair<std::string, float>>;

std::vector<Part> parts() {
  std::vector<Part> out;
  const float ow = 0.012f;  // detail line width
  // Torso: pelvis, spine, chest and neck in one strip.
  {
    Part p{"torso", 0.0f, {-0.17f, 0.84f}, {0.17f, 1.58f}, false, {}, {}};
    p.rows = {{1.58f, W{{"neck", 0.5f}, {"head", 0.5f}}}, {1.47f, W{{"chest", 0.6f}, {"neck", 0.4f}}},
              {1.37f, W{{"chest", 1}}}, {1.27f, W{{"spine", 0.5f}, {"chest", 0.5f}}},
              {1.17f, W{{"spine", 1}}}, {1.07f, W{{"pelvis", 0.5f}, {"spine", 0.5f}}},
              {0.95f, W{{"pelvis", 1}}}, {0.84f, W{{"pelvis", 1}}}};
    p.layers = {
        {capsule({0.0f, 1.42f}, {0.015f, 1.57f}, 0.05f, 0.045f), kSkin},
        {rounded_box({-0.12f, 0.86f}, {0.12f, 1.04f}, 0.05f), kPants},
        {[](vec2 q) {  // shirt: a rounded torso, a little fuller at the chest
           const float box = rounded_box({-0.125f, 1.0f}, {0.12f, 1.46f}, 0.07f)(q);
           return std::min(box, ellipse({0.03f, 1.33f}, 0.11f, 0.11f)(q));
         },
         kShirt, ow},
        {rounded_box({-0.125f, 0.985f}, {0.125f, 1.03f}, 0.008f), kBelt, 0.008f},
        {rounded_box({0.05f, 0.992f}, {0.09f, 1.023f}, 0.005f), rgb(214, 178, 90), 0.006f, false},
    };
    out.push_back(p);
  }
  // Head.
  {
    Part p{"head", 0.05f, {-0.15f, 1.50f}, {0.18f, 1.86f}, false, {}, {}};
    p.rows = {{1.86f, W{{"head", 1}}}, {1.50f, W{{"head", 1}}}};
    p.layers = {
        {ellipse({0.015f, 1.675f}, 0.115f, 0.13f), kSkin},
        {circle({0.125f, 1.66f}, 0.026f), kSkin},                                   // nose
        {clip(ellipse({-0.005f, 1.715f}, 0.128f, 0.105f), {0.0f, 1.705f}, {0.45f, -1.0f}), kHair, ow},
        {circle({-0.015f, 1.65f}, 0.026f), kSkin, 0.01f, false},                    // ear
        {ellipse({0.072f, 1.69f}, 0.014f, 0.02f), kOutline, 0.0f, false},            // eye
        {circle({0.076f, 1.697f}, 0.005f), kWhite, 0.0f, false},
        {capsule({0.05f, 1.725f}, {0.095f, 1.73f}, 0.006f, 0.006f), kHair, 0.0f, false},  // brow
        {capsule({0.075f, 1.6f}, {0.105f, 1.607f}, 0.006f, 0.006f), kMouth, 0.0f, false},
    };
    out.push_back(p);
  }
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const bool far = side == 1;
    const float sign = far ? -1.0f : 1.0f;
    // Leg: thigh and shin in one strip, blended at the hip and the knee.
    {
      const float x = far ? kFarLegDx : 0.0f;
      Part p{"leg" + s, 0.1f * sign, {x - 0.105f, 0.04f}, {x + 0.105f, 1.03f}, false, {}, {}};
      p.far = far;
      p.rows = {{1.03f, W{{"pelvis", 0.5f}, {"thigh" + s, 0.5f}}},
                {0.93f, W{{"pelvis", 0.2f}, {"thigh" + s, 0.8f}}},
                {0.75f, W{{"thigh" + s, 1}}},
                {0.58f, W{{"thigh" + s, 0.85f}, {"shin" + s, 0.15f}}},
                {0.50f, W{{"thigh" + s, 0.5f}, {"shin" + s, 0.5f}}},
                {0.42f, W{{"thigh" + s, 0.15f}, {"shin" + s, 0.85f}}},
                {0.25f, W{{"shin" + s, 1}}},
                {0.10f, W{{"shin" + s, 0.9f}, {"foot" + s, 0.1f}}},
                {0.04f, W{{"shin" + s, 0.8f}, {"foot" + s, 0.2f}}}};
      p.layers = {
          {capsule({x, 0.5f}, {x, 0.1f}, 0.068f, 0.055f), kPants},
          {capsule({x, 0.94f}, {x, 0.5f}, 0.092f, 0.07f), kPants},
          {rounded_box({x - 0.06f, 0.06f}, {x + 0.06f, 0.13f}, 0.01f), kPants},  // cuff
      };
      out.push_back(p);
    }
    // Foot (shoe), rows along x.
    {
      const float x = far ? kFarLegDx : 0.0f;
      Part p{"foot" + s, 0.12f * sign, {x - 0.08f, -0.005f}, {x + 0.22f, 0.13f}, true, {}, {}};
      p.far = far;
      p.rows = {{x - 0.08f, W{{"foot" + s, 0.8f}, {"shin" + s, 0.2f}}},
                {x + 0.06f, W{{"foot" + s, 1}}},
                {x + 0.22f, W{{"foot" + s, 1}}}};
      p.layers = {
          {[=](vec2 q) {
             return std::min(capsule({x - 0.01f, 0.055f}, {x + 0.15f, 0.045f}, 0.05f, 0.04f)(q),
                             rounded_box({x - 0.055f, 0.04f}, {x + 0.045f, 0.115f}, 0.02f)(q));
           },
           kShoe},
          {rounded_box({x - 0.065f, 0.0f}, {x + 0.195f, 0.022f}, 0.01f), kSole, 0.006f},
          {capsule({x + 0.02f, 0.09f}, {x + 0.07f, 0.07f}, 0.005f, 0.005f), rgb(220, 210, 190),
           0.0f, false},  // lace
      };
      out.push_back(p);
    }
    // Arm: upper arm (short sleeve) and forearm, blended at the shoulder and the elbow.
    {
      const float x = far ? kFarArmDx : 0.0f;
      Part p{"arm" + s, 0.2f * sign, {x - 0.075f, 0.86f}, {x + 0.075f, 1.50f}, false, {}, {}};
      p.far = far;
      p.rows = {{1.50f, W{{"chest", 0.5f}, {"upper_arm" + s, 0.5f}}},
                {1.40f, W{{"chest", 0.15f}, {"upper_arm" + s, 0.85f}}},
                {1.28f, W{{"upper_arm" + s, 1}}},
                {1.21f, W{{"upper_arm" + s, 0.85f}, {"lower_arm" + s, 0.15f}}},
                {1.15f, W{{"upper_arm" + s, 0.5f}, {"lower_arm" + s, 0.5f}}},
                {1.09f, W{{"upper_arm" + s, 0.15f}, {"lower_arm" + s, 0.85f}}},
                {0.98f, W{{"lower_arm" + s, 1}}},
                {0.86f, W{{"lower_arm" + s, 0.8f}, {"hand" + s, 0.2f}}}};
      p.layers = {
          {capsule({x, 1.15f}, {x, 0.9f}, 0.045f, 0.038f), kSkin},
          {capsule({x, 1.41f}, {x, 1.15f}, 0.055f, 0.047f), kSkin},
          {clip(capsule({x, 1.42f}, {x, 1.2f}, 0.066f, 0.058f), {x, 1.25f}, {0.0f, -1.0f}), kShirt,
           0.012f},
      };
      out.push_back(p);
    }
    // Hand.
    {
      const float x = far ? kFarArmDx : 0.0f;
      Part p{"hand" + s, 0.21f * sign, {x - 0.06f, 0.76f}, {x + 0.07f, 0.94f}, false, {}, {}};
      p.far = far;
      p.rows = {{0.94f, W{{"hand" + s, 0.7f}, {"lower_arm" + s, 0.3f}}}, {0.76f, W{{"hand" + s, 1}}}};
      p.layers = {
          {capsule({x, 0.905f}, {x + 0.005f, 0.83f}, 0.042f, 0.045f), kSkin},
          {capsule({x + 0.03f, 0.87f}, {x + 0.045f, 0.83f}, 0.016f, 0.014f), kSkin, 0.008f, false},
      };
      out.push_back(p);
    }
  }
  return out;
}

// Packs the parts' regions in shelves; returns the texture size.
constexpr float kPixelsPerMetre = 400.0f;
constexpr int kPad = 4;

glm::ivec2 pack(std::vector<Part>& ps, int width) {
  int x = kPad, y = kPad, shelf = 0;
  std::vector<Part*> order;
  for (Part& p : ps) order.push_back(&p);
  std::stable_sort(order.begin(), order.end(),
                   [](const Part* a, const Part* b) { return a->hi.y - a->lo.y > b->hi.y - b->lo.y; });
  for (Part* p : order) {
    p->pw = static_cast<int>(std::ceil((p->hi.x - p->lo.x) * kPixelsPerMetre));
    p->ph = static_cast<int>(std::ceil((p->hi.y - p->lo.y) * kPixelsPerMetre));
    if (x + p->pw + kPad > width) {
      x = kPad;
      y += shelf + kPad;
      shelf = 0;
    }
    p->px = x;
    p->py = y;
    x += p->pw + kPad;
    shelf = std::max(shelf, p->ph);
  }
  int height = 64;
  while (height < y + shelf + kPad) height *= 2;
  return {width, height};
}

// Model-space point of a texel centre of part p, and the texture coordinate (top-left origin)
// of a model-space point.
vec2 texel_to_model(const Part& p, int ix, int iy) {
  return {p.lo.x + (static_cast<float>(ix - p.px) + 0.5f) / kPixelsPerMetre,
          p.hi.y - (static_cast<float>(iy - p.py) + 0.5f) / kPixelsPerMetre};
}
vec2 model_to_uv(const Part& p, vec2 q, glm::ivec2 size) {
  return {(static_cast<float>(p.px) + (q.x - p.lo.x) * kPixelsPerMetre) / static_cast<float>(size.x),
          (static_cast<float>(p.py) + (p.hi.y - q.y) * kPixelsPerMetre) / static_cast<float>(size.y)};
}

void draw(const Part& p, glm::ivec2 size, std::vector<uint8_t>& rgba) {
  const float px = 1.0f / kPixelsPerMetre, outline = 0.016f;
  const float shade = p.far ? 0.68f : 1.0f;
  for (int iy = p.py; iy < p.py + p.ph; ++iy) {
    for (int ix = p.px; ix < p.px + p.pw; ++ix) {
      const vec2 q = texel_to_model(p, ix, iy);
      Rgb c = kOutline;
      float alpha = 0.0f, silhouette = 1e9f;
      for (const Layer& l : p.layers) {
        const float d = l.sdf(q);
        const float cover = std::clamp(0.5f - d / px, 0.0f, 1.0f);
        c = glm::mix(c, l.colour * shade, alpha == 0.0f ? 1.0f : cover);
        alpha = std::max(alpha, cover);
        if (l.detail_line > 0.0f) {
          const float line = std::clamp(0.5f - (std::fabs(d + 0.5f * l.detail_line) - 0.5f * l.detail_line) / px, 0.0f, 1.0f);
          c = glm::mix(c, kOutline, line);
        }
        if (l.silhouette) silhouette = std::min(silhouette, d);
      }
      // The outer outline lies just inside the silhouette.
      const float edge = std::clamp(0.5f - (silhouette + outline) / px, 0.0f, 1.0f);
      c = glm::mix(kOutline, c, silhouette < 1e8f ? edge : 1.0f);
      uint8_t* o = &rgba[(static_cast<size_t>(iy) * size.x + ix) * 4];
      for (int k = 0; k < 3; ++k) o[k] = static_cast<uint8_t>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
      o[3] = static_cast<uint8_t>(std::lround(alpha * 255.0f));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Export

template <class T>
T* new_array(size_t n) { return n ? new T[n] : nullptr; }

int run(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  const std::vector<BoneDef> bones = skeleton();
  std::map<std::string, int> index;
  for (size_t i = 0; i < bones.size(); ++i) index[bones[i].name] = static_cast<int>(i);
  std::vector<Part> ps = parts();
  const glm::ivec2 size = pack(ps, 1024);

  // Texture.
  std::vector<uint8_t> rgba(static_cast<size_t>(size.x) * size.y * 4, 0);
  for (size_t i = 0; i < rgba.size(); i += 4) {  // transparent, outline-coloured (no bright fringe)
    rgba[i] = 38, rgba[i + 1] = 30, rgba[i + 2] = 36;
  }
  for (const Part& p : ps) draw(p, size, rgba);
  const std::string png = (dir / "humanoid.png").string();
  if (!stbi_write_png(png.c_str(), size.x, size.y, 4, rgba.data(), size.x * 4)) {
    std::fprintf(stderr, "ossa-make-character: %s: cannot write the PNG\n", png.c_str());
    return 1;
  }

  // Mesh: two vertices per row, quads between rows, parts in depth order.
  std::stable_sort(ps.begin(), ps.end(), [](const Part& a, const Part& b) { return a.z < b.z; });
  std::vector<vec3> positions;
  std::vector<vec2> uvs;
  std::vector<std::vector<std::pair<int, float>>> weights;  // per vertex
  std::vector<unsigned> tris;
  for (const Part& p : ps) {
    const unsigned base = static_cast<unsigned>(positions.size());
    for (const Row& r : p.rows) {
      for (int k = 0; k < 2; ++k) {
        const vec2 q = p.horizontal ? vec2(r.at, k ? p.hi.y : p.lo.y) : vec2(k ? p.hi.x : p.lo.x, r.at);
        positions.push_back({q.x, q.y, p.z});
        uvs.push_back(model_to_uv(p, q, size));
        std::vector<std::pair<int, float>> w;
        for (const auto& [name, wt] : r.weights) w.push_back({index.at(name), wt});
        weights.push_back(w);
      }
    }
    for (unsigned i = 0; i + 1 < p.rows.size(); ++i) {
      unsigned a = base + 2 * i, b = a + 1, c = a + 3, d = a + 2;  // a,b this row; d,c next
      const vec3 e1 = positions[b] - positions[a], e2 = positions[c] - positions[a];
      if (e1.x * e2.y - e1.y * e2.x < 0.0f) std::swap(b, d);  // counter-clockwise, facing +z
      tris.insert(tris.end(), {a, b, c, a, c, d});
    }
  }

  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("humanoid");
  std::vector<aiNode*> nodes;
  std::vector<std::vector<aiNode*>> children(bones.size() + 1);
  for (const BoneDef& b : bones) {
    aiNode* node = new aiNode(b.name);
    const Mat2x3 local = b.parent.empty() ? frame(b) : inverse(frame(bones[index.at(b.parent)])) * frame(b);
    node->mTransformation = to_ai(local);
    nodes.push_back(node);
    children[b.parent.empty() ? bones.size() : static_cast<size_t>(index.at(b.parent))].push_back(node);
  }
  aiNode* mesh_node = new aiNode("humanoid_mesh");
  mesh_node->mNumMeshes = 1;
  mesh_node->mMeshes = new unsigned[1]{0};
  children[bones.size()].push_back(mesh_node);
  for (size_t i = 0; i <= bones.size(); ++i) {
    aiNode* parent = i == bones.size() ? scene->mRootNode : nodes[i];
    parent->mNumChildren = static_cast<unsigned>(children[i].size());
    parent->mChildren = new_array<aiNode*>(children[i].size());
    for (size_t k = 0; k < children[i].size(); ++k) {
      parent->mChildren[k] = children[i][k];
      children[i][k]->mParent = parent;
    }
  }

  aiMesh* mesh = new aiMesh;
  mesh->mName = "humanoid_sprites";
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = static_cast<unsigned>(positions.size());
  mesh->mVertices = new aiVector3D[positions.size()];
  mesh->mNormals = new aiVector3D[positions.size()];
  mesh->mTextureCoords[0] = new aiVector3D[positions.size()];
  mesh->mNumUVComponents[0] = 2;
  for (size_t i = 0; i < positions.size(); ++i) {
    mesh->mVertices[i] = aiVector3D(positions[i].x, positions[i].y, positions[i].z);
    mesh->mNormals[i] = aiVector3D(0.0f, 0.0f, 1.0f);
    // Assimp's scene convention has v up; its glTF exporter flips to glTF's top-left origin.
    mesh->mTextureCoords[0][i] = aiVector3D(uvs[i].x, 1.0f - uvs[i].y, 0.0f);
  }
  mesh->mNumFaces = static_cast<unsigned>(tris.size() / 3);
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    mesh->mFaces[f].mNumIndices = 3;
    mesh->mFaces[f].mIndices = new unsigned[3]{tris[3 * f], tris[3 * f + 1], tris[3 * f + 2]};
  }
  mesh->mNumBones = static_cast<unsigned>(bones.size());
  mesh->mBones = new aiBone*[bones.size()];
  for (size_t bi = 0; bi < bones.size(); ++bi) {
    aiBone* bone = new aiBone;
    bone->mName = bones[bi].name;
    bone->mOffsetMatrix = to_ai(inverse(frame(bones[bi])));  // model space → bone frame
    std::vector<aiVertexWeight> ws;
    for (size_t v = 0; v < weights.size(); ++v) {
      for (const auto& [b, w] : weights[v]) {
        if (b == static_cast<int>(bi)) ws.push_back(aiVertexWeight(static_cast<unsigned>(v), w));
      }
    }
    bone->mNumWeights = static_cast<unsigned>(ws.size());
    bone->mWeights = new_array<aiVertexWeight>(ws.size());
    std::copy(ws.begin(), ws.end(), bone->mWeights);
    mesh->mBones[bi] = bone;
  }
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1]{mesh};

  aiMaterial* material = new aiMaterial;
  const aiString material_name("humanoid");
  material->AddProperty(&material_name, AI_MATKEY_NAME);
  const aiColor4D white(1.0f, 1.0f, 1.0f, 1.0f);
  material->AddProperty(&white, 1, AI_MATKEY_COLOR_DIFFUSE);
  material->AddProperty(&white, 1, AI_MATKEY_BASE_COLOR);
  const aiString tex("humanoid.png");
  material->AddProperty(&tex, AI_MATKEY_TEXTURE_DIFFUSE(0));
  material->AddProperty(&tex, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{material};

  const std::string gltf = (dir / "humanoid.gltf").string();
  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), "gltf2", gltf) != aiReturn_SUCCESS) {
    std::fprintf(stderr, "ossa-make-character: %s: glTF export failed: %s\n", gltf.c_str(),
                 exporter.GetErrorString());
    return 1;
  }

  // Limb roles for the animator (format documented in src/ossa/render/rigged_mesh.h).
  Json rig = {{"format", "ossa.rig"}, {"version", 1}, {"mesh", "humanoid.gltf"},
              {"root", "pelvis"}, {"spine", {"spine", "chest"}}, {"neck", "neck"}, {"head", "head"}};
  for (const char* s : {"_l", "_r"}) {
    const std::string side = std::string(s) == "_l" ? "near" : "far";
    rig["legs"].push_back({{"side", side}, {"upper", std::string("thigh") + s},
                           {"lower", std::string("shin") + s}, {"foot", std::string("foot") + s}});
    rig["arms"].push_back({{"side", side}, {"upper", std::string("upper_arm") + s},
                           {"lower", std::string("lower_arm") + s}, {"hand", std::string("hand") + s}});
  }
  const std::string rig_path = (dir / "humanoid.rig.json").string();
  if (Status s = write_json_atomic(rig_path, rig); !s.ok()) {
    std::fprintf(stderr, "ossa-make-character: %s\n", s.message().c_str());
    return 1;
  }
  std::printf("wrote %s, %s (%dx%d), %s: %zu bones, %zu vertices, %zu triangles\n", gltf.c_str(),
              png.c_str(), size.x, size.y, rig_path.c_str(), bones.size(), positions.size(),
              tris.size() / 3);
  return 0;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// [SECTION] main

int main(int argc, char** argv) {
  std::filesystem::path out = data_path("assets/characters");
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: ossa-make-character [--out DIR]  (default: %s)\n", out.string().c_str());
      return 0;
    } else {
      std::fprintf(stderr, "ossa-make-character: unknown argument \"%s\"; usage: "
                   "ossa-make-character [--out DIR]\n", a.c_str());
      return 2;
    }
  }
  return run(out);
}
