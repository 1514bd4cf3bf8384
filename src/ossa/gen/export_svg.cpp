#include "ossa/gen/export_svg.h"

// Sections:
//   [SECTION] Creature drawing — layers, ground, viewBox
//   [SECTION] Documents — creature_svg, sheet_svg
// Path data and bone shapes: svg_path.h, svg_bone_shapes.h.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "ossa/gen/svg_bone_shapes.h"
#include "ossa/gen/svg_path.h"
#include "ossa/skeleton/pose.h"

namespace ossa {
namespace {

using namespace svg;

// [SECTION] Creature drawing -----------------------------------------------------------------

struct LayerStyle {
  const char* fill;
  const char* stroke;
  const char* hole;
};
constexpr LayerStyle kLayerStyles[kLayerCount] = {
    {"#9c9382", "#4a443a", "#5c554a"},   // far: darker, behind the body
    {"#e2d6ba", "#6b5d45", "#8a7c62"},   // body
    {"#e8dcc0", "#6b5d45", "#8a7c62"},   // near
};

// Drawing order inside a layer: ribs behind girdles behind the spine and skull, limbs on top
// from the girdle outwards.
int kind_order(BoneKind kind) {
  switch (kind) {
    case BoneKind::kRib: return 0;
    case BoneKind::kScapula:
    case BoneKind::kPelvis: return 1;
    case BoneKind::kNeckVertebra:
    case BoneKind::kBackVertebra:
    case BoneKind::kTailVertebra:
    case BoneKind::kRoot: return 2;
    case BoneKind::kSkull: return 3;
    case BoneKind::kUpperLimb: return 4;
    case BoneKind::kLowerLimb: return 5;
    case BoneKind::kHand: return 6;
  }
  return 7;
}

bool finite(const Mat2x3& m) {
  for (float v : m.m) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

int auto_skull_variant(const Creature& c) {
  int wings = 0, legs = 0, fins = 0;
  for (const Limb& l : c.limbs) {
    wings += l.kind == LimbKind::kWing;
    legs += l.kind == LimbKind::kLeg;
    fins += l.kind == LimbKind::kFin;
  }
  if (wings > 0) return 1;
  if (legs == 0 && fins > 0) return 3;
  if (c.skull >= 0) {
    const float L = c.skeleton.length(c.skull), w = c.skeleton.width(c.skull);
    if (w > 0.0f && L > 2.6f * w) return 2;
  }
  return 0;
}

// `dir_ms`: the hand/foot bone's unit direction in model space.
HandShape hand_shape(const Creature& c, const Limb& limb, bool winged, const Skeleton& s,
                     glm::vec2 dir_ms) {
  switch (limb.kind) {
    case LimbKind::kWing: return HandShape::kWingHand;
    case LimbKind::kFin: return HandShape::kFin;
    case LimbKind::kArm: return HandShape::kHand;
    case LimbKind::kLeg: break;
  }
  if (c.contact == ContactMode::kFlat) return HandShape::kFlat;
  // Tip contact: ungulates stand on long, steep metapodials (cannon bones) ending in a hoof;
  // a foot that lies nearly flat (kangaroo, a resting bird's tarsus) reads as a flat foot;
  // birds' steep ones as bird feet; the rest as a paw.
  const float lower = s.length(limb.bones[1]);
  const float steep = std::fabs(dir_ms.y);
  if (steep < 0.5f) return HandShape::kFlat;
  if (winged) return HandShape::kBirdFoot;
  return steep > 0.7f && s.length(limb.bones[2]) >= 0.45f * lower ? HandShape::kHoof
                                                                   : HandShape::kPaw;
}

struct Drawing {
  std::string content;  // a <g> in model coordinates, y flipped
  float vx = 0.0f, vy = 0.0f, vw = 1.0f, vh = 1.0f;  // viewBox
};

Drawing draw_creature(const Creature& c, const SvgOptions& options) {
  const Skeleton& s = c.skeleton;
  const int n = s.bone_count();
  const std::vector<BoneLocal>& locals =
      c.rest_pose.locals.size() == static_cast<size_t>(n) ? c.rest_pose.locals : s.rest_locals();
  const std::vector<Mat2x3> m = model_matrices(s, locals);

  // Spine bones on the chain from the head end to the root point headward (+x to the head).
  std::vector<char> headward(static_cast<size_t>(n), 0);
  int head_end = !c.neck.empty() ? c.neck.front() : !c.back.empty() ? c.back.front() : -1;
  if (c.skull >= 0 && c.skull < n) head_end = c.skull;
  for (int b = head_end; b >= 0 && b < n; b = s.parent(b)) headward[static_cast<size_t>(b)] = 1;

  std::vector<int> limb_of(static_cast<size_t>(n), -1);
  bool winged = false;
  for (size_t i = 0; i < c.limbs.size(); ++i) {
    const Limb& l = c.limbs[i];
    winged |= l.kind == LimbKind::kWing;
    for (int b : l.bones) {
      if (b >= 0 && b < n) limb_of[static_cast<size_t>(b)] = static_cast<int>(i);
    }
  }
  const int skull_variant =
      options.skull_variant >= 0 ? options.skull_variant % 4 : auto_skull_variant(c);

  // Bone order: by layer, then by kind, then by index.
  std::vector<int> order;
  for (int i = 0; i < n; ++i) {
    if (s.length(i) > 0.0f && std::isfinite(s.length(i)) && std::isfinite(s.width(i)) &&
        finite(m[static_cast<size_t>(i)])) {
      order.push_back(i);
    }
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const int la = static_cast<int>(s.layer(a)), lb = static_cast<int>(s.layer(b));
    if (la != lb) return la < lb;
    return kind_order(s.kind(a)) < kind_order(s.kind(b));
  });

  Bounds bounds;
  float max_extent = 0.0f;
  std::string layers[kLayerCount];
  if (!options.bones) order.clear();
  if (options.body) {
    bounds.add(options.body->lo);
    bounds.add(options.body->hi);
  }
  for (int i : order) {
    const Mat2x3& mi = m[static_cast<size_t>(i)];
    const float L = s.length(i);
    const float w = s.width(i) > 0.0f ? s.width(i) : 0.15f * L;
    BoneContext ctx;
    ctx.length = L;
    ctx.width = w;
    ctx.headward = headward[static_cast<size_t>(i)] != 0;
    const glm::vec2 fx(mi.m[0], mi.m[2]), uy(mi.m[1], mi.m[3]);
    ctx.forward_ls = glm::length(fx) > 0.0f ? glm::normalize(fx) : glm::vec2(1.0f, 0.0f);
    ctx.up_ls = glm::length(uy) > 0.0f ? glm::normalize(uy) : glm::vec2(0.0f, 1.0f);

    const bool vertebra_bone = s.kind(i) == BoneKind::kNeckVertebra ||
                               s.kind(i) == BoneKind::kBackVertebra ||
                               s.kind(i) == BoneKind::kTailVertebra;
    const bool flip = vertebra_bone && !ctx.headward;
    PathBuilder shape(flip, L), holes(flip, L);
    switch (s.kind(i)) {
      case BoneKind::kRoot: break;
      case BoneKind::kSkull: skull(shape, holes, L, w, skull_variant); break;
      case BoneKind::kNeckVertebra: vertebra(shape, L, w, 0.35f * w); break;
      case BoneKind::kBackVertebra: vertebra(shape, L, w, 1.1f * w); break;
      case BoneKind::kTailVertebra: vertebra(shape, L, w, 0.25f * w); break;
      case BoneKind::kRib: {
        PathBuilder r;  // ribs bulge towards the tail (model -x)
        rib(r, L, w, ctx.forward_ls.y > 0.0f ? -1.0f : 1.0f);
        shape = r;
        break;
      }
      case BoneKind::kScapula: {
        PathBuilder sp, marks;
        scapula(sp, marks, L, w);
        shape = sp;
        holes = marks;
        break;
      }
      case BoneKind::kPelvis: {
        PathBuilder pv, hl;
        pelvis(pv, hl, L, w);
        shape = pv;
        holes = hl;
        break;
      }
      case BoneKind::kUpperLimb:
      case BoneKind::kLowerLimb: {
        PathBuilder lb;
        const int li = limb_of[static_cast<size_t>(i)];
        const bool fin = li >= 0 && c.limbs[static_cast<size_t>(li)].kind == LimbKind::kFin;
        long_bone(lb, L, fin ? 0.6f * w : w);
        shape = lb;
        break;
      }
      case BoneKind::kHand: {
        PathBuilder hb, hh;
        const int li = limb_of[static_cast<size_t>(i)];
        const HandShape hs = li >= 0 ? hand_shape(c, c.limbs[static_cast<size_t>(li)], winged, s,
                                                          glm::normalize(glm::vec2(mi.m[0], mi.m[1])))
                                     : HandShape::kFlat;
        hand(hb, hh, ctx, hs);
        shape = hb;
        holes = hh;
        break;
      }
    }
    if (shape.empty()) continue;
    for (glm::vec2 p : shape.points()) bounds.add(mi.apply(p));
    max_extent = std::max(max_extent, L);

    std::string& out = layers[static_cast<int>(s.layer(i))];
    out += "<g transform=\"matrix(";
    for (int k = 0; k < 6; ++k) {
      if (k) out += ' ';
      append_num(out, mi.m[k]);
    }
    out += ")\" data-bone=\"" + xml_escape(s.name(i)) + "\"><path d=\"" + shape.data() + "\"/>";
    if (!holes.empty()) {
      out += "<path fill=\"" + std::string(kLayerStyles[static_cast<int>(s.layer(i))].hole) +
             "\" d=\"" + holes.data() + "\"/>";
    }
    out += "</g>\n";
  }

  if (bounds.empty()) bounds.add({0.0f, 0.0f}), bounds.add({1.0f, 1.0f});
  const float extent = std::max({bounds.hi.x - bounds.lo.x, bounds.hi.y - bounds.lo.y, 1e-6f});
  const float margin = std::max(0.0f, options.margin) * extent;
  const float stroke = 0.0025f * extent;

  Drawing d;
  std::string& g = d.content;
  g += "<g transform=\"scale(1 -1)\" stroke-width=\"" + num(stroke) +
       "\" stroke-linejoin=\"round\">\n";
  if (options.ground) {
    const float x0 = bounds.lo.x - margin, x1 = bounds.hi.x + margin;
    const float depth = 0.6f * margin;
    g += "<rect x=\"" + num(x0) + "\" y=\"" + num(-depth) + "\" width=\"" + num(x1 - x0) +
         "\" height=\"" + num(depth) + "\" fill=\"#d8d2c4\" stroke=\"none\"/>\n";
    g += "<line x1=\"" + num(x0) + "\" y1=\"0\" x2=\"" + num(x1) + "\" y2=\"0\" stroke=\"#7a705e\" "
         "stroke-width=\"" + num(2.0f * stroke) + "\"/>\n";
    bounds.add({x0, -depth});
    bounds.add({x1, 0.0f});
  }
  for (int l = 0; l < kLayerCount; ++l) {
    if (!layers[l].empty()) {
      g += "<g class=\"" + std::string(layer_name(static_cast<Layer>(l))) + "\" fill=\"" +
           kLayerStyles[l].fill + "\" stroke=\"" + kLayerStyles[l].stroke + "\">\n" + layers[l] +
           "</g>\n";
    }
    if (options.body && !options.body->layers[static_cast<size_t>(l)].empty()) {
      g += "<g class=\"body-" + std::string(layer_name(static_cast<Layer>(l))) + "\" stroke=\"none\"";
      if (options.body->opacity < 1.0f) g += " opacity=\"" + num(options.body->opacity) + "\"";
      g += ">\n" + options.body->layers[static_cast<size_t>(l)] + "</g>\n";
    }
  }
  g += "</g>\n";
  d.vx = bounds.lo.x - margin;
  d.vy = -(bounds.hi.y + margin);
  d.vw = bounds.hi.x - bounds.lo.x + 2.0f * margin;
  d.vh = bounds.hi.y - bounds.lo.y + 2.0f * margin;
  if (options.ground) d.vh -= margin;  // the soil strip already adds space below y = 0
  return d;
}

std::string view_box(const Drawing& d) {
  return num(d.vx) + " " + num(d.vy) + " " + num(d.vw) + " " + num(d.vh);
}

}  // namespace

// [SECTION] Documents ------------------------------------------------------------------------

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters other than tab/newline are not allowed in XML 1.0.
        if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') {
          out += '?';
        } else {
          out += ch;
        }
    }
  }
  return out;
}

std::string creature_svg(const Creature& creature, const SvgOptions& options) {
  const Drawing d = draw_creature(creature, options);
  const int width = std::max(16, options.width_px);
  const int height = std::max(16, static_cast<int>(std::lround(width * d.vh / d.vw)));
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" viewBox=\"" + view_box(d) + "\">\n";
  if (options.title) out += "<title>" + xml_escape(creature.name) + "</title>\n";
  out += "<rect x=\"" + num(d.vx) + "\" y=\"" + num(d.vy) + "\" width=\"" + num(d.vw) +
         "\" height=\"" + num(d.vh) + "\" fill=\"#ffffff\"/>\n";
  out += d.content;
  out += "</svg>\n";
  return out;
}

std::string sheet_svg(const std::vector<std::pair<std::string, Creature>>& creatures,
                      int columns, const std::vector<int>& skull_variants,
                      const SvgOptions& options, const std::vector<SvgBody>& bodies) {
  columns = std::max(1, columns);
  const int count = static_cast<int>(creatures.size());
  const int rows = std::max(1, (count + columns - 1) / columns);
  const int cell_w = 240, cell_h = 170, label_h = 36, pad = 8;
  const int width = columns * cell_w, height = rows * (cell_h + label_h);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
         " " + std::to_string(height) + "\">\n<rect width=\"" + std::to_string(width) +
         "\" height=\"" + std::to_string(height) + "\" fill=\"#ffffff\"/>\n";
  for (int i = 0; i < count; ++i) {
    SvgOptions o = options;
    if (skull_variants.size() == creatures.size()) o.skull_variant = skull_variants[static_cast<size_t>(i)];
    if (bodies.size() == creatures.size()) o.body = &bodies[static_cast<size_t>(i)];
    const Drawing d = draw_creature(creatures[static_cast<size_t>(i)].second, o);
    const int x = (i % columns) * cell_w, y = (i / columns) * (cell_h + label_h);
    out += "<svg x=\"" + std::to_string(x + pad) + "\" y=\"" + std::to_string(y + pad) +
           "\" width=\"" + std::to_string(cell_w - 2 * pad) + "\" height=\"" +
           std::to_string(cell_h - pad) + "\" viewBox=\"" + view_box(d) +
           "\" preserveAspectRatio=\"xMidYMax meet\">\n" + d.content + "</svg>\n";
    // Label: "english (German)" on two lines, the part in parentheses smaller.
    const std::string& label = creatures[static_cast<size_t>(i)].first;
    const size_t paren = label.find(" (");
    const std::string line1 = label.substr(0, paren);
    const std::string line2 = paren == std::string::npos ? std::string() : label.substr(paren + 1);
    out += "<text x=\"" + std::to_string(x + cell_w / 2) + "\" y=\"" +
           std::to_string(y + cell_h + 14) +
           "\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"15\" "
           "fill=\"#333333\">" + xml_escape(line1);
    if (!line2.empty()) {
      out += "<tspan x=\"" + std::to_string(x + cell_w / 2) +
             "\" dy=\"16\" font-size=\"12\" fill=\"#666666\">" + xml_escape(line2) + "</tspan>";
    }
    out += "</text>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace ossa
