// LDtk import, the art (ldtk_art.h).

#include "ossa/level/ldtk_art.h"

#include <cctype>
#include <cmath>
#include <map>

#include "ossa/io/json.h"

namespace ossa::ldtk_detail {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool is_foreground(const std::string& identifier) {
  const std::string id = lower(identifier);
  return id.rfind("foreground", 0) == 0 || id == "fg" || id.rfind("fg_", 0) == 0;
}

struct Reader {
  const Json& project;
  const std::string& project_file;
  const ArtFrame& frame;
  JsonReader& r;
  LevelArt& art;
  std::vector<std::string>& warnings;
  std::map<long long, int> tileset_of_uid;     // defs.tilesets uid -> art.tilesets index (-1: not drawn)
  std::map<long long, glm::vec2> parallax_of_layer_def;
  int64_t tiles = 0;
  bool full = false;

  double x_ws(double px) const { return (frame.world_x + px) / frame.ppm; }
  double y_ws(double px) const { return -(frame.world_y + px) / frame.ppm; }

  void read_defs() {
    if (!project.is_object() || !project.contains("defs") || !project["defs"].is_object()) return;
    const Json& defs = project["defs"];
    if (defs.contains("tilesets") && defs["tilesets"].is_array()) {
      const Json& list = defs["tilesets"];
      for (size_t i = 0; i < list.size() && !r.failed(); ++i) {
        const Json& t = list[i];
        const std::string path = json_path("defs.tilesets", i);
        if (!r.expect_object(t, path)) return;
        const long long uid = r.integer(t, path, "uid");
        const std::string rel = r.string_or(t, path, "relPath", "");
        const long long grid = r.integer_or(t, path, "tileGridSize", 0, 0, 1000000);
        ArtTileset ts;
        ts.name = r.string_or(t, path, "identifier", "");
        ts.margin_px = static_cast<int>(r.integer_or(t, path, "padding", 0, 0, 1000000));
        ts.spacing_px = static_cast<int>(r.integer_or(t, path, "spacing", 0, 0, 1000000));
        ts.columns = static_cast<int>(r.integer_or(t, path, "__cWid", 0, 0, 1000000));
        const long long w = r.integer_or(t, path, "pxWid", 0, 0, 1000000);
        const long long h = r.integer_or(t, path, "pxHei", 0, 0, 1000000);
        if (r.failed()) return;
        if (rel.empty() || grid <= 0) {
          tileset_of_uid[uid] = -1;  // LDtk's embedded icons, or no grid: nothing to draw
          continue;
        }
        ts.tile_w_px = ts.tile_h_px = static_cast<int>(grid);
        ts.images.push_back(art.add_image(art_path_near(project_file, rel), rel, static_cast<int>(w), static_cast<int>(h)));
        tileset_of_uid[uid] = static_cast<int>(art.tilesets.size());
        art.tilesets.push_back(std::move(ts));
      }
    }
    if (defs.contains("layers") && defs["layers"].is_array()) {
      const Json& list = defs["layers"];
      for (size_t i = 0; i < list.size() && !r.failed(); ++i) {
        const Json& l = list[i];
        const std::string path = json_path("defs.layers", i);
        if (!r.expect_object(l, path)) return;
        const long long uid = r.integer(l, path, "uid");
        const double fx = r.number_or(l, path, "parallaxFactorX", 0.0, -1.0, 1.0);
        const double fy = r.number_or(l, path, "parallaxFactorY", 0.0, -1.0, 1.0);
        if (r.failed()) return;
        parallax_of_layer_def[uid] = {static_cast<float>(1.0 - fx), static_cast<float>(1.0 - fy)};
      }
    }
  }

  // One tile array (gridTiles or autoLayerTiles) of a layer into `out`.
  void tile_list(const Json& layer, const std::string& path, const char* key, int tileset, double offx, double offy,
                 ArtLayer& out) {
    if (!r.has(layer, key)) return;
    const Json* list = r.array(layer, path, key);
    if (!list || list->empty()) return;
    const ArtTileset& ts = art.tilesets[static_cast<size_t>(tileset)];
    const double g = ts.tile_w_px;
    ArtBatch batch{tileset, {}};
    batch.tiles.reserve(list->size());
    for (size_t i = 0; i < list->size() && !r.failed(); ++i) {
      const Json& t = (*list)[i];
      const std::string tpath = json_path(json_path(path, key), i);
      if (!r.expect_object(t, tpath)) return;
      const Json* px = r.array(t, tpath, "px");
      if (!px) return;
      if (px->size() != 2) {
        r.fail(json_path(tpath, "px"), "expected [x, y], got " + std::to_string(px->size()) + " elements");
        return;
      }
      const double x = r.as_number((*px)[0], json_path(json_path(tpath, "px"), 0), -1e9, 1e9);
      const double y = r.as_number((*px)[1], json_path(json_path(tpath, "px"), 1), -1e9, 1e9);
      long long id = r.integer_or(t, tpath, "t", -1, -1, 0x0FFFFFFF);
      const long long f = r.integer_or(t, tpath, "f", 0, 0, 3);
      const double a = r.number_or(t, tpath, "a", 1.0, 0.0, 1.0);
      if (id < 0 && r.has(t, "src")) {
        // Older files: the tile from its pixel position in the tileset.
        const Json* src = r.array(t, tpath, "src");
        if (!src || src->size() != 2) {
          r.fail(json_path(tpath, "src"), "expected [x, y]");
          return;
        }
        const double sx = r.as_number((*src)[0], json_path(tpath, "src"), 0, 1e9);
        const double sy = r.as_number((*src)[1], json_path(tpath, "src"), 0, 1e9);
        const double step = g + ts.spacing_px;
        const long long col = static_cast<long long>(std::floor((sx - ts.margin_px) / step));
        const long long row = static_cast<long long>(std::floor((sy - ts.margin_px) / step));
        id = row * std::max(1, ts.columns) + col;
      }
      if (r.failed()) return;
      if (id < 0) {
        r.fail(tpath, "expected a tile id \"t\" (or \"src\")");
        return;
      }
      if (tiles >= kMaxArtTiles) {
        if (!full) {
          warnings.push_back("the art has more than " + std::to_string(kMaxArtTiles) +
                             " tiles; the tiles after that are not drawn (the colliders all count)");
        }
        full = true;
        break;
      }
      ++tiles;
      ArtTile tile;
      // px is the tile's top-left: its bottom-left is g pixels lower.
      const double left = x_ws(offx + x), bottom = y_ws(offy + y + g);
      if (!(std::abs(left) <= 1e6) || !(std::abs(bottom) <= 1e6)) {
        r.fail(tpath, "lies too far from the origin");
        return;
      }
      tile.min_ws = {static_cast<float>(left), static_cast<float>(bottom)};
      tile.size_ws = glm::vec2(static_cast<float>(g / frame.ppm));
      tile.tile = static_cast<uint32_t>(id);
      tile.flags = static_cast<uint8_t>(((f & 1) ? kArtFlipX : 0) | ((f & 2) ? kArtFlipY : 0));
      tile.alpha = static_cast<uint8_t>(std::lround(a * 255.0));
      batch.tiles.push_back(tile);
    }
    if (!batch.tiles.empty()) out.batches.push_back(std::move(batch));
  }

  void layer(const Json& l, const std::string& path) {
    if (!r.expect_object(l, path)) return;
    const std::string type = r.string(l, path, "__type");
    const std::string id = r.string_or(l, path, "__identifier", "");
    const bool visible = r.boolean_or(l, path, "visible", true);
    const double opacity = r.number_or(l, path, "__opacity", 1.0, 0.0, 1.0);
    const double offx = r.number_or(l, path, "__pxTotalOffsetX", 0.0, -1e9, 1e9);
    const double offy = r.number_or(l, path, "__pxTotalOffsetY", 0.0, -1e9, 1e9);
    const long long uid = r.integer_or(l, path, "__tilesetDefUid", -1);
    const long long def = r.integer_or(l, path, "layerDefUid", -1);
    if (r.failed() || !visible || type == "Entities" || uid < 0) return;
    const auto ts = tileset_of_uid.find(uid);
    if (ts == tileset_of_uid.end()) {
      r.fail(json_path(path, "__tilesetDefUid"), "layer \"" + id + "\": no tileset with uid " + std::to_string(uid) +
                                                     " in defs.tilesets");
      return;
    }
    if (ts->second < 0) return;
    ArtLayer out;
    out.name = id;
    out.opacity = static_cast<float>(opacity);
    if (const auto p = parallax_of_layer_def.find(def); p != parallax_of_layer_def.end()) out.parallax = p->second;
    out.front = is_foreground(id);
    tile_list(l, path, "gridTiles", ts->second, offx, offy, out);
    tile_list(l, path, "autoLayerTiles", ts->second, offx, offy, out);
    if (!out.batches.empty()) art.layers.push_back(std::move(out));
  }

  void background(const Json& level, const std::string& path) {
    const std::string colour = r.string_or(level, path, "__bgColor", "");
    if (r.failed()) return;
    if (!colour.empty()) {
      art.background = parse_hex_colour(colour);
      if (!art.background) {
        r.fail(json_path(path, "__bgColor"), "expected \"#RRGGBB\", got " + describe_json(level["__bgColor"]));
        return;
      }
    }
    const std::string rel = r.string_or(level, path, "bgRelPath", "");
    if (r.failed() || rel.empty()) return;
    ArtLayer bg;
    bg.kind = ArtLayer::Kind::kImage;
    bg.name = "background";
    bg.image = art.add_image(art_path_near(project_file, rel), rel, 0, 0);
    bg.metres_per_px = static_cast<float>(1.0 / frame.ppm);
    double left = 0.0, top = 0.0;
    if (r.has(level, "__bgPos")) {
      const Json* pos = r.object(level, path, "__bgPos");
      if (!pos) return;
      const std::string ppath = json_path(path, "__bgPos");
      auto pair = [&](const char* key, double fallback) -> glm::dvec2 {
        if (!r.has(*pos, key)) return glm::dvec2(fallback);
        const Json* a = r.array(*pos, ppath, key);
        if (!a || a->size() < 2) {
          r.fail(json_path(ppath, key), "expected [x, y]");
          return glm::dvec2(fallback);
        }
        return {r.as_number((*a)[0], json_path(ppath, key), -1e9, 1e9), r.as_number((*a)[1], json_path(ppath, key), -1e9, 1e9)};
      };
      const glm::dvec2 tl = pair("topLeftPx", 0.0);
      const glm::dvec2 scale = pair("scale", 1.0);
      left = tl.x;
      top = tl.y;
      bg.scale = glm::vec2(scale);
      if (r.has(*pos, "cropRect")) {
        const Json* c = r.array(*pos, ppath, "cropRect");
        if (c && c->size() == 4) {
          for (int k = 0; k < 4; ++k) bg.crop_px[k] = static_cast<float>(r.as_number((*c)[static_cast<size_t>(k)], json_path(ppath, "cropRect"), 0, 1e9));
        }
      }
    }
    if (r.failed()) return;
    bg.origin_ws = {static_cast<float>(x_ws(left)), static_cast<float>(y_ws(top))};
    // Behind every layer.
    art.layers.insert(art.layers.begin(), std::move(bg));
  }
};

}  // namespace

void read_art(const Json& project, const Json& level, const std::string& level_path, const std::string& project_file,
              const ArtFrame& frame, JsonReader& r, LevelArt& art, std::vector<std::string>& warnings) {
  Reader reader{project, project_file, frame, r, art, warnings, {}, {}, 0, false};
  art.parallax_origin_ws = {static_cast<float>(reader.x_ws(0.0)), static_cast<float>(reader.y_ws(0.0))};
  reader.read_defs();
  if (r.failed() || !r.has(level, "layerInstances")) return;
  const Json* list = r.array(level, level_path, "layerInstances");
  if (!list) return;
  // Front to back in the file: drawn from the last.
  for (size_t i = list->size(); i-- > 0 && !r.failed();) {
    reader.layer((*list)[i], json_path(json_path(level_path, "layerInstances"), i));
  }
  if (r.failed()) return;
  reader.background(level, level_path);
}

}  // namespace ossa::ldtk_detail
