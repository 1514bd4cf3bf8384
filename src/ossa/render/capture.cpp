#include "ossa/render/capture.h"

#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <vector>

// stb is third-party code: its warnings are not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "ossa/io/file.h"
#include "ossa/render/gl.h"

namespace ossa {
namespace {

constexpr int kCubeR = 6, kCubeG = 7, kCubeB = 6;      // 252 entries
constexpr int kCubeSize = kCubeR * kCubeG * kCubeB;
constexpr uint8_t kGreys[4] = {51, 102, 153, 204};       // entries 252..255

int level(int v, int steps) { return (v * (steps - 1) + 127) / 255; }
int value(int level, int steps) { return level * 255 / (steps - 1); }

}  // namespace

Image read_framebuffer(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<size_t>(width) * height * 4);
  std::vector<uint8_t> raw(image.rgba.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
  const size_t row = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height; ++y) {
    std::memcpy(&image.rgba[y * row], &raw[(height - 1 - y) * row], row);
  }
  return image;
}

Status write_png(const std::string& path, const Image& image) {
  if (image.empty()) return Error{path + ": cannot write an empty image"};
  // Encode in memory, then save atomically like every other file ossa writes.
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4)) {
    return Error{path + ": cannot encode PNG"};
  }
  return write_file_atomic(path, bytes);
}

uint32_t gif_palette_colour(int i) {
  if (i >= kCubeSize) {
    const uint32_t g = kGreys[std::clamp(i - kCubeSize, 0, 3)];
    return (g << 16) | (g << 8) | g;
  }
  const int r = i / (kCubeG * kCubeB), g = (i / kCubeB) % kCubeG, b = i % kCubeB;
  return (static_cast<uint32_t>(value(r, kCubeR)) << 16) |
         (static_cast<uint32_t>(value(g, kCubeG)) << 8) | static_cast<uint32_t>(value(b, kCubeB));
}

uint8_t gif_palette_index(uint8_t r, uint8_t g, uint8_t b) {
  const int lr = level(r, kCubeR), lg = level(g, kCubeG), lb = level(b, kCubeB);
  const int cube = (lr * kCubeG + lg) * kCubeB + lb;
  auto dist = [&](uint32_t c) {
    const int dr = static_cast<int>((c >> 16) & 255) - r, dg = static_cast<int>((c >> 8) & 255) - g,
              db = static_cast<int>(c & 255) - b;
    return dr * dr + dg * dg + db * db;
  };
  int best = cube, best_d = dist(gif_palette_colour(cube));
  for (int k = 0; k < 4; ++k) {
    const int d = dist(gif_palette_colour(kCubeSize + k));
    if (d < best_d) {
      best_d = d;
      best = kCubeSize + k;
    }
  }
  return static_cast<uint8_t>(best);
}

struct GifWriter::Impl {
  GifFileType* gif = nullptr;
  std::string path;
  std::string bytes;  // the encoded GIF, saved atomically by close()
  int width = 0, height = 0, delay_cs = 4, frames = 0;
  std::string error;

  void fail(const std::string& what, int code) {
    if (error.empty()) error = path + ": " + what + ": " + GifErrorString(code);
  }
  ~Impl() {
    if (gif) {
      int err = 0;
      EGifCloseFile(gif, &err);
    }
  }
};

GifWriter::GifWriter() : impl_(std::make_unique<Impl>()) {}
GifWriter::~GifWriter() = default;
GifWriter::GifWriter(GifWriter&&) noexcept = default;
GifWriter& GifWriter::operator=(GifWriter&&) noexcept = default;

Result<GifWriter> GifWriter::open(const std::string& path, int width, int height, int delay_cs) {
  if (width <= 0 || height <= 0 || width > 65535 || height > 65535) {
    return Error{path + ": GIF size must be in [1, 65535]"};
  }
  GifWriter w;
  Impl& s = *w.impl_;
  s.path = path;
  s.width = width;
  s.height = height;
  s.delay_cs = std::clamp(delay_cs, 1, 65535);
  int err = 0;
  // Encode into memory (Impl lives on the heap, so its address is stable across moves).
  auto append = [](GifFileType* f, const GifByteType* data, int n) {
    static_cast<Impl*>(f->UserData)->bytes.append(reinterpret_cast<const char*>(data), static_cast<size_t>(n));
    return n;
  };
  s.gif = EGifOpen(&s, append, &err);
  if (!s.gif) return Error{path + ": cannot start a GIF: " + GifErrorString(err)};
  EGifSetGifVersion(s.gif, true);  // GIF89a: frame delays and looping

  GifColorType colours[256];
  for (int i = 0; i < 256; ++i) {
    const uint32_t c = gif_palette_colour(i);
    colours[i] = {static_cast<GifByteType>(c >> 16), static_cast<GifByteType>((c >> 8) & 255),
                  static_cast<GifByteType>(c & 255)};
  }
  ColorMapObject* map = GifMakeMapObject(256, colours);
  const int ok = EGifPutScreenDesc(s.gif, width, height, 8, 0, map);
  GifFreeMapObject(map);
  if (ok == GIF_ERROR) return Error{path + ": cannot write the GIF header: " + GifErrorString(s.gif->Error)};

  // NETSCAPE2.0 application block: loop forever.
  const GifByteType loop[3] = {1, 0, 0};
  if (EGifPutExtensionLeader(s.gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(s.gif, 11, "NETSCAPE2.0") == GIF_ERROR ||
      EGifPutExtensionBlock(s.gif, 3, loop) == GIF_ERROR ||
      EGifPutExtensionTrailer(s.gif) == GIF_ERROR) {
    return Error{path + ": cannot write the GIF loop block: " + GifErrorString(s.gif->Error)};
  }
  return w;
}

Status GifWriter::add_frame(const Image& frame) {
  Impl& s = *impl_;
  if (!s.gif) return Error{s.path + ": GIF is closed"};
  if (frame.width != s.width || frame.height != s.height) {
    return Error{s.path + ": frame is " + std::to_string(frame.width) + "x" +
                 std::to_string(frame.height) + ", expected " + std::to_string(s.width) + "x" +
                 std::to_string(s.height)};
  }
  GraphicsControlBlock gcb{};
  gcb.DisposalMode = DISPOSE_DO_NOT;
  gcb.DelayTime = s.delay_cs;
  gcb.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType ext[4];
  const size_t n = EGifGCBToExtension(&gcb, ext);
  if (EGifPutExtension(s.gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(n), ext) == GIF_ERROR ||
      EGifPutImageDesc(s.gif, 0, 0, s.width, s.height, false, nullptr) == GIF_ERROR) {
    s.fail("cannot write a frame", s.gif->Error);
    return Error{s.error};
  }
  std::vector<GifPixelType> row(static_cast<size_t>(s.width));
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x) {
      const uint8_t* p = frame.pixel(x, y);
      row[x] = gif_palette_index(p[0], p[1], p[2]);
    }
    if (EGifPutLine(s.gif, row.data(), s.width) == GIF_ERROR) {
      s.fail("cannot write a frame", s.gif->Error);
      return Error{s.error};
    }
  }
  ++s.frames;
  return {};
}

Status GifWriter::close() {
  Impl& s = *impl_;
  if (s.gif) {
    int err = 0;
    if (EGifCloseFile(s.gif, &err) == GIF_ERROR) s.fail("cannot close GIF", err);
    s.gif = nullptr;
    if (s.error.empty()) {
      if (Status w = write_file_atomic(s.path, s.bytes); !w.ok()) return w;
    }
    s.bytes.clear();
  }
  if (!s.error.empty()) return Error{s.error};
  return {};
}

int GifWriter::frame_count() const { return impl_->frames; }

}  // namespace ossa
