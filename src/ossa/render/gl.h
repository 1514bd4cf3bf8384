#pragma once
// The one include for OpenGL in ossa (libepoxy: loads GL entry points for GLX and EGL
// contexts alike, so the offscreen driver needs no special case), plus render logging.

#include <epoxy/gl.h>

#include <string>

namespace ossa {

// Resource failures are logged, not thrown (DESIGN.md §11): GL/SDL/texture problems go to
// stderr prefixed "ossa render: " and the caller falls back visibly.
void render_log(const std::string& message);
// The number of messages logged so far (tests check that a fallback was reported).
int render_log_count();
// The last message logged, or "".
std::string render_last_log();

// Drains glGetError(); logs and returns false when errors were pending. `where` names the caller.
bool check_gl(const char* where);

}  // namespace ossa
