// Bodies (issue 30): every example and random creature gets a body whose parts are closed,
// simple outlines filled exactly by their triangles, skinned like the bones, and whose mass —
// recomputed here from the vertices alone — matches the genome's weight at the creature's size.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/gen/true_size.h"
#include "ossa/skeleton/pose.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

Creature example(const std::string& name) {
  return build_creature(scenes::generator().example(name).value()).value();
}

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Whether segments ab and cd cross (proper intersections and overlaps; shared end points of
// neighbouring edges are not crossings).
bool segments_cross(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d) {
  const glm::dvec2 p(a), r(glm::dvec2(b) - glm::dvec2(a)), q(c), s(glm::dvec2(d) - glm::dvec2(c));
  const double rxs = cross(r, s);
  if (std::fabs(rxs) < 1e-18) return false;  // parallel: ignored (no area)
  const double t = cross(q - p, s) / rxs, u = cross(q - p, r) / rxs;
  const double eps = 1e-7;
  return t > eps && t < 1.0 - eps && u > eps && u < 1.0 - eps;
}

// The first pair of non-adjacent outline edges that cross, as "i j", or "".
std::string self_intersection(const std::vector<glm::vec2>& loop) {
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_cross(loop[i], loop[(i + 1) % n], loop[j], loop[(j + 1) % n])) {
        return std::to_string(i) + " " + std::to_string(j);
      }
    }
  }
  return "";
}

double shoelace(const std::vector<glm::vec2>& p) {
  double a = 0.0;
  for (size_t i = 0; i < p.size(); ++i) a += cross(glm::dvec2(p[i]), glm::dvec2(p[(i + 1) % p.size()]));
  return 0.5 * a;
}

bool inside(const std::vector<glm::vec2>& poly, glm::vec2 p) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
        p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x) {
      in = !in;
    }
  }
  return in;
}

// The body's mass from its vertices (body_mass.h's rules, written out again).
double recomputed_mass(const BodyMesh& m) {
  std::vector<glm::vec2> axial;
  for (const BodyPart& p : m.parts) {
    if (p.kind == BodyPartKind::kAxial) {
      for (uint32_t i : p.outline) axial.push_back(m.vertices[i].position_ms);
    }
  }
  double volume = 0.0;
  for (const BodyPart& p : m.parts) {
    if (!p.sections.empty()) {
      const bool limb = p.kind == BodyPartKind::kLeg || p.kind == BodyPartKind::kArm;
      for (size_t i = 0; i + 1 < p.sections.size(); ++i) {
        double area[2], count[2];
        glm::dvec2 mid[2];
        for (int k = 0; k < 2; ++k) {
          const glm::vec2 top = m.vertices[p.sections[i + k].top].position_ms;
          const glm::vec2 bottom = m.vertices[p.sections[i + k].bottom].position_ms;
          const double h = glm::length(glm::dvec2(top) - glm::dvec2(bottom));
          area[k] = 0.25 * M_PI * p.depth * h * h;
          mid[k] = 0.5 * (glm::dvec2(top) + glm::dvec2(bottom));
          count[k] = limb && inside(axial, glm::vec2(mid[k])) ? 0.0 : 1.0;
        }
        volume += 0.5 * (count[0] + count[1]) * 0.5 * (area[0] + area[1]) * glm::length(mid[1] - mid[0]);
      }
    } else if (p.kind != BodyPartKind::kEye) {
      std::vector<glm::vec2> loop;
      glm::vec2 lo(1e30f), hi(-1e30f);
      for (uint32_t i : p.outline) {
        loop.push_back(m.vertices[i].position_ms);
        lo = glm::min(lo, loop.back());
        hi = glm::max(hi, loop.back());
      }
      volume += std::fabs(shoelace(loop)) * p.depth * std::max(hi.x - lo.x, hi.y - lo.y);
    }
  }
  return 1000.0 * volume;
}

}  // namespace

TEST_CASE("every example's body weighs what its genome's weight asks at its size, within 25 %", "[body]") {
  const bool print = std::getenv("OSSA_PRINT_MASS_TABLE") != nullptr;
  if (print) {
    std::printf("| example | weight kg | scale m/fu | true scale m/fu | expected kg (weight x (scale/true)^3) | body kg | body/expected | girth | depth scale |\n");
    std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  }
  int within = 0;
  for (const Animal& a : scenes::generator().dataset().animals) {
    const Genome g = scenes::generator().example(a.name).value();
    const Creature c = build_creature(g).value();
    const std::optional<float> t = true_scale(c, g);
    REQUIRE(t.has_value());
    // The weight at this creature's size, from its actual scale (so the check holds unchanged
    // when creatures are built at their true size: then scale == true scale).
    const double ratio = static_cast<double>(c.scale) / *t;
    const double expected = g.pca[kWeightKg] * ratio * ratio * ratio * g.look.fatness;
    const BodyMesh body = build_body(c);
    const double mass = recomputed_mass(body);
    CHECK(mass == Approx(body.mass_kg).epsilon(1e-3));
    if (print) {
      std::printf("| %s | %g | %.5f | %.5f | %.4g | %.4g | %.2f | %.2f | %.2f |\n", a.name.c_str(), g.pca[kWeightKg],
                  static_cast<double>(c.scale), static_cast<double>(*t), expected, mass, mass / expected,
                  static_cast<double>(body.girth), static_cast<double>(body.depth_scale));
    }
    INFO(a.name << ": body " << mass << " kg, expected " << expected << " kg, girth " << body.girth);
    CHECK(mass / expected > 0.75);
    CHECK(mass / expected < 1.25);
    within += mass / expected > 0.75 && mass / expected < 1.25;
  }
  CHECK(within == static_cast<int>(scenes::generator().dataset().animals.size()));
}

namespace {

void check_body(const Creature& c, const std::string& who) {
  const BodyMesh m = build_body(c);
  INFO(who);
  REQUIRE(!m.parts.empty());
  REQUIRE(m.floor_entry() <= 256);
  // Skinning: weights sum to 1, indices inside the palette; the rest palette gives the rest pose.
  const auto model = model_matrices(c.skeleton, c.rest_pose.locals);
  std::vector<Mat2x3> palette(static_cast<size_t>(m.palette_size()));
  body_palette(m, model, palette);
  for (const BodyVertex& v : m.vertices) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      sum += v.weights[static_cast<size_t>(k)];
      if (v.weights[static_cast<size_t>(k)] > 0.0f) REQUIRE(v.bones[static_cast<size_t>(k)] < m.floor_entry());
    }
    REQUIRE(sum == Approx(1.0f).margin(1e-5));
    REQUIRE(glm::length(skin_body_vertex(v, palette) - v.position_ms) < 1e-4f * m.parts.size() + 1e-4f);
  }
  // Parts: one closed, simple outline each, its triangles filling exactly its area; layers in
  // order; indices in range.
  for (const BodyPart& p : m.parts) {
    INFO(body_part_name(p.kind) << " part");
    std::vector<glm::vec2> loop;
    for (uint32_t i : p.outline) loop.push_back(m.vertices[i].position_ms);
    REQUIRE(loop.size() >= 3);
    CHECK(shoelace(loop) > 0.0);  // counter-clockwise
    CHECK(self_intersection(loop) == "");
    double filled = 0.0;
    for (uint32_t i = p.first_index; i < p.first_index + p.index_count; i += 3) {
      filled += std::fabs(shoelace({m.vertices[m.indices[i]].position_ms, m.vertices[m.indices[i + 1]].position_ms,
                                    m.vertices[m.indices[i + 2]].position_ms}));
    }
    CHECK(filled == Approx(std::fabs(shoelace(loop))).epsilon(0.01));
  }
  for (int l = 0; l < kLayerCount; ++l) CHECK(m.layer_begin[static_cast<size_t>(l)] <= m.layer_begin[static_cast<size_t>(l) + 1]);
  CHECK(m.layer_begin[kLayerCount] == m.indices.size());
  for (uint32_t i : m.indices) REQUIRE(i < m.vertices.size());
}

}  // namespace

TEST_CASE("bodies of every example: closed simple outlines, filled exactly, skinned to rest", "[body]") {
  for (const Animal& a : scenes::generator().dataset().animals) check_body(example(a.name), a.name);
}

TEST_CASE("bodies of random creatures: closed simple outlines, filled exactly, skinned to rest", "[body]") {
  for (uint64_t seed = 1; seed <= 50; ++seed) {
    check_body(build_creature(scenes::generator().random(seed)).value(), "random " + std::to_string(seed));
  }
}

TEST_CASE("body part masses (diagnostic)", "[.body-diag]") {
  for (const char* name : {"horse", "dromedary", "wildebeest", "snake", "magpie", "crocodile", "rock hyrax", "frog", "trout"}) {
    const Creature c = example(name);
    BodyOptions o;
    o.min_girth = o.max_girth = 0.25f;
    const BodyMesh m = build_body(c, o);
    std::printf("%s: girth 1 mass %.1f kg (expected %.1f)\n", name, m.mass_kg, c.body_mass_kg ? *c.body_mass_kg : -1.0f);
    for (const BodyPart& p : m.parts) {
      if (p.mass_kg > 0.01f * m.mass_kg) std::printf("   %-10s layer %d  %.1f kg\n", body_part_name(p.kind), static_cast<int>(p.layer), p.mass_kg);
      if (p.kind == BodyPartKind::kAxial && std::string(name) == "snake") {
        for (size_t i = 0; i < p.sections.size(); i += 8) {
          const glm::vec2 t = m.vertices[p.sections[i].top].position_ms, b = m.vertices[p.sections[i].bottom].position_ms;
          std::printf("      section %zu: top (%.3f, %.3f) bottom (%.3f, %.3f)\n", i, t.x, t.y, b.x, b.y);
        }
      }
    }
  }
}

// Writes OSSA_BODY_DUMP's part outlines as SVG (a debugging aid): OSSA_BODY_DUMP=horse.
TEST_CASE("dump a body's outlines (diagnostic)", "[.body-dump]") {
  const char* who = std::getenv("OSSA_BODY_DUMP");
  if (!who) return;
  const std::string name = who;
  const Creature c = name.rfind("random", 0) == 0 ? build_creature(scenes::generator().random(std::stoull(name.substr(6)))).value()
                                                    : example(name);
  const BodyMesh m = build_body(c);
  const Box b = body_bounds(m);
  const float s = 1000.0f / std::max(b.max_ws.x - b.min_ws.x, b.max_ws.y - b.min_ws.y);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1100\" height=\"1100\"><rect width=\"1100\" height=\"1100\" fill=\"white\"/>\n";
  const auto X = [&](glm::vec2 p) { return std::to_string(50 + (p.x - b.min_ws.x) * s) + "," + std::to_string(1050 - (p.y - b.min_ws.y) * s); };
  for (const BodyPart& p : m.parts) {
    std::vector<glm::vec2> loop;
    for (uint32_t i : p.outline) loop.push_back(m.vertices[i].position_ms);
    const std::string bad = self_intersection(loop);
    svg += "<polygon fill=\"none\" stroke=\"" + std::string(bad.empty() ? "#888" : "red") + "\" stroke-width=\"1\" points=\"";
    for (glm::vec2 q : loop) svg += X(q) + " ";
    svg += "\"/>\n";
    if (!bad.empty()) {
      const size_t i = std::stoul(bad), j = std::stoul(bad.substr(bad.find(' ') + 1));
      std::printf("%s: %s crosses at edges %zu and %zu of %zu\n", name.c_str(), body_part_name(p.kind), i, j, loop.size());
      for (size_t k : {i, j}) svg += "<line stroke=\"blue\" stroke-width=\"3\" x1=\"" + X(loop[k]).substr(0, X(loop[k]).find(',')) + "\" y1=\"" + X(loop[k]).substr(X(loop[k]).find(',') + 1) + "\" x2=\"" + X(loop[(k + 1) % loop.size()]).substr(0, X(loop[(k + 1) % loop.size()]).find(',')) + "\" y2=\"" + X(loop[(k + 1) % loop.size()]).substr(X(loop[(k + 1) % loop.size()]).find(',') + 1) + "\"/>\n";
    }
  }
  svg += "</svg>\n";
  FILE* f = std::fopen(("out/dump_" + name + ".svg").c_str(), "w");
  if (f) {
    std::fputs(svg.c_str(), f);
    std::fclose(f);
  }
}
