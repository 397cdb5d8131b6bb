// The vectorised [cos, sin] of the force kernels (dynamics/sincos.hpp): its error against the
// x87 long double functions, exactness of the values the polynomials must hit, the C library's
// bits beyond the reduced range, and the promise the kernels rely on: an angle's bits do not
// depend on its place in the array (vector body or padded tail), on the thread count or on the
// instruction set.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "dynamics/sincos.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"

using namespace hmfnet;

namespace {

struct ErrorInUlps {
  double cos = 0.0;
  double sin = 0.0;
};

// Error of a double against the long double reference, in units of the double's last place at
// the reference value (the spacing of doubles at |ref|; at least the smallest normal's).
double ulps(double value, long double ref) {
  const double r = static_cast<double>(ref);
  const double spacing = std::max(std::abs(std::nextafter(r, INFINITY) - r), DBL_MIN);
  return static_cast<double>(std::abs(static_cast<long double>(value) - ref)) / spacing;
}

ErrorInUlps largest_error(const std::vector<double>& x) {
  std::vector<double> cs(2 * x.size());
  sincos_interleaved(x.data(), x.size(), cs.data());
  ErrorInUlps e;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const auto xl = static_cast<long double>(x[k]);
    e.cos = std::max(e.cos, ulps(cs[2 * k], cosl(xl)));
    e.sin = std::max(e.sin, ulps(cs[2 * k + 1], sinl(xl)));
  }
  return e;
}

std::vector<double> uniform_angles(double half_width, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-half_width, half_width);
  std::vector<double> x(n);
  for (auto& v : x) v = u(rng);
  return x;
}

}  // namespace

TEST_CASE("sincos: error against long double within 1 ulp up to 10^7", "[sincos]") {
  // The bound: Cephes' polynomials are accurate to ~0.5 ulp on [-pi/4, pi/4] and the final
  // addition rounds once more; x87 sinl/cosl reduce by a 66-bit pi, accurate to ~2^-60 |x|
  // relative up to 10^7, below 0.01 ulp of the double results here. Measured on the development
  // machine: at most 0.70-0.8 ulp on every range.
  for (const double half_width : {0.78, 3.2, 100.0, 1e4, 1e7}) {
    const ErrorInUlps e = largest_error(uniform_angles(half_width, 200000, 7));
    INFO("range +-" << half_width << ": cos " << e.cos << " ulp, sin " << e.sin << " ulp");
    CHECK(e.cos <= 1.0);
    CHECK(e.sin <= 1.0);
  }
}

TEST_CASE("sincos: exact values and the quadrant signs", "[sincos]") {
  const std::vector<double> x = {0.0, -0.0, M_PI / 6, -M_PI / 6, M_PI / 2, M_PI, -M_PI / 2};
  std::vector<double> cs(2 * x.size());
  sincos_interleaved(x.data(), x.size(), cs.data());
  CHECK(cs[0] == 1.0);
  CHECK(cs[1] == 0.0);
  CHECK(cs[2] == 1.0);
  CHECK(cs[3] == 0.0);  // the sign of a zero sine is not kept (no force term can tell)
  CHECK(cs[3 * 2 + 1] == -cs[2 * 2 + 1]);  // sin is odd
  CHECK(cs[3 * 2] == cs[2 * 2]);           // cos is even
  // The doubles nearest pi/2 and pi: cos(pi/2 rounded) = 6.123e-17, sin(pi rounded) = 1.2246e-16
  // (the rounding of pi itself), which the four-part reduction must keep to full precision.
  CHECK(cs[4 * 2] == Approx(6.123233995736766e-17).epsilon(1e-15));
  CHECK(cs[4 * 2 + 1] == 1.0);
  CHECK(cs[5 * 2] == -1.0);
  CHECK(cs[5 * 2 + 1] == Approx(1.2246467991473532e-16).epsilon(1e-15));
  CHECK(cs[6 * 2 + 1] == -1.0);
}

TEST_CASE("sincos: beyond the reduced range and non-finite angles take the C library's values",
          "[sincos]") {
  const std::vector<double> x = {
      kReducedRange, std::nextafter(kReducedRange, INFINITY),  -1e8, 1e300,
      INFINITY,      std::numeric_limits<double>::quiet_NaN(), 0.5};
  std::vector<double> cs(2 * x.size());
  sincos_interleaved(x.data(), x.size(), cs.data());
  for (std::size_t k = 1; k < 4; ++k) {
    double s = 0.0;
    double c = 0.0;
    ::sincos(x[k], &s, &c);
    CHECK(cs[2 * k] == c);
    CHECK(cs[2 * k + 1] == s);
  }
  CHECK(std::isnan(cs[8]));
  CHECK(std::isnan(cs[9]));
  CHECK(std::isnan(cs[10]));
  CHECK(std::isnan(cs[11]));
  CHECK(cs[12] == Approx(std::cos(0.5)).epsilon(1e-15));  // the angle after them is unharmed
}

TEST_CASE("sincos: an angle's bits do not depend on its place, the threads or the instruction set",
          "[sincos]") {
  const std::vector<double> x = uniform_angles(50.0, 4099, 11);  // not a multiple of any width
  std::vector<double> whole(2 * x.size());
  sincos_interleaved(x.data(), x.size(), whole.data());
  // Every angle alone (a tail of one) and in arrays starting at every offset below 8.
  for (std::size_t k = 0; k < x.size(); k += 37) {
    double one[2];
    sincos_interleaved(&x[k], 1, one);
    REQUIRE(one[0] == whole[2 * k]);
    REQUIRE(one[1] == whole[2 * k + 1]);
  }
  for (std::size_t offset = 1; offset < 8; ++offset) {
    std::vector<double> part(2 * (x.size() - offset));
    sincos_interleaved(x.data() + offset, x.size() - offset, part.data());
    REQUIRE(std::equal(part.begin(), part.end(),
                       whole.begin() + static_cast<std::ptrdiff_t>(2 * offset)));
  }
  // The x86-64 baseline version gives the same bits as the one chosen for this CPU (AVX2 where
  // it has it; on a CPU without, both are the baseline and this compares it with itself).
  std::vector<double> baseline(2 * x.size());
  sincos_interleaved_baseline(x.data(), x.size(), baseline.data());
  REQUIRE(baseline == whole);
  const std::vector<double> wide = uniform_angles(1e7, 100003, 13);
  std::vector<double> wide_chosen(2 * wide.size());
  std::vector<double> wide_baseline(2 * wide.size());
  sincos_interleaved(wide.data(), wide.size(), wide_chosen.data());
  sincos_interleaved_baseline(wide.data(), wide.size(), wide_baseline.data());
  REQUIRE(wide_chosen == wide_baseline);
  // In a team of two threads (blocks shared out) the same bits.
  const ThreadCountScope two(2);
  std::vector<double> team(2 * x.size(), 0.0);
  in_team([&] { sincos_interleaved_team(x.data(), x.size(), team.data()); });
  CHECK(team == whole);
}
