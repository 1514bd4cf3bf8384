// ossa-render — renders creatures offscreen to a PNG (issue "Renderer", DESIGN.md §9): N
// creatures side by side in their rest pose on the ground, the camera fitting them. Uses the
// same Window / Renderer / CreatureBatch as the game, through SDL's offscreen driver, so it
// runs with no display. Every failure prints one clear message and exits non-zero.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "ossa/body/body_mesh.h"
#include "ossa/gen/generator.h"
#include "ossa/gen/genome.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/io/parse_arg.h"
#include "ossa/level/level_io.h"
#include "ossa/render/level_view.h"
#include "ossa/platform/window.h"
#include "ossa/render/capture.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/render/renderer.h"
#include "ossa/render/character_mesh.h"
#include "ossa/render/rigged_batch.h"
#include "ossa/draw/sprite_mesh.h"
#include "ossa/render/texture.h"

namespace {

using namespace ossa;

constexpr const char* kUsage = R"(usage: ossa-render SOURCE [--level F] --png OUT [options]

Render creatures offscreen (no display needed) standing in their rest pose on the ground.

source (one of):
  --example NAME          one of the 44 example animals (English or German name)
  --random                a random creature (with --seed N, default 1)
  --creature F            a saved genome (.creature.json)
  --mesh F                a rigged sprite character made in another tool (glTF, FBX, DAE)
  --character F           a rigged character: its rig mapping (.rig.json) and the mesh it
                          names, in its rest pose (the bones the animator drives with --bones)
options:
  --seed N                seed of the random choices (default 1)
  --size true|FRAME_M     a generated creature's size: true (the animal's true size from its
                          weight and body plan, the default for --example and --random) or a
                          fixed frame of FRAME_M metres (0.05 to 50); a --creature genome is
                          resized (default: as saved)
  --level F               stand on this level's ground under its spawn point (an ossa level,
                          a Tiled .tmj/.tmx map or an LDtk project, F#LevelName), drawn
                          as the game draws it (its tile art, its look or its boxes) at
                          least 6 m high
  --pixels-per-metre P    scale of Tiled/LDtk maps without a pixels_per_metre property or
                          a tile size (default 32)
  --png OUT               write the frame as PNG
  --width W --height H    image size in pixels (default 1024 x 576)
  --count N               N creatures side by side (default 1, at most 10000)
  --look L                body (default: the creature's flesh, skin and coat), xray (the body
                          translucent over the bone sprites) or bones (the bone sprites alone);
                          rigged meshes and characters are always drawn as made
  --bones                 draw skeleton lines over the creature
  --rigid                 no smooth skinning: every sprite follows its own bone (as a genome
                          with "options": {"smooth_skinning": false} asks)
  --stats                 print JSON: draw_calls, creatures, bones, vertices, triangles,
                          max_weights_per_vertex (of the bone sprites), and for a generated
                          creature body_vertices, body_triangles, body_area_m2 (every part's
                          side-view area, overlaps counted), body_mass_kg,
                          expected_mass_kg (the genome's weight at the creature's size),
                          body_girth and scale (metres per frame unit: --size's outcome)
  --help                  this text
)";

struct Args {
  std::optional<std::string> example, creature, mesh, character, level, png;
  bool random = false, stats = false, bones = false, rigid = false;
  CreatureLook look = CreatureLook::kBody;
  uint64_t seed = 1;
  std::optional<SizeChoice> size;  // --size: the genome's size choice
  int width = 1024, height = 576, count = 1;
  float pixels_per_metre = 32.0f;  // LevelLoadOptions::pixels_per_metre
};

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "ossa-render: %s\n", message.c_str());
  std::exit(1);
}

long long parse_int(const std::string& flag, const std::string& text, long long lo, long long hi) {
  Result<long long> v = parse_int_arg(flag, text, lo, hi);
  if (!v) fail(v.message());
  return *v;
}

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail(flag + ": missing value");
      return argv[++i];
    };
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (flag == "--example") {
      a.example = value();
    } else if (flag == "--mesh") {
      a.mesh = value();
    } else if (flag == "--character") {
      a.character = value();
    } else if (flag == "--creature") {
      a.creature = value();
    } else if (flag == "--random") {
      a.random = true;
    } else if (flag == "--seed") {
      a.seed = static_cast<uint64_t>(parse_int(flag, value(), 0, 2147483647L));
    } else if (flag == "--size") {
      Result<SizeChoice> size = parse_size_arg(flag, value());
      if (!size) fail(size.message());
      a.size = *size;
    } else if (flag == "--level") {
      a.level = value();
    } else if (flag == "--pixels-per-metre") {
      const std::string text = value();
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end || !(v > 0.0 && v <= 1e6)) fail(flag + ": expected a number in (0, 1000000], got \"" + text + "\"");
      a.pixels_per_metre = static_cast<float>(v);
    } else if (flag == "--png") {
      a.png = value();
    } else if (flag == "--width") {
      a.width = static_cast<int>(parse_int(flag, value(), 16, 8192));
    } else if (flag == "--height") {
      a.height = static_cast<int>(parse_int(flag, value(), 16, 8192));
    } else if (flag == "--count") {
      a.count = static_cast<int>(parse_int(flag, value(), 1, 10000));
    } else if (flag == "--stats") {
      a.stats = true;
    } else if (flag == "--look") {
      const std::string v = value();
      const auto look = creature_look_from_name(v);
      if (!look) fail("--look: expected body, xray or bones, got \"" + v + "\"");
      a.look = *look;
    } else if (flag == "--bones") {
      a.bones = true;
    } else if (flag == "--rigid") {
      a.rigid = true;
    } else {
      fail("unknown argument \"" + flag + "\" (see --help)");
    }
  }
  const int sources = (a.example ? 1 : 0) + (a.creature ? 1 : 0) + (a.random ? 1 : 0) + (a.mesh ? 1 : 0) + (a.character ? 1 : 0);
  if (sources == 0) fail("nothing to render: give --example NAME, --random, --creature F, --mesh F or --character F");
  if (sources > 1) fail("give only one of --example, --random, --creature, --mesh, --character");
  if (a.size && (a.mesh || a.character)) fail("--size: a rigged mesh or character has the size it was made at; drop --size");
  if (!a.png && !a.stats) fail("nothing to do: give --png OUT and/or --stats");
  if (a.png) {  // no output may be one of the inputs (io/file.h)
    std::vector<std::string> inputs;
    for (const auto* in : {&a.creature, &a.mesh, &a.character, &a.level}) {
      if (*in) inputs.push_back(**in);
    }
    if (Status st = check_output_path("--png", *a.png, inputs); !st) fail(st.message());
  }
  return a;
}

// The smallest on-screen width (pixels) of one creature in a --count row.
constexpr float kMinCreaturePixels = 4.0f;

Creature make_creature(const Args& a) {
  Genome genome;
  std::optional<Generator> generator;
  if (!a.creature || a.size) {
    auto g = Generator::load(data_path("assets/creatures/examples.json"), ossa::body_volume_m3);
    if (!g.ok()) fail(g.message());
    generator.emplace(std::move(g.value()));
  }
  GenerateOptions options;
  if (a.size) a.size->apply_to(options.genome);
  if (a.creature) {
    auto g = load_genome(*a.creature);
    if (!g.ok()) fail(g.message());
    genome = std::move(g.value());
    if (a.size) {  // resized: its scale made again for the size asked for
      a.size->apply_to(genome.options);
      generator->apply_size(genome);
    }
  } else if (a.example) {
    auto g = generator->example(*a.example, a.seed, options);
    if (!g.ok()) fail(g.message());
    genome = std::move(g.value());
  } else {
    genome = generator->random(a.seed, options);
  }
  if (a.rigid) genome.options.smooth_skinning = false;
  auto creature = build_creature(genome);
  if (!creature.ok()) fail(creature.message());
  return std::move(creature.value());
}

// A rigged character as a "creature" for this tool: its skeleton, rest pose and name.
Creature creature_from_rig(const Skeleton& skeleton, const std::string& name) {
  Creature c;
  c.skeleton = skeleton;
  c.rest_pose = Pose::rest(skeleton);
  c.name = name;
  return c;
}

int run(const Args& a) {
  std::optional<RiggedMesh> rig;
  if (a.mesh) {
    auto m = load_rigged_mesh(*a.mesh);
    if (!m.ok()) fail(m.message());
    rig = std::move(m.value());
    if (rig->texture_rgba.empty() && !rig->texture_path.empty()) {
      if (auto t = load_rigged_texture(*rig); !t.ok()) render_log(t.message() + " (drawing with the checker texture)");
    }
  }
  std::optional<LoadedCharacter> character;
  if (a.character) {
    auto c = load_character(*a.character);
    if (!c.ok()) fail(c.message());
    character = std::move(c.value());
    rig = character->mesh;
  }
  Creature creature = character ? creature_from_rig(character->character->skeleton, character->character->name)
                      : rig     ? creature_from_rig(rigged_skeleton(*rig), *a.mesh)
                                : make_creature(a);

  std::optional<Level> level;
  if (a.level) {
    LevelLoadOptions level_options;
    level_options.pixels_per_metre = a.pixels_per_metre;
    auto l = load_level(*a.level, level_options);
    if (!l.ok()) fail(l.message());
    for (const std::string& w : level_warnings(*l)) std::fprintf(stderr, "warning: %s: %s\n", a.level->c_str(), w.c_str());
    level = std::move(l.value());
  }

  WindowDesc desc;
  desc.title = "ossa-render";
  desc.width = a.width;
  desc.height = a.height;
  desc.offscreen = true;
  auto window = Window::create(desc);
  if (!window.ok()) fail(window.message());
  auto renderer = Renderer::create(default_shader_dir());
  if (!renderer.ok()) fail(renderer.message());

  Atlas atlas = Atlas::load(default_sprite_dir());

  // Side by side, 15 % of a body length apart, on the ground under each creature. The body box
  // holds every sprite vertex of the rest (bind) pose, and for creatures the ground line y = 0.
  const SpriteMesh mesh = character ? character->sprite_mesh
                          : rig     ? rigged_sprite_mesh(*rig)
                                    : build_sprite_mesh(creature, atlas.sprites);
  // A generated creature's body (rigged meshes and characters bring their own drawing).
  const CreatureLook look = rig ? CreatureLook::kBones : a.look;
  std::optional<BodyMesh> flesh;
  if (!rig) {
    auto b = try_build_body(creature);
    if (!b.ok()) fail(b.message());
    flesh = std::move(b.value());
  }
  const bool show_sprites = look != CreatureLook::kBody, show_body = flesh && look != CreatureLook::kBones;
  Box body = sprite_mesh_bounds(mesh);
  if (show_body && !flesh->vertices.empty()) body = body.united(body_bounds(*flesh));
  float lift = 0.0f;  // model y that stands on the ground: 0 for creatures and characters, the feet for meshes
  if (character) {
    // Bind-pose vertices are in the mesh's own space: the body box in model space (y = 0 on
    // the ground the character's feet stand on).
    const Mat2x3& s = character->character->mesh_to_model;
    const Box raw = body;
    body = Box{glm::vec2(1e30f), glm::vec2(-1e30f)};
    for (glm::vec2 c : {raw.min_ws, raw.max_ws, glm::vec2(raw.min_ws.x, raw.max_ws.y), glm::vec2(raw.max_ws.x, raw.min_ws.y)}) {
      body.min_ws = glm::min(body.min_ws, s.apply(c));
      body.max_ws = glm::max(body.max_ws, s.apply(c));
    }
    body.min_ws.y = std::min(body.min_ws.y, 0.0f);
  } else if (rig) {
    lift = -body.min_ws.y;
    body = body.translated({0.0f, lift});
  } else {
    body.min_ws.y = std::min(body.min_ws.y, 0.0f);
  }
  const float spacing = body.width() * 1.15f;
  const glm::vec2 start = level ? level->spawn_ws : glm::vec2(0.0f);
  Texture rig_texture;
  if (rig) {
    rig_texture = rig->texture_rgba.empty()
                      ? Texture::checker()
                      : Texture::from_image(Image{rig->texture_width, rig->texture_height, rig->texture_rgba});
  }
  const Texture& texture = rig ? rig_texture : atlas.texture;
  // Where each creature stands: the highest ground under its body, searching from well above
  // the spawn.
  std::vector<glm::vec2> feet(static_cast<size_t>(a.count));
  Box view{{1e9f, 1e9f}, {-1e9f, -1e9f}};
  for (int i = 0; i < a.count; ++i) {
    const float x = start.x + spacing * static_cast<float>(i);
    float ground = start.y;
    if (level) {
      if (auto hit = level->ground_height_below(x + body.min_ws.x, x + body.max_ws.x, start.y + 2.0f, 100.0f)) {
        ground = hit->height_ws;
      }
    }
    feet[static_cast<size_t>(i)] = {x, ground};
    view = view.united(body.translated({x, ground}));
  }
  Camera2D& camera = renderer->camera;
  camera.fit(view, static_cast<float>(a.width) / static_cast<float>(a.height), 0.08f);
  // The camera fits the whole row, so a row too long for the picture would draw creatures
  // narrower than a pixel: nothing visible. Refuse it and say what fits (before building it).
  const float creature_px = static_cast<float>(a.width) * body.width() / (2.0f * camera.half_height * camera.aspect);
  if (creature_px < kMinCreaturePixels) {
    const int fits = std::max(1, static_cast<int>(static_cast<float>(a.count) * creature_px / kMinCreaturePixels));
    fail("--count " + std::to_string(a.count) + ": side by side in a " + std::to_string(a.width) +
         " px wide picture each creature would be " + std::to_string(creature_px) + " px wide (under " +
         std::to_string(static_cast<int>(kMinCreaturePixels)) + " px: nothing would show); use --count " +
         std::to_string(fits) + " or less, or a larger --width");
  }
  // The creatures: their sprites and/or bodies, as the look shows them.
  CreatureBatch batch;
  for (const glm::vec2& at : feet) {
    Transform2D place;
    place.translation = {at.x, at.y + lift};
    if (show_sprites) {
      const int id = batch.add(mesh, creature.skeleton);
      batch.set_pose(id, creature.skeleton, creature.rest_pose.locals, place.to_mat2x3());
    }
    if (show_body) {
      const int id = batch.add_body(*flesh, creature.skeleton);
      batch.set_pose(id, creature.skeleton, creature.rest_pose.locals, place.to_mat2x3());
      // Its flesh rests on the ground as in the game (body_floor.h).
      std::vector<Mat2x3> world = model_matrices(creature.skeleton, creature.rest_pose.locals);
      for (Mat2x3& m : world) m = place.to_mat2x3() * m;
      batch.set_floor(id, level ? body_floor(*level, creature.skeleton, world, flesh->reach, flesh->feet) : flat_floor(at.y));
    }
  }
  batch.upload_palettes();

  // The ground: the level as the game draws it (its art, its look or its boxes: level_view.h),
  // or a plain strip under the creatures.
  DebugDraw debug;
  const glm::vec4 ground_fill{0.42f, 0.36f, 0.27f, 1.0f}, ground_edge{0.25f, 0.20f, 0.14f, 1.0f};
  // On a level, show at least 6 m of it in height (its steps and ledges around the creatures).
  if (level) camera.half_height = std::max(camera.half_height, 3.0f);
  // Keep the ground near the bottom edge (a long row would otherwise float mid-frame).
  camera.center_ws.y = view.min_ws.y - 0.2f * camera.half_height + camera.half_height;
  const Box visible = camera.visible_box();
  if (!level) {
    debug.add_box({{visible.min_ws.x - 1.0f, visible.min_ws.y - 1.0f}, {visible.max_ws.x + 1.0f, start.y}},
                  ground_fill, true);
    debug.add_line({visible.min_ws.x - 1.0f, start.y}, {visible.max_ws.x + 1.0f, start.y}, ground_edge);
  }

  const glm::vec3 sky = level && level->background ? level->background->colour
                                                   : glm::vec3(0.55f, 0.70f, 0.85f);
  renderer->begin_frame(window->width(), window->height(), sky);
  std::optional<LevelView> level_view;
  if (level) {
    auto lv = LevelView::create(default_shader_dir());
    if (!lv.ok()) fail(lv.message());
    level_view.emplace(std::move(lv.value()));
    level_view->draw_back(*renderer, *level, *a.level);
    (void)level_view->take_warnings();  // already on stderr (render_log: "ossa render: ...")
  } else {
    renderer->draw_debug(debug);
  }
  const int calls_before = renderer->stats.draw_calls;
  const Texture* textures[1] = {&texture};
  renderer->draw_creatures(batch, textures, look);
  const int creature_calls = renderer->stats.draw_calls - calls_before;
  if (level_view) level_view->draw_front(*renderer, *level);
  if (a.bones) renderer->draw_bones(batch, {0.9f, 0.1f, 0.1f, 1.0f});
  if (!check_gl("ossa-render")) fail("OpenGL reported an error while drawing (see above)");

  if (a.png) {
    const Image frame = read_framebuffer(window->width(), window->height());
    if (auto s = write_png(*a.png, frame); !s.ok()) fail(s.message());
  }
  if (a.stats) {
    const DrawStats& st = renderer->stats;
    std::string body_stats;
    if (flesh) {
      char buf[512];
      std::snprintf(buf, sizeof buf,
                    "  \"look\": \"%s\",\n  \"body_vertices\": %zu,\n  \"body_triangles\": %d,\n"
                    "  \"body_area_m2\": %.6g,\n  \"body_mass_kg\": %.6g,\n  \"expected_mass_kg\": %s,\n"
                    "  \"body_girth\": %.4g,\n  \"scale\": %.6g,\n",
                    creature_look_name(look), flesh->vertices.size(), flesh->triangle_count(),
                    static_cast<double>(flesh->area_m2), static_cast<double>(flesh->mass_kg),
                    creature.body_mass_kg ? std::to_string(*creature.body_mass_kg).c_str() : "null",
                    static_cast<double>(flesh->girth), static_cast<double>(creature.scale));
      body_stats = buf;
    }
    std::printf(
        "{\n  \"name\": \"%s\",\n%s  \"creatures\": %d,\n  \"bones\": %d,\n  \"vertices\": %d,\n"
        "  \"triangles\": %d,\n  \"max_weights_per_vertex\": %d,\n  \"draw_calls\": %d,\n"
        "  \"creature_draw_calls\": %d,\n  \"atlas_missing_sprites\": %d,\n  \"width\": %d,\n"
        "  \"height\": %d\n}\n",
        creature.name.c_str(), body_stats.c_str(), a.count, a.count * creature.skeleton.bone_count(),
        show_sprites ? batch.vertex_count() : 0,
        show_sprites ? batch.triangle_count() : 0, max_weights_per_vertex(mesh), st.draw_calls, creature_calls, atlas.missing,
        window->width(), window->height());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse_args(argc, argv));
  } catch (const std::exception& e) {
    fail(std::string("unexpected error: ") + e.what());
  }
}
