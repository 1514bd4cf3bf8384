#include "ossa/draw/image.h"

#include "ossa/io/file.h"
#include "ossa/io/image_info.h"

// stb_image, the one copy ossa compiles (static: it cannot clash with an embedder's own or
// Assimp's).
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace ossa {

Result<Image> decode_image(std::string_view bytes, const std::string& name) {
  if (Result<ImageInfo> info = check_image(bytes, name); !info) return info.error();
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                                          &w, &h, &channels, 4);
  if (!pixels) return Error{name + ": cannot load image: " + stbi_failure_reason()};
  Image image;
  image.width = w;
  image.height = h;
  image.rgba.assign(pixels, pixels + static_cast<size_t>(w) * h * 4);
  stbi_image_free(pixels);
  if (image.empty()) return Error{name + ": image has no pixels"};
  return image;
}

Result<Image> decode_image_file(const std::string& path) {
  Result<std::string> bytes = read_file(path, kMaxImageFileBytes);
  if (!bytes) return bytes.error();
  return decode_image(*bytes, path);
}

Image checker_image(int width, int height, int cell) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool on = ((x / cell) + (y / cell)) % 2 == 0;
      uint8_t* p = image.pixel(x, y);
      p[0] = on ? 255 : 40;
      p[1] = on ? 0 : 40;
      p[2] = on ? 255 : 40;
      p[3] = 255;
    }
  }
  return image;
}

}  // namespace ossa
