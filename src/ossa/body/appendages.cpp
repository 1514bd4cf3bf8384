// Appendages of the body (gen/look.h): ears, horns, antlers, frill, crest, mane, trunk, sail,
// plates, shell, dorsal and tail fins, and the eye (body_parts.h). Head parts are placed in
// the skull's frame (origin at the back of the skull, +x to the snout, +y its top; the
// skull's length Ls and height Hs size them) and follow the skull; back parts stand on the
// axial body's back line and follow its vertebrae; tail fins follow the last tail vertebra.
// A part's size factor (Appendage::size) scales its default size for the body.

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "ossa/body/body_parts.h"

namespace ossa::body {

namespace {

constexpr float kPi = 3.14159265f;

glm::vec2 polar(float angle, float r) { return {r * std::cos(angle), r * std::sin(angle)}; }

struct HeadFrame {
  Mat2x3 m;
  float Ls = 0.0f, Hs = 0.0f;
  Skin skin;
  glm::vec2 at(float x, float y) const { return m.apply({x, y}); }
};

// A tube along points (model space) with radii, rigid to `skin`.
TubePlan curve_tube(const std::vector<glm::vec2>& pts, const std::vector<float>& radii, BodyPartKind kind,
                    const Skin& skin) {
  TubePlan t;
  t.kind = kind;
  t.depth = 1.0f;
  t.start_cap = Cap::kRound;
  t.end_cap = Cap::kPoint;
  t.pattern = 0.0f;
  for (size_t i = 0; i < pts.size(); ++i) {
    const glm::vec2 d = pts[std::min(i + 1, pts.size() - 1)] - pts[i > 0 ? i - 1 : 0];
    const float len = glm::length(d);
    Section s;
    s.centre = pts[i];
    s.dorsal = dorsal_of(len > 1e-9f ? d / len : glm::vec2(1.0f, 0.0f));
    s.top_fixed = s.bottom_fixed = radii[i];
    s.skin = skin;
    t.sections.push_back(s);
  }
  return t;
}

// Points along a circular arc from `start` leaving at `angle`, turning `turn` radians over
// `length` (model space).
std::vector<glm::vec2> arc(glm::vec2 start, float angle, float turn, float length, int n) {
  std::vector<glm::vec2> pts{start};
  glm::vec2 p = start;
  for (int i = 1; i <= n; ++i) {
    const float a = angle + turn * (static_cast<float>(i) - 0.5f) / static_cast<float>(n);
    p += polar(a, length / static_cast<float>(n));
    pts.push_back(p);
  }
  return pts;
}

float skull_angle(const HeadFrame& h) { return std::atan2(h.m.m[1], h.m.m[0]); }

FlatPlan flat(BodyPartKind kind, std::vector<glm::vec2> outline, const Skin& skin, glm::vec4 colour, float depth) {
  FlatPlan f;
  f.kind = kind;
  glm::vec2 c(0.0f);
  for (const glm::vec2 p : outline) c += p;
  f.centre = c / static_cast<float>(std::max<size_t>(outline.size(), 1));
  f.outline = std::move(outline);
  f.skin.assign(f.outline.size(), skin);
  f.centre_skin = skin;
  f.colour = colour;
  f.depth = depth;
  return f;
}

// The axial body's back line at `girth` between arc lengths [s0, s1] of its sections:
// (section index, top point, skin).
struct BackPoint {
  glm::vec2 top, dorsal;
  float thickness;
  Skin skin;
  float s;
};

std::vector<BackPoint> back_line(const BodyRig& rig, const TubePlan& axial, float s0, float s1, float girth) {
  std::vector<BackPoint> out;
  // Section arc lengths: distances along the centre line from the snout.
  float s = 0.0f;
  for (size_t i = 0; i < axial.sections.size(); ++i) {
    if (i > 0) s += glm::length(axial.sections[i].centre - axial.sections[i - 1].centre);
    if (s < s0 || s > s1) continue;
    const Section& sec = axial.sections[i];
    out.push_back({section_top(sec, girth), sec.dorsal, sec.top(girth) + sec.bottom(girth), sec.skin, s});
  }
  (void)rig;
  return out;
}

}  // namespace

void plan_appendages(const BodyRig& rig, BodyParts& plan, float girth) {
  const Creature& c = *rig.creature;
  const Look& look = c.look;
  const float B = rig.back_length;
  // A copy: appending tubes below moves plan.tubes.
  std::optional<TubePlan> axial;
  for (const TubePlan& t : plan.tubes) {
    if (t.kind == BodyPartKind::kAxial) axial = t;
  }
  if (!axial) return;
  const float floor = 0.002f * B;
  const auto above_ground = [&](std::vector<glm::vec2>& pts) {
    for (glm::vec2& p : pts) p.y = std::max(p.y, floor);
  };
  bool trunk = false, frill = false;
  for (const Appendage& a : c.appendages) {
    trunk |= a.kind == AppendageKind::kTrunk;
    frill |= a.kind == AppendageKind::kFrill;
  }
  const glm::vec4 horn_colour(0.2f, 0.18f, 0.16f, 1.0f);
  const glm::vec4 dark(glm::mix(look.base, look.pattern_colour, 0.6f), 1.0f);

  HeadFrame head;
  const bool has_head = c.skull >= 0 && rig.skull_length > 0.0f;
  if (has_head) {
    head.m = rig.rest[static_cast<size_t>(c.skull)];
    head.Ls = rig.skull_length;
    head.Hs = std::max(rig.skull_height, 0.1f * rig.skull_length);
    head.skin = Skin::rigid(c.skull);
  }
  const float up_angle = has_head ? skull_angle(head) : 0.0f;  // model angle of the skull's +x

  for (const Appendage& a : c.appendages) {
    const float k = a.size;
    switch (a.kind) {
      case AppendageKind::kEars: {
        if (!has_head) break;
        for (int side = 0; side < 2; ++side) {
          const bool near = side == 0;
          const glm::vec2 base = head.at((near ? 0.2f : 0.14f) * head.Ls, 0.4f * head.Hs);
          std::vector<glm::vec2> pts;
          if (trunk) {  // a flap hanging behind the head, from the cranium down to the jaw
            const float len = k * 0.6f * head.Hs;
            const glm::vec2 top = head.at((near ? 0.12f : 0.08f) * head.Ls, 0.35f * head.Hs);
            pts.push_back(top);
            for (int i = 0; i <= 8; ++i) {
              const float t = static_cast<float>(i) / 8.0f;
              // From pointing back to pointing down, the flap's edge.
              pts.push_back(top + polar(kPi * (0.95f + 0.6f * t), len * (0.75f + 0.35f * std::sin(kPi * t))));
            }
          } else {  // a leaf standing up and back
            const float len = k * 0.55f * head.Hs, w = 0.2f * len;
            const float a0 = up_angle + kPi * 0.62f;
            const glm::vec2 dir = polar(a0, 1.0f), n(-dir.y, dir.x);
            pts = {base - n * w, base + dir * (0.5f * len) - n * (1.3f * w), base + dir * len,
                   base + dir * (0.55f * len) + n * (1.2f * w), base + n * w};
          }
          above_ground(pts);
          FlatPlan f = flat(BodyPartKind::kEar, std::move(pts), head.skin, glm::vec4(-1.0f), 0.05f);
          f.layer = near ? Layer::kNear : Layer::kFar;
          f.pattern = 0.5f;
          plan.flats.push_back(std::move(f));
        }
        break;
      }
      case AppendageKind::kHorns: {
        if (!has_head) break;
        // Brow horns pointing forward on a frilled head; else a bovid's curve, up and back
        // then forward.
        const glm::vec2 base = frill ? head.at(0.55f * head.Ls, 0.45f * head.Hs) : head.at(0.28f * head.Ls, 0.45f * head.Hs);
        const float len = (frill ? 0.9f * head.Ls : 0.8f * head.Hs) * k;
        const std::vector<glm::vec2> pts = frill ? arc(base, up_angle + 0.55f, 0.3f, len, 6)
                                                 : arc(base, up_angle + 1.9f, -2.2f, len, 8);
        std::vector<float> r;
        for (size_t i = 0; i < pts.size(); ++i) r.push_back(0.11f * len * (1.0f - static_cast<float>(i) / static_cast<float>(pts.size() - 1)) + 0.004f * len);
        TubePlan t = curve_tube(pts, r, BodyPartKind::kHorn, head.skin);
        t.colour = horn_colour;
        t.order = 3;
        plan.tubes.push_back(std::move(t));
        break;
      }
      case AppendageKind::kAntlers: {
        if (!has_head) break;
        const glm::vec2 base = head.at(0.3f * head.Ls, 0.45f * head.Hs);
        const float len = k * 1.6f * head.Hs;
        const std::vector<glm::vec2> beam = arc(base, up_angle + 1.95f, -1.4f, len, 10);
        const glm::vec4 antler(0.55f, 0.47f, 0.36f, 1.0f);
        std::vector<float> r;
        for (size_t i = 0; i < beam.size(); ++i) r.push_back(0.05f * len * (1.0f - 0.7f * static_cast<float>(i) / static_cast<float>(beam.size() - 1)));
        TubePlan t = curve_tube(beam, r, BodyPartKind::kAntler, head.skin);
        t.colour = antler;
        t.order = 3;
        plan.tubes.push_back(std::move(t));
        for (const float at : {0.25f, 0.5f, 0.75f}) {  // tines, forward and up
          const size_t i = static_cast<size_t>(at * static_cast<float>(beam.size() - 1));
          const std::vector<glm::vec2> tine = arc(beam[i], up_angle + 0.9f, 0.4f, 0.35f * len, 4);
          std::vector<float> tr;
          for (size_t j = 0; j < tine.size(); ++j) tr.push_back(0.6f * r[i] * (1.0f - static_cast<float>(j) / static_cast<float>(tine.size())));
          TubePlan tt = curve_tube(tine, tr, BodyPartKind::kAntler, head.skin);
          tt.colour = antler;
          tt.order = 3;
          plan.tubes.push_back(std::move(tt));
        }
        break;
      }
      case AppendageKind::kFrill: {
        if (!has_head) break;
        const glm::vec2 centre = head.at(0.15f * head.Ls, 0.1f * head.Hs);
        const float R = k * 0.85f * head.Ls;
        std::vector<glm::vec2> pts{head.at(0.35f * head.Ls, 0.35f * head.Hs)};
        for (int i = 0; i <= 10; ++i) {
          const float t = static_cast<float>(i) / 10.0f;
          const float scallop = 1.0f - 0.06f * (i % 2);
          pts.push_back(centre + polar(up_angle + 1.2f + 1.7f * t, R * scallop));
        }
        pts.push_back(head.at(0.0f, -0.2f * head.Hs));
        above_ground(pts);
        FlatPlan f = flat(BodyPartKind::kFrill, std::move(pts), head.skin, glm::vec4(glm::mix(look.base, look.pattern_colour, 0.3f), 1.0f), 0.06f);
        f.order = 1;
        plan.flats.push_back(std::move(f));
        break;
      }
      case AppendageKind::kCrest: {
        if (!has_head) break;
        const glm::vec2 base = head.at(0.45f * head.Ls, 0.35f * head.Hs);
        const float len = k * 0.45f * head.Ls;
        const std::vector<glm::vec2> pts = arc(base, up_angle + 2.6f, -0.25f, len, 6);
        std::vector<float> r;
        for (size_t i = 0; i < pts.size(); ++i) r.push_back(head.Hs * (0.16f - 0.08f * static_cast<float>(i) / static_cast<float>(pts.size() - 1)));
        TubePlan t = curve_tube(pts, r, BodyPartKind::kCrest, head.skin);
        t.end_cap = Cap::kRound;
        const glm::vec4 crest(glm::mix(look.base, look.pattern_colour, 0.4f), 1.0f);
        t.colour = crest;
        t.order = 2;
        plan.tubes.push_back(std::move(t));
        break;
      }
      case AppendageKind::kTrunk: {
        if (!has_head) break;
        const glm::vec2 tip = head.at(head.Ls, -0.05f * head.Hs);
        const float len = k * 1.7f * head.Ls;
        std::vector<glm::vec2> pts = arc(tip, -kPi * 0.5f - 0.35f, -0.6f, len, 10);
        // A trunk reaching the ground curls up instead.
        const float low = pts.front().y - floor - 0.02f * B;
        for (size_t i = 1; i < pts.size(); ++i) {
          const float drop = pts.front().y - pts[i].y;
          if (drop > low && drop > 0.0f) pts[i].y = pts.front().y - low * (0.9f + 0.1f * low / std::max(drop, 1e-6f));
        }
        std::vector<float> r;
        for (size_t i = 0; i < pts.size(); ++i) r.push_back(head.Hs * (0.26f - 0.18f * static_cast<float>(i) / static_cast<float>(pts.size() - 1)));
        TubePlan t = curve_tube(pts, r, BodyPartKind::kTrunk, head.skin);
        t.end_cap = Cap::kRound;
        t.pattern = 1.0f;
        t.order = 2;
        plan.tubes.push_back(std::move(t));
        break;
      }
      case AppendageKind::kMane: {
        const std::vector<BackPoint> line = back_line(rig, *axial, rig.snout_s, rig.shoulder_s + 0.12f * B, girth);
        if (line.size() < 2) break;
        std::vector<glm::vec2> inner, outer;
        std::vector<Skin> skins;
        for (size_t i = 0; i < line.size(); ++i) {
          const BackPoint& p = line[i];
          const float h = k * (0.05f * B) * (0.6f + 0.4f * std::sin(kPi * static_cast<float>(i) / static_cast<float>(line.size() - 1)));
          inner.push_back(p.top - p.dorsal * (0.1f * p.thickness));
          outer.push_back(p.top + p.dorsal * (h * (i % 2 ? 0.8f : 1.0f)));
          skins.push_back(p.skin);
        }
        FlatPlan f;
        f.kind = BodyPartKind::kMane;
        for (const glm::vec2 p : outer) f.outline.push_back(p);
        for (size_t i = inner.size(); i-- > 0;) f.outline.push_back(inner[i]);
        for (const Skin& s : skins) f.skin.push_back(s);
        for (size_t i = skins.size(); i-- > 0;) f.skin.push_back(skins[i]);
        f.centre = 0.5f * (inner[inner.size() / 2] + outer[outer.size() / 2]);
        f.centre_skin = skins[skins.size() / 2];
        f.colour = glm::vec4(glm::mix(look.base * 0.45f, look.pattern_colour, 0.5f), 1.0f);
        f.depth = 0.05f;
        f.order = 2;
        plan.flats.push_back(std::move(f));
        break;
      }
      case AppendageKind::kSail:
      case AppendageKind::kDorsalFin: {
        const bool sail = a.kind == AppendageKind::kSail;
        const float back_len = rig.hip_s - rig.shoulder_s;
        const float s0 = rig.shoulder_s + (sail ? 0.08f : 0.35f) * back_len, s1 = rig.shoulder_s + (sail ? 0.92f : 0.65f) * back_len;
        const std::vector<BackPoint> line = back_line(rig, *axial, s0, s1, girth);
        if (line.size() < 2) break;
        const float height = k * (sail ? 0.45f : 0.16f) * B;
        std::vector<glm::vec2> pts;
        std::vector<Skin> skins;
        for (const BackPoint& p : line) {  // the base, inside the back
          pts.push_back(p.top - p.dorsal * (0.25f * p.thickness));
          skins.push_back(p.skin);
        }
        std::reverse(pts.begin(), pts.end());
        std::reverse(skins.begin(), skins.end());
        for (size_t i = 0; i < line.size(); ++i) {  // the edge
          const float t = static_cast<float>(i) / static_cast<float>(line.size() - 1);
          const float h = sail ? height * std::sin(kPi * (0.08f + 0.84f * t)) : height * std::pow(1.0f - t, 0.7f);
          const glm::vec2 lean = sail ? glm::vec2(0.0f) : glm::normalize(line.back().top - line.front().top) * (0.35f * h);
          pts.push_back(line[i].top + line[i].dorsal * h + lean);
          skins.push_back(line[i].skin);
        }
        FlatPlan f;
        f.kind = sail ? BodyPartKind::kSail : BodyPartKind::kDorsalFin;
        f.outline = std::move(pts);
        f.skin = std::move(skins);
        f.centre = 0.5f * (line[line.size() / 2].top + line[line.size() / 2].top + line[line.size() / 2].dorsal * (0.3f * height));
        f.centre_skin = line[line.size() / 2].skin;
        f.colour = glm::vec4(look.base * (sail ? 0.85f : 0.8f), sail ? 1.0f : 0.95f);
        f.depth = sail ? 0.03f : 0.08f;
        f.order = -1;
        plan.flats.push_back(std::move(f));
        break;
      }
      case AppendageKind::kPlates: {
        const float s0 = rig.shoulder_s + 0.05f * (rig.hip_s - rig.shoulder_s);
        const float s1 = rig.hip_s + 0.6f * (rig.tail_s - rig.hip_s);
        const std::vector<BackPoint> line = back_line(rig, *axial, s0, s1, girth);
        const int plates = 11;
        if (line.size() < 2) break;
        for (int i = 0; i < plates; ++i) {
          const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(plates);
          const BackPoint& p = line[std::min(line.size() - 1, static_cast<size_t>(t * static_cast<float>(line.size())))];
          const float h = k * 0.24f * B * (0.35f + 0.65f * std::sin(kPi * std::min(1.0f, 0.15f + 0.95f * t)));
          const glm::vec2 d = p.dorsal, along(-d.y, d.x);
          const glm::vec2 base = p.top - d * (0.2f * p.thickness);
          std::vector<glm::vec2> pts{base - along * (0.32f * h), base + d * (0.55f * h) - along * (0.38f * h),
                                     base + d * h - along * (0.1f * h), base + d * (0.6f * h) + along * (0.25f * h),
                                     base + along * (0.3f * h)};
          FlatPlan f = flat(BodyPartKind::kPlate, std::move(pts), p.skin, glm::vec4(glm::mix(look.base, look.pattern_colour, 0.35f), 1.0f), 0.05f);
          f.order = i % 2 ? -2 : -1;
          plan.flats.push_back(std::move(f));
        }
        // Tail spikes near the tip (the thagomizer), pointing back and up.
        if (!c.tail.empty()) {
          const int tip_bone = c.tail[c.tail.size() * 4 / 5];
          const glm::vec2 at = rig.bone_start(tip_bone), dir = rig.bone_dir(tip_bone);
          for (const float a : {0.7f, 1.1f}) {
            const float len = k * 0.16f * B;
            const glm::vec2 spike_dir = glm::vec2(dir.x * std::cos(a) - dir.y * std::sin(a), dir.x * std::sin(a) + dir.y * std::cos(a));
            TubePlan t = curve_tube({at, at + spike_dir * len}, {0.09f * len, 0.0f}, BodyPartKind::kHorn, Skin::rigid(tip_bone));
            t.colour = horn_colour;
            t.order = -1;
            plan.tubes.push_back(std::move(t));
          }
        }
        break;
      }
      case AppendageKind::kShell: {
        // A carapace over the trunk: a plate thin over the spine, its rim down to the belly
        // line, from a little before the shoulder to a little behind the hip.
        const float back_len = rig.hip_s - rig.shoulder_s;
        const float s0 = rig.shoulder_s - 0.1f * back_len, s1 = rig.hip_s + 0.1f * back_len;
        const std::vector<BackPoint> line = back_line(rig, *axial, s0, s1, girth);
        if (line.size() < 3) break;
        TubePlan t;
        t.kind = BodyPartKind::kShell;
        t.depth = 1.1f;
        t.start_cap = t.end_cap = Cap::kRound;
        t.end_cap_length = 0.35f;
        t.order = 1;
        t.pattern = 1.0f;
        for (size_t i = 0; i < line.size(); ++i) {
          const float x = 2.0f * static_cast<float>(i) / static_cast<float>(line.size() - 1) - 1.0f;
          const float rim = std::sqrt(std::max(1.0f - x * x, 0.0f));
          Section sec;
          sec.dorsal = line[i].dorsal;
          sec.centre = line[i].top;
          sec.top_fixed = k * 0.05f * B * (0.4f + 0.6f * rim);
          sec.bottom_fixed = std::max(0.85f * line[i].thickness * (0.35f + 0.65f * rim), 0.02f * B);
          sec.skin = line[i].skin;
          const float room = std::max(sec.centre.y - 0.25f * floor - 0.02f * B, 0.0f);
          if (sec.dorsal.y > 0.05f) sec.bottom_cap = room / sec.dorsal.y;
          t.sections.push_back(sec);
        }
        const glm::vec4 shell(glm::mix(look.base, look.pattern_colour, 0.3f), 1.0f);
        t.colour = shell;
        plan.tubes.push_back(std::move(t));
        break;
      }
      case AppendageKind::kTailFin: {
        if (c.tail.empty() && c.back.empty()) break;
        const int bone = !c.tail.empty() ? c.tail.back() : c.back.back();
        const glm::vec2 tip = rig.bone_end(bone), dir = rig.bone_dir(bone);
        const glm::vec2 up(-dir.y, dir.x);
        const glm::vec2 n = up.y >= 0.0f ? up : -up;  // the fin's upper side
        const float len = k * 0.2f * B;
        std::vector<glm::vec2> pts;
        if (c.skull_variant == 0) {  // a whale's fluke, seen edge-on: a thin blade
          pts = {tip + n * (0.05f * len), tip + dir * len + n * (0.1f * len), tip + dir * (1.05f * len), tip + dir * len - n * (0.08f * len),
                 tip - n * (0.05f * len)};
        } else {  // a fish's forked fin (an ichthyosaur's crescent)
          const float fork = c.skull_variant == 2 ? 0.35f : 0.55f;
          pts = {tip + n * (0.12f * len), tip + dir * len + n * (0.75f * len), tip + dir * (fork * len),
                 tip + dir * len - n * (0.7f * len), tip - n * (0.12f * len)};
        }
        // Above the ground: the fin shrinks toward the tail's tip (its shape kept) until its
        // lowest point clears it.
        float lowest = tip.y;
        for (const glm::vec2 p : pts) lowest = std::min(lowest, p.y);
        if (lowest < floor && tip.y > floor) {
          const float k_shrink = (tip.y - floor) / std::max(tip.y - lowest, 1e-6f);
          for (glm::vec2& p : pts) {
            if (p.y < tip.y) p = tip + (p - tip) * glm::vec2(1.0f, k_shrink);
          }
        }
        above_ground(pts);
        FlatPlan f = flat(BodyPartKind::kTailFin, std::move(pts), Skin::rigid(bone), glm::vec4(look.base * 0.85f, 1.0f), 0.06f);
        f.order = -1;
        plan.flats.push_back(std::move(f));
        break;
      }
      case AppendageKind::kHump: break;  // part of the axial body's back line (axial.cpp)
    }
  }

  // The eye, on the near side of the head.
  if (has_head) {
    const float eye_u = std::clamp(rig.snout + 0.1f * (1.0f - rig.snout), 0.0f, 0.95f);
    const float r = head.Hs * (c.skull_variant == 1 ? 0.1f : c.skull_variant == 3 ? 0.11f : 0.075f);
    const glm::vec2 centre = head.at(head.Ls * (1.0f - eye_u), (c.skull_variant == 3 ? 0.1f : 0.17f) * head.Hs);
    std::vector<glm::vec2> pts;
    for (int i = 0; i < 10; ++i) pts.push_back(centre + polar(2.0f * kPi * static_cast<float>(i) / 10.0f, r));
    FlatPlan f = flat(BodyPartKind::kEye, std::move(pts), head.skin, glm::vec4(0.08f, 0.06f, 0.05f, 1.0f), 0.0f);
    f.order = 9;
    plan.flats.push_back(std::move(f));
  }
}

}  // namespace ossa::body
