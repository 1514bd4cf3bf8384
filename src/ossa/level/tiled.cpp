#include "ossa/level/tiled.h"

// [SECTION] Shared helpers (tiled_internal.h)
// [SECTION] Objects and layers
// [SECTION] Entry points
// Tilesets and tile layers: tiled_tiles.cpp; export: tiled_export.cpp.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "ossa/level/level_io.h"
#include "ossa/level/tile_merge.h"
#include "ossa/level/tiled_internal.h"

namespace ossa {

namespace tiled_detail {

// ---- [SECTION] Shared helpers ----------------------------------------------------------------

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

const Json* find_property_ci(const Json& element, const char* name) {
  if (!element.is_object()) return nullptr;
  auto it = element.find("properties");
  if (it == element.end()) return nullptr;
  if (it->is_object()) {
    for (auto p = it->begin(); p != it->end(); ++p) {
      if (lower(p.key()) == name) return &p.value();
    }
    return nullptr;
  }
  if (!it->is_array()) return nullptr;
  for (const Json& p : *it) {
    if (p.is_object() && p.contains("name") && p["name"].is_string() &&
        lower(p["name"].get<std::string>()) == name && p.contains("value")) {
      return &p["value"];
    }
  }
  return nullptr;
}

bool truthy(const Json* v) {
  if (!v) return false;
  if (v->is_boolean()) return v->get<bool>();
  if (v->is_string()) return lower(v->get<std::string>()) == "true";
  if (v->is_number()) return v->get<double>() != 0.0;
  return false;
}

std::string kind_of(const Json& element) {
  if (!element.is_object()) return "";
  for (const char* key : {"class", "type"}) {
    auto it = element.find(key);
    if (it != element.end() && it->is_string() && !it->get<std::string>().empty()) return lower(it->get<std::string>());
  }
  return "";
}

// ---- [SECTION] Objects and layers --------------------------------------------------------------

void Importer::object(const Json& o, const std::string& path, double offx, double offy) {
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

void Importer::layers(const Json& parent, const std::string& parent_path, double offx, double offy, int depth,
                      const LayerStyle& parent_style) {
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
    const LayerStyle style = layer_style(layer, path, parent_style);
    if (r.failed()) return;
    if (type == "objectgroup") {
      const Json* objects = r.array(layer, path, "objects");
      if (!objects) return;
      for (size_t k = 0; k < objects->size() && !r.failed(); ++k) {
        object((*objects)[k], json_path(json_path(path, "objects"), k), lx, ly);
      }
    } else if (type == "tilelayer") {
      tile_layer(layer, path, lx, ly, style);
    } else if (type == "group") {
      if (depth >= kMaxGroupDepth) {
        r.fail(path, "group layers nested more than " + std::to_string(kMaxGroupDepth) + " deep");
        return;
      }
      layers(layer, path, lx, ly, depth + 1, style);
    } else if (type == "imagelayer") {
      art_image_layer(layer, path, lx, ly, style);
      if (!have_image) {
        have_image = true;
        if (!background) background = Background{};
        background->image = r.string_or(layer, path, "image", "");
        background->parallax = static_cast<float>(r.number_or(layer, path, "parallaxx", 1.0, 0.0, 1.0));
      }
    }
  }
}

}  // namespace tiled_detail

namespace {

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

}  // namespace

using tiled_detail::find_property_ci;
using tiled_detail::Importer;
using tiled_detail::LayerStyle;

// ---- [SECTION] Entry points --------------------------------------------------------------------

Result<Level> import_tiled_json(const Json& map, std::string_view file, const TiledOptions& options,
                                LevelLoadReport* report) {
  OSSA_ASSERT(options.pixels_per_metre > 0.0f && std::isfinite(options.pixels_per_metre),
              "TiledOptions::pixels_per_metre must be > 0");
  Importer im{JsonReader{std::string(file)}};
  im.ppm = options.pixels_per_metre;
  im.options = &options;
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
  im.tile_h_px = static_cast<double>(tile_h);
  im.tile_w_px = static_cast<double>(r.integer_or(map, "", "tilewidth", 0, 0, 1000000));
  if (r.failed()) return r.error();
  im.map_h_px = static_cast<double>(height) * static_cast<double>(tile_h);
  // Scale: the map property, else one tile = 0.5 m, else the option (tiled.h).
  const char* scale_from = "option";
  if (options.tile_is_half_metre && im.tile_w_px > 0.0) {
    im.ppm = 2.0 * im.tile_w_px;
    scale_from = "tile size";
  }
  if (const Json* p = find_property_ci(map, "pixels_per_metre")) {
    if (!p->is_number() || !(p->get<double>() > 0.0 && p->get<double>() <= 1e6)) {
      return Error::at(file, "properties.pixels_per_metre", "expected a number in (0, 1000000], got " + describe_json(*p));
    }
    im.ppm = p->get<double>();
    scale_from = "map property";
  }
  im.read_tilesets(map);
  if (r.failed()) return r.error();
  if (r.has(map, "backgroundcolor")) {
    const std::string s = r.string(map, "", "backgroundcolor");
    const auto c = parse_colour(s);
    if (!r.failed() && !c) r.fail("backgroundcolor", "expected \"#RRGGBB\" or \"#AARRGGBB\", got " + describe_json(map["backgroundcolor"]));
    if (c) im.background = Background{"", 0.5f, *c};
    im.art.background = parse_hex_colour(s);
  }
  im.art.file = std::string(file);
  im.art.parallax_origin_ws = {static_cast<float>(r.number_or(map, "", "parallaxoriginx", 0.0) / im.ppm),
                               static_cast<float>((im.map_h_px - r.number_or(map, "", "parallaxoriginy", 0.0)) / im.ppm)};
  im.layers(map, "", 0.0, 0.0, 0, LayerStyle{});
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
  } else {
    level.spawn_ws = default_map_spawn(level);
  }
  if (!im.art.empty()) level.art = std::make_shared<const LevelArt>(std::move(im.art));
  if (report) {
    for (std::string& w : im.warnings) report->warnings.push_back(std::move(w));
    report->pixels_per_metre = static_cast<float>(im.ppm);
    report->scale_from = scale_from;
    report->solid_cells += im.solid_cells;
    report->boxes_from_cells += im.boxes_from_cells;
  }
  return level;
}

Result<Level> import_tiled(std::string_view text, std::string_view file, const TiledOptions& options,
                           LevelLoadReport* report) {
  Result<Json> doc = parse_json(text, file);
  if (!doc) return doc.error();
  return import_tiled_json(*doc, file, options, report);
}

Result<Level> import_tmx(std::string_view text, std::string_view file, const TiledOptions& options,
                         LevelLoadReport* report) {
  Result<Json> doc = tmx_to_json(text, file);
  if (!doc) return doc.error();
  return import_tiled_json(*doc, file, options, report);
}

}  // namespace ossa
