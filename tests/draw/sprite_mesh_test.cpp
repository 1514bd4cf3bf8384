#include "ossa/draw/sprite_mesh.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>

#include "ossa/gen/generator.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/math/angle.h"
#include "ossa/math/rng.h"
#include "ossa/skeleton/pose.h"
#include "shared/scenes.h"

using namespace ossa;

namespace {

// All 44 examples, built once.
const std::vector<Creature>& examples() {
  static const std::vector<Creature> creatures = [] {
    std::vector<Creature> out;
    const Generator& gen = scenes::generator();
    for (const Animal& a : gen.dataset().animals) {
      Result<Genome> g = gen.example(a.name);
      OSSA_ASSERT(g.ok(), "example genome");
      Result<Creature> c = build_creature(*g);
      OSSA_ASSERT(c.ok(), "example creature");
      out.push_back(std::move(c.value()));
    }
    return out;
  }();
  return creatures;
}

const Creature& example(const std::string& name) {
  for (const Creature& c : examples()) {
    if (c.name == name) return c;
  }
  FAIL("no example " << name);
  return examples().front();
}

// The vertex of `bone` at unit-box (u, v); with the default set uv = (u, 1 - v).
const SpriteVertex* find_vertex(const SpriteMesh& mesh, int bone, float u, float v) {
  for (const SpriteVertex& vert : mesh.vertices) {
    if (vert.bones[0] == bone && std::fabs(vert.uv.x - u) < 1e-6f && std::fabs(vert.uv.y - v) < 1e-6f) {
      return &vert;
    }
  }
  return nullptr;
}

// Where the unit-box point (u, anchor_v) of a bone's sprite lies: the sprite map is affine
// in v along a column, so it is the mix of the column's two vertices.
glm::vec2 anchor_position(const SpriteMesh& mesh, int bone, glm::vec2 anchor) {
  const SpriteVertex* lo = find_vertex(mesh, bone, anchor.x, 0.0f);
  const SpriteVertex* hi = find_vertex(mesh, bone, anchor.x, 1.0f);
  REQUIRE(lo);
  REQUIRE(hi);
  return lo->position_ms + anchor.y * (hi->position_ms - lo->position_ms);
}

glm::vec2 skin(const SpriteVertex& v, const std::vector<Mat2x3>& palette) {
  glm::vec2 p(0.0f);
  for (int k = 0; k < 4; ++k) {
    if (v.weights[k] != 0.0f) p += v.weights[k] * palette[v.bones[k]].apply(v.position_ms);
  }
  return p;
}

// The palette of a pose given by its model matrices: bones, then smooth skinning's mid joints.
std::vector<Mat2x3> palette_of(const std::vector<Mat2x3>& model, const SpriteMesh& mesh) {
  std::vector<Mat2x3> palette(static_cast<size_t>(mesh.palette_size()));
  for (size_t i = 0; i < model.size(); ++i) palette[i] = model[i] * mesh.inverse_bind[i];
  mid_joint_palette(mesh.mid_joints, model, palette);
  return palette;
}

SpriteMeshOptions rigid() {
  SpriteMeshOptions o;
  o.smooth_weights = false;
  return o;
}

// 0.1 frame units (0.2 mm in the 2 m frame): in the creature's own size, so that a 3 cm frog is
// held as tightly as a horse (1e-4 m would be a frame unit of it); float rounding is ~1e-7 of
// the creature.
float tolerance(const Creature& c) { return 0.1f * c.scale; }

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  REQUIRE(write_file_atomic(path, text).ok());
  return path;
}

}  // namespace

TEST_CASE("the shipped sprites.json loads and agrees with the built-in defaults", "[draw]") {
  const std::string path = scenes::source_path("assets/sprites/bones/sprites.json");
  Result<SpriteSet> loaded = load_sprite_set(path);
  REQUIRE(loaded.ok());
  const SpriteSet defaults = default_sprite_set();
  for (int i = 0; i < static_cast<int>(SpriteId::kCount); ++i) {
    const auto id = static_cast<SpriteId>(i);
    INFO(sprite_name(id));
    const SpriteInfo& a = (*loaded)[id];
    const SpriteInfo& b = defaults[id];
    CHECK(a.name == sprite_name(id));
    CHECK(b.name == sprite_name(id));
    CHECK(a.file == b.file);
    CHECK(sprite_id_from_name(a.name) == id);
    CHECK(a.parent_anchor.x == Approx(b.parent_anchor.x).margin(1e-6));
    CHECK(a.parent_anchor.y == Approx(b.parent_anchor.y).margin(1e-6));
    CHECK(a.child_anchor.x == Approx(b.child_anchor.x).margin(1e-6));
    CHECK(a.child_anchor.y == Approx(b.child_anchor.y).margin(1e-6));
    CHECK(a.aspect == Approx(b.aspect).margin(1e-6));
    CHECK(a.thickness == Approx(b.thickness).margin(1e-6));
    CHECK(a.contact_from == Approx(b.contact_from).margin(1e-6));
    CHECK(a.snout_from == Approx(b.snout_from).margin(1e-6));
    CHECK(std::filesystem::exists(scenes::source_path("assets/sprites/bones/" + a.file)));
    CHECK(std::filesystem::exists(scenes::source_path("assets/sprites/bones/src/" + a.name + ".svg")));
  }
  CHECK(sprite_id_from_name("nope") == SpriteId::kCount);
}

TEST_CASE("bad sprite files give errors naming the file and field", "[draw]") {
  const std::string good = read_file(scenes::source_path("assets/sprites/bones/sprites.json")).value();
  struct Case {
    std::string from, to, expect;
  };
  const std::vector<Case> cases = {
      {"\"ossa.sprites\"", "\"ossa.level\"", "format: expected \"ossa.sprites\""},
      {"\"version\": 2", "\"version\": 3", "version: expected an integer in [1, 2]"},
      {"\"thickness\": 0.6800", "\"thickness\": 1.5", "sprites.long_bone.thickness: expected a number in [0.001, 1]"},
      {"\"contact_from\": 0.8359", "\"contact_from\": 0.01", "sprites.paw.contact_from: expected a number in"},
      {"\"snout_from\": 0.5469", "\"snout_from\": \"x\"", "sprites.skull_mammal.snout_from"},
      {"\"parent_anchor\": [0.0469, 0.2222]", "\"parent_anchor\": [0.0469]", "sprites.vertebra.parent_anchor: expected [u, v]"},
      {"\"parent_anchor\": [0.0469, 0.2222]", "\"parent_anchor\": [0.0469, 1.5]", "sprites.vertebra.parent_anchor[1]"},
      {"\"parent_anchor\": [0.0469, 0.2222]", "\"parent_anchor\": [0.0469, \"x\"]", "sprites.vertebra.parent_anchor[1]"},
      {"\"child_anchor\": [0.9531, 0.2222]", "\"child_anchor\": [0.01, 0.2222]", "sprites.vertebra.child_anchor: expected u greater"},
      {"\"aspect\": 1.2414", "\"aspect\": -1", "sprites.vertebra.aspect"},
      {"\"aspect\": 0.2034", "\"aspect\": 50", "sprites.wing_hand.aspect: expected 1 / aspect"},
      {"\"file\": \"vertebra.png\"", "\"file\": \"../x.png\"", "sprites.vertebra.file"},
      {"\"file\": \"vertebra.png\"", "\"file\": 3", "sprites.vertebra.file"},
      {"\"fin\": {", "\"fins\": {", "sprites.fins: unknown sprite name"},
      {"\"sprites\": {", "\"sprites\": [", "sprites"},
  };
  for (const Case& c : cases) {
    INFO(c.to);
    std::string text = good;
    const size_t at = text.find(c.from);
    REQUIRE(at != std::string::npos);
    text.replace(at, c.from.size(), c.to);
    const std::string path = write_temp("ossa_bad_sprites.json", text);
    Result<SpriteSet> r = load_sprite_set(path);
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains(path));
    CHECK_THAT(r.message(), Catch::Contains(c.expect));
    std::filesystem::remove(path);
  }
  SECTION("missing sprite, syntax error, missing file") {
    std::string text = good;
    text.replace(text.find("\"fin\": {"), 8, "\"bird_foot\": {");  // a second bird_foot, no fin
    Result<SpriteSet> r = load_sprite_set(write_temp("ossa_bad_sprites.json", text));
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains("sprites.bird_foot: duplicate key"));
    Json without_fin = Json::parse(good);
    without_fin["sprites"].erase("fin");
    r = load_sprite_set(write_temp("ossa_bad_sprites.json", without_fin.dump()));
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains("sprites.fin: missing"));
    r = load_sprite_set(write_temp("ossa_bad_sprites.json", "{\"format\": "));
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains("ossa_bad_sprites.json"));
    r = load_sprite_set("/nonexistent/sprites.json");
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.message(), Catch::Contains("/nonexistent/sprites.json"));
  }
}

TEST_CASE("sprite choice follows kind, limb, contact and skull variant", "[draw]") {
  const Creature& horse = example("horse");
  const Creature& kangaroo = example("kangaroo");
  for (const Creature* c : {&horse, &kangaroo}) {
    for (const Limb& l : c->limbs) {
      CHECK(sprite_for_bone(*c, l.bones[0]) == SpriteId::kLongBone);
      CHECK(sprite_for_bone(*c, l.bones[1]) == SpriteId::kLongBone);
    }
    CHECK(sprite_for_bone(*c, c->root) == SpriteId::kVertebra);
    if (c->hip >= 0) CHECK(sprite_for_bone(*c, c->hip) == SpriteId::kPelvis);
    if (c->shoulder >= 0) CHECK(sprite_for_bone(*c, c->shoulder) == SpriteId::kScapula);
  }
  for (const Limb& l : horse.limbs) CHECK(sprite_for_bone(horse, l.bones[2]) == SpriteId::kHoof);
  // Every example: the rules of sprite_mesh.h, and a skull per variant.
  for (const Creature& c : examples()) {
    INFO(c.name);
    const bool winged = c.count(LimbKind::kWing) > 0;
    if (c.skull >= 0) {
      CHECK(static_cast<int>(sprite_for_bone(c, c.skull)) == std::clamp(c.skull_variant, 0, 3));
    }
    for (int t : c.tail) CHECK(sprite_for_bone(c, t) == SpriteId::kTailVertebra);
    for (int b : c.neck) CHECK(sprite_for_bone(c, b) == SpriteId::kTailVertebra);
    for (int b : c.back) CHECK(sprite_for_bone(c, b) == SpriteId::kVertebra);
    for (const Limb& l : c.limbs) {
      const SpriteId hand = sprite_for_bone(c, l.bones[2]);
      switch (l.kind) {
        case LimbKind::kWing: CHECK(hand == SpriteId::kWingHand); break;
        case LimbKind::kFin: CHECK(hand == SpriteId::kFin); break;
        case LimbKind::kArm: CHECK(hand == SpriteId::kFlatFoot); break;
        case LimbKind::kLeg:
          // A bird's foot, unless it lies nearly flat (then its sole is drawn on the ground).
          if (winged) CHECK((hand == SpriteId::kBirdFoot || hand == SpriteId::kFlatFoot));
          else if (c.contact == ContactMode::kFlat) CHECK(hand == SpriteId::kFlatFoot);
          else CHECK((hand == SpriteId::kHoof || hand == SpriteId::kPaw || hand == SpriteId::kFlatFoot));
          break;
      }
    }
  }
}

TEST_CASE("every example's sprite anchors land on its bone starts and ends", "[draw]") {
  const SpriteSet sprites = default_sprite_set();
  REQUIRE(examples().size() == 44);
  for (const Creature& c : examples()) {
    INFO(c.name);
    const Skeleton& s = c.skeleton;
    REQUIRE(s.bone_count() <= kMaxSpriteMeshBones);
    const SpriteMesh mesh = build_sprite_mesh(c, sprites, rigid());  // bind pose = rest pose
    const auto model = model_matrices(s, c.rest_pose.locals);
    REQUIRE(mesh.inverse_bind.size() == static_cast<size_t>(s.bone_count()));
    REQUIRE(mesh.bone_sprites.size() == static_cast<size_t>(s.bone_count()));
    const float tol = tolerance(c);
    int quads = 0;
    for (int b = 0; b < s.bone_count(); ++b) {
      INFO(s.name(b));
      const SpriteInfo& info = sprites[mesh.bone_sprites[static_cast<size_t>(b)]];
      if (s.length(b) <= 1e-6f) {
        CHECK_FALSE(find_vertex(mesh, b, 0.0f, 0.0f));  // the root gets no quad
        continue;
      }
      ++quads;
      const glm::vec2 start = bone_start(model[static_cast<size_t>(b)]);
      const glm::vec2 end = bone_end(model[static_cast<size_t>(b)], s.length(b));
      const glm::vec2 pa = anchor_position(mesh, b, info.parent_anchor);
      const glm::vec2 ca = anchor_position(mesh, b, info.child_anchor);
      CHECK(pa.x == Approx(start.x).margin(tol));
      CHECK(pa.y == Approx(start.y).margin(tol));
      CHECK(ca.x == Approx(end.x).margin(tol));
      CHECK(ca.y == Approx(end.y).margin(tol));
      // Height: width / thickness (or max(aspect × length, width) for a sprite without one),
      // measured across the sprite at the parent anchor.
      const SpriteVertex* lo = find_vertex(mesh, b, info.parent_anchor.x, 0.0f);
      const SpriteVertex* hi = find_vertex(mesh, b, info.parent_anchor.x, 1.0f);
      const glm::vec2 across = hi->position_ms - lo->position_ms;
      const glm::vec2 axis = (end - start) / s.length(b);
      const float height = axis.x * across.y - axis.y * across.x;  // signed: up = +v
      const float expect = info.thickness > 0.0f && s.width(b) > 0.0f ? s.width(b) / info.thickness
                                                                       : std::max(info.aspect * s.length(b), s.width(b));
      CHECK(std::fabs(height) == Approx(expect).margin(tol));
      CHECK((height < 0.0f) == s.sprite_flip_y(b));  // flipped sprites have +v on local -y
    }
    CHECK(quads == s.bone_count() - 1);  // every bone but the zero-length root
  }
}

TEST_CASE("sprite meshes: skinning the rest pose gives the rest pose, weights sum to 1, layers", "[draw]") {
  const SpriteSet sprites = default_sprite_set();
  for (bool smooth : {false, true}) {
    for (const Creature& c : examples()) {
      INFO(c.name << (smooth ? " smooth" : ""));
      SpriteMeshOptions options;
      options.smooth_weights = smooth;
      const SpriteMesh mesh = build_sprite_mesh(c, sprites, options);
      const auto model = model_matrices(c.skeleton, c.rest_pose.locals);
      const auto palette = palette_of(model, mesh);
      const float tol = tolerance(c);
      const int n = c.skeleton.bone_count();
      const std::vector<int> chain = chain_children(c.skeleton, c.rest_pose.locals);
      REQUIRE(mesh.rest_positions.size() == mesh.vertices.size());
      int blended = 0;
      for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const SpriteVertex& v = mesh.vertices[i];
        const float sum = v.weights[0] + v.weights[1] + v.weights[2] + v.weights[3];
        REQUIRE(sum == Approx(1.0f).margin(1e-6));
        int weights = 0;
        for (int k = 0; k < 4; ++k) {
          REQUIRE(v.weights[k] >= 0.0f);
          REQUIRE(v.bones[k] < mesh.palette_size());
          if (k == 0 || v.weights[k] == 0.0f) continue;
          ++weights;
          // The other influences: the bone's chain parent or child, or a mid joint of its own.
          const int b = v.bones[k], self = v.bones[0];
          if (b >= n) {
            const MidJoint& j = mesh.mid_joints[static_cast<size_t>(b - n)];
            CHECK((j.parent == self || j.child == self));
          } else {
            CHECK((chain[static_cast<size_t>(self)] == b || chain[static_cast<size_t>(b)] == self));
          }
        }
        blended += weights > 0;
        // Skinned to the rest pose: the rest pose as drawn (the bind pose itself when rigid).
        const glm::vec2 p = skin(v, palette);
        REQUIRE(p.x == Approx(mesh.rest_positions[i].x).margin(tol));
        REQUIRE(p.y == Approx(mesh.rest_positions[i].y).margin(tol));
        if (!smooth) REQUIRE(mesh.rest_positions[i] == v.position_ms);
        const bool far = c.skeleton.layer(v.bones[0]) == Layer::kFar;
        CHECK((far ? v.shade < 1.0f : v.shade == 1.0f));
        CHECK(v.uv.x >= 0.0f);
        CHECK(v.uv.x <= 1.0f);
        CHECK(v.uv.y >= 0.0f);
        CHECK(v.uv.y <= 1.0f);
      }
      CHECK((smooth ? blended > 0 : blended == 0));
      CHECK(max_weights_per_vertex(mesh) == (smooth ? 2 : 1));
      // Knee (elbow) and ankle (wrist), each kSmoothJointFrames frames: every example has room;
      // a leg's foot drawn flat keeps its ankle rigid (its sole lies on the ground from the
      // ankle on). Plus, when smooth, one level frame per foot that stands on the ground.
      size_t level = 0, joints = 0;
      for (const MidJoint& j : mesh.mid_joints) level += j.level;
      for (const Limb& l : c.limbs) {
        joints += l.bones[1] >= 0;
        joints += l.bones[2] >= 0 && !(l.kind == LimbKind::kLeg &&
                                       mesh.bone_sprites[static_cast<size_t>(l.bones[2])] == SpriteId::kFlatFoot);
      }
      CHECK(mesh.mid_joints.size() - level == (smooth ? kSmoothJointFrames * joints : 0));
      // One level frame per leg whose foot's sprite has a contact part (hoof, paw, bird's
      // toes), whatever the foot's rest angle: a pig's hind hoof stands straight down at rest
      // (its contact part turned by 0) and still rolls over its tip in stance.
      size_t contact_feet = 0;
      for (const Limb& l : c.limbs) {
        contact_feet += l.kind == LimbKind::kLeg && l.bones[2] >= 0 &&
                        sprites[mesh.bone_sprites[static_cast<size_t>(l.bones[2])]].contact_from >= 0.0f;
      }
      CHECK(level == (smooth ? contact_feet : 0));
      // Layer ranges: ordered, covering all indices, each triangle in the layer of its bone.
      REQUIRE(mesh.layer_begin[0] == 0);
      REQUIRE(mesh.layer_begin[3] == mesh.indices.size());
      REQUIRE(mesh.indices.size() % 3 == 0);
      for (int l = 0; l < kLayerCount; ++l) {
        REQUIRE(mesh.layer_begin[l] <= mesh.layer_begin[l + 1]);
        REQUIRE(mesh.layer_begin[l] % 3 == 0);
        for (uint32_t i = mesh.layer_begin[l]; i < mesh.layer_begin[l + 1]; ++i) {
          REQUIRE(mesh.indices[i] < mesh.vertices.size());
          REQUIRE(static_cast<int>(c.skeleton.layer(mesh.vertices[mesh.indices[i]].bones[0])) == l);
        }
      }
      if (c.count(LimbKind::kLeg) > 0) CHECK(mesh.layer_begin[1] > 0);  // far legs exist
    }
  }
}

TEST_CASE("a bone's sprite moves with it and its joints stay together", "[draw]") {
  const SpriteSet sprites = default_sprite_set();
  for (const char* name : {"horse", "kangaroo"}) {
    const Creature& c = example(name);
    const Skeleton& s = c.skeleton;
    const SpriteMesh mesh = build_sprite_mesh(c, sprites, rigid());
    for (const Limb& limb : c.limbs) {
      const int lower = limb.bones[1], hand = limb.bones[2];
      Pose pose = c.rest_pose;
      pose.locals[static_cast<size_t>(lower)].angle_ls += 0.6f;
      const auto model = model_matrices(s, pose.locals);
      const auto palette = palette_of(model, mesh);
      const auto rest = model_matrices(s, c.rest_pose.locals);
      const float tol = tolerance(c);
      for (const SpriteVertex& v : mesh.vertices) {
        const glm::vec2 p = skin(v, palette);
        const int b = v.bones[0];
        if (b == lower || b == hand) {
          // Rigidly attached: the vertex keeps its coordinates in the bone frame.
          const glm::vec2 local = mesh.inverse_bind[static_cast<size_t>(b)].apply(v.position_ms);
          const glm::vec2 expect = model[static_cast<size_t>(b)].apply(local);
          REQUIRE(p.x == Approx(expect.x).margin(tol));
          REQUIRE(p.y == Approx(expect.y).margin(tol));
          if (b == lower) CHECK(glm::length(p - v.position_ms) > 0.0f);
        } else if (b != limb.bones[0] && b != limb.girdle_bone) {
          REQUIRE(p.x == Approx(v.position_ms.x).margin(tol));  // other bones stay
          REQUIRE(p.y == Approx(v.position_ms.y).margin(tol));
        }
      }
      // The hand's parent anchor follows the end of the bent lower bone.
      const SpriteInfo& hi = sprites[mesh.bone_sprites[static_cast<size_t>(hand)]];
      const glm::vec2 anchor_rest = anchor_position(mesh, hand, hi.parent_anchor);
      const glm::vec2 anchor_now = palette[static_cast<size_t>(hand)].apply(anchor_rest);
      const glm::vec2 joint = bone_end(model[static_cast<size_t>(lower)], s.length(lower));
      CHECK(anchor_now.x == Approx(joint.x).margin(tol));
      CHECK(anchor_now.y == Approx(joint.y).margin(tol));
      CHECK(glm::length(joint - bone_end(rest[static_cast<size_t>(lower)], s.length(lower))) > 1e-3f);
    }
  }
}

TEST_CASE("sprite meshes refuse more bones than uint8 indices hold", "[draw]") {
  Creature c;
  c.skeleton = scenes::chain_skeleton(300, 0.01f);
  c.rest_pose = Pose::rest(c.skeleton);
  c.name = "chain300";
  Result<SpriteMesh> r = try_build_sprite_mesh(c, default_sprite_set());
  REQUIRE_FALSE(r.ok());
  CHECK_THAT(r.message(), Catch::Contains("at most 255 bones"));
  c.skeleton = scenes::chain_skeleton(255, 0.01f, 0.01f);
  c.rest_pose = Pose::rest(c.skeleton);
  Result<SpriteMesh> ok = try_build_sprite_mesh(c, default_sprite_set());
  REQUIRE(ok.ok());
  CHECK(ok->inverse_bind.size() == 255);
  int max_bone = 0;
  for (const SpriteVertex& v : ok->vertices) max_bone = std::max(max_bone, static_cast<int>(v.bones[0]));
  CHECK(max_bone == 254);
}

TEST_CASE("mid-joint frames turn a quarter, half and three quarters of the child's turn", "[draw]") {
  // frame(t, a, k): translate t, rotate a, scale k.
  const auto frame = [](glm::vec2 t, float a, float k) {
    Mat2x3 m;
    m.m[0] = k * std::cos(a), m.m[1] = k * std::sin(a), m.m[2] = -m.m[1], m.m[3] = m.m[0];
    m.m[4] = t.x, m.m[5] = t.y;
    return m;
  };
  Rng rng(15);
  for (int i = 0; i < 1000; ++i) {
    const auto a = static_cast<float>(rng.uniform(-kPi, kPi));
    const auto turn = static_cast<float>(rng.uniform(-0.99 * kPi, 0.99 * kPi));
    const auto scale = static_cast<float>(rng.uniform(0.5, 2.0));
    const bool mirror = i % 2 == 1;  // a creature facing left
    Mat2x3 place = Mat2x3::identity();
    if (mirror) place.m[0] = -1.0f;
    const Mat2x3 parent = place * frame({static_cast<float>(rng.uniform(-1.0, 1.0)), 0.3f}, a, scale);
    const Mat2x3 child = parent * frame({0.7f, 0.0f}, turn, 1.0f);
    for (float share : {0.25f, 0.5f, 0.75f}) {
      INFO("turn " << turn << " share " << share << (mirror ? " mirrored" : ""));
      const Mat2x3 mid = mid_joint_frame(parent, child, share);
      const Mat2x3 expect = parent * frame({0.7f, 0.0f}, share * turn, 1.0f);
      for (int k = 0; k < 6; ++k) CHECK(mid.m[k] == Approx(expect.m[k]).margin(1e-4f * scale));
    }
  }
}

TEST_CASE("atlas rectangles map the sprite's unit box", "[draw]") {
  SpriteSet sprites = default_sprite_set();
  for (SpriteInfo& info : sprites.sprites) {
    info.uv_min = {0.25f, 0.5f};
    info.uv_max = {0.5f, 0.75f};
  }
  const SpriteMesh mesh = build_sprite_mesh(example("horse"), sprites);
  glm::vec2 lo(1.0f), hi(0.0f);
  for (const SpriteVertex& v : mesh.vertices) {
    lo = glm::min(lo, v.uv);
    hi = glm::max(hi, v.uv);
  }
  CHECK(lo.x == Approx(0.25f));
  CHECK(lo.y == Approx(0.5f));
  CHECK(hi.x == Approx(0.5f));
  CHECK(hi.y == Approx(0.75f));
}
