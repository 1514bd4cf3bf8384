#pragma once
// SpriteAtlas — every bone sprite packed into one RGBA image (stb_rect_pack) with each
// sprite's rectangle in it, so that all creatures draw with one texture, in any renderer.
// No SDL or GL: ossa::render uploads the image as its Atlas texture (render/texture.h), an
// embedder hands it to its own renderer (tests/embed/herd_sdl.cpp: SDL_Renderer).
//
// SpriteInfo::uv_min / uv_max are in GL's convention (t grows UP the image, sprite_mesh.h);
// creature_draw.h turns them into image coordinates (v down) for its draw data.

#include <string>
#include <vector>

#include "ossa/draw/image.h"
#include "ossa/draw/sprite_mesh.h"

namespace ossa {

struct SpriteAtlas {
  SpriteSet sprites;        // the input set with uv_min / uv_max and the joint reaches
                            // (measure_joint_reach) filled in
  Image image;              // the packed pixels (rows top to bottom), square, a power of two
  int missing = 0;          // sprites that fell back to a checker tile
  std::vector<std::string> problems;  // what fell back and why (files, sprites.json), for a log
};

// Packs every sprite of `sprites` (`<sprite_dir>/<name>.png`, decode_image_file) with 2 px
// padding into the smallest square power of two (≤ 4096) that fits; a missing or broken PNG
// is packed as a checker tile (counted in missing, named in problems).
SpriteAtlas pack_sprite_atlas(const SpriteSet& sprites, const std::string& sprite_dir);
// The bone sprites of `sprite_dir`: its sprites.json (when that fails to load, the message
// goes to problems and the built-in anchors are used) packed by pack_sprite_atlas().
SpriteAtlas load_sprite_atlas(const std::string& sprite_dir);

// Measures `info`'s parent_reach and child_reach (SpriteInfo) from its image's alpha: over
// u in [0, 2 × parent anchor u] and [2 × child anchor u - 1, 1], how far opaque pixels
// (alpha ≥ 128) reach below and above each anchor's v. pack_sprite_atlas calls it for every
// sprite whose image loaded.
void measure_joint_reach(SpriteInfo& info, const Image& image);

// The bone sprite folder: data_path("assets/sprites/bones") (ossa/io/data_dir.h); an
// installed ossa has it under ossa_DATA_DIR/assets/sprites/bones.
std::string default_sprite_dir();

}  // namespace ossa
