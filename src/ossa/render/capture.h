#pragma once
// Capture — screenshots and animated GIFs of rendered frames (DESIGN.md §8, §9).
//
//   Image frame = read_framebuffer(width, height);     // after drawing, before swap
//   write_png("shot.png", frame);
//   auto gif = GifWriter::open("walk.gif", width, height, 4);   // 4/100 s per frame
//   gif->add_frame(frame); ... gif->close();
//
// GIF colours: a fixed 256-colour palette (a 6×7×6 RGB cube plus four greys); each pixel
// takes the nearest entry. Simple and deterministic; enough for bone sprites on flat colours.

#include <memory>
#include <string>

#include "ossa/io/result.h"
#include "ossa/platform/image.h"

namespace ossa {

// Reads the current read framebuffer's colour (0, 0)-(width, height) as RGBA, rows top to
// bottom (GL's bottom-up rows are flipped). Needs a current GL context.
Image read_framebuffer(int width, int height);

// Writes an RGBA image as PNG (stb_image_write). Errors name the file.
Status write_png(const std::string& path, const Image& image);

// The fixed GIF palette: entry i as 0xRRGGBB, and the index nearest to a colour.
uint32_t gif_palette_colour(int index);
uint8_t gif_palette_index(uint8_t r, uint8_t g, uint8_t b);

class GifWriter {
 public:
  // Starts a looping GIF of width × height frames shown `delay_cs` hundredths of a second
  // each. Frames are encoded in memory; close() saves the file atomically (an unwritable
  // path is reported there).
  static Result<GifWriter> open(const std::string& path, int width, int height, int delay_cs = 4);

  GifWriter();
  ~GifWriter();  // closes the file if close() was not called
  GifWriter(GifWriter&&) noexcept;
  GifWriter& operator=(GifWriter&&) noexcept;

  // Appends a frame; its size must match the GIF's.
  Status add_frame(const Image& frame);
  // Finishes the file. Returns the first error of the whole run.
  Status close();
  int frame_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ossa
