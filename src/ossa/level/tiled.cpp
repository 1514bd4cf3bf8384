#include "ossa/level/tiled.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include <zlib.h>

#include "ossa/level/level_io.h"
#include "ossa/level/tile_merge.h"

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


// A custom property of any Tiled element (map, layer, tile), in either form above.
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

constexpr uint32_t kGidFlags = 0xF0000000u;       // flip x, flip y, flip diagonal, hex rotation
constexpr int64_t kMaxCellsPerLayer = 1LL << 24;  // 16 M cells (64 MB of gids) per layer or chunk

// Standard base64 (RFC 4648), whitespace ignored. nullopt on any other character.
std::optional<std::string> decode_base64(std::string_view in) {
  std::string out;
  out.reserve(in.size() / 4 * 3);
  uint32_t acc = 0;
  int bits = 0;
  for (char ch : in) {
    int v;
    if (ch >= 'A' && ch <= 'Z') v = ch - 'A';
    else if (ch >= 'a' && ch <= 'z') v = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9') v = ch - '0' + 52;
    else if (ch == '+') v = 62;
    else if (ch == '/') v = 63;
    else if (ch == '=' || ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t') continue;
    else return std::nullopt;
    acc = (acc << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xFFu));
    }
  }
  return out;
}

// zlib or gzip stream (detected from the header) inflated to exactly `size` bytes.
std::optional<std::string> inflate_exact(const std::string& in, size_t size, std::string& why) {
  std::string out(size, '\0');
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) {
    why = "zlib could not start";
    return std::nullopt;
  }
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(size);
  const int rc = inflate(&z, Z_FINISH);
  const size_t produced = size - z.avail_out;
  inflateEnd(&z);
  if (rc == Z_STREAM_END && produced == size) return out;
  if (rc == Z_BUF_ERROR && produced == size) {
    why = "decompresses to more than the layer's " + std::to_string(size / 4) + " cells";
  } else if (rc == Z_STREAM_END) {
    why = "decompresses to " + std::to_string(produced / 4) + " cells, expected " + std::to_string(size / 4);
  } else {
    why = std::string("is not a valid zlib/gzip stream") + (z.msg ? std::string(" (") + z.msg + ")" : "");
  }
  return std::nullopt;
}

// A tileset's solid tiles: local tile ids marked as colliders.
struct Tileset {
  uint32_t firstgid = 1;
  std::vector<uint32_t> solid;  // sorted local ids
};

struct Importer {
  explicit Importer(JsonReader reader) : r(std::move(reader)) {}

  JsonReader r;
  double ppm = 1.0;
  double map_h_px = 0.0;
  std::vector<Box> boxes;
  std::optional<glm::vec2> spawn;
  std::string spawn_path;
  std::optional<Background> background;
  bool have_image = false;
  const TiledOptions* options = nullptr;
  double tile_w_px = 0.0, tile_h_px = 0.0;
  std::vector<Tileset> tilesets;  // by firstgid
  int64_t solid_cells = 0;
  int64_t boxes_from_cells = 0;
  std::string layer_what;  // 'tile layer "Ground": ', the start of tile layer errors

  // Pixel x / y (y-down) to metres, checked against the level file's coordinate bound.
  float to_x(double px, const std::string& path) {
    const double m = px / ppm;
    if (!(std::abs(m) <= kMaxLevelCoordinate)) {
      r.fail(path, "lies more than " + std::to_string(static_cast<int>(kMaxLevelCoordinate)) + " m from the origin");
      return 0.0f;  // a float cast of an out-of-range double is undefined
    }
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


  // ---- Tilesets ---------------------------------------------------------------------------
  // Reads the solid tiles of one tileset document (embedded in the map or external).
  void tileset_tiles(const Json& ts, const std::string& path, Tileset& out) {
    if (!r.expect_object(ts, path)) return;
    if (!r.has(ts, "tiles")) return;
    const Json* tiles = r.array(ts, path, "tiles");
    if (!tiles) return;
    for (size_t i = 0; i < tiles->size() && !r.failed(); ++i) {
      const Json& t = (*tiles)[i];
      const std::string tpath = json_path(json_path(path, "tiles"), i);
      if (!r.expect_object(t, tpath)) return;
      const long long id = r.integer(t, tpath, "id", 0, 0x0FFFFFFF);
      if (r.failed()) return;
      bool solid = truthy(find_property_ci(t, "collider")) || kind_of(t) == "collider";
      if (!solid && r.has(t, "objectgroup")) {
        const Json& og = t["objectgroup"];
        solid = og.is_object() && og.contains("objects") && og["objects"].is_array() && !og["objects"].empty();
      }
      if (solid) out.solid.push_back(static_cast<uint32_t>(id));
    }
    std::sort(out.solid.begin(), out.solid.end());
  }

  void read_tilesets(const Json& map) {
    if (!r.has(map, "tilesets")) return;
    const Json* list = r.array(map, "", "tilesets");
    if (!list) return;
    for (size_t i = 0; i < list->size() && !r.failed(); ++i) {
      const Json& ts = (*list)[i];
      const std::string path = json_path("tilesets", i);
      if (!r.expect_object(ts, path)) return;
      Tileset set;
      set.firstgid = static_cast<uint32_t>(r.integer(ts, path, "firstgid", 1, 0x0FFFFFFF));
      if (r.failed()) return;
      if (r.has(ts, "source")) {
        const std::string source = r.string(ts, path, "source");
        if (r.failed()) return;
        const std::string where = json_path(path, "source");
        if (!options->read_file) {
          r.fail(where, "external tileset \"" + source + "\" cannot be read here (no file access); embed the tileset");
          return;
        }
        const std::filesystem::path ts_path = std::filesystem::path(r.file()).parent_path() / source;
        Result<std::string> text = options->read_file(ts_path.string());
        if (!text) {
          r.fail(where, "external tileset: " + text.message());
          return;
        }
        const std::string ext = lower(ts_path.extension().string());
        const size_t first = text->find_first_not_of(" \t\r\n\xEF\xBB\xBF");
        const bool xml = ext == ".tsx" || (first < text->size() && (*text)[first] == '<');
        Result<Json> doc = xml ? tsx_to_json(*text, ts_path.string()) : parse_json(*text, ts_path.string());
        if (!doc) {
          r.fail(where, "external tileset: " + doc.message());
          return;
        }
        JsonReader inner{ts_path.string()};
        std::swap(r, inner);
        tileset_tiles(*doc, "", set);
        std::swap(r, inner);
        if (inner.failed()) {
          r.fail(where, "external tileset: " + inner.error().message);
          return;
        }
      } else {
        tileset_tiles(ts, path, set);
      }
      tilesets.push_back(std::move(set));
    }
    std::sort(tilesets.begin(), tilesets.end(), [](const Tileset& a, const Tileset& b) { return a.firstgid < b.firstgid; });
  }

  bool gid_solid(uint32_t gid) const {
    gid &= ~kGidFlags;
    if (gid == 0) return false;
    // The tileset with the largest firstgid <= gid holds the tile.
    auto it = std::upper_bound(tilesets.begin(), tilesets.end(), gid,
                               [](uint32_t g, const Tileset& t) { return g < t.firstgid; });
    if (it == tilesets.begin()) return false;
    --it;
    return std::binary_search(it->solid.begin(), it->solid.end(), gid - it->firstgid);
  }

  // ---- Tile layers --------------------------------------------------------------------------
  // The gids of a layer or chunk `holder` (fields data, width, height) in row order.
  bool read_gids(const Json& holder, const std::string& path, const std::string& encoding,
                 const std::string& compression, std::vector<uint32_t>& gids, long long& w, long long& h) {
    w = r.integer(holder, path, "width", 0, kMaxCellsPerLayer);
    h = r.integer(holder, path, "height", 0, kMaxCellsPerLayer);
    if (r.failed()) return false;
    if (w * h > kMaxCellsPerLayer) {
      r.fail(path, layer_what + "has " + std::to_string(w * h) + " cells; at most " + std::to_string(kMaxCellsPerLayer) + " per layer or chunk");
      return false;
    }
    const size_t n = static_cast<size_t>(w * h);
    if (!r.has(holder, "data")) {
      r.fail(json_path(path, "data"), layer_what + "missing (required field)");
      return false;
    }
    const Json& data = holder["data"];
    const std::string dpath = json_path(path, "data");
    gids.assign(n, 0u);
    if (data.is_array()) {
      if (data.size() != n) {
        r.fail(dpath, layer_what + "expected " + std::to_string(n) + " tiles (width x height), got " + std::to_string(data.size()));
        return false;
      }
      for (size_t i = 0; i < n; ++i) {
        const Json& g = data[i];
        if (!g.is_number_integer() || g.get<long long>() < 0 || g.get<long long>() > 0xFFFFFFFFLL) {
          r.fail(json_path(dpath, i), layer_what + "expected a tile gid (an integer in [0, 4294967295]), got " + describe_json(g));
          return false;
        }
        gids[i] = static_cast<uint32_t>(g.get<long long>());
      }
      return true;
    }
    if (!data.is_string()) {
      r.fail(dpath, layer_what + "expected an array of gids or a base64 string, got " + describe_json(data));
      return false;
    }
    if (encoding != "base64") {
      r.fail(dpath, layer_what + "a string needs \"encoding\": \"base64\", got encoding " + describe_json(Json(encoding)));
      return false;
    }
    std::optional<std::string> bytes = decode_base64(data.get<std::string>());
    if (!bytes) {
      r.fail(dpath, layer_what + "expected base64 text (A-Z a-z 0-9 + / =)");
      return false;
    }
    if (compression == "zlib" || compression == "gzip") {
      std::string why;
      std::optional<std::string> raw = inflate_exact(*bytes, n * 4, why);
      if (!raw) {
        r.fail(dpath, layer_what + compression + " data " + why);
        return false;
      }
      bytes = std::move(raw);
    } else if (compression == "zstd") {
      r.fail(json_path(path, "compression"), layer_what + "zstd is not supported; save the map with zlib, gzip or no compression (Map Properties > Tile Layer Format)");
      return false;
    } else if (!compression.empty()) {
      r.fail(json_path(path, "compression"), layer_what + "expected \"zlib\", \"gzip\" or none, got " + describe_json(Json(compression)));
      return false;
    }
    if (bytes->size() != n * 4) {
      r.fail(dpath, layer_what + "expected " + std::to_string(n * 4) + " bytes (4 per tile), got " + std::to_string(bytes->size()));
      return false;
    }
    for (size_t i = 0; i < n; ++i) {
      const auto* b = reinterpret_cast<const unsigned char*>(bytes->data() + 4 * i);
      gids[i] = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;  // little-endian
    }
    return true;
  }

  void tile_layer(const Json& layer, const std::string& path, double offx, double offy) {
    layer_what = "tile layer \"" + (layer.contains("name") && layer["name"].is_string() ? layer["name"].get<std::string>() : std::string()) + "\": ";
    if (!(tile_w_px > 0.0) || !(tile_h_px > 0.0)) {
      r.fail(path, layer_what + "needs the map's tilewidth and tileheight > 0");
      return;
    }
    const std::string encoding = r.string_or(layer, path, "encoding", "csv");
    const std::string compression = r.string_or(layer, path, "compression", "");
    const std::string name = lower(r.string_or(layer, path, "name", ""));
    const std::string cls = kind_of(layer);
    if (r.failed()) return;
    const bool all_solid = cls == "collision" || cls == "colliders" || name == "collision" || name == "colliders";
    std::vector<Cell> cells;
    std::vector<uint32_t> gids;
    auto collect = [&](long long x0, long long y0, long long w, long long h) {
      for (long long y = 0; y < h; ++y) {
        for (long long x = 0; x < w; ++x) {
          const uint32_t g = gids[static_cast<size_t>(y * w + x)];
          if (all_solid ? (g & ~kGidFlags) != 0 : gid_solid(g)) cells.push_back({x0 + x, y0 + y});
        }
      }
    };
    long long w = 0, h = 0;
    if (r.has(layer, "chunks")) {
      const Json* chunks = r.array(layer, path, "chunks");
      if (!chunks) return;
      for (size_t i = 0; i < chunks->size() && !r.failed(); ++i) {
        const Json& c = (*chunks)[i];
        const std::string cpath = json_path(json_path(path, "chunks"), i);
        if (!r.expect_object(c, cpath)) return;
        const long long cx = r.integer(c, cpath, "x", -kMaxCellsPerLayer * 64, kMaxCellsPerLayer * 64);
        const long long cy = r.integer(c, cpath, "y", -kMaxCellsPerLayer * 64, kMaxCellsPerLayer * 64);
        if (r.failed() || !read_gids(c, cpath, encoding, compression, gids, w, h)) return;
        collect(cx, cy, w, h);
        if (cells.size() > static_cast<size_t>(kMaxCellsPerLayer)) {
          r.fail(path, layer_what + "more than " + std::to_string(kMaxCellsPerLayer) + " solid cells in one layer");
          return;
        }
      }
    } else {
      if (!read_gids(layer, path, encoding, compression, gids, w, h)) return;
      collect(0, 0, w, h);
    }
    MergedCells merged = merge_cells(cells);
    solid_cells += merged.cells;
    boxes_from_cells += static_cast<int64_t>(merged.rects.size());
    for (const CellRect& c : merged.rects) {
      const double x0 = offx + static_cast<double>(c.x) * tile_w_px, x1 = x0 + static_cast<double>(c.w) * tile_w_px;
      const double y0 = offy + static_cast<double>(c.y) * tile_h_px, y1 = y0 + static_cast<double>(c.h) * tile_h_px;
      const Box box{{to_x(x0, path), to_y(y1, path)}, {to_x(x1, path), to_y(y0, path)}};
      if (r.failed()) return;
      if (!box.is_valid()) {
        r.fail(path, layer_what + "tiles at cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) + ") are too small to be represented at this position");
        return;
      }
      if (boxes.size() >= static_cast<size_t>(kMaxLevelColliders)) {
        r.fail(path, layer_what + "more than " + std::to_string(kMaxLevelColliders) + " colliders");
        return;
      }
      boxes.push_back(box);
    }
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
      } else if (type == "tilelayer") {
        tile_layer(layer, path, lx, ly);
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
  } else {
    level.spawn_ws = default_map_spawn(level);
  }
  if (report) {
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
