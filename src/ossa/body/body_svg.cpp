#include "ossa/body/body_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>

#include "ossa/body/coat.h"

namespace ossa {

namespace {

void append_num(std::string& out, float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.5g", std::isfinite(v) ? static_cast<double>(v) : 0.0);
  out += buf;
}

// The colour of a triangle: its vertices' mean coat with the pattern at its centre.
std::array<uint8_t, 4> triangle_colour(const BodyVertex& a, const BodyVertex& b, const BodyVertex& c) {
  glm::vec4 col(0.0f), pat(0.0f);
  for (const BodyVertex* v : {&a, &b, &c}) {
    for (int i = 0; i < 4; ++i) {
      col[i] += v->colour[static_cast<size_t>(i)] / (3.0f * 255.0f);
      pat[i] += v->pattern[static_cast<size_t>(i)] / (3.0f * 255.0f);
    }
  }
  const auto kind = static_cast<CoatPattern>(a.pattern_kind);
  if (kind != CoatPattern::kNone && pat.a > 0.0f) {
    const float m = coat_pattern(kind, (a.coat_uv + b.coat_uv + c.coat_uv) / 3.0f) * pat.a;
    col = glm::vec4(glm::mix(glm::vec3(col), glm::vec3(pat), m), col.a);
  }
  // Quantised to 5 bits a channel, so neighbouring triangles of one colour share a path.
  std::array<uint8_t, 4> out = to_rgba8(col);
  for (int i = 0; i < 3; ++i) out[static_cast<size_t>(i)] = static_cast<uint8_t>(std::min(255, (out[static_cast<size_t>(i)] & 0xf8) + 4));
  out[3] = static_cast<uint8_t>(out[3] & 0xf0);
  return out;
}

}  // namespace

SvgBody body_svg_layers(const BodyMesh& mesh, float opacity) {
  SvgBody out;
  out.opacity = opacity;
  const Box box = body_bounds(mesh);
  out.lo = box.min_ws;
  out.hi = box.max_ws;
  for (int l = 0; l < kLayerCount; ++l) {
    std::string& g = out.layers[static_cast<size_t>(l)];
    std::array<uint8_t, 4> current{0, 0, 0, 0};
    bool open = false;
    for (uint32_t i = mesh.layer_begin[static_cast<size_t>(l)]; i + 2 < mesh.layer_begin[static_cast<size_t>(l) + 1]; i += 3) {
      const BodyVertex& a = mesh.vertices[mesh.indices[i]];
      const BodyVertex& b = mesh.vertices[mesh.indices[i + 1]];
      const BodyVertex& c = mesh.vertices[mesh.indices[i + 2]];
      const std::array<uint8_t, 4> col = triangle_colour(a, b, c);
      if (col[3] == 0) continue;
      if (!open || col != current) {
        if (open) g += "\"/>\n";
        char head[96];
        std::snprintf(head, sizeof head, "<path fill=\"#%02x%02x%02x\"%s", col[0], col[1], col[2], col[3] < 255 ? "" : "");
        g += head;
        if (col[3] < 240) {
          g += " fill-opacity=\"";
          append_num(g, col[3] / 255.0f);
          g += "\"";
        }
        // A hairline of the fill's own colour closes the gaps renderers leave between triangles.
        std::snprintf(head, sizeof head, " stroke=\"#%02x%02x%02x\" stroke-width=\"", col[0], col[1], col[2]);
        g += head;
        append_num(g, 0.0015f * std::max(box.max_ws.x - box.min_ws.x, box.max_ws.y - box.min_ws.y));
        g += "\" stroke-linejoin=\"round\" d=\"";
        current = col;
        open = true;
      }
      g += 'M';
      for (const BodyVertex* v : {&a, &b, &c}) {
        append_num(g, v->position_ms.x);
        g += ' ';
        append_num(g, v->position_ms.y);
        g += v == &c ? 'Z' : 'L';
      }
    }
    if (open) g += "\"/>\n";
  }
  return out;
}

std::string look_svg(const Creature& creature, CreatureLook look, const SvgOptions& options) {
  if (look == CreatureLook::kBones) return creature_svg(creature, options);
  const BodyMesh mesh = build_body(creature);
  const SvgBody body = body_svg_layers(mesh, look == CreatureLook::kXray ? kXrayBodyAlpha : 1.0f);
  SvgOptions o = options;
  o.body = &body;
  o.bones = look == CreatureLook::kXray;
  return creature_svg(creature, o);
}

std::string look_sheet_svg(const std::vector<std::pair<std::string, Creature>>& creatures, int columns,
                           const std::vector<int>& skull_variants, CreatureLook look, const SvgOptions& options) {
  if (look == CreatureLook::kBones) return sheet_svg(creatures, columns, skull_variants, options);
  std::vector<SvgBody> bodies;
  for (const auto& [name, creature] : creatures) {
    bodies.push_back(body_svg_layers(build_body(creature), look == CreatureLook::kXray ? kXrayBodyAlpha : 1.0f));
  }
  SvgOptions o = options;
  o.bones = look == CreatureLook::kXray;
  return sheet_svg(creatures, columns, skull_variants, o, bodies);
}

}  // namespace ossa
