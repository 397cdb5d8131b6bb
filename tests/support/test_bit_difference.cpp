#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "support/bit_difference.hpp"

using hmfnet::test::bit_difference;

TEST_CASE(
    "bit_difference: empty for the same bits, else the count, the first index and both values",
    "[bit_difference]") {
  const std::vector<double> a{0.5, 1.0, -2.0, 3.0};
  CHECK(bit_difference(a, a) == "");
  std::vector<double> b = a;
  b[2] = std::nextafter(-2.0, 0.0);
  b[3] = 4.0;
  CHECK(bit_difference(b, a) ==
        "2 of 4 values differ, the first at 2: -1.9999999999999998 where -2 was expected");
  CHECK(bit_difference(std::vector<double>{1.0}, a) == "1 values where 4 were expected");
}

TEST_CASE("bit_difference: -0.0 and 0.0 differ, a NaN of the same bits does not",
          "[bit_difference]") {
  // The claim is the same bits, which == does not test: -0.0 == 0.0 and NaN != NaN.
  CHECK(bit_difference(std::vector<double>{-0.0}, std::vector<double>{0.0}) ==
        "1 of 1 values differ, the first at 0: -0 where 0 was expected");
  const std::vector<float> nan{std::nanf("")};
  CHECK(bit_difference(nan, nan) == "");
}

TEST_CASE("bit_difference: integers print as numbers", "[bit_difference]") {
  CHECK(bit_difference(std::vector<std::uint8_t>{7, 65}, std::vector<std::uint8_t>{7, 66}) ==
        "1 of 2 values differ, the first at 1: 65 where 66 was expected");
  // An unsigned 64-bit index above the signed range prints as itself, not wrapped negative.
  CHECK(bit_difference(std::vector<std::uint64_t>{~std::uint64_t{0}},
                       std::vector<std::uint64_t>{0}) ==
        "1 of 1 values differ, the first at 0: 18446744073709551615 where 0 was expected");
}

TEST_CASE("bit_difference: a difference in 10^6 values is reported at once", "[bit_difference]") {
  // The reason it exists: CHECK(a == b) on vectors this long prints them whole (minutes to hours).
  std::vector<double> a(1000000, 1.0), b = a;
  b[999999] = 2.0;
  CHECK(bit_difference(b, a) ==
        "1 of 1000000 values differ, the first at 999999: 2 where 1 was expected");
}
