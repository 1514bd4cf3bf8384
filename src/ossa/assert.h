#pragma once
// OSSA_ASSERT — the programmer-error tier of DESIGN.md §11. Bad data never reaches an assert:
// it becomes an ossa::Error (io/result.h). Asserts stay on in release builds because the
// checks guarded here are cheap; expensive invariant checks go behind OSSA_VALIDATION.

#include <cstdio>
#include <cstdlib>

namespace ossa::detail {
[[noreturn]] inline void assert_failed(const char* cond, const char* msg, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: assertion failed: %s (%s)\n", file, line, cond, msg);
  std::abort();
}
}  // namespace ossa::detail

#define OSSA_ASSERT(cond, msg)                                              \
  do {                                                                      \
    if (!(cond)) ::ossa::detail::assert_failed(#cond, msg, __FILE__, __LINE__); \
  } while (false)

#if defined(OSSA_VALIDATION)
#define OSSA_VALIDATE(cond, msg) OSSA_ASSERT(cond, msg)
#else
#define OSSA_VALIDATE(cond, msg) ((void)0)
#endif
