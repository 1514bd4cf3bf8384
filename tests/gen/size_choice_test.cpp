// The size choice as the tools and the game take it on the command line (--size true|FRAME_M,
// issue 29): true size or a frame in metres within the genome file's range.

#include <catch2/catch.hpp>

#include "ossa/gen/genome.h"

using namespace ossa;

TEST_CASE("the size choice on a command line: true or a frame in metres, else an error naming the flag", "[gen]") {
  auto t = parse_size_arg("--size", "true");
  REQUIRE(t.ok());
  CHECK(t->true_size);
  auto two = parse_size_arg("--size", "2");
  REQUIRE(two.ok());
  CHECK_FALSE(two->true_size);
  CHECK(two->frame_m == 2.0f);
  CHECK(parse_size_arg("--size", "0.05").ok());  // the file's range, ends in
  CHECK(parse_size_arg("--size", "50").ok());
  CHECK(parse_size_arg("--size", "big").message() ==
        "--size: expected true or a frame in metres (a number in [0.05, 50]), got \"big\"");
  for (const char* bad : {"", "True", "false", "0.04", "51", "2m", "nan", "1280x720"}) {
    INFO(bad);
    CHECK_FALSE(parse_size_arg("--size", bad).ok());
  }

  // Applied to a genome's options: a frame sets both, true size keeps the frame it had.
  GenomeOptions o;
  two->apply_to(o);
  CHECK_FALSE(o.true_size);
  CHECK(o.frame_m == 2.0f);
  o.frame_m = 3.0f;
  t->apply_to(o);
  CHECK(o.true_size);
  CHECK(o.frame_m == 3.0f);
}
