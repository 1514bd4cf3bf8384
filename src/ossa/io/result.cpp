#include "ossa/io/result.h"

#include <cstdio>
#include <cstdlib>

namespace ossa {

namespace detail {
void value_on_error(const Error& error) {
  std::fprintf(stderr, "Result::value() on an error: %s\n", error.message.c_str());
  std::fflush(stderr);
  std::abort();
}
}  // namespace detail

Error Error::at(std::string_view file, std::string_view field, std::string_view what) {
  std::string m;
  if (!file.empty()) m.append(file).append(": ");
  if (!field.empty()) m.append(field).append(": ");
  m.append(what);
  return Error{std::move(m)};
}

}  // namespace ossa
