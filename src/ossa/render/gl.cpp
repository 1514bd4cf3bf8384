#include "ossa/render/gl.h"

#include <cstdio>
#include <mutex>

namespace ossa {
namespace {
std::mutex g_log_mutex;
int g_log_count = 0;
std::string g_last_log;
}  // namespace

void render_log(const std::string& message) {
  std::lock_guard<std::mutex> lock(g_log_mutex);
  ++g_log_count;
  g_last_log = message;
  std::fprintf(stderr, "ossa render: %s\n", message.c_str());
}

int render_log_count() {
  std::lock_guard<std::mutex> lock(g_log_mutex);
  return g_log_count;
}

std::string render_last_log() {
  std::lock_guard<std::mutex> lock(g_log_mutex);
  return g_last_log;
}

bool check_gl(const char* where) {
  bool ok = true;
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "0x%04x", e);
    render_log(std::string(where) + ": GL error " + buf);
    ok = false;
  }
  return ok;
}

}  // namespace ossa
