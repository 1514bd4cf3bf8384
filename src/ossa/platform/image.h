#pragma once
// Image — 8-bit RGBA pixels on the CPU, rows top to bottom — and loading through SDL2_image
// (PNG, JPEG, ...). Used by textures, the sprite atlas and frame capture.

#include <cstdint>
#include <string>
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

// Loads an image file as RGBA: a regular file of at most kMaxImageFileBytes, PNG, JPEG or BMP,
// whose size check_image accepts from its header before anything is decoded (io/image_info.h).
// Errors name the file and the reason.
Result<Image> load_image(const std::string& path);

// A magenta/dark-grey checkerboard of `cell`-pixel squares: the visible fallback for a
// missing or broken texture (DESIGN.md §11).
Image checker_image(int width = 64, int height = 64, int cell = 8);

}  // namespace ossa
