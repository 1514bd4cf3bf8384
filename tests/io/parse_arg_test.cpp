#include "ossa/io/parse_arg.h"

#include <catch2/catch.hpp>

using namespace ossa;

TEST_CASE("command-line integers: the whole text, in range, or an error naming the flag", "[io]") {
  CHECK(parse_int_arg("--hz", "120", 30, 480).value() == 120);
  CHECK(parse_int_arg("--seed", "-3", -5, 5).value() == -3);
  CHECK(parse_int_arg("--seed", "4611686018427387904", 0, 1LL << 62).value() == (1LL << 62));
  CHECK(parse_int_arg("--hz", "fast", 30, 480).message() == "--hz: expected an integer in [30, 480], got \"fast\"");
  CHECK(parse_int_arg("--hz", "", 30, 480).message() == "--hz: expected an integer in [30, 480], got \"\"");
  CHECK_FALSE(parse_int_arg("--hz", "120x", 30, 480).ok());
  CHECK_FALSE(parse_int_arg("--hz", "29", 30, 480).ok());
  CHECK_FALSE(parse_int_arg("--hz", "481", 30, 480).ok());
  CHECK_FALSE(parse_int_arg("--seed", "99999999999999999999", 0, 1LL << 62).ok());  // out of long long
}

TEST_CASE("command-line numbers: the whole text, finite, in range, or an error naming the flag", "[io]") {
  CHECK(parse_number_arg("--sigma", "0.5", 0.0, 10.0).value() == 0.5);
  CHECK(parse_number_arg("--sigma", "1e1", 0.0, 10.0).value() == 10.0);
  CHECK(parse_number_arg("--frame", "0.05", 0.05, 50.0).ok());  // the ends are in
  CHECK(parse_number_arg("--sigma", "far", 0.0, 10.0).message() == "--sigma: expected a number in [0, 10], got \"far\"");
  CHECK(parse_number_arg("--frame", "", 0.05, 50.0).message() == "--frame: expected a number in [0.05, 50], got \"\"");
  for (const char* bad : {"2m", "nan", "inf", "-0.1", "10.5", "1e999"}) {
    INFO(bad);
    CHECK_FALSE(parse_number_arg("--sigma", bad, 0.0, 10.0).ok());
  }
}
