#include "ossa/render/creature_image.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <glm/common.hpp>

#include "ossa/math/transform2d.h"
#include "ossa/platform/window.h"
#include "ossa/render/capture.h"
#include "ossa/render/creature_batch.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/render/render_target.h"
#include "ossa/draw/sprite_mesh.h"

namespace ossa {
namespace {

// The frame was drawn over transparent black, so its colours are premultiplied by alpha
// (the blend adds src·a + dst·(1 − a), and alpha accumulates a + dst_a·(1 − a)). Composite it
// over `background` ("over", premultiplied) and store straight alpha, as PNG expects.
void composite_over(Image& image, glm::vec4 background) {
  const float bg_a = std::clamp(background.a, 0.0f, 1.0f);
  const glm::vec3 bg = glm::clamp(glm::vec3(background), 0.0f, 1.0f) * bg_a;  // premultiplied
  for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    uint8_t* p = &image.rgba[i];
    const float a = p[3] / 255.0f;
    const float out_a = a + bg_a * (1.0f - a);
    for (int c = 0; c < 3; ++c) {
      const float premultiplied = p[c] / 255.0f + bg[c] * (1.0f - a);
      const float straight = out_a > 0.0f ? std::min(premultiplied / out_a, 1.0f) : 0.0f;
      p[c] = static_cast<uint8_t>(std::lround(straight * 255.0f));
    }
    p[3] = static_cast<uint8_t>(std::lround(out_a * 255.0f));
  }
}

}  // namespace

Result<Image> render_creature_image(Renderer& renderer, const Atlas& atlas, const Creature& creature,
                                    const CreatureImageOptions& options) {
  if (!gl_context_is_current()) return Error{"no current OpenGL context to draw with"};
  if (!(options.margin >= 0.0f) || !std::isfinite(options.margin)) {
    return Error{"margin: expected a number >= 0"};
  }
  auto mesh = try_build_sprite_mesh(creature, atlas.sprites);
  if (!mesh.ok()) return Error{mesh.message()};
  if (mesh->vertices.empty()) return Error{"the creature has no bone sprites to draw"};
  const bool sprites = options.look != CreatureLook::kBody;
  std::optional<BodyMesh> body;
  if (options.look != CreatureLook::kBones) {
    auto b = try_build_body(creature);
    if (!b.ok()) return Error{b.message()};
    if (!b->vertices.empty()) body = std::move(b.value());
  }
  Box bounds = sprite_mesh_bounds(*mesh);
  if (body) bounds = sprites ? bounds.united(body_bounds(*body)) : body_bounds(*body);
  if (options.ground) bounds.min_ws.y = std::min(bounds.min_ws.y, 0.0f);
  if (!std::isfinite(bounds.min_ws.x + bounds.min_ws.y + bounds.max_ws.x + bounds.max_ws.y)) {
    return Error{"the creature's rest pose is not finite"};
  }

  (void)check_gl("before render_creature_image");  // errors of earlier draws are not ours
  GlFrameState saved_state;
  const Camera2D saved_camera = renderer.camera;
  const DrawStats saved_stats = renderer.stats;
  auto target = RenderTarget::create(options.width, options.height);
  if (!target.ok()) return Error{target.message()};

  Image image;
  {
    const Skeleton& skeleton = creature.skeleton;
    const bool have_rest = creature.rest_pose.locals.size() == static_cast<size_t>(skeleton.bone_count());
    CreatureBatch batch;
    const auto& locals = have_rest ? creature.rest_pose.locals : skeleton.rest_locals();
    if (sprites) batch.set_pose(batch.add(*mesh, skeleton), skeleton, locals, Mat2x3::identity());
    if (body) {
      const int id = batch.add_body(*body, skeleton);
      batch.set_pose(id, skeleton, locals, Mat2x3::identity());
      if (options.ground) batch.set_floor(id, flat_floor(0.0f));  // the flesh rests on the ground line
    }
    batch.upload_palettes();
    renderer.begin_frame(*target, glm::vec4(0.0f));  // transparent black: see composite_over
    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    renderer.camera.fit(bounds, aspect, options.margin);
    if (options.frame_height > 0.0f) {
      // A common scale (a contact sheet at true relative size): the creature stands on the
      // image's lower edge plus the margin.
      renderer.camera.half_height = 0.5f * options.frame_height;
      renderer.camera.center_ws = {0.5f * (bounds.min_ws.x + bounds.max_ws.x),
                                   bounds.min_ws.y - options.margin * options.frame_height + renderer.camera.half_height};
    }
    if (options.ground && options.frame_height <= 0.0f) {
      // The ground near the lower edge: the creature stands on it, little soil shows.
      const Box view = renderer.camera.visible_box();
      const float below = std::max(view.min_ws.y - bounds.min_ws.y, 0.0f);
      renderer.camera.center_ws.y += (0.0f - options.margin * 0.5f * (view.max_ws.y - view.min_ws.y)) - (view.min_ws.y + below);
    }
    if (options.ground) {
      DebugDraw ground;
      const Box view = renderer.camera.visible_box();
      ground.add_box({{view.min_ws.x - 1.0f, view.min_ws.y - 1.0f}, {view.max_ws.x + 1.0f, 0.0f}}, {0.42f, 0.36f, 0.27f, 1.0f}, true);
      ground.add_line({view.min_ws.x - 1.0f, 0.0f}, {view.max_ws.x + 1.0f, 0.0f}, {0.25f, 0.2f, 0.14f, 1.0f});
      renderer.draw_debug(ground);
    }
    const Texture* textures[1] = {&atlas.texture};
    renderer.draw_creatures(batch, textures, options.look);
    image = target->read();
  }
  const bool gl_ok = check_gl("render_creature_image");
  renderer.camera = saved_camera;
  renderer.stats = saved_stats;
  if (!gl_ok) return Error{"OpenGL reported an error while drawing the creature (see the log)"};
  composite_over(image, options.background);
  return image;
}

Status write_creature_png(const std::string& path, const Creature& creature,
                          const CreatureImageOptions& options, const std::string& shader_dir,
                          const std::string& sprite_dir) {
  if (!gl_context_is_current()) {
    return Error::at(path, "", "no current OpenGL context to draw with (PNG export needs the game's window)");
  }
  auto renderer = Renderer::create(shader_dir);
  if (!renderer.ok()) return Error::at(path, "", renderer.message());
  const Atlas atlas = Atlas::load(sprite_dir);
  auto image = render_creature_image(*renderer, atlas, creature, options);
  if (!image.ok()) return Error::at(path, "", image.message());
  return write_png(path, *image);
}

}  // namespace ossa
