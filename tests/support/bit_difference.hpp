#pragma once
// Where two arrays differ in their bits, in a line: the tests' check that two paths (fused and
// separate passes, AVX-512 and baseline lanes, one thread and two, a cut and the unblocked rows)
// give the same numbers.
//
// Why not CHECK(a == b) on the vectors: Catch2 then prints both vectors whole and wraps that text
// in time quadratic in its length (measured with Catch2 2.13.10: 1.4 s for one failed check of
// two 64,000-value vectors, 4x per doubling); the rank-one fused tests' 156,000-value states made
// one wrong bit a run of hours instead of a failure. And == calls -0.0 and 0.0 equal and a NaN
// unequal to itself, where the claim is the same bits.
#include <cstddef>
#include <cstring>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace hmfnet::test {

/// "" where `actual` and `expected` hold the same values bit for bit (and are of one length);
/// otherwise the lengths, or how many values differ, the first index that does and both values
/// there in full precision. Use as CHECK(bit_difference(a, b) == "") so that a failure prints it.
template <typename T>
std::string bit_difference(const std::vector<T>& actual, const std::vector<T>& expected) {
  static_assert(std::is_arithmetic_v<T>, "numbers: compared by their bits, printed as numbers");
  std::ostringstream out;
  if (actual.size() != expected.size()) {
    out << actual.size() << " values where " << expected.size() << " were expected";
    return out.str();
  }
  std::size_t first = actual.size(), count = 0;
  for (std::size_t k = 0; k < actual.size(); ++k) {
    if (std::memcmp(&actual[k], &expected[k], sizeof(T)) == 0) continue;
    if (count++ == 0) first = k;
  }
  if (count == 0) return "";
  // Integers print as integers of their signedness; char-sized ones as numbers, not characters.
  using Integer = std::conditional_t<std::is_signed_v<T>, long long, unsigned long long>;
  using Printed = std::conditional_t<std::is_floating_point_v<T>, T, Integer>;
  out << std::setprecision(std::numeric_limits<T>::max_digits10) << count << " of " << actual.size()
      << " values differ, the first at " << first << ": " << static_cast<Printed>(actual[first])
      << " where " << static_cast<Printed>(expected[first]) << " was expected";
  return out.str();
}

}  // namespace hmfnet::test
