#include "ossa/platform/image.h"

#include <SDL2/SDL.h>
#include <SDL2/SDL_image.h>

#include <cstring>

#include "ossa/io/file.h"
#include "ossa/io/image_info.h"

namespace ossa {

Result<Image> load_image(const std::string& path) {
  // The input rule (io/file.h) and the size from the header before SDL_image decodes anything
  // (io/image_info.h): SDL_image would open a pipe and wait, and decode any size it is given.
  Result<std::string> bytes = read_file(path, kMaxImageFileBytes);
  if (!bytes) return bytes.error();
  if (Result<ImageInfo> info = check_image(*bytes, path); !info) return info.error();
  SDL_RWops* rw = SDL_RWFromConstMem(bytes->data(), static_cast<int>(bytes->size()));
  if (!rw) return Error{path + ": cannot load image: " + SDL_GetError()};
  SDL_Surface* loaded = IMG_Load_RW(rw, 1);
  if (!loaded) return Error{path + ": cannot load image: " + IMG_GetError()};
  // RGBA32 is R, G, B, A in byte order whatever the endianness: what GL_RGBA/UNSIGNED_BYTE reads.
  SDL_Surface* rgba = SDL_ConvertSurfaceFormat(loaded, SDL_PIXELFORMAT_RGBA32, 0);
  SDL_FreeSurface(loaded);
  if (!rgba) return Error{path + ": cannot convert image to RGBA: " + SDL_GetError()};
  Image image;
  image.width = rgba->w;
  image.height = rgba->h;
  image.rgba.resize(static_cast<size_t>(rgba->w) * rgba->h * 4);
  SDL_LockSurface(rgba);
  for (int y = 0; y < rgba->h; ++y) {
    std::memcpy(&image.rgba[static_cast<size_t>(y) * rgba->w * 4],
                static_cast<const uint8_t*>(rgba->pixels) + static_cast<size_t>(y) * rgba->pitch,
                static_cast<size_t>(rgba->w) * 4);
  }
  SDL_UnlockSurface(rgba);
  SDL_FreeSurface(rgba);
  if (image.empty()) return Error{path + ": image has no pixels"};
  return image;
}

}  // namespace ossa
