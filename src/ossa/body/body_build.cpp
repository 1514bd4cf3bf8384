// build_body: the parts planned (axial.cpp, limbs.cpp, appendages.cpp), the girth factor that
// gives the body its mass, then the mesh — parts in draw order, each stroke before its fill,
// coloured by the coat (coat.h) — and its mass (body_mass.h). See body_mesh.h.

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "ossa/assert.h"
#include "ossa/body/body_mass.h"
#include "ossa/body/body_parts.h"
#include "ossa/body/coat.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

const char* creature_look_name(CreatureLook look) {
  switch (look) {
    case CreatureLook::kBody: return "body";
    case CreatureLook::kXray: return "xray";
    case CreatureLook::kBones: return "bones";
  }
  return "body";
}

std::optional<CreatureLook> creature_look_from_name(std::string_view name) {
  for (int i = 0; i < kCreatureLookCount; ++i) {
    if (name == creature_look_name(static_cast<CreatureLook>(i))) return static_cast<CreatureLook>(i);
  }
  return std::nullopt;
}

const char* body_part_name(BodyPartKind kind) {
  switch (kind) {
    case BodyPartKind::kAxial: return "axial";
    case BodyPartKind::kLeg: return "leg";
    case BodyPartKind::kArm: return "arm";
    case BodyPartKind::kWing: return "wing";
    case BodyPartKind::kFin: return "fin";
    case BodyPartKind::kEar: return "ear";
    case BodyPartKind::kHorn: return "horn";
    case BodyPartKind::kAntler: return "antler";
    case BodyPartKind::kFrill: return "frill";
    case BodyPartKind::kCrest: return "crest";
    case BodyPartKind::kMane: return "mane";
    case BodyPartKind::kTrunk: return "trunk";
    case BodyPartKind::kSail: return "sail";
    case BodyPartKind::kPlate: return "plate";
    case BodyPartKind::kShell: return "shell";
    case BodyPartKind::kDorsalFin: return "dorsal_fin";
    case BodyPartKind::kTailFin: return "tail_fin";
    case BodyPartKind::kEye: return "eye";
  }
  return "unknown";
}

namespace {

using namespace body;

// An outline edge skinned over a bending spine stretches on the outside of the bend: the floor
// holds a part up this many times its longest rest edge past a top's ends.
constexpr float kOverhangStretch = 1.25f;

const TubePlan* find_axial(const BodyParts& parts) {
  for (const TubePlan& t : parts.tubes) {
    if (t.kind == BodyPartKind::kAxial) return &t;
  }
  return nullptr;
}

// The girth a tube takes of the body's: limbs follow it to 1.25, then slowly (an animal
// heavier than its skeleton's default carries the weight in its trunk, not in thighs that
// would outgrow the body).
float tube_girth(const TubePlan& t, float girth) {
  const bool limb = t.kind == BodyPartKind::kLeg || t.kind == BodyPartKind::kArm;
  return limb && girth > 1.25f ? 1.25f + 0.3f * (girth - 1.25f) : girth;
}

// The body's mass at `girth` from its plan, by body_mass.h's rules (the mesh built at that
// girth measures the same: its sections are these points).
double plan_mass(const BodyParts& parts, float girth) {
  const TubePlan* axial = find_axial(parts);
  const std::vector<glm::vec2> axial_outline = axial ? tube_outline(*axial, girth) : std::vector<glm::vec2>{};
  double volume = 0.0;
  std::vector<glm::vec2> tops, bottoms;
  std::vector<float> counts;
  for (const TubePlan& t : parts.tubes) {
    tops.clear();
    bottoms.clear();
    counts.clear();
    const bool limb = t.kind == BodyPartKind::kLeg || t.kind == BodyPartKind::kArm;
    for (const Section& s : t.sections) {
      tops.push_back(section_top(s, tube_girth(t, girth)));
      bottoms.push_back(section_bottom(s, tube_girth(t, girth)));
      const glm::vec2 mid = 0.5f * (tops.back() + bottoms.back());
      counts.push_back(limb && !axial_outline.empty() && inside_polygon(axial_outline, mid) ? 0.0f : 1.0f);
    }
    volume += tube_volume(tops, bottoms, t.depth, counts);
  }
  for (const FlatPlan& f : parts.flats) {
    if (f.kind == BodyPartKind::kEye || f.outline.size() < 3) continue;
    glm::vec2 lo = f.outline.front(), hi = f.outline.front();
    for (const glm::vec2 q : f.outline) lo = glm::min(lo, q), hi = glm::max(hi, q);
    volume += polygon_area(f.outline) * f.depth * std::max(hi.x - lo.x, hi.y - lo.y);
  }
  return volume * kBodyDensity;
}

// Countershading of points off the axial body: their fraction between its back and belly
// lines, read at the section whose cross-section line passes nearest.
struct Countershade {
  std::vector<glm::vec2> centre, dorsal;
  std::vector<float> top, bottom;
  explicit Countershade(const TubePlan* axial, float girth) {
    if (!axial) return;
    for (const Section& s : axial->sections) {
      centre.push_back(s.centre);
      dorsal.push_back(s.dorsal);
      top.push_back(s.top(girth));
      bottom.push_back(s.bottom(girth));
    }
  }
  float at(glm::vec2 p) const {
    float best = 1e30f, v = 0.5f;
    for (size_t i = 0; i < centre.size(); ++i) {
      const glm::vec2 d = p - centre[i];
      const float across = glm::dot(d, dorsal[i]);
      const float along = std::fabs(d.x * dorsal[i].y - d.y * dorsal[i].x);
      if (along < best) {
        best = along;
        v = (top[i] - across) / std::max(top[i] + bottom[i], 1e-6f);
      }
    }
    return v;
  }
};

}  // namespace

double body_volume_m3(const Creature& c) {
  BodyRig rig = make_rig(c);
  if (rig.axial.bones.empty() || rig.bone_count > 255) return 0.0;
  BodyParts parts;
  plan_axial(rig, parts);
  plan_limbs(rig, parts);
  plan_appendages(rig, parts);
  return plan_mass(parts, 1.0f) / kBodyDensity;
}

BodyMesh build_body(const Creature& c, const BodyOptions& options) {
  BodyMesh mesh;
  BodyRig rig = make_rig(c);
  OSSA_ASSERT(rig.bone_count <= 255, "build_body: more bones than uint8 palette indices hold");
  mesh.inverse_bind.reserve(rig.rest.size());
  for (const Mat2x3& m : rig.rest) mesh.inverse_bind.push_back(inverse(m));
  if (rig.axial.bones.empty()) return mesh;

  BodyParts parts;
  plan_axial(rig, parts);
  plan_limbs(rig, parts);
  mesh.mid_joints = rig.mid_joints;
  OSSA_ASSERT(mesh.floor_entry() <= 256, "build_body: palette entries beyond uint8 indices");
  const BodyParts base = parts;  // before the appendages, which sit on the back line

  // The girth: the factor on muscle and fat that gives the body the mass its weight asks for.
  // Appendages on the back move with it, so it is solved twice: with them planned at girth 1,
  // then planned where that girth puts the back line.
  plan_appendages(rig, parts);
  mesh.default_mass_kg = static_cast<float>(plan_mass(parts, 1.0f));
  const double target = c.body_mass_kg ? static_cast<double>(*c.body_mass_kg)
                                       : static_cast<double>(mesh.default_mass_kg) * c.look.fatness;
  float girth = 1.0f;
  for (int round = 0; round < 2; ++round) {
    if (round > 0) {
      parts = base;
      plan_appendages(rig, parts, girth);
    }
    float lo = options.min_girth, hi = options.max_girth;
    mesh.depth_scale = 1.0f;
    mesh.mass_matched = true;
    if (plan_mass(parts, lo) >= target) {
      // Heavier than the weight even as lean as a body gets (a skeleton large for its weight,
      // or a laterally slim animal: a chameleon): the silhouette stays at the least girth and
      // the body is narrower across instead, every part's depth scaled (body_mass.h).
      girth = lo;
      const double at_least = plan_mass(parts, lo);
      const float scale = at_least > 0.0 ? static_cast<float>(target / at_least) : 1.0f;
      mesh.depth_scale = std::max(scale, options.min_depth_scale);
      mesh.mass_matched = scale >= options.min_depth_scale;
    } else if (plan_mass(parts, hi) <= target) {
      // Lighter than the weight even as stout as a silhouette gets (a skeleton small for its
      // weight: a frog, an ichthyostega): wider across instead, every depth scaled up.
      girth = hi;
      const double at_most = plan_mass(parts, hi);
      const float scale = at_most > 0.0 ? static_cast<float>(target / at_most) : 1.0f;
      mesh.depth_scale = std::min(scale, options.max_depth_scale);
      mesh.mass_matched = scale <= options.max_depth_scale;
    } else {
      for (int i = 0; i < 28 && hi - lo > 1e-4f; ++i) {
        girth = 0.5f * (lo + hi);
        (plan_mass(parts, girth) < target ? lo : hi) = girth;
      }
      girth = 0.5f * (lo + hi);
    }
  }
  for (TubePlan& t : parts.tubes) t.depth *= mesh.depth_scale;
  for (FlatPlan& f : parts.flats) f.depth *= mesh.depth_scale;
  mesh.girth = girth;
  for (TubePlan& t : parts.tubes) {
    unfold_sections(t.sections, tube_girth(t, girth));
    untangle_tube(t, tube_girth(t, girth));
  }

  // Draw order: far, body, near; within a layer by order (the axial body 0), then as planned.
  struct Entry {
    bool tube;
    size_t index;
    Layer layer;
    int order;
  };
  std::vector<Entry> order;
  for (size_t i = 0; i < parts.tubes.size(); ++i) order.push_back({true, i, parts.tubes[i].layer, parts.tubes[i].order});
  for (size_t i = 0; i < parts.flats.size(); ++i) order.push_back({false, i, parts.flats[i].layer, parts.flats[i].order});
  std::stable_sort(order.begin(), order.end(), [](const Entry& a, const Entry& b) {
    if (a.layer != b.layer) return static_cast<int>(a.layer) < static_cast<int>(b.layer);
    return a.order < b.order;
  });

  const TubePlan* axial = find_axial(parts);
  const Countershade shade(axial, girth);
  const std::vector<glm::vec2> axial_outline = axial ? tube_outline(*axial, girth) : std::vector<glm::vec2>{};
  const Look& look = c.look;
  const float cell = std::max(look.pattern_scale * rig.back_length, 1e-5f);
  uint32_t h = 0x9e3779b9u;
  for (const char ch : c.name) h = coat_hash(h ^ static_cast<uint8_t>(ch));
  const glm::vec2 offset(static_cast<float>(h % 997u) * 0.137f, static_cast<float>((h / 997u) % 991u) * 0.173f);
  const glm::vec3 outline = outline_colour(look);
  const float stroke = options.outline ? options.outline_width * rig.back_length : 0.0f;

  mesh.vertices.reserve(2600);
  mesh.indices.reserve(9000);
  int layer = 0;
  mesh.layer_begin[0] = 0;
  for (const Entry& e : order) {
    while (layer < static_cast<int>(e.layer)) mesh.layer_begin[static_cast<size_t>(++layer)] = static_cast<uint32_t>(mesh.indices.size());
    const float dim = e.layer == Layer::kFar ? options.far_shade : 1.0f;
    const bool axial_part = e.tube && parts.tubes[e.index].kind == BodyPartKind::kAxial;
    const Painter paint = [&](BodyVertex& v, float across, glm::vec4 over, float pattern) {
      const glm::vec2 p = v.position_ms;
      glm::vec3 rgb;
      float alpha = 1.0f;
      if (over.r >= 0.0f) {
        rgb = glm::vec3(over);
        alpha = over.a;
      } else {
        rgb = countershade(look, axial_part && across >= 0.0f ? across : shade.at(p));
      }
      v.colour = to_rgba8(glm::vec4(rgb * dim, alpha));
      v.coat_uv = p / cell + offset;
      const float strength = look.pattern == CoatPattern::kNone ? 0.0f : pattern;
      v.pattern = to_rgba8(glm::vec4(look.pattern_colour * dim, strength));
      v.pattern_kind = static_cast<uint8_t>(look.pattern);
    };
    const auto fill_first = static_cast<uint32_t>(mesh.indices.size());
    const size_t vertex_first = mesh.vertices.size();
    BodyPart part = e.tube ? emit_tube(parts.tubes[e.index], tube_girth(parts.tubes[e.index], girth), mesh, paint) : emit_flat(parts.flats[e.index], mesh, paint);
    if (part.index_count == 0) {
      mesh.indices.resize(fill_first);
      continue;
    }
    // A leg's vertices are held up past a box top's ends only by the top its own foot stands
    // on (BodyVertex::overhang, body_floor.h), each as far as its own outline edges reach,
    // stretched (inside the outline, its longest edge); set before the stroke, which copies
    // its outline's vertices.
    if (part.kind == BodyPartKind::kLeg && part.limb >= 0 && mesh.feet.size() < static_cast<size_t>(kBodyFloorFeet)) {
      const Limb& limb = c.limbs[static_cast<size_t>(part.limb)];
      const auto foot = static_cast<uint8_t>(mesh.feet.size());
      mesh.feet.push_back({limb.bones[2], c.contact == ContactMode::kFlat ? limb.bones[1] : -1});
      const size_t n = part.outline.size();
      std::vector<float> edge(n);
      float longest = 0.0f;
      for (size_t k = 0; k < n; ++k) {
        edge[k] = glm::length(mesh.vertices[part.outline[(k + 1) % n]].position_ms - mesh.vertices[part.outline[k]].position_ms);
        longest = std::max(longest, edge[k]);
      }
      for (size_t v = vertex_first; v < mesh.vertices.size(); ++v) {
        mesh.vertices[v].overhang = kOverhangStretch * longest;
        mesh.vertices[v].foot = foot;
      }
      for (size_t k = 0; k < n; ++k) mesh.vertices[part.outline[k]].overhang = kOverhangStretch * std::max(edge[k], edge[(k + n - 1) % n]);
    }
    if (stroke > 0.0f && part.kind != BodyPartKind::kEye) {
      const bool fade = e.tube && parts.tubes[e.index].fade_start;
      add_stroke(part, mesh, stroke, glm::vec4(outline * dim, 1.0f),
                 fade ? std::span<const glm::vec2>(axial_outline) : std::span<const glm::vec2>());
      // The stroke goes under the fill: rotate its indices in front of the fill's.
      std::rotate(mesh.indices.begin() + fill_first, mesh.indices.begin() + part.stroke_first_index, mesh.indices.end());
      part.stroke_first_index = fill_first;
      part.first_index = fill_first + part.stroke_index_count;
    }
    // How far past a box top's ends the floor holds this part up (BodyVertex::overhang): its
    // longest outline edge, with room for the skin stretching on the outside of a bend (a
    // leg's, above). Arms keep 0: a hand set down beside a riser keeps its shape.
    if (part.kind != BodyPartKind::kLeg && part.kind != BodyPartKind::kArm) {
      float edge = 0.0f;
      for (size_t k = 0; k < part.outline.size(); ++k) {
        const glm::vec2 a = mesh.vertices[part.outline[k]].position_ms;
        const glm::vec2 b = mesh.vertices[part.outline[(k + 1) % part.outline.size()]].position_ms;
        edge = std::max(edge, glm::length(b - a));
      }
      for (size_t v = vertex_first; v < mesh.vertices.size(); ++v) mesh.vertices[v].overhang = kOverhangStretch * edge;
    }
    mesh.parts.push_back(std::move(part));
  }
  while (layer < kLayerCount) mesh.layer_begin[static_cast<size_t>(++layer)] = static_cast<uint32_t>(mesh.indices.size());
  body_mass(mesh);
  // How far the flesh reaches past the box around the bones (rest pose).
  glm::vec2 bones_lo(1e30f), bones_hi(-1e30f);
  for (int b = 0; b < rig.bone_count; ++b) {
    for (const glm::vec2 p : {rig.bone_start(b), rig.bone_end(b)}) bones_lo = glm::min(bones_lo, p), bones_hi = glm::max(bones_hi, p);
  }
  for (const BodyVertex& v : mesh.vertices) {
    const glm::vec2 out = glm::max(bones_lo - v.position_ms, v.position_ms - bones_hi);
    mesh.reach = std::max(mesh.reach, std::max(out.x, out.y));
  }
  return mesh;
}

Result<BodyMesh> try_build_body(const Creature& c, const BodyOptions& options) {
  if (c.skeleton.bone_count() > 255) {
    return Error::at(c.name, "skeleton", "expected at most 255 bones for a body mesh, got " + std::to_string(c.skeleton.bone_count()));
  }
  return build_body(c, options);
}

glm::vec2 skin_body_vertex(const BodyVertex& v, std::span<const Mat2x3> palette) {
  glm::vec2 p(0.0f);
  for (size_t k = 0; k < 4; ++k) {
    if (v.weights[k] != 0.0f) p += v.weights[k] * palette[v.bones[k]].apply(v.position_ms);
  }
  return p;
}

glm::vec2 drawn_body_vertex(const BodyVertex& v, std::span<const Mat2x3> palette, const BodyFloor& floor) {
  return floor_point(skin_body_vertex(v, palette), floor, v.overhang, v.foot);
}

void body_palette(const BodyMesh& mesh, std::span<const Mat2x3> world, std::span<Mat2x3> palette, const BodyFloor& floor) {
  OSSA_ASSERT(world.size() == mesh.inverse_bind.size() && palette.size() >= static_cast<size_t>(mesh.palette_size()),
              "body_palette: one world matrix per bone, a palette entry per bone, mid joint and floor entry");
  for (size_t i = 0; i < world.size(); ++i) palette[i] = world[i] * mesh.inverse_bind[i];
  mid_joint_palette(mesh.mid_joints, world, palette.first(static_cast<size_t>(mesh.floor_entry())));
  encode_floor(floor, palette.subspan(static_cast<size_t>(mesh.floor_entry()), static_cast<size_t>(kBodyFloorEntries)));
}

Box body_bounds(const BodyMesh& mesh) {
  if (mesh.vertices.empty()) return Box{};
  Box b{mesh.vertices.front().position_ms, mesh.vertices.front().position_ms};
  for (const BodyVertex& v : mesh.vertices) {
    b.min_ws = glm::min(b.min_ws, v.position_ms);
    b.max_ws = glm::max(b.max_ws, v.position_ms);
  }
  return b;
}

}  // namespace ossa
