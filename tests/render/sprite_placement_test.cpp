// Bone sprites on their bones (issue 30): every sprite's joint anchors — found through the
// texture, where the art puts them — land on its bone's joints within a pixel of a 1024 px wide
// picture, in the rest pose and mid-stride, for the 44 examples and 50 random creatures; feet
// stand on their contact with no claw, hoof or toe below the ground; a sprite is as thick as
// its bone's width, not its length; a skull's muzzle follows the genome; and the art is drawn
// the right way up.

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <algorithm>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "ossa/game/player.h"
#include "ossa/platform/image.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/skeleton/pose.h"
#include "shared/level_scenes.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

std::vector<std::pair<std::string, std::shared_ptr<const Creature>>> creatures() {
  std::vector<std::pair<std::string, std::shared_ptr<const Creature>>> out;
  for (const Animal& a : scenes::generator().dataset().animals) {
    out.emplace_back(a.name, std::make_shared<const Creature>(build_creature(scenes::generator().example(a.name).value()).value()));
  }
  // The random creatures in the 2 m frame, the moment sampled mid-stride as before true size.
  // (Sampled: one moment. At other moments random 7 and 50 stand on a forefoot turned 2.6 rad
  // from rest, the flat-foot art upside down, 5-6 px into the ground at either size — the
  // animator's foot roll, README Known limits.)
  GenerateOptions framed;
  framed.genome.true_size = false;
  for (uint64_t seed = 1; seed <= 50; ++seed) {
    out.emplace_back("random " + std::to_string(seed),
                     std::make_shared<const Creature>(build_creature(scenes::generator().random(seed, framed)).value()));
  }
  return out;
}

// The palette of a pose (bones' world matrices), with the mesh's mid joints.
std::vector<Mat2x3> palette_of(const SpriteMesh& mesh, const std::vector<Mat2x3>& world) {
  std::vector<Mat2x3> palette(static_cast<size_t>(mesh.palette_size()));
  for (size_t i = 0; i < world.size(); ++i) palette[i] = world[i] * mesh.inverse_bind[i];
  mid_joint_palette(mesh.mid_joints, world, palette);
  return palette;
}

// Where the texture point `uv` of `bone`'s sprite is drawn: the triangle of the bone's strip
// holding it in texture space, its corners skinned and mixed by barycentric weights.
std::optional<glm::vec2> drawn_at(const SpriteMesh& mesh, int bone, glm::vec2 uv, const std::vector<Mat2x3>& palette) {
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const SpriteVertex* v[3] = {&mesh.vertices[mesh.indices[i]], &mesh.vertices[mesh.indices[i + 1]],
                                &mesh.vertices[mesh.indices[i + 2]]};
    if (v[0]->bones[0] != bone || v[1]->bones[0] != bone || v[2]->bones[0] != bone) continue;
    const glm::vec2 a = v[0]->uv, b = v[1]->uv, c = v[2]->uv;
    const float det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (std::fabs(det) < 1e-12f) continue;
    const float l1 = ((uv.x - a.x) * (c.y - a.y) - (c.x - a.x) * (uv.y - a.y)) / det;
    const float l2 = ((b.x - a.x) * (uv.y - a.y) - (uv.x - a.x) * (b.y - a.y)) / det;
    const float l0 = 1.0f - l1 - l2;
    if (l0 < -1e-4f || l1 < -1e-4f || l2 < -1e-4f) continue;
    return l0 * skin_vertex(*v[0], palette) + l1 * skin_vertex(*v[1], palette) + l2 * skin_vertex(*v[2], palette);
  }
  return std::nullopt;
}

// One pixel of a 1024 px wide picture of the creature (its rest pose's sprites).
float pixel(const SpriteMesh& mesh) { return std::max(sprite_mesh_bounds(mesh).width(), 1e-6f) / 1024.0f; }

// A pose half way through a walk on flat ground: 0.9 s of walking, then 0.3 s of running.
std::vector<Mat2x3> mid_stride(const std::shared_ptr<const Creature>& c, const Level& level, std::vector<int>* stance = nullptr,
                               std::vector<glm::vec2>* contact = nullptr, const Animator** out = nullptr) {
  static std::unique_ptr<Player> player;
  player = std::make_unique<Player>(c, SplinePrototypes::defaults());
  player->animator().reset(level.spawn_ws, level);
  for (int t = 0; t < 108; ++t) player->step(1.0f / 120.0f, {0.5f, false, false}, level);
  for (int t = 0; t < 36; ++t) player->step(1.0f / 120.0f, {1.0f, true, false}, level);
  const Animator& a = player->animator();
  if (stance) {
    stance->clear();
    contact->clear();
    for (int leg = 0; leg < a.leg_count(); ++leg) {
      stance->push_back(a.leg_state(leg) == LegState::kStance ? a.leg_limb(leg).bones[2] : -1);
      contact->push_back(a.foot_ws(leg));
    }
  }
  if (out) *out = &a;
  return a.world_matrices();
}

}  // namespace

TEST_CASE("every sprite's joint anchors, found through the texture, land on its bone's joints within a pixel", "[render][sprites]") {
  const SpriteSet sprites = default_sprite_set();  // texture rectangles = unit boxes
  const Level level = scenes::flat_level(200.0f);
  for (const auto& entry : creatures()) {
    const std::string& name = entry.first;
    const auto& c = entry.second;  // (not a structured binding: clang 14 lambdas cannot capture one)
    for (bool smooth : {false, true}) {
      SpriteMeshOptions o;
      o.smooth_weights = smooth;
      const SpriteMesh mesh = build_sprite_mesh(*c, sprites, o);
      const float tol = pixel(mesh);
      const std::vector<int> chain = chain_children(c->skeleton, c->rest_pose.locals);
      std::vector<int> chain_parent(chain.size(), -1);
      for (size_t p = 0; p < chain.size(); ++p) {
        if (chain[p] >= 0) chain_parent[static_cast<size_t>(chain[p])] = static_cast<int>(p);
      }
      for (int pose = 0; pose < 2; ++pose) {
        const std::vector<Mat2x3> world = pose == 0 ? model_matrices(c->skeleton, c->rest_pose.locals) : mid_stride(c, level);
        const std::vector<Mat2x3> palette = palette_of(mesh, world);
        const auto start = [&](int b) { return bone_start(world[static_cast<size_t>(b)]); };
        const auto end = [&](int b) { return bone_end(world[static_cast<size_t>(b)], c->skeleton.length(b)); };
        for (int b = 0; b < c->skeleton.bone_count(); ++b) {
          if (!(c->skeleton.length(b) > 1e-6f)) continue;
          const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(b)]];
          INFO(name << (smooth ? " smooth " : " rigid ") << (pose ? "mid-stride " : "rest ") << c->skeleton.name(b));
          const std::optional<glm::vec2> p = drawn_at(mesh, b, info.parent_anchor, palette);
          const std::optional<glm::vec2> q = drawn_at(mesh, b, info.child_anchor, palette);
          REQUIRE(p.has_value());
          REQUIRE(q.has_value());
          // A blended joint sits where both bones put it; should a pose part the two (the
          // animator's legless crawl and body placement part a few neck joints from the back,
          // README Known limits), half way between them.
          const int cp = smooth ? chain_parent[static_cast<size_t>(b)] : -1, cc = smooth ? chain[static_cast<size_t>(b)] : -1;
          const glm::vec2 want_p = cp >= 0 ? 0.5f * (end(cp) + start(b)) : start(b);
          const glm::vec2 want_q = cc >= 0 ? 0.5f * (end(b) + start(cc)) : end(b);
          CHECK(glm::length(*p - want_p) <= tol);
          CHECK(glm::length(*q - want_q) <= tol);
          if (pose == 0 || !smooth) {  // the bone's own joints exactly
            CHECK(glm::length(*p - start(b)) <= tol);
            CHECK(glm::length(*q - end(b)) <= tol);
          }
        }
      }
    }
  }
}

TEST_CASE("feet stand on their contact: no claw, hoof or toe below the ground at rest or in stance", "[render][sprites]") {
  const SpriteSet sprites = default_sprite_set();
  std::vector<Image> images;
  for (const SpriteInfo& info : sprites.sprites) {
    auto image = load_image(scenes::source_path("assets/sprites/bones/" + info.file));
    REQUIRE(image.ok());
    images.push_back(std::move(image.value()));
  }
  const Level level = scenes::flat_level(200.0f);
  for (const auto& entry : creatures()) {
    const std::string& name = entry.first;
    const auto& c = entry.second;  // (not a structured binding: clang 14 lambdas cannot capture one)
    const SpriteMesh mesh = build_sprite_mesh(*c, sprites);
    const float tol = pixel(mesh);
    std::vector<int> stance;
    std::vector<glm::vec2> contact;
    for (int pose = 0; pose < 2; ++pose) {
      const std::vector<Mat2x3> world = pose == 0 ? model_matrices(c->skeleton, c->rest_pose.locals) : mid_stride(c, level, &stance, &contact);
      const std::vector<Mat2x3> palette = palette_of(mesh, world);
      for (const Limb& limb : c->limbs) {
        if (limb.kind != LimbKind::kLeg) continue;
        const int foot = limb.bones[2];
        // At rest every foot stands on y = 0; mid-stride the planted ones on their contact.
        float floor = 0.0f;
        if (pose == 1) {
          const auto it = std::find(stance.begin(), stance.end(), foot);
          if (it == stance.end()) continue;
          floor = contact[static_cast<size_t>(it - stance.begin())].y;
        }
        // The art's opaque texels, where the sprite draws them.
        const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(foot)]];
        const Image& art = images[static_cast<size_t>(mesh.bone_sprites[static_cast<size_t>(foot)])];
        float lowest = 1e30f;
        for (int y = 0; y < art.height; y += 2) {
          for (int x = 0; x < art.width; x += 2) {
            if (art.pixel(x, y)[3] < 128) continue;
            const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(art.width),
                               1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(art.height));
            if (const auto at = drawn_at(mesh, foot, uv, palette)) lowest = std::min(lowest, at->y);
          }
        }
        (void)info;
        INFO(name << (pose ? " mid-stride " : " rest ") << c->skeleton.name(foot) << ": lowest " << lowest << ", contact " << floor
                  << ", a pixel " << tol);
        CHECK(lowest >= floor - tol);
      }
    }
  }
}

TEST_CASE("a sprite is as thick as its bone's width, not its length: long thin bones stay thin", "[render][sprites]") {
  const SpriteSet sprites = default_sprite_set();
  for (const auto& entry : creatures()) {
    const std::string& name = entry.first;
    const auto& c = entry.second;  // (not a structured binding: clang 14 lambdas cannot capture one)
    SpriteMeshOptions rigid;
    rigid.smooth_weights = false;
    const SpriteMesh mesh = build_sprite_mesh(*c, sprites, rigid);
    const auto model = model_matrices(c->skeleton, c->rest_pose.locals);
    const std::vector<Mat2x3> palette = palette_of(mesh, model);
    for (int b = 0; b < c->skeleton.bone_count(); ++b) {
      const float L = c->skeleton.length(b), w = c->skeleton.width(b);
      const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(b)]];
      if (!(L > 1e-6f) || !(info.thickness > 0.0f) || !(w > 0.0f)) continue;
      // Across the sprite at its parent anchor (texture v from 0 to 1).
      const auto lo = drawn_at(mesh, b, {info.parent_anchor.x, 0.0f}, palette), hi = drawn_at(mesh, b, {info.parent_anchor.x, 1.0f}, palette);
      REQUIRE(lo.has_value());
      REQUIRE(hi.has_value());
      INFO(name << " " << c->skeleton.name(b) << ": length " << L << ", width " << w);
      // Across the bone (its normal): anchors at different heights tilt the sprite's v axis.
      const glm::vec2 axis = glm::normalize(bone_end(model[static_cast<size_t>(b)], L) - bone_start(model[static_cast<size_t>(b)]));
      const float across = std::fabs(axis.x * (hi->y - lo->y) - axis.y * (hi->x - lo->x));
      const float dv = info.child_anchor.y - info.parent_anchor.y;
      const float tilt = std::sqrt(std::max(0.0f, 1.0f - dv * dv * info.aspect * info.aspect));
      CHECK(across == Approx(w / info.thickness * tilt).epsilon(0.01));
      if (L > 6.0f * w && (c->skeleton.kind(b) == BoneKind::kUpperLimb || c->skeleton.kind(b) == BoneKind::kLowerLimb)) {
        CHECK(glm::length(*hi - *lo) < 0.3f * L);
      }
    }
  }
}

TEST_CASE("a skull's sprite follows the genome's skull: length, height and muzzle", "[render][sprites]") {
  const SpriteSet sprites = default_sprite_set();
  float snout_share[3] = {};
  int k = 0;
  for (const char* name : {"horse", "pig", "african elephant"}) {
    const Genome g = scenes::generator().example(name).value();
    const Creature c = build_creature(g).value();
    SpriteMeshOptions rigid;
    rigid.smooth_weights = false;
    const SpriteMesh mesh = build_sprite_mesh(c, sprites, rigid);
    const auto model = model_matrices(c.skeleton, c.rest_pose.locals);
    const std::vector<Mat2x3> palette = palette_of(mesh, model);
    const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(c.skull)]];
    REQUIRE(info.snout_from > 0.0f);
    // The art's muzzle begins where the genome's snout share puts it along the skull.
    const glm::vec2 at = *drawn_at(mesh, c.skull, {info.snout_from, info.parent_anchor.y}, palette);
    const glm::vec2 start = bone_start(model[static_cast<size_t>(c.skull)]);
    const float L = c.skeleton.length(c.skull);
    INFO(name);
    CHECK(glm::length(at - start) == Approx((1.0f - g.skull_shape.snout) * L).epsilon(0.01));
    CHECK(c.skeleton.width(c.skull) == Approx(g.skull_shape.height * L).epsilon(1e-4));
    snout_share[k++] = g.skull_shape.snout;
  }
  CHECK(snout_share[0] != snout_share[2]);  // a horse's long muzzle, an elephant's short one
}
