// ossa::draw's draw lists (draw/creature_draw.h) against the GL renderer: the triangles an
// embedder's renderer draws cover what CreatureBatch draws on the GPU, for bodies and bone
// sprites, from the same creature and pose.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gl_fixture.h"
#include "ossa/draw/creature_draw.h"
#include "ossa/gen/skeleton_builder.h"
#include "ossa/render/capture.h"
#include "ossa/render/creature_batch.h"
#include "ossa/skeleton/pose.h"

using namespace ossa;
using namespace ossa::test;

namespace {

bool background(const uint8_t* p, glm::vec3 bg) {
  return std::abs(p[0] - bg.r * 255.0f) < 3.0f && std::abs(p[1] - bg.g * 255.0f) < 3.0f && std::abs(p[2] - bg.b * 255.0f) < 3.0f;
}

// The pixels whose centres lie in a triangle of `list` (top row first, as read_framebuffer).
std::vector<uint8_t> rasterise(const DrawList& list, const Camera2D& camera) {
  std::vector<glm::vec2> px(list.vertices.size());
  for (size_t i = 0; i < px.size(); ++i) px[i] = camera.world_to_pixel(list.vertices[i].position_ws, kW, kH);
  return covered_pixels(px, list.indices);
}

}  // namespace

TEST_CASE("draw lists cover what the GL renderer draws of the same creature and pose", "[render][draw]") {
  Gl& g = gl();
  REQUIRE(g.error.empty());
  const glm::vec3 bg{0.1f, 0.2f, 0.3f};
  const Creature c = build_creature(scenes::generator().example("horse").value()).value();
  // A walking-like pose: the rest pose with the limbs turned a little, facing left.
  std::vector<BoneLocal> locals = c.rest_pose.locals;
  for (size_t b = 0; b < locals.size(); ++b) locals[b].angle_ls += 0.15f * std::sin(static_cast<float>(b));
  Transform2D place;
  place.mirror_x = true;
  const std::vector<Mat2x3> model = model_matrices(c.skeleton, locals);
  std::vector<Mat2x3> world(model.size());
  for (size_t b = 0; b < model.size(); ++b) world[b] = place.to_mat2x3() * model[b];

  for (const CreatureLook look : {CreatureLook::kBody, CreatureLook::kBones}) {
    INFO("look " << creature_look_name(look));
    CreatureDrawOptions options;
    options.look = look;
    const CreatureDrawable d = make_creature_drawable(c, g.atlas->sprites, options).value();
    DrawList list;
    append_creature(list, d, world);

    CreatureBatch batch;
    const int id = look == CreatureLook::kBody ? batch.add_body(d.body, c.skeleton) : batch.add(d.sprites, c.skeleton);
    batch.set_world(id, world);
    batch.upload_palettes();
    const Box b = creature_draw_bounds(list, 0);
    g.renderer->camera.fit({b.min_ws - glm::vec2(0.1f), b.max_ws + glm::vec2(0.1f)}, float(kW) / kH);
    g.renderer->begin_frame(kW, kH, bg);
    const Texture* textures[] = {&g.atlas->texture};
    g.renderer->draw_creatures(batch, textures, look);
    const Image img = read_framebuffer(kW, kH);
    const std::vector<uint8_t> cpu = rasterise(list, g.renderer->camera);

    int both = 0, gpu_only = 0, cpu_only = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const bool gpu = !background(img.pixel(x, y), bg);
        const bool mine = cpu[static_cast<size_t>(y * kW + x)] != 0;
        both += gpu && mine;
        gpu_only += gpu && !mine;
        cpu_only += !gpu && mine;
      }
    }
    INFO("both " << both << ", GPU only " << gpu_only << ", draw list only " << cpu_only);
    REQUIRE(both > 2000);
    // Nothing drawn outside the draw list's triangles but antialiased edges.
    CHECK(gpu_only < both / 50);
    if (look == CreatureLook::kBody) {
      CHECK(cpu_only < both / 50);  // flat-coloured: the same pixels
    } else {
      CHECK(cpu_only < both * 2);   // sprites: a quad's transparent texels are not drawn
    }
  }
}
