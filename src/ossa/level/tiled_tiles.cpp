// Tiled import, tilesets and tile layers (tiled.h): external and embedded tilesets and their
// solid tiles, layer data in CSV, base64, zlib or gzip, and the solid cells merged into boxes.

#include <algorithm>
#include <filesystem>

#include <zlib.h>

#include "ossa/level/tile_merge.h"
#include "ossa/level/tiled_internal.h"

namespace ossa::tiled_detail {

namespace {

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

}  // namespace

// Reads the solid tiles of one tileset document (embedded in the map or external).
void Importer::tileset_tiles(const Json& ts, const std::string& path, Tileset& out) {
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

void Importer::read_tilesets(const Json& map) {
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
      if (!r.failed()) art_tileset(*doc, "", ts_path.string(), set);
      std::swap(r, inner);
      if (inner.failed()) {
        r.fail(where, "external tileset: " + inner.error().message);
        return;
      }
    } else {
      tileset_tiles(ts, path, set);
      if (!r.failed()) art_tileset(ts, path, r.file(), set);
    }
    tilesets.push_back(std::move(set));
  }
  std::sort(tilesets.begin(), tilesets.end(), [](const Tileset& a, const Tileset& b) { return a.firstgid < b.firstgid; });
}

bool Importer::gid_solid(uint32_t gid) const {
  gid &= ~kGidFlags;
  if (gid == 0) return false;
  // The tileset with the largest firstgid <= gid holds the tile.
  auto it = std::upper_bound(tilesets.begin(), tilesets.end(), gid,
                             [](uint32_t g, const Tileset& t) { return g < t.firstgid; });
  if (it == tilesets.begin()) return false;
  --it;
  return std::binary_search(it->solid.begin(), it->solid.end(), gid - it->firstgid);
}

// The gids of a layer or chunk `holder` (fields data, width, height) in row order.
bool Importer::read_gids(const Json& holder, const std::string& path, const std::string& encoding,
               const std::string& compression, std::vector<uint32_t>& gids, long long& w, long long& h) {
  w = r.integer(holder, path, "width", 0, kMaxMapCells);
  h = r.integer(holder, path, "height", 0, kMaxMapCells);
  if (r.failed()) return false;
  // The cells of every layer and chunk of the map count together (level_load.h kMaxMapCells):
  // many layers of a highly compressible map may not add up to more work than one may.
  const int64_t before = cells_read;
  cells_read += w * h;
  if (cells_read > kMaxMapCells) {
    r.fail(path, layer_what + "has " + std::to_string(w * h) + " cells" +
                     (before > 0 ? ", " + std::to_string(cells_read) + " with the layers before" : std::string()) +
                     "; at most " + std::to_string(kMaxMapCells) + " in all the layers of a map");
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

void Importer::tile_layer(const Json& layer, const std::string& path, double offx, double offy, const LayerStyle& style) {
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
  // The art of a visible layer (a hidden one still collides).
  std::optional<ArtLayer> drawn;
  if (style.visible) drawn = art_layer(layer, style);
  auto collect = [&](long long x0, long long y0, long long w, long long h) {
    for (long long y = 0; y < h; ++y) {
      for (long long x = 0; x < w; ++x) {
        const uint32_t g = gids[static_cast<size_t>(y * w + x)];
        if (all_solid ? (g & ~kGidFlags) != 0 : gid_solid(g)) cells.push_back({x0 + x, y0 + y});
      }
    }
    if (drawn) art_tiles(gids, x0, y0, w, h, offx, offy, path, *drawn);
  };
  long long w = 0, h = 0;
  if (r.has(layer, "chunks")) {
    const Json* chunks = r.array(layer, path, "chunks");
    if (!chunks) return;
    for (size_t i = 0; i < chunks->size() && !r.failed(); ++i) {
      const Json& c = (*chunks)[i];
      const std::string cpath = json_path(json_path(path, "chunks"), i);
      if (!r.expect_object(c, cpath)) return;
      const long long cx = r.integer(c, cpath, "x", -kMaxMapCells * 64, kMaxMapCells * 64);
      const long long cy = r.integer(c, cpath, "y", -kMaxMapCells * 64, kMaxMapCells * 64);
      if (r.failed() || !read_gids(c, cpath, encoding, compression, gids, w, h)) return;
      collect(cx, cy, w, h);
    }
  } else {
    if (!read_gids(layer, path, encoding, compression, gids, w, h)) return;
    collect(0, 0, w, h);
  }
  if (drawn && !drawn->batches.empty()) art.layers.push_back(std::move(*drawn));
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

}  // namespace ossa::tiled_detail
