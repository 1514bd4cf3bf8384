#include "ossa/level/tiled.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "ossa/level/level_io.h"

namespace ossa {

namespace {

constexpr int kMaxGroupDepth = 32;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// "#RRGGBB" or "#AARRGGBB" -> RGB in [0, 1].
std::optional<glm::vec3> parse_colour(const std::string& s) {
  if (s.size() != 7 && s.size() != 9) return std::nullopt;
  if (s[0] != '#') return std::nullopt;
  for (size_t i = 1; i < s.size(); ++i) {
    if (!std::isxdigit(static_cast<unsigned char>(s[i]))) return std::nullopt;
  }
  const size_t o = s.size() == 9 ? 3 : 1;
  glm::vec3 c;
  for (int i = 0; i < 3; ++i) c[i] = static_cast<float>(std::stoi(s.substr(o + 2 * i, 2), nullptr, 16)) / 255.0f;
  return c;
}

// A map property by name: Tiled >= 1.2 writes an array of {name, type, value}, older
// versions an object of name -> value.
const Json* find_property(const Json& map, const char* name) {
  auto it = map.find("properties");
  if (it == map.end()) return nullptr;
  if (it->is_object()) {
    auto p = it->find(name);
    return p == it->end() ? nullptr : &*p;
  }
  if (!it->is_array()) return nullptr;
  for (const Json& p : *it) {
    if (p.is_object() && p.contains("name") && p["name"] == name && p.contains("value")) return &p["value"];
  }
  return nullptr;
}

struct Importer {
  JsonReader r;
  double ppm;
  double map_h_px;
  std::vector<Box> boxes;
  std::optional<glm::vec2> spawn;
  std::string spawn_path;
  std::optional<Background> background;
  bool have_image = false;

  // Pixel x / y (y-down) to metres, checked against the level file's coordinate bound.
  float to_x(double px, const std::string& path) {
    const double m = px / ppm;
    if (!(std::abs(m) <= kMaxLevelCoordinate)) r.fail(path, "lies more than 1000000 m from the origin");
    return static_cast<float>(m);
  }
  float to_y(double px, const std::string& path) { return to_x(map_h_px - px, path); }

  void object(const Json& o, const std::string& path, double offx, double offy) {
    if (!r.expect_object(o, path)) return;
    const std::string type = r.string_or(o, path, "type", "");
    const std::string cls = r.string_or(o, path, "class", "");
    const std::string kind = lower(cls.empty() ? type : cls);
    const std::string name = lower(r.string_or(o, path, "name", ""));
    const bool is_spawn = kind == "spawn" || name == "spawn";
    if (!is_spawn && !kind.empty() && kind != "collider") return;  // someone else's object
    const double x = r.number(o, path, "x") + offx;
    const double y = r.number(o, path, "y") + offy;
    const double w = r.number_or(o, path, "width", 0.0, 0.0);
    const double h = r.number_or(o, path, "height", 0.0, 0.0);
    const double rotation = r.number_or(o, path, "rotation", 0.0);
    const bool point = r.boolean_or(o, path, "point", false);
    const bool ellipse = r.boolean_or(o, path, "ellipse", false);
    if (r.failed()) return;
    const bool tile = r.has(o, "gid");
    const std::string id = r.has(o, "id") ? " (id " + describe_json(o["id"]) + ")" : "";
    if (is_spawn) {
      if (spawn) {
        r.fail(path, "a second spawn object" + id + "; the first is " + spawn_path);
        return;
      }
      // Tile objects are anchored at their bottom-left, every other shape at its top-left.
      const double bottom = tile ? y : y + h;
      spawn = glm::vec2(to_x(x + 0.5 * w, path), to_y(bottom, path));
      spawn_path = path;
      return;
    }
    const char* shape = point ? "a point" : ellipse ? "an ellipse"
                        : r.has(o, "polygon") ? "a polygon" : r.has(o, "polyline") ? "a polyline"
                        : r.has(o, "text") ? "a text object" : tile ? "a tile object" : nullptr;
    if (shape) {
      r.fail(path, std::string("collider") + id + " is " + shape +
                       "; colliders must be rectangles (give it another class to skip it)");
      return;
    }
    if (rotation != 0.0) {
      r.fail(json_path(path, "rotation"), "collider" + id + " is rotated by " + describe_json(o["rotation"]) +
                                              " degrees; colliders must be axis-aligned (rotation 0)");
      return;
    }
    if (!(w > 0.0) || !(h > 0.0)) {
      r.fail(path, "collider" + id + " has an empty size; expected width and height > 0");
      return;
    }
    const Box box{{to_x(x, path), to_y(y + h, path)}, {to_x(x + w, path), to_y(y, path)}};
    if (r.failed()) return;
    if (!box.is_valid()) {
      r.fail(path, "collider" + id + " is too small to be represented at this position");
      return;
    }
    if (boxes.size() >= static_cast<size_t>(kMaxLevelColliders)) {
      r.fail(path, "more than " + std::to_string(kMaxLevelColliders) + " colliders");
      return;
    }
    boxes.push_back(box);
  }

  void layers(const Json& parent, const std::string& parent_path, double offx, double offy, int depth) {
    const Json* list = r.array(parent, parent_path, "layers");
    if (!list) return;
    const std::string list_path = json_path(parent_path, "layers");
    for (size_t i = 0; i < list->size() && !r.failed(); ++i) {
      const Json& layer = (*list)[i];
      const std::string path = json_path(list_path, i);
      if (!r.expect_object(layer, path)) return;
      const std::string type = r.string(layer, path, "type");
      const double lx = offx + r.number_or(layer, path, "offsetx", 0.0);
      const double ly = offy + r.number_or(layer, path, "offsety", 0.0);
      if (r.failed()) return;
      if (type == "objectgroup") {
        const Json* objects = r.array(layer, path, "objects");
        if (!objects) return;
        for (size_t k = 0; k < objects->size() && !r.failed(); ++k) {
          object((*objects)[k], json_path(json_path(path, "objects"), k), lx, ly);
        }
      } else if (type == "group") {
        if (depth >= kMaxGroupDepth) {
          r.fail(path, "group layers nested more than " + std::to_string(kMaxGroupDepth) + " deep");
          return;
        }
        layers(layer, path, lx, ly, depth + 1);
      } else if (type == "imagelayer" && !have_image) {
        have_image = true;
        if (!background) background = Background{};
        background->image = r.string_or(layer, path, "image", "");
        background->parallax = static_cast<float>(r.number_or(layer, path, "parallaxx", 1.0, 0.0, 1.0));
      }
    }
  }
};

}  // namespace

Result<Level> import_tiled_json(const Json& map, std::string_view file, const TiledOptions& options) {
  OSSA_ASSERT(options.pixels_per_metre > 0.0f && std::isfinite(options.pixels_per_metre),
              "TiledOptions::pixels_per_metre must be > 0");
  Importer im{JsonReader{std::string(file)}, options.pixels_per_metre, 0.0, {}, {}, {}, {}, false};
  JsonReader& r = im.r;
  if (!r.expect_object(map, "")) return r.error();
  if (r.has(map, "type") && r.string(map, "", "type") != "map") {
    r.fail("type", "expected \"map\", got " + describe_json(map["type"]));
  }
  if (r.has(map, "orientation") && r.string(map, "", "orientation") != "orthogonal") {
    r.fail("orientation", "expected \"orthogonal\" (the only orientation ossa imports), got " +
                              describe_json(map["orientation"]));
  }
  const long long height = r.integer(map, "", "height", 0, 1000000000);
  const long long tile_h = r.integer(map, "", "tileheight", 1, 1000000);
  if (r.failed()) return r.error();
  im.map_h_px = static_cast<double>(height) * static_cast<double>(tile_h);
  if (r.has(map, "backgroundcolor")) {
    const std::string s = r.string(map, "", "backgroundcolor");
    const auto c = parse_colour(s);
    if (!r.failed() && !c) r.fail("backgroundcolor", "expected \"#RRGGBB\" or \"#AARRGGBB\", got " + describe_json(map["backgroundcolor"]));
    if (c) im.background = Background{"", 0.5f, *c};
  }
  im.layers(map, "", 0.0, 0.0, 0);
  if (r.failed()) return r.error();

  Level level(std::move(im.boxes));
  level.background = im.background;
  if (level.background) {
    if (const Json* p = find_property(map, "parallax"); p && p->is_number()) {
      const double v = p->get<double>();
      if (!(v >= 0.0 && v <= 1.0)) return Error::at(file, "properties.parallax", "expected a number in [0, 1], got " + describe_json(*p));
      level.background->parallax = static_cast<float>(v);
    }
  }
  if (const Json* p = find_property(map, "name"); p && p->is_string()) {
    level.name = p->get<std::string>();
  } else {
    level.name = std::filesystem::path(std::string(file)).stem().string();
  }
  if (im.spawn) {
    level.spawn_ws = *im.spawn;
  } else if (!level.empty()) {
    Box b = level.box(0);
    for (const Box& c : level.colliders()) b = b.united(c);
    const float x = b.min_ws.x + 1.0f;
    const auto g = level.ground_height_below(x, x, b.max_ws.y, b.height());
    level.spawn_ws = {x, g ? g->height_ws : b.max_ws.y};
  }
  return level;
}

Result<Level> import_tiled(std::string_view text, std::string_view file, const TiledOptions& options) {
  Result<Json> doc = parse_json(text, file);
  if (!doc) return doc.error();
  return import_tiled_json(*doc, file, options);
}

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
