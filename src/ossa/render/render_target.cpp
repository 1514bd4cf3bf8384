#include "ossa/render/render_target.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "ossa/render/gl.h"

namespace ossa {

Result<RenderTarget> RenderTarget::create(int width, int height) {
  GLint driver_max = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &driver_max);
  const int max_side = driver_max > 0 ? std::min(kMaxSize, static_cast<int>(driver_max)) : kMaxSize;
  if (width < 1 || height < 1 || width > max_side || height > max_side) {
    return Error{"image size " + std::to_string(width) + "x" + std::to_string(height) +
                 ": expected 1 to " + std::to_string(max_side) + " pixels per side"};
  }
  RenderTarget t;
  t.width_ = width;
  t.height_ = height;
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glGenRenderbuffers(1, &t.colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, t.colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &t.framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", status);
    return Error{"offscreen framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                 " is incomplete (status " + code + ")"};
  }
  if (!check_gl("RenderTarget::create")) return Error{"OpenGL error while creating an offscreen framebuffer"};
  return t;
}

RenderTarget::~RenderTarget() { release(); }

RenderTarget::RenderTarget(RenderTarget&& o) noexcept
    : framebuffer_(std::exchange(o.framebuffer_, 0u)),
      colour_(std::exchange(o.colour_, 0u)),
      width_(std::exchange(o.width_, 0)),
      height_(std::exchange(o.height_, 0)) {}

RenderTarget& RenderTarget::operator=(RenderTarget&& o) noexcept {
  if (this != &o) {
    release();
    framebuffer_ = std::exchange(o.framebuffer_, 0u);
    colour_ = std::exchange(o.colour_, 0u);
    width_ = std::exchange(o.width_, 0);
    height_ = std::exchange(o.height_, 0);
  }
  return *this;
}

void RenderTarget::release() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (colour_) glDeleteRenderbuffers(1, &colour_);
  framebuffer_ = colour_ = 0;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

Image RenderTarget::read() const {
  Image image;
  if (!is_valid()) return image;
  image.width = width_;
  image.height = height_;
  image.rgba.resize(static_cast<size_t>(width_) * height_ * 4);
  std::vector<uint8_t> raw(image.rgba.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
  // GL rows run bottom to top.
  const size_t row = static_cast<size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    std::memcpy(&image.rgba[y * row], &raw[(height_ - 1 - y) * row], row);
  }
  return image;
}

GlFrameState::GlFrameState() {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer_);
  glGetIntegerv(GL_VIEWPORT, viewport_);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear_colour_);
  glGetIntegerv(GL_BLEND_SRC_RGB, &blend_src_rgb_);
  glGetIntegerv(GL_BLEND_DST_RGB, &blend_dst_rgb_);
  glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend_src_alpha_);
  glGetIntegerv(GL_BLEND_DST_ALPHA, &blend_dst_alpha_);
  blend_ = glIsEnabled(GL_BLEND);
  scissor_ = glIsEnabled(GL_SCISSOR_TEST);
  depth_ = glIsEnabled(GL_DEPTH_TEST);
  cull_ = glIsEnabled(GL_CULL_FACE);
}

GlFrameState::~GlFrameState() {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  glClearColor(clear_colour_[0], clear_colour_[1], clear_colour_[2], clear_colour_[3]);
  glBlendFuncSeparate(static_cast<GLenum>(blend_src_rgb_), static_cast<GLenum>(blend_dst_rgb_),
                      static_cast<GLenum>(blend_src_alpha_), static_cast<GLenum>(blend_dst_alpha_));
  auto set = [](GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); };
  set(GL_BLEND, blend_);
  set(GL_SCISSOR_TEST, scissor_);
  set(GL_DEPTH_TEST, depth_);
  set(GL_CULL_FACE, cull_);
}

}  // namespace ossa
