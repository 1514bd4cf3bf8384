// Tiled JSON export (tiled.h): one object layer of collider rectangles, a spawn point, the
// background as map properties and an image layer.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ossa/io/json.h"
#include "ossa/level/level_io.h"
#include "ossa/level/tiled.h"

namespace ossa {

Json export_tiled(const Level& level, const TiledOptions& options) {
  OSSA_ASSERT(options.pixels_per_metre > 0.0f && options.tile_width_px > 0 && options.tile_height_px > 0,
              "TiledOptions: sizes must be > 0");
  const double ppm = options.pixels_per_metre;
  const Box b = level.bounds();
  // The grid spans x >= 0 and 0 <= y <= the highest point; anything outside stays valid.
  const auto width = std::max(1LL, static_cast<long long>(std::ceil(std::max(0.0f, b.max_ws.x) * ppm / options.tile_width_px)));
  const auto height = std::max(1LL, static_cast<long long>(std::ceil(std::max(0.0f, b.max_ws.y) * ppm / options.tile_height_px)));
  const double map_h_px = static_cast<double>(height) * options.tile_height_px;

  Json objects = Json::array();
  int next_id = 1;
  for (const Box& box : level.colliders()) {
    const double x0 = box.min_ws.x, x1 = box.max_ws.x, y0 = box.min_ws.y, y1 = box.max_ws.y;
    objects.push_back({{"id", next_id++}, {"name", ""}, {"type", "collider"},
                       {"x", x0 * ppm}, {"y", map_h_px - y1 * ppm},
                       {"width", (x1 - x0) * ppm}, {"height", (y1 - y0) * ppm},
                       {"rotation", 0}, {"visible", true}});
  }
  objects.push_back({{"id", next_id++}, {"name", "spawn"}, {"type", "spawn"}, {"point", true},
                     {"x", double(level.spawn_ws.x) * ppm}, {"y", map_h_px - double(level.spawn_ws.y) * ppm},
                     {"width", 0}, {"height", 0}, {"rotation", 0}, {"visible", true}});

  Json layers = Json::array();
  int layer_id = 1;
  Json properties = Json::array();
  properties.push_back({{"name", "name"}, {"type", "string"}, {"value", level.name}});
  Json map = Json::object();
  if (level.background) {
    const Background& bg = *level.background;
    char colour[8];
    auto channel = [](float c) { return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
    std::snprintf(colour, sizeof(colour), "#%02x%02x%02x", channel(bg.colour.r), channel(bg.colour.g), channel(bg.colour.b));
    map["backgroundcolor"] = colour;
    properties.push_back({{"name", "parallax"}, {"type", "float"}, {"value", shortest_decimal(bg.parallax)}});
    if (!bg.image.empty()) {
      layers.push_back({{"id", layer_id++}, {"name", "background"}, {"type", "imagelayer"},
                        {"image", bg.image}, {"parallaxx", shortest_decimal(bg.parallax)},
                        {"parallaxy", shortest_decimal(bg.parallax)}, {"opacity", 1}, {"visible", true},
                        {"x", 0}, {"y", 0}});
    }
  }
  layers.push_back({{"id", layer_id++}, {"name", "colliders"}, {"type", "objectgroup"},
                    {"draworder", "topdown"}, {"objects", std::move(objects)}, {"opacity", 1},
                    {"visible", true}, {"x", 0}, {"y", 0}});
  map["type"] = "map";
  map["version"] = "1.10";
  map["tiledversion"] = "1.10.2";
  map["orientation"] = "orthogonal";
  map["renderorder"] = "right-down";
  map["compressionlevel"] = -1;
  map["infinite"] = false;
  map["width"] = width;
  map["height"] = height;
  map["tilewidth"] = options.tile_width_px;
  map["tileheight"] = options.tile_height_px;
  map["nextlayerid"] = layer_id;
  map["nextobjectid"] = next_id;
  map["layers"] = std::move(layers);
  map["tilesets"] = Json::array();
  map["properties"] = std::move(properties);
  return map;
}

}  // namespace ossa
