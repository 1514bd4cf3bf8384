#include "ossa/io/parse_arg.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace ossa {

Result<long long> parse_int_arg(std::string_view flag, std::string_view text, long long lo, long long hi) {
  const std::string s(text);
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno != 0 || v < lo || v > hi) {
    return Error{std::string(flag) + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                 "], got \"" + s + "\""};
  }
  return v;
}

Result<double> parse_number_arg(std::string_view flag, std::string_view text, double lo, double hi) {
  const std::string s(text);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || errno != 0 || !std::isfinite(v) || v < lo || v > hi) {
    char range[64];
    std::snprintf(range, sizeof range, "[%g, %g]", lo, hi);
    return Error{std::string(flag) + ": expected a number in " + range + ", got \"" + s + "\""};
  }
  return v;
}

}  // namespace ossa
