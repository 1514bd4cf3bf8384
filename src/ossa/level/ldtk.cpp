#include "ossa/level/ldtk.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "ossa/io/json.h"
#include "ossa/level/ldtk_art.h"
#include "ossa/level/level_io.h"
#include "ossa/level/tile_merge.h"

namespace ossa {

namespace {


std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// IntGrid value -> identifier, per layer definition uid.
using IntGridNames = std::map<long long, std::map<long long, std::string>>;

struct LdtkImporter {
  JsonReader r;
  const LdtkOptions* options = nullptr;
  double ppm = 32.0;
  double world_x = 0.0, world_y = 0.0;  // px
  IntGridNames names;
  std::vector<Box> boxes;
  std::optional<glm::vec2> spawn;
  std::string spawn_path;
  int64_t solid_cells = 0, boxes_from_cells = 0;
  int64_t cells_read = 0;  // IntGrid cells of every layer so far (level_load.h kMaxMapCells)

  float to_x(double px, const std::string& path) {
    const double m = (world_x + px) / ppm;
    if (!(std::abs(m) <= kMaxLevelCoordinate)) {
      r.fail(path, "lies more than " + std::to_string(static_cast<long long>(kMaxLevelCoordinate)) + " m from the origin");
      return 0.0f;  // a float cast of an out-of-range double is undefined
    }
    return static_cast<float>(m);
  }
  float to_y(double px, const std::string& path) {
    const double m = -(world_y + px) / ppm;
    if (!(std::abs(m) <= kMaxLevelCoordinate)) {
      r.fail(path, "lies more than " + std::to_string(static_cast<long long>(kMaxLevelCoordinate)) + " m from the origin");
      return 0.0f;  // a float cast of an out-of-range double is undefined
    }
    return static_cast<float>(m);
  }

  void read_defs(const Json& project) {
    if (!r.has(project, "defs")) return;
    const Json* defs = r.object(project, "", "defs");
    if (!defs || !r.has(*defs, "layers")) return;
    const Json* layers = r.array(*defs, "defs", "layers");
    if (!layers) return;
    for (size_t i = 0; i < layers->size() && !r.failed(); ++i) {
      const Json& l = (*layers)[i];
      const std::string path = json_path("defs.layers", i);
      if (!r.expect_object(l, path)) return;
      const long long uid = r.integer(l, path, "uid");
      if (r.failed() || !r.has(l, "intGridValues")) continue;
      const Json* values = r.array(l, path, "intGridValues");
      if (!values) return;
      for (size_t k = 0; k < values->size() && !r.failed(); ++k) {
        const Json& v = (*values)[k];
        const std::string vpath = json_path(json_path(path, "intGridValues"), k);
        if (!r.expect_object(v, vpath)) return;
        const long long value = r.integer(v, vpath, "value");
        const std::string id = r.string_or(v, vpath, "identifier", "");
        if (!r.failed()) names[uid][value] = lower(id);
      }
    }
  }

  bool passable(long long layer_uid, long long value) const {
    auto l = names.find(layer_uid);
    if (l == names.end()) return false;
    auto v = l->second.find(value);
    if (v == l->second.end()) return false;
    for (const std::string& p : options->passable) {
      if (lower(p) == v->second) return true;
    }
    return false;
  }

  void intgrid(const Json& layer, const std::string& path, const std::string& what, double offx, double offy) {
    const long long w = r.integer(layer, path, "__cWid", 0, kMaxMapCells);
    const long long h = r.integer(layer, path, "__cHei", 0, kMaxMapCells);
    const long long grid = r.integer(layer, path, "__gridSize", 1, 1000000);
    const long long uid = r.integer_or(layer, path, "layerDefUid", -1);
    if (r.failed()) return;
    cells_read += w * h;  // every layer of the level counts towards one limit
    if (w * h > kMaxMapCells || cells_read > kMaxMapCells) {
      r.fail(path, what + " has " + std::to_string(w * h) + " cells, " + std::to_string(cells_read) +
                       " with the layers before; at most " + std::to_string(kMaxMapCells) + " in all the layers of a level");
      return;
    }
    const Json* csv = r.array(layer, path, "intGridCsv");
    if (!csv) return;
    if (csv->size() != static_cast<size_t>(w * h)) {
      r.fail(json_path(path, "intGridCsv"), what + ": expected " + std::to_string(w * h) +
                                                " values (__cWid x __cHei), got " + std::to_string(csv->size()));
      return;
    }
    std::vector<Cell> cells;
    for (long long i = 0; i < w * h; ++i) {
      const Json& v = (*csv)[static_cast<size_t>(i)];
      if (!v.is_number_integer()) {
        r.fail(json_path(json_path(path, "intGridCsv"), static_cast<size_t>(i)),
               what + ": expected an integer IntGrid value, got " + describe_json(v));
        return;
      }
      const long long value = v.get<long long>();
      if (value != 0 && !passable(uid, value)) cells.push_back({i % w, i / w});
    }
    MergedCells merged = merge_cells(cells);
    solid_cells += merged.cells;
    boxes_from_cells += static_cast<int64_t>(merged.rects.size());
    const double g = static_cast<double>(grid);
    for (const CellRect& c : merged.rects) {
      const double x0 = offx + c.x * g, x1 = x0 + c.w * g;
      const double y0 = offy + c.y * g, y1 = y0 + c.h * g;
      const Box box{{to_x(x0, path), to_y(y1, path)}, {to_x(x1, path), to_y(y0, path)}};
      if (r.failed()) return;
      if (!box.is_valid()) {
        r.fail(path, what + ": cells too small to be represented at this position");
        return;
      }
      if (boxes.size() >= static_cast<size_t>(kMaxLevelColliders)) {
        r.fail(path, "more than " + std::to_string(kMaxLevelColliders) + " colliders");
        return;
      }
      boxes.push_back(box);
    }
  }

  void entities(const Json& layer, const std::string& path, const std::string& what, double offx, double offy) {
    const Json* list = r.array(layer, path, "entityInstances");
    if (!list) return;
    for (size_t i = 0; i < list->size() && !r.failed(); ++i) {
      const Json& e = (*list)[i];
      const std::string epath = json_path(json_path(path, "entityInstances"), i);
      if (!r.expect_object(e, epath)) return;
      const std::string id = lower(r.string(e, epath, "__identifier"));
      if (r.failed()) return;
      if (id != "player" && id != "spawn") continue;
      if (spawn) {
        r.fail(epath, what + ": a second Player/Spawn entity; the first is " + spawn_path);
        return;
      }
      const Json* px = r.array(e, epath, "px");
      if (!px) return;
      if (px->size() != 2) {
        r.fail(json_path(epath, "px"), "expected [x, y], got " + std::to_string(px->size()) + " elements");
        return;
      }
      const double x = r.as_number((*px)[0], json_path(json_path(epath, "px"), 0));
      const double y = r.as_number((*px)[1], json_path(json_path(epath, "px"), 1));
      if (r.failed()) return;
      spawn = glm::vec2(to_x(offx + x, epath), to_y(offy + y, epath));
      spawn_path = epath;
    }
  }

  void layers(const Json& level, const std::string& level_path, const std::string& level_id) {
    const Json* list = r.array(level, level_path, "layerInstances");
    if (!list) return;
    for (size_t i = 0; i < list->size() && !r.failed(); ++i) {
      const Json& layer = (*list)[i];
      const std::string path = json_path(json_path(level_path, "layerInstances"), i);
      if (!r.expect_object(layer, path)) return;
      const std::string type = r.string(layer, path, "__type");
      const std::string id = r.string_or(layer, path, "__identifier", "");
      const double offx = r.number_or(layer, path, "__pxTotalOffsetX", 0.0);
      const double offy = r.number_or(layer, path, "__pxTotalOffsetY", 0.0);
      if (r.failed()) return;
      const std::string what = "level \"" + level_id + "\" layer \"" + id + "\"";
      if (type == "IntGrid") {
        intgrid(layer, path, what, offx, offy);
      } else if (type == "Entities") {
        entities(layer, path, what, offx, offy);
      }
    }
  }
};

}  // namespace

Result<Level> import_ldtk_json(const Json& project, std::string_view file, const std::string& level_name,
                               const LdtkOptions& options, LevelLoadReport* report) {
  OSSA_ASSERT(options.pixels_per_metre > 0.0f && std::isfinite(options.pixels_per_metre),
              "LdtkOptions::pixels_per_metre must be > 0");
  LdtkImporter im{JsonReader{std::string(file)}, &options, 32.0, 0.0, 0.0, {}, {}, {}, {}, 0, 0};
  JsonReader& r = im.r;
  if (!r.expect_object(project, "")) return r.error();
  const Json* levels = r.array(project, "", "levels");
  if (!levels) return r.error();
  if (levels->empty()) return Error::at(file, "levels", "expected at least one level, got none");
  // The level: by identifier, else the first.
  size_t index = 0;
  if (!level_name.empty()) {
    index = levels->size();
    std::string known;
    for (size_t i = 0; i < levels->size(); ++i) {
      const Json& l = (*levels)[i];
      if (!l.is_object() || !l.contains("identifier") || !l["identifier"].is_string()) continue;
      if (l["identifier"] == level_name) {
        index = i;
        break;
      }
      if (known.size() < 200) known += (known.empty() ? "" : ", ") + l["identifier"].get<std::string>();
    }
    if (index == levels->size()) {
      return Error::at(file, "levels", "no level named \"" + level_name + "\" (the levels are " + known + ")");
    }
  }
  const std::string level_path = json_path("levels", index);
  const Json& level_json = (*levels)[index];
  if (!r.expect_object(level_json, level_path)) return r.error();
  const std::string id = r.string_or(level_json, level_path, "identifier", "");
  const long long grid = r.integer_or(project, "", "defaultGridSize", 0, 0, 1000000);
  const std::string layout = r.string_or(project, "", "worldLayout", "");
  if (layout.rfind("Linear", 0) != 0) {
    im.world_x = r.number_or(level_json, level_path, "worldX", 0.0, -1e12, 1e12);
    im.world_y = r.number_or(level_json, level_path, "worldY", 0.0, -1e12, 1e12);
  }
  im.read_defs(project);
  if (r.failed()) return r.error();

  // Scale: the level's field, else one grid cell = 0.5 m, else the option.
  im.ppm = options.pixels_per_metre;
  const char* scale_from = "option";
  if (grid > 0) {
    im.ppm = 2.0 * static_cast<double>(grid);
    scale_from = "tile size";
  }
  if (level_json.contains("fieldInstances") && level_json["fieldInstances"].is_array()) {
    for (const Json& f : level_json["fieldInstances"]) {
      if (!f.is_object() || !f.contains("__identifier") || !f["__identifier"].is_string() ||
          lower(f["__identifier"].get<std::string>()) != "pixels_per_metre") {
        continue;
      }
      const Json v = f.contains("__value") ? f["__value"] : Json();
      if (!v.is_number() || !(v.get<double>() > 0.0 && v.get<double>() <= 1e6)) {
        return Error::at(file, json_path(level_path, "fieldInstances"),
                         "level \"" + id + "\" field pixels_per_metre: expected a number in (0, 1000000], got " + describe_json(v));
      }
      im.ppm = v.get<double>();
      scale_from = "map property";
    }
  }

  // The layers: in the project, or in an external level file. The art from the same JSON.
  LevelArt art;
  art.file = std::string(file) + (id.empty() ? "" : "#" + id);
  std::vector<std::string> warnings;
  const ldtk_detail::ArtFrame frame{im.ppm, im.world_x, im.world_y};
  const bool external = !level_json.contains("layerInstances") || level_json["layerInstances"].is_null();
  if (external) {
    const std::string rel = r.string(level_json, level_path, "externalRelPath");
    if (r.failed()) return r.error();
    const std::string where = json_path(level_path, "externalRelPath");
    if (!options.read_file) {
      return Error::at(file, where, "level \"" + id + "\" is in an external file \"" + rel + "\" that cannot be read here (no file access)");
    }
    const std::string ext_path = (std::filesystem::path(std::string(file)).parent_path() / rel).string();
    Result<std::string> text = options.read_file(ext_path);
    if (!text) return Error::at(file, where, "level \"" + id + "\": " + text.message());
    Result<Json> doc = parse_json(*text, ext_path);
    if (!doc) return doc.error();
    LdtkImporter inner = std::move(im);
    inner.r = JsonReader{ext_path};
    if (!inner.r.expect_object(*doc, "")) return inner.r.error();
    inner.layers(*doc, "", id);
    if (!inner.r.failed()) ldtk_detail::read_art(project, *doc, "", std::string(file), frame, inner.r, art, warnings);
    if (inner.r.failed()) return inner.r.error();
    im = std::move(inner);
  } else {
    im.layers(level_json, level_path, id);
    if (!r.failed()) ldtk_detail::read_art(project, level_json, level_path, std::string(file), frame, r, art, warnings);
    if (r.failed()) return r.error();
  }

  Level level(std::move(im.boxes));
  level.name = id;
  if (art.background) level.background = Background{"", 0.5f, glm::vec3(*art.background)};
  if (!art.empty()) level.art = std::make_shared<const LevelArt>(std::move(art));
  if (im.spawn) {
    level.spawn_ws = *im.spawn;
  } else {
    level.spawn_ws = default_map_spawn(level);
  }
  if (report) {
    for (std::string& w : warnings) report->warnings.push_back(std::move(w));
    report->level_name = id;
    report->pixels_per_metre = static_cast<float>(im.ppm);
    report->scale_from = scale_from;
    report->solid_cells += im.solid_cells;
    report->boxes_from_cells += im.boxes_from_cells;
  }
  return level;
}

Result<Level> import_ldtk(std::string_view text, std::string_view file, const std::string& level_name,
                          const LdtkOptions& options, LevelLoadReport* report) {
  Result<Json> doc = parse_json(text, file);
  if (!doc) return doc.error();
  return import_ldtk_json(*doc, file, level_name, options, report);
}

}  // namespace ossa
