#include "shared/level_scenes.h"

#include "ossa/math/rng.h"

namespace ossa::scenes {

Level flat_level(float width) {
  return Level({Box::from_corner(0.0f, -1.0f, width, 1.0f)}, {1.0f, 0.0f}, "flat");
}

Level random_level(uint64_t seed, int box_count, const RandomLevelOptions& o) {
  Rng rng(seed);
  const double world_width = static_cast<double>(box_count) * o.metres_per_box;
  std::vector<Box> boxes;
  boxes.reserve(static_cast<size_t>(box_count));
  for (int i = 0; i < box_count; ++i) {
    const auto x = static_cast<float>(rng.uniform(0.0, world_width));
    const auto y = static_cast<float>(rng.uniform(0.0, o.world_height));
    const auto w = static_cast<float>(rng.uniform(o.min_size, o.max_size));
    const auto h = static_cast<float>(rng.uniform(o.min_size, o.max_size));
    boxes.push_back(Box::from_corner(x, y, w, h));
  }
  return Level(std::move(boxes), {1.0f, o.world_height + o.max_size}, "random");
}

Level stairs_level(int steps, float rise, float tread) {
  std::vector<Box> boxes;
  float x = 0.0f;
  boxes.push_back(Box::from_corner(x, -1.0f, 4.0f, 1.0f));
  x += 4.0f;
  for (int i = 1; i <= steps; ++i, x += tread) {
    boxes.push_back(Box{{x, -1.0f}, {x + tread, static_cast<float>(i) * rise}});
  }
  boxes.push_back(Box{{x, -1.0f}, {x + 2.0f, static_cast<float>(steps + 1) * rise}});
  x += 2.0f;
  for (int i = steps; i >= 1; --i, x += tread) {
    boxes.push_back(Box{{x, -1.0f}, {x + tread, static_cast<float>(i) * rise}});
  }
  boxes.push_back(Box::from_corner(x, -1.0f, 4.0f, 1.0f));
  return Level(std::move(boxes), {1.0f, 0.0f}, "stairs");
}

std::vector<GroundQuery> random_ground_queries(uint64_t seed, const Level& level, int count) {
  Rng rng(seed);
  const Box b = level.bounds();
  std::vector<GroundQuery> queries;
  queries.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    GroundQuery q;
    q.x_min = static_cast<float>(rng.uniform(b.min_ws.x - 1.0, b.max_ws.x + 1.0));
    q.x_max = q.x_min + static_cast<float>(rng.uniform(0.0, 0.5));
    q.from_y = static_cast<float>(rng.uniform(b.min_ws.y - 1.0, b.max_ws.y + 1.0));
    q.max_drop = static_cast<float>(rng.uniform(0.0, 4.0));
    queries.push_back(q);
  }
  return queries;
}

}  // namespace ossa::scenes
