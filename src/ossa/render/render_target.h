#pragma once
// RenderTarget — an offscreen framebuffer (a framebuffer object with an RGBA8 colour buffer)
// to draw into instead of the window and read back as an Image: exports that must not touch
// what the window shows, like the creature panel's PNG (creature_image.h).
//
//   GlFrameState saved;                          // when drawing in the middle of a frame
//   auto target = RenderTarget::create(800, 600);
//   renderer.begin_frame(*target, glm::vec4(0.0f));   // binds it; viewport = its size
//   renderer.draw_batch(batch, atlas.texture);
//   Image image = target->read();                // rows top to bottom
//   // ~GlFrameState puts the window's framebuffer, viewport and blending back
//
// Needs a current GL context from creation to destruction (DESIGN.md §9).

#include "ossa/io/result.h"
#include "ossa/platform/image.h"

namespace ossa {

class RenderTarget {
 public:
  // Largest side accepted by create(), pixels (the driver's limit may be lower).
  static constexpr int kMaxSize = 8192;

  // Creates a width × height target. Errors: a size outside [1, kMaxSize] or above the
  // driver's renderbuffer limit, or a framebuffer the driver reports incomplete.
  static Result<RenderTarget> create(int width, int height);

  RenderTarget() = default;
  ~RenderTarget();
  RenderTarget(RenderTarget&& o) noexcept;
  RenderTarget& operator=(RenderTarget&& o) noexcept;
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  bool is_valid() const { return framebuffer_ != 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  unsigned framebuffer() const { return framebuffer_; }

  // Binds the target for drawing and reading and sets the viewport to its size.
  void bind() const;
  // Its pixels as RGBA, rows top to bottom (binds it for reading).
  Image read() const;

 private:
  void release();
  unsigned framebuffer_ = 0, colour_ = 0;
  int width_ = 0, height_ = 0;
};

// Saves the GL state that a frame setup (Renderer::begin_frame) changes — draw and read
// framebuffer bindings, viewport, clear colour, blending and its functions, the scissor, depth
// and cull switches — and restores it when destroyed. Programs, vertex arrays and texture
// bindings are not saved: every draw sets its own.
class GlFrameState {
 public:
  GlFrameState();
  ~GlFrameState();
  GlFrameState(const GlFrameState&) = delete;
  GlFrameState& operator=(const GlFrameState&) = delete;

 private:
  int draw_framebuffer_ = 0, read_framebuffer_ = 0;
  int viewport_[4] = {0, 0, 0, 0};
  float clear_colour_[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  int blend_src_rgb_ = 0, blend_dst_rgb_ = 0, blend_src_alpha_ = 0, blend_dst_alpha_ = 0;
  bool blend_ = false, scissor_ = false, depth_ = false, cull_ = false;
};

}  // namespace ossa
