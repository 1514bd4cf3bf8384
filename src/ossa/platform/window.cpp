#include "ossa/platform/window.h"

#include <SDL2/SDL.h>

#include <cstdio>
#include <cstdlib>

namespace ossa {

struct Window::Impl {
  SDL_Window* window = nullptr;
  SDL_GLContext context = nullptr;
  bool offscreen = false;

  ~Impl() {
    if (context) SDL_GL_DeleteContext(context);
    if (window) SDL_DestroyWindow(window);
  }
};

bool no_display_available() {
  const char* x = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (!x || !*x) && (!w || !*w);
}

bool gl_context_is_current() { return SDL_GL_GetCurrentContext() != nullptr; }

Result<Window> Window::create(const WindowDesc& desc) {
  if (desc.width <= 0 || desc.height <= 0) {
    return Error{"window: expected a positive size, got " + std::to_string(desc.width) + "x" +
                 std::to_string(desc.height)};
  }
  const bool offscreen = desc.offscreen || no_display_available();
  // The driver is chosen at SDL_Init; an explicit SDL_VIDEODRIVER from the user wins.
  if (offscreen) setenv("SDL_VIDEODRIVER", "offscreen", 0);
  if (!SDL_WasInit(SDL_INIT_VIDEO) && SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
    return Error{std::string("SDL_Init(video) failed: ") + SDL_GetError()};
  }
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_FLAGS, SDL_GL_CONTEXT_FORWARD_COMPATIBLE_FLAG);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_RED_SIZE, 8);
  SDL_GL_SetAttribute(SDL_GL_GREEN_SIZE, 8);
  SDL_GL_SetAttribute(SDL_GL_BLUE_SIZE, 8);
  SDL_GL_SetAttribute(SDL_GL_ALPHA_SIZE, 8);

  Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_ALLOW_HIGHDPI;
  if (desc.resizable) flags |= SDL_WINDOW_RESIZABLE;
  if (desc.hidden || offscreen) flags |= SDL_WINDOW_HIDDEN;

  Window w;
  w.impl_->offscreen = offscreen;
  w.impl_->window = SDL_CreateWindow(desc.title.c_str(), SDL_WINDOWPOS_CENTERED,
                                     SDL_WINDOWPOS_CENTERED, desc.width, desc.height, flags);
  if (!w.impl_->window) return Error{std::string("SDL_CreateWindow failed: ") + SDL_GetError()};
  w.impl_->context = SDL_GL_CreateContext(w.impl_->window);
  if (!w.impl_->context) {
    return Error{std::string("OpenGL 3.3 core context not available: ") + SDL_GetError()};
  }
  SDL_GL_MakeCurrent(w.impl_->window, w.impl_->context);
  if (!offscreen) w.set_vsync(desc.vsync);
  return w;
}

Window::Window() : impl_(std::make_unique<Impl>()) {}
Window::~Window() = default;
Window::Window(Window&&) noexcept = default;
Window& Window::operator=(Window&&) noexcept = default;

bool Window::is_valid() const { return impl_ && impl_->window && impl_->context; }

int Window::width() const {
  int w = 0, h = 0;
  if (is_valid()) SDL_GL_GetDrawableSize(impl_->window, &w, &h);
  return w;
}

int Window::height() const {
  int w = 0, h = 0;
  if (is_valid()) SDL_GL_GetDrawableSize(impl_->window, &w, &h);
  return h;
}

bool Window::is_offscreen() const { return impl_ && impl_->offscreen; }

std::string Window::driver() const {
  const char* d = SDL_GetCurrentVideoDriver();
  return d ? d : "";
}

void Window::make_current() {
  if (is_valid()) SDL_GL_MakeCurrent(impl_->window, impl_->context);
}

void Window::swap() {
  if (is_valid()) SDL_GL_SwapWindow(impl_->window);
}

bool Window::set_vsync(bool on) { return SDL_GL_SetSwapInterval(on ? 1 : 0) == 0; }

bool Window::poll_quit() {
  SDL_Event e;
  bool open = true;
  while (SDL_PollEvent(&e)) {
    if (e.type == SDL_QUIT) open = false;
    if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE) open = false;
  }
  return open;
}

}  // namespace ossa
