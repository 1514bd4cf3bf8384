#pragma once
// The size of an image read from its header, so that no image is decoded before its
// dimensions are known (a 55 KB PNG may declare 16384 × 16384 pixels: 1 GiB as RGBA).
//
// Every image ossa decodes — level backgrounds, bone sprites, rigged characters' textures
// (files and embedded) — passes check_image first: it must be PNG, JPEG or BMP, at most
// kMaxImageSide pixels on a side and kMaxImagePixels in all, so decoding takes at most
// 4 × kMaxImagePixels bytes of RGBA (64 MiB) plus the decoder's own copy. The file itself is
// read with read_file (regular files of at most kMaxImageFileBytes).

#include <cstdint>
#include <string>
#include <string_view>

#include "ossa/io/result.h"

namespace ossa {

inline constexpr int kMaxImageSide = 16384;                 // pixels, either side
inline constexpr int64_t kMaxImagePixels = 4096LL * 4096;   // 16 M pixels
inline constexpr long long kMaxImageFileBytes = 64ll * 1024 * 1024;

struct ImageInfo {
  std::string format;  // "PNG", "JPEG" or "BMP"
  int64_t width = 0;   // pixels, as the header declares them
  int64_t height = 0;
};

// Reads the format and the declared size from the first bytes of an image file. Errors name
// `file`: an unknown or truncated header.
Result<ImageInfo> read_image_info(std::string_view bytes, std::string_view file);

// read_image_info, then the limits above. Errors name `file`, the size and the limit, e.g.
// `bg.png: is 1 × 1000000 pixels; images may be at most 16384 pixels on a side and 16777216
// pixels in all`.
Result<ImageInfo> check_image(std::string_view bytes, std::string_view file);

}  // namespace ossa
