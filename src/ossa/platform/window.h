#pragma once
// Window — an SDL2 window with an OpenGL 3.3 core context (DESIGN.md §9). The only place
// that creates SDL video state; render headers never include SDL.
//
// Offscreen: when `offscreen` is set, or when no display is available (no DISPLAY /
// WAYLAND_DISPLAY), SDL's "offscreen" video driver gives the same code path an EGL context
// (Mesa llvmpipe) with no display — tools and tests render and read back the default
// framebuffer exactly as the game does on screen.

#include <memory>
#include <string>

#include "ossa/io/result.h"

namespace ossa {

struct WindowDesc {
  std::string title = "ossa";
  int width = 1280;         // pixels, > 0
  int height = 720;         // pixels, > 0
  bool vsync = true;        // swap interval 1 (ignored offscreen)
  bool resizable = true;
  bool hidden = false;      // create the window unmapped (tools on a display)
  bool offscreen = false;   // force SDL's offscreen driver (no display needed)
};

class Window {
 public:
  // Initialises SDL video (once per process), creates the window and the GL 3.3 core context
  // and makes it current. Errors carry SDL's message.
  static Result<Window> create(const WindowDesc& desc);

  Window();
  ~Window();
  Window(Window&&) noexcept;
  Window& operator=(Window&&) noexcept;
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  bool is_valid() const;
  // Drawable size in pixels (the framebuffer size; may differ from the window on HiDPI).
  int width() const;
  int height() const;
  bool is_offscreen() const;
  // The SDL video driver in use ("x11", "wayland", "offscreen", ...).
  std::string driver() const;

  void make_current();
  void swap();
  // Swap interval: true = vsync. Returns false when the driver refuses.
  bool set_vsync(bool on);
  // Pumps SDL events; returns false once the user closed the window.
  bool poll_quit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// True when no display server is reachable (DISPLAY and WAYLAND_DISPLAY unset).
bool no_display_available();

// True when this thread has a current OpenGL context (made by a Window). Code that draws on
// its own (e.g. the creature panel's PNG export) checks this and reports an error instead of
// calling GL without a context.
bool gl_context_is_current();

}  // namespace ossa
