// Tiled import, the art (tiled.h, level_art.h): how tilesets' tiles are drawn (a grid in one
// image, or a collection of images), tile layers' tiles with their flips, image layers, and
// what groups pass down (opacity, tint, parallax, visibility, "foreground").
//
// Placement follows Tiled's orthogonal renderer: a tile's bottom-left corner sits at the
// bottom-left corner of its cell, moved by the tileset's tileoffset; it is drawn at the
// tileset's tile size (a collection image at its own size; tilerendersize "grid": the map's).

#include <algorithm>
#include <cmath>

#include "ossa/level/tiled_internal.h"

namespace ossa::tiled_detail {

namespace {

constexpr uint32_t kFlipH = 0x80000000u, kFlipV = 0x40000000u, kFlipD = 0x20000000u;

bool is_true(const Json* v) { return v && ((v->is_boolean() && v->get<bool>()) || (v->is_number() && v->get<double>() != 0.0)); }

}  // namespace

LayerStyle Importer::layer_style(const Json& layer, const std::string& path, const LayerStyle& parent) {
  LayerStyle s = parent;
  s.opacity *= static_cast<float>(r.number_or(layer, path, "opacity", 1.0, 0.0, 1.0));
  s.parallax.x *= static_cast<float>(r.number_or(layer, path, "parallaxx", 1.0, -1000.0, 1000.0));
  s.parallax.y *= static_cast<float>(r.number_or(layer, path, "parallaxy", 1.0, -1000.0, 1000.0));
  if (r.has(layer, "visible")) s.visible = s.visible && r.boolean_or(layer, path, "visible", true);
  if (r.has(layer, "tintcolor")) {
    const std::string text = r.string(layer, path, "tintcolor");
    if (r.failed()) return s;
    const std::optional<glm::vec4> tint = parse_hex_colour(text);
    if (!tint) {
      r.fail(json_path(path, "tintcolor"), "expected \"#RRGGBB\" or \"#AARRGGBB\", got " + describe_json(layer["tintcolor"]));
      return s;
    }
    s.tint *= *tint;
  }
  if (is_true(find_property_ci(layer, "foreground"))) s.front = true;
  return s;
}

ArtLayer Importer::art_layer(const Json& layer, const LayerStyle& style) const {
  ArtLayer a;
  a.kind = ArtLayer::Kind::kTiles;
  if (layer.contains("name") && layer["name"].is_string()) a.name = layer["name"].get<std::string>();
  a.opacity = style.opacity;
  a.tint = style.tint;
  a.parallax = style.parallax;
  a.front = style.front;
  return a;
}

void Importer::art_tileset(const Json& ts, const std::string& path, const std::string& file, Tileset& set) {
  ArtTileset out;
  out.name = r.string_or(ts, path, "name", "");
  const long long tw = r.integer_or(ts, path, "tilewidth", 0, 0, 1000000);
  const long long th = r.integer_or(ts, path, "tileheight", 0, 0, 1000000);
  out.margin_px = static_cast<int>(r.integer_or(ts, path, "margin", 0, 0, 1000000));
  out.spacing_px = static_cast<int>(r.integer_or(ts, path, "spacing", 0, 0, 1000000));
  out.columns = static_cast<int>(r.integer_or(ts, path, "columns", 0, 0, 1000000));
  if (r.has(ts, "tileoffset")) {
    const Json* o = r.object(ts, path, "tileoffset");
    if (o) {
      set.offset_x_px = r.number_or(*o, json_path(path, "tileoffset"), "x", 0.0, -1e6, 1e6);
      set.offset_y_px = r.number_or(*o, json_path(path, "tileoffset"), "y", 0.0, -1e6, 1e6);
    }
  }
  set.grid_size = r.string_or(ts, path, "tilerendersize", "tile") == "grid";
  if (r.failed()) return;
  out.tile_w_px = static_cast<int>(tw);
  out.tile_h_px = static_cast<int>(th);
  set.tile_w_px = static_cast<double>(tw);
  set.tile_h_px = static_cast<double>(th);
  if (r.has(ts, "image")) {
    // A grid of tiles in one image.
    const std::string source = r.string(ts, path, "image");
    const long long iw = r.integer_or(ts, path, "imagewidth", 0, 0, 1000000);
    const long long ih = r.integer_or(ts, path, "imageheight", 0, 0, 1000000);
    if (r.failed() || source.empty()) return;
    if (tw <= 0 || th <= 0) {
      r.fail(path, "tileset \"" + out.name + "\" has an image but no tilewidth/tileheight > 0");
      return;
    }
    out.images.push_back(art.add_image(art_path_near(file, source), source, static_cast<int>(iw), static_cast<int>(ih)));
  } else if (r.has(ts, "tiles")) {
    // A collection of images: each tile its own picture.
    const Json* tiles = r.array(ts, path, "tiles");
    if (!tiles) return;
    out.collection = true;
    for (size_t i = 0; i < tiles->size() && !r.failed(); ++i) {
      const Json& t = (*tiles)[i];
      const std::string tpath = json_path(json_path(path, "tiles"), i);
      if (!t.is_object() || !t.contains("image")) continue;
      const long long id = r.integer(t, tpath, "id", 0, 0x0FFFFFFF);
      const std::string source = r.string(t, tpath, "image");
      const long long iw = r.integer_or(t, tpath, "imagewidth", 0, 0, 1000000);
      const long long ih = r.integer_or(t, tpath, "imageheight", 0, 0, 1000000);
      if (r.failed()) return;
      if (iw <= 0 || ih <= 0) {
        r.fail(tpath, "tile " + std::to_string(id) + " of the image collection \"" + out.name +
                          "\": expected imagewidth and imageheight > 0");
        return;
      }
      const uint32_t index = static_cast<uint32_t>(out.images.size());
      out.images.push_back(art.add_image(art_path_near(file, source), source, static_cast<int>(iw), static_cast<int>(ih)));
      set.collection.push_back({static_cast<uint32_t>(id), index, static_cast<double>(iw), static_cast<double>(ih)});
    }
    std::sort(set.collection.begin(), set.collection.end(),
              [](const Tileset::CollectionTile& a, const Tileset::CollectionTile& b) { return a.id < b.id; });
    if (out.images.empty()) return;  // tiles with properties only: nothing to draw
  } else {
    return;  // no image: nothing to draw (a collision-only tileset)
  }
  set.art = static_cast<int>(art.tilesets.size());
  art.tilesets.push_back(std::move(out));
}

void Importer::art_tiles(const std::vector<uint32_t>& gids, long long x0, long long y0, long long w, long long h,
                         double offx, double offy, const std::string& path, ArtLayer& layer) {
  for (long long y = 0; y < h && !r.failed(); ++y) {
    for (long long x = 0; x < w; ++x) {
      const uint32_t raw = gids[static_cast<size_t>(y * w + x)];
      const uint32_t gid = raw & ~kGidFlags;
      if (gid == 0) continue;
      auto it = std::upper_bound(tilesets.begin(), tilesets.end(), gid,
                                 [](uint32_t g, const Tileset& t) { return g < t.firstgid; });
      if (it == tilesets.begin()) continue;  // a gid below every tileset: Tiled draws nothing
      --it;
      if (it->art < 0) continue;
      uint32_t tile = gid - it->firstgid;
      double tw = it->tile_w_px, th = it->tile_h_px;
      if (!it->collection.empty()) {
        auto c = std::lower_bound(it->collection.begin(), it->collection.end(), tile,
                                  [](const Tileset::CollectionTile& t, uint32_t id) { return t.id < id; });
        if (c == it->collection.end() || c->id != tile) continue;  // no image for this id
        tile = c->index;
        tw = c->w_px;
        th = c->h_px;
      }
      if (it->grid_size) {
        tw = tile_w_px;
        th = tile_h_px;
      }
      if (art_tiles_total >= kMaxArtTiles) {
        if (!art_full) {
          warnings.push_back(layer_what + "the art has more than " + std::to_string(kMaxArtTiles) +
                             " tiles; the tiles after that are not drawn (the colliders all count)");
        }
        art_full = true;
        return;
      }
      ++art_tiles_total;
      // Bottom-left of the cell, y down, pixels; then the tileset's offset.
      const double left = offx + static_cast<double>(x0 + x) * tile_w_px + it->offset_x_px;
      const double bottom = offy + static_cast<double>(y0 + y + 1) * tile_h_px + it->offset_y_px;
      ArtTile t;
      t.min_ws = {to_x(left, path), to_y(bottom, path)};
      t.size_ws = {static_cast<float>(tw / ppm), static_cast<float>(th / ppm)};
      t.tile = tile;
      t.flags = static_cast<uint8_t>(((raw & kFlipH) ? kArtFlipX : 0) | ((raw & kFlipV) ? kArtFlipY : 0) |
                                     ((raw & kFlipD) ? kArtFlipDiagonal : 0));
      if (r.failed()) return;
      if (!(t.size_ws.x > 0.0f) || !(t.size_ws.y > 0.0f)) continue;
      ArtBatch* batch = layer.batches.empty() || layer.batches.back().tileset != it->art ? nullptr : &layer.batches.back();
      if (!batch) {
        for (ArtBatch& b : layer.batches) {
          if (b.tileset == it->art) batch = &b;
        }
      }
      if (!batch) {
        layer.batches.push_back({it->art, {}});
        batch = &layer.batches.back();
      }
      batch->tiles.push_back(t);
    }
  }
}

void Importer::art_image_layer(const Json& layer, const std::string& path, double offx, double offy, const LayerStyle& style) {
  if (!style.visible) return;
  const std::string source = r.string_or(layer, path, "image", "");
  const long long iw = r.integer_or(layer, path, "imagewidth", 0, 0, 1000000);
  const long long ih = r.integer_or(layer, path, "imageheight", 0, 0, 1000000);
  const bool repeat_x = r.boolean_or(layer, path, "repeatx", false);
  const bool repeat_y = r.boolean_or(layer, path, "repeaty", false);
  if (r.failed() || source.empty()) return;
  ArtLayer a = art_layer(layer, style);
  a.kind = ArtLayer::Kind::kImage;
  a.image = art.add_image(art_path_near(r.file(), source), source, static_cast<int>(iw), static_cast<int>(ih));
  a.origin_ws = {to_x(offx, path), to_y(offy, path)};
  a.metres_per_px = static_cast<float>(1.0 / ppm);
  a.repeat_x = repeat_x;
  a.repeat_y = repeat_y;
  if (r.failed()) return;
  art.layers.push_back(std::move(a));
}

}  // namespace ossa::tiled_detail
