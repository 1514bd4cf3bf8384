// Linked into the test executables that load the system's OpenGL driver (render, editor, app;
// tests/CMakeLists.txt), in sanitizer builds only: Mesa is dlopened and unloaded again, so its
// allocations show as leaks from an unknown module. AddressSanitizer reads these defaults
// before ASAN_OPTIONS (tools/test leaves detect_leaks out of it so that they hold), and the
// programs these tests start (the game, ossa-render), which load Mesa too, get the same
// through ASAN_OPTIONS in their environment.

#include <cstdlib>
#include <string>

extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }

namespace {

struct ChildrenToo {
  ChildrenToo() {
    const char* now = std::getenv("ASAN_OPTIONS");
    std::string options = now ? now : "";
    if (options.find("detect_leaks") != std::string::npos) return;
    options += options.empty() ? "detect_leaks=0" : ":detect_leaks=0";
    setenv("ASAN_OPTIONS", options.c_str(), 1);
  }
} children_too;

}  // namespace
