#pragma once
// Command-line values, shared by the tools and the game's options: the whole of `text` as an
// integer (or a finite number) in [lo, hi], or an error naming the flag, the range and what was
// given ("--hz: expected an integer in [30, 480], got \"fast\"").

#include <string_view>

#include "ossa/io/result.h"

namespace ossa {

Result<long long> parse_int_arg(std::string_view flag, std::string_view text, long long lo, long long hi);
// "--sigma: expected a number in [0, 10], got \"far\"" (the range's ends as %g prints them).
Result<double> parse_number_arg(std::string_view flag, std::string_view text, double lo, double hi);

}  // namespace ossa
