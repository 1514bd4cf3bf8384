#pragma once
// Image — 8-bit RGBA pixels on the CPU, rows top to bottom — and decoding image files without
// SDL or GL (stb_image). ossa::draw's sprite atlas is one; ossa::render's textures, frame
// capture and SDL2_image loader (platform/image.h) use the same struct.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ossa/io/result.h"

namespace ossa {

struct Image {
  int width = 0;                  // pixels
  int height = 0;                 // pixels
  std::vector<uint8_t> rgba;      // width * height * 4 bytes, first row = top of the image

  bool empty() const { return width <= 0 || height <= 0; }
  uint8_t* pixel(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  const uint8_t* pixel(int x, int y) const {
    return &rgba[(static_cast<size_t>(y) * width + x) * 4];
  }
};

// Decodes an image file as RGBA with stb_image: a regular file of at most kMaxImageFileBytes,
// PNG, JPEG or BMP, whose size check_image accepts from its header before anything is decoded
// (io/image_info.h) — the same input rule as platform/image.h's load_image (SDL2_image), which
// ossa::render uses; this one needs neither SDL nor GL. Errors name the file and the reason.
Result<Image> decode_image_file(const std::string& path);
// The same for an image already in memory (an embedded texture); `name` heads the errors.
Result<Image> decode_image(std::string_view bytes, const std::string& name);

// A magenta/dark-grey checkerboard of `cell`-pixel squares: the visible fallback for a
// missing or broken texture (DESIGN.md §11).
Image checker_image(int width = 64, int height = 64, int cell = 8);

}  // namespace ossa
