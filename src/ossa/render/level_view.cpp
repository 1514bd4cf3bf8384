#include "ossa/render/level_view.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include "ossa/io/data_dir.h"
#include "ossa/level/level_load.h"
#include "ossa/platform/image.h"
#include "ossa/render/background.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/render/tile_atlas.h"

namespace ossa {

std::span<const VertexAttrib> TileVertex::layout() {
  static const VertexAttrib attribs[] = {
      {0, 2, GL_FLOAT, false, false, offsetof(TileVertex, position_ws)},
      {1, 2, GL_FLOAT, false, false, offsetof(TileVertex, uv)},
      {2, 4, GL_UNSIGNED_BYTE, true, false, offsetof(TileVertex, rgba)},
  };
  return attribs;
}

namespace {

uint32_t white_with_alpha(uint8_t alpha) { return 0x00ffffffu | (static_cast<uint32_t>(alpha) << 24); }

// Appends a quad (two triangles) to vertices and indices.
void add_quad(std::vector<TileVertex>& v, std::vector<uint32_t>& idx, const std::array<TileVertex, 4>& corners) {
  const auto base = static_cast<uint32_t>(v.size());
  v.insert(v.end(), corners.begin(), corners.end());
  for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(base + k);
}

// The texture coordinate a tile's corner (s right, t down in [0, 1]) samples after its flips
// (Tiled's order: the diagonal flip, then the horizontal, then the vertical one).
glm::vec2 flipped_uv(const TileAtlas& atlas, uint32_t tile, float s, float t, uint8_t flags) {
  if (flags & kArtFlipY) t = 1.0f - t;
  if (flags & kArtFlipX) s = 1.0f - s;
  if (flags & kArtFlipDiagonal) std::swap(s, t);
  const glm::vec2 tl = atlas.uv_tl[tile], br = atlas.uv_br[tile];
  return {tl.x + s * (br.x - tl.x), tl.y + t * (br.y - tl.y)};
}

// The part (x, y, w, h) of an image; w = 0 (or a crop outside it): the whole image.
Image crop(const Image& image, glm::vec4 crop_px) {
  const int x = static_cast<int>(crop_px.x), y = static_cast<int>(crop_px.y);
  const int w = static_cast<int>(crop_px.z), h = static_cast<int>(crop_px.w);
  if (w <= 0 || h <= 0 || x < 0 || y < 0 || x + w > image.width || y + h > image.height) return image;
  Image out{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 4)};
  for (int row = 0; row < h; ++row) {
    std::copy_n(image.pixel(x, y + row), static_cast<size_t>(w) * 4, out.pixel(0, row));
  }
  return out;
}

// A texture made with Wrap::kRepeat repeated along the axes asked for only, clamped along the
// others (linear filtering at a clamped edge must not blend in the opposite edge's pixels).
void repeat_only(const Texture& texture, bool along_u, bool along_v) {
  if (!texture.is_valid()) return;
  texture.bind(0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, along_u ? GL_REPEAT : GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, along_v ? GL_REPEAT : GL_CLAMP_TO_EDGE);
}

}  // namespace

// The GPU side of one LevelArt: a texture per tileset and per image layer, every tile quad in
// one vertex array, a range of it per (layer, tileset).
struct LevelView::ArtGpu {
  // What this was built from (Level::art is shared and immutable): held, so that a new level's
  // art is never taken for this one at a reused address.
  std::shared_ptr<const LevelArt> art;
  std::vector<Texture> tilesets;  // per tileset; invalid when its image is missing
  std::vector<Texture> images;    // per layer: an image layer's (cropped) picture
  struct Draw {
    int layer = 0;
    int tileset = 0;
    int first = 0, count = 0;     // indices
  };
  std::vector<Draw> draws;        // in layer order
  VertexArray<TileVertex> va;
  int tiles = 0;
  bool missing = false;
};

struct LevelView::LookGpu {
  const Level* level = nullptr;
  std::uint64_t revision = 0;
  std::string file;
  LevelLook look;
  bool ok = false;
  std::array<Texture, kLookPartCount> textures;
  std::array<std::pair<int, int>, kLookPartCount> ranges{};  // first index, count
  VertexArray<TileVertex> va;
};

Result<LevelView> LevelView::create(const std::string& shader_dir) {
  auto program = ShaderProgram::load(shader_dir + "/tile.vert", shader_dir + "/tile.frag");
  if (!program) return Error{program.message()};
  LevelView view;
  view.program_ = std::move(program.value());
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  view.max_texture_ = std::clamp(static_cast<int>(max_side), 1024, 8192);
  return view;
}

LevelView::LevelView() = default;
LevelView::~LevelView() = default;
LevelView::LevelView(LevelView&&) noexcept = default;
LevelView& LevelView::operator=(LevelView&&) noexcept = default;

std::vector<std::string> LevelView::take_warnings() { return std::exchange(warnings_, {}); }

void LevelView::reload_shaders_if_changed() { program_.reload_if_changed(); }

void LevelView::warn(const std::string& message) {
  if (std::find(warned_.begin(), warned_.end(), message) != warned_.end()) return;
  warned_.push_back(message);
  warnings_.push_back(message);
  render_log(message);
}

void LevelView::prepare_art(const Level& level) {
  const LevelArt* art = level.art.get();
  if (!art) {
    art_.reset();
    return;
  }
  if (art_ && art_->art.get() == art) return;
  art_ = std::make_unique<ArtGpu>();
  ArtGpu& g = *art_;
  g.art = level.art;

  // Every image once.
  std::vector<Image> images(art->images.size());
  std::vector<bool> loaded(art->images.size(), false);
  for (size_t i = 0; i < art->images.size(); ++i) {
    Result<Image> img = load_image(art->images[i].path);
    if (img) {
      images[i] = std::move(img.value());
      loaded[i] = true;
    } else {
      g.missing = true;
      warn(art->file + ": image " + art->images[i].path + " (\"" + art->images[i].source + "\"): " + img.message() +
           "; drawing the level's boxes");
    }
  }

  // Tilesets: one atlas texture each.
  std::vector<TileAtlas> atlases(art->tilesets.size());
  g.tilesets.resize(art->tilesets.size());
  for (size_t t = 0; t < art->tilesets.size(); ++t) {
    const ArtTileset& set = art->tilesets[t];
    TileAtlas& atlas = atlases[t];
    bool extruded = true;
    if (set.collection) {
      std::vector<const Image*> pictures;
      for (int i : set.images) {
        const bool ok = i >= 0 && static_cast<size_t>(i) < images.size() && loaded[static_cast<size_t>(i)];
        pictures.push_back(ok ? &images[static_cast<size_t>(i)] : nullptr);
      }
      atlas = build_collection_atlas(pictures, max_texture_);
    } else if (!set.images.empty() && set.images[0] >= 0 && static_cast<size_t>(set.images[0]) < images.size() &&
               loaded[static_cast<size_t>(set.images[0])]) {
      const Image& src = images[static_cast<size_t>(set.images[0])];
      atlas = build_grid_atlas(src, set, max_texture_);
      extruded = !(atlas.image.width == src.width && atlas.image.height == src.height && atlas.image.rgba == src.rgba);
    }
    if (atlas.image.empty()) {
      if (!set.images.empty() && !set.collection) continue;  // its image's warning was given
      if (set.collection && !set.images.empty()) {
        g.missing = true;
        warn(art->file + ": tileset \"" + set.name + "\": its images do not fit one " + std::to_string(max_texture_) +
             " px texture; drawing the level's boxes");
      }
      continue;
    }
    g.tilesets[t] = Texture::from_image(atlas.image, extruded);
  }

  // Tile quads, a range per (layer, tileset); image layers' pictures.
  std::vector<TileVertex> vertices;
  std::vector<uint32_t> indices;
  g.images.resize(art->layers.size());
  for (size_t l = 0; l < art->layers.size(); ++l) {
    const ArtLayer& layer = art->layers[l];
    if (layer.kind == ArtLayer::Kind::kImage) {
      if (layer.image >= 0 && static_cast<size_t>(layer.image) < images.size() && loaded[static_cast<size_t>(layer.image)]) {
        g.images[l] = Texture::from_image(crop(images[static_cast<size_t>(layer.image)], layer.crop_px), true,
                                          Texture::Wrap::kRepeat);
        repeat_only(g.images[l], layer.repeat_x, layer.repeat_y);
      }
      continue;
    }
    for (const ArtBatch& batch : layer.batches) {
      if (batch.tileset < 0 || static_cast<size_t>(batch.tileset) >= g.tilesets.size()) continue;
      const auto ts = static_cast<size_t>(batch.tileset);
      if (!g.tilesets[ts].is_valid()) continue;
      const TileAtlas& atlas = atlases[ts];
      ArtGpu::Draw draw{static_cast<int>(l), batch.tileset, static_cast<int>(indices.size()), 0};
      for (const ArtTile& tile : batch.tiles) {
        if (!atlas.has(tile.tile)) continue;
        const glm::vec2 a = tile.min_ws, b = tile.min_ws + tile.size_ws;
        const uint32_t c = white_with_alpha(tile.alpha);
        // Corners counter-clockwise from the bottom-left; (s, t) with t down.
        add_quad(vertices, indices,
                 {TileVertex{{a.x, a.y}, flipped_uv(atlas, tile.tile, 0.0f, 1.0f, tile.flags), c},
                  TileVertex{{b.x, a.y}, flipped_uv(atlas, tile.tile, 1.0f, 1.0f, tile.flags), c},
                  TileVertex{{b.x, b.y}, flipped_uv(atlas, tile.tile, 1.0f, 0.0f, tile.flags), c},
                  TileVertex{{a.x, b.y}, flipped_uv(atlas, tile.tile, 0.0f, 0.0f, tile.flags), c}});
        ++g.tiles;
      }
      draw.count = static_cast<int>(indices.size()) - draw.first;
      if (draw.count > 0) g.draws.push_back(draw);
    }
  }
  g.va.upload(vertices, indices, GL_STATIC_DRAW);
}

void LevelView::prepare_look(const Level& level, const std::string& level_file) {
  if (!level.look) {
    look_.reset();
    return;
  }
  const LevelLook& look = *level.look;
  const bool same_image = look_ && look_->file == level_file && look_->look.tileset == look.tileset &&
                          look_->look.tile_px == look.tile_px;
  if (same_image && look_->level == &level && look_->revision == level.revision() && look_->look == look) return;
  if (!same_image) {
    look_ = std::make_unique<LookGpu>();
    look_->file = level_file;
    look_->look = look;
    Result<std::string> path = resolve_level_resource(level_file, "look.tileset", look.tileset, data_path("assets"));
    Result<Image> image = path ? load_image(*path) : Result<Image>(Error{path.message()});
    if (!image) {
      warn(level_file + ": look tileset " + (path ? *path : look.tileset) + ": " + image.message() +
           "; drawing the level's boxes");
      return;
    }
    const Image& img = image.value();
    const int side = look.tile_px;
    const int cols = side > 0 ? img.width / side : 0, rows = side > 0 ? img.height / side : 0;
    look_->ok = true;
    for (int p = 0; p < kLookPartCount; ++p) {
      const int tile = look_tile(look, static_cast<LookPart>(p));
      if (tile < 0) continue;
      if (tile >= cols * rows) {
        warn(level_file + ": look tileset " + *path + " has no tile " + std::to_string(tile) + " (" +
             std::to_string(cols * rows) + " tiles of " + std::to_string(side) + " px); drawing the level's boxes");
        look_->ok = false;
        return;
      }
      const Image cell = crop(img, glm::vec4((tile % cols) * side, (tile / cols) * side, side, side));
      Texture& texture = look_->textures[static_cast<size_t>(p)];
      texture = Texture::from_image(cell, true, Texture::Wrap::kRepeat);
      // The fill repeats both ways, the top row along x, the sides along y, corners not at all.
      const auto part = static_cast<LookPart>(p);
      repeat_only(texture, part == LookPart::kFill || part == LookPart::kTop,
                  part == LookPart::kFill || part == LookPart::kLeft || part == LookPart::kRight);
    }
  }
  look_->level = &level;
  look_->revision = level.revision();
  look_->look = look;
  if (!look_->ok) return;
  const BoxLookGeometry geometry = build_box_look(level, look);
  std::vector<TileVertex> vertices;
  std::vector<uint32_t> indices;
  const uint32_t white = 0xffffffffu;
  for (int p = 0; p < kLookPartCount; ++p) {
    const int first = static_cast<int>(indices.size());
    for (const LookQuad& q : geometry.parts[static_cast<size_t>(p)]) {
      const Box& r = q.rect_ws;
      add_quad(vertices, indices,
               {TileVertex{{r.min_ws.x, r.min_ws.y}, {q.uv_min.x, q.uv_min.y}, white},
                TileVertex{{r.max_ws.x, r.min_ws.y}, {q.uv_max.x, q.uv_min.y}, white},
                TileVertex{{r.max_ws.x, r.max_ws.y}, {q.uv_max.x, q.uv_max.y}, white},
                TileVertex{{r.min_ws.x, r.max_ws.y}, {q.uv_min.x, q.uv_max.y}, white}});
    }
    look_->ranges[static_cast<size_t>(p)] = {first, static_cast<int>(indices.size()) - first};
  }
  look_->va.upload(vertices, indices, GL_STATIC_DRAW);
}

void LevelView::draw_quads(Renderer& r, const VertexArray<TileVertex>& va, int first, int count, const Texture& texture,
                           glm::vec2 shift_ws, glm::vec4 tint) {
  if (count <= 0 || !texture.is_valid()) return;
  program_.use();
  program_.set("u_view_proj", r.camera.view_proj());
  program_.set("u_shift_ws", shift_ws);
  program_.set("u_tint", tint);
  program_.set("u_texture", 0);
  texture.bind(0);
  va.draw_indices(GL_TRIANGLES, first, count);
  r.stats.draw_calls += 1;
  r.stats.vertices += count;
  stats_.draw_calls += 1;
}

void LevelView::draw_sky(Renderer& r, const Level& level, const std::string& level_file) {
  if (level.art && level.art->background) {
    DebugDraw fill;
    fill.add_box(r.camera.visible_box(), *level.art->background, true);
    r.draw_debug(fill);
    stats_.draw_calls += 1;
    return;
  }
  BackgroundStyle style;
  if (level.background) {
    style.sky_bottom = level.background->colour;
    style.sky_top = level.background->colour * glm::vec3(0.62f, 0.75f, 0.95f);
    style.parallax = level.background->parallax;
  }
  style.horizon_ws = level.spawn_ws.y;
  DebugDraw scene;
  add_background(scene, r.camera, style);
  r.draw_debug(scene);
  stats_.draw_calls += 1;
  if (!level.background || level.background->image.empty()) return;
  // The level's image, repeated and scrolled by its parallax in one draw (background.h).
  const std::string key = level_file + "\n" + level.background->image;
  auto it = background_images_.find(key);
  if (it == background_images_.end()) {
    // Relative to the level's folder (resolve_level_resource), else assets/.
    Result<std::string> file =
        resolve_level_resource(level_file, "background.image", level.background->image, data_path("assets"));
    Texture texture;
    if (file) {
      Result<Image> image = load_image(*file);
      if (image) texture = Texture::from_image(image.value(), true, Texture::Wrap::kRepeat);
      else warn(level_file + ": background image " + *file + ": " + image.message());
    } else {
      warn(file.message() + " (no background image)");
    }
    it = background_images_.emplace(key, std::move(texture)).first;
  }
  draw_background_image(r, it->second, level.background->parallax);
  if (it->second.is_valid()) stats_.draw_calls += 1;
}

void LevelView::draw_layers(Renderer& r, bool front) {
  if (!art_) return;
  const LevelArt& art = *art_->art;
  const glm::vec2 centre = r.camera.center_ws;
  const auto shift_of = [&](const ArtLayer& layer) { return (1.0f - layer.parallax) * (centre - art.parallax_origin_ws); };
  size_t d = 0;
  for (size_t l = 0; l < art.layers.size(); ++l) {
    const ArtLayer& layer = art.layers[l];
    const glm::vec4 tint{glm::vec3(layer.tint), layer.tint.a * layer.opacity};
    const glm::vec2 shift = shift_of(layer);
    const bool mine = layer.front == front;
    if (layer.kind == ArtLayer::Kind::kTiles) {
      for (; d < art_->draws.size() && art_->draws[d].layer == static_cast<int>(l); ++d) {
        const ArtGpu::Draw& draw = art_->draws[d];
        if (!mine) continue;
        draw_quads(r, art_->va, draw.first, draw.count, art_->tilesets[static_cast<size_t>(draw.tileset)], shift, tint);
        stats_.tiles_drawn += draw.count / 6;
      }
      continue;
    }
    const Texture& texture = art_->images[l];
    if (!mine || !texture.is_valid()) continue;
    // The picture's rectangle (its top-left at origin_ws), stretched over the view along a
    // repeated axis with the texture coordinates counting repeats.
    const glm::vec2 size = glm::vec2(texture.width(), texture.height()) * layer.metres_per_px * layer.scale;
    if (!(size.x > 0.0f && size.y > 0.0f)) continue;
    const Box view = r.camera.visible_box();
    const glm::vec2 lo = view.min_ws - shift, hi = view.max_ws - shift;
    const glm::vec2 bottom_left{layer.origin_ws.x, layer.origin_ws.y - size.y};
    glm::vec2 a = bottom_left, b = bottom_left + size;
    if (layer.repeat_x) a.x = lo.x, b.x = hi.x;
    if (layer.repeat_y) a.y = lo.y, b.y = hi.y;
    const glm::vec2 uv_a = (a - bottom_left) / size, uv_b = (b - bottom_left) / size;
    const uint32_t white = 0xffffffffu;
    const TileVertex v[4] = {{{a.x, a.y}, {uv_a.x, uv_a.y}, white},
                             {{b.x, a.y}, {uv_b.x, uv_a.y}, white},
                             {{b.x, b.y}, {uv_b.x, uv_b.y}, white},
                             {{a.x, b.y}, {uv_a.x, uv_b.y}, white}};
    const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    if (!quad_) quad_ = std::make_unique<VertexArray<TileVertex>>();
    quad_->upload(v, idx, GL_STREAM_DRAW);
    draw_quads(r, *quad_, 0, 6, texture, shift, tint);
  }
}

void LevelView::draw_look(Renderer& r) {
  if (!look_ || !look_->ok) return;
  for (size_t p = 0; p < look_->ranges.size(); ++p) {
    const auto [first, count] = look_->ranges[p];
    draw_quads(r, look_->va, first, count, look_->textures[p], glm::vec2(0.0f), glm::vec4(1.0f));
    stats_.tiles_drawn += count / 6;
  }
}

void LevelView::draw_back(Renderer& renderer, const Level& level, const std::string& level_file) {
  stats_ = {};
  prepare_art(level);
  prepare_look(level, level_file);
  draw_sky(renderer, level, level_file);
  draw_layers(renderer, false);
  if (level.art) {
    boxes_ = level.art->empty() || !art_ || art_->missing;
  } else {
    boxes_ = !look_ || !look_->ok;
  }
  if (boxes_) {
    DebugDraw ground;
    add_level_scenery(ground, level, renderer.camera.visible_box());
    renderer.draw_debug(ground);
    stats_.draw_calls += 1;
  } else if (!level.art) {
    draw_look(renderer);
  }
  stats_.textures = 0;
  if (art_) {
    for (const Texture& t : art_->tilesets) stats_.textures += t.is_valid() ? 1 : 0;
    for (const Texture& t : art_->images) stats_.textures += t.is_valid() ? 1 : 0;
  }
  if (look_) {
    for (const Texture& t : look_->textures) stats_.textures += t.is_valid() ? 1 : 0;
  }
}

void LevelView::draw_front(Renderer& renderer, const Level& level) {
  if (!level.art || !art_ || art_->art != level.art) return;
  draw_layers(renderer, true);
}

}  // namespace ossa
