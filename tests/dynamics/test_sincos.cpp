// The vectorised [cos, sin] of the force kernels (dynamics/sincos.hpp): its error against glibc's
// long double cosl/sinl (random angles and the doubles nearest multiples of pi/2), the values the
// polynomials must hit, the C library's bits beyond the reduced range, pinned bits, and the
// promise the kernels rely on: an angle's bits do not depend on its place in the array (vector
// body or padded tail), on the thread count or on the instruction set.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "dynamics/sincos.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"
#include "support/bit_difference.hpp"
#include "support/sincos_hard_cases.hpp"

using namespace hmfnet;

namespace {

struct ErrorInUlps {
  double cos = 0.0;
  double sin = 0.0;
};

// Error of a double against the long double reference, in units of the last place of doubles in
// the reference's binade, 2^(ilogb(ref) - 52) (taken from the reference itself, so that a value
// just below a power of two is measured in the finer unit of its own binade).
double ulps(double value, long double ref) {
  if (ref == 0.0L) return value == 0.0 ? 0.0 : INFINITY;
  const long double unit = std::ldexp(1.0L, std::ilogb(ref) - 52);
  return static_cast<double>(std::abs(static_cast<long double>(value) - ref) / unit);
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

// The references: glibc's x86-64 cosl/sinl reduce the argument in software with enough bits of
// pi (__ieee754_rem_pio2l) and evaluate in the 64-bit x87 format, so they are accurate to far
// below one double ulp (2^-11 of it) at every angle here. The bound, 1 ulp: Cephes' polynomials
// are accurate to ~0.5 ulp on [-pi/4, pi/4], the result is rounded once more, and the reduced
// angle carries its own rounding (r + r_lo); measured on the development machine 0.72-0.77 ulp
// on random angles (1.45-1.6 ulp before r_lo was carried) and below 0.5 ulp at the doubles
// nearest multiples of pi/2 (up to ~3900 ulp before the rounding of the small products was).
TEST_CASE("sincos: error against long double within 1 ulp up to 10^7", "[sincos]") {
  for (const double half_width : {0.78, 3.2, 100.0, 1e4, 1e7}) {
    const ErrorInUlps e = largest_error(uniform_angles(half_width, 200000, 7));
    INFO("range +-" << half_width << ": cos " << e.cos << " ulp, sin " << e.sin << " ulp");
    CHECK(e.cos <= 1.0);
    CHECK(e.sin <= 1.0);
  }
}

TEST_CASE("sincos: within 1 ulp at the doubles nearest multiples of pi/2", "[sincos]") {
  // tests/support/sincos_hard_cases.hpp: the doubles nearest k pi/2 up to |x| ~ 10^7.
  const std::vector<double> x = test::sincos_hard_angles();
  const ErrorInUlps e = largest_error(x);
  INFO(x.size() << " angles: cos " << e.cos << " ulp, sin " << e.sin << " ulp");
  CHECK(e.cos <= 1.0);
  CHECK(e.sin <= 1.0);
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
  // The doubles nearest pi/2 and pi: cos(pi/2 rounded) = 6.12e-17 and sin(pi rounded) =
  // 1.22e-16 are the roundings of pi itself, which the four-part reduction must keep to full
  // precision (the same 1 ulp against cosl/sinl as everywhere, see above).
  CHECK(ulps(cs[4 * 2], cosl(static_cast<long double>(M_PI / 2))) <= 1.0);
  CHECK(cs[4 * 2 + 1] == 1.0);
  CHECK(cs[5 * 2] == -1.0);
  CHECK(ulps(cs[5 * 2 + 1], sinl(static_cast<long double>(M_PI))) <= 1.0);
  CHECK(cs[6 * 2 + 1] == -1.0);
}

TEST_CASE("sincos: beyond the reduced range and non-finite angles take the C library's values",
          "[sincos]") {
  const std::vector<double> x = {
      k_reduced_range, std::nextafter(k_reduced_range, INFINITY), -1e8, 1e300,
      INFINITY,        std::numeric_limits<double>::quiet_NaN(),  0.5};
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
  CHECK(ulps(cs[12], cosl(0.5L)) <= 1.0);  // the angle after them is unharmed (1 ulp: above)
}

TEST_CASE("sincos: an angle's bits do not depend on its place, the threads or the instruction set",
          "[sincos]") {
  const std::vector<double> x = uniform_angles(50.0, 4099, 11);  // not a multiple of any width
  std::vector<double> whole(2 * x.size());
  sincos_interleaved(x.data(), x.size(), whole.data());
  // Every angle alone (a tail of one) and in arrays starting at every offset below 16 (the
  // AVX-512 version's 16 lanes: every tail length).
  for (std::size_t k = 0; k < x.size(); k += 37) {
    double one[2];
    sincos_interleaved(&x[k], 1, one);
    REQUIRE(one[0] == whole[2 * k]);
    REQUIRE(one[1] == whole[2 * k + 1]);
  }
  for (std::size_t offset = 1; offset < 16; ++offset) {
    std::vector<double> part(2 * (x.size() - offset));
    sincos_interleaved(x.data() + offset, x.size() - offset, part.data());
    REQUIRE(std::equal(part.begin(), part.end(),
                       whole.begin() + static_cast<std::ptrdiff_t>(2 * offset)));
  }
  // Every version this CPU runs (the x86-64 baseline; AVX2 and AVX-512 where it has them) gives
  // the bits of the one chosen, in the vector body, in a padded tail and beyond the reduced range.
  const std::vector<double> wide = uniform_angles(1.2e7, 100003, 13);  // some beyond 10^7
  std::vector<double> wide_chosen(2 * wide.size());
  sincos_interleaved(wide.data(), wide.size(), wide_chosen.data());
  for (const SincosIsa isa : {SincosIsa::baseline, SincosIsa::avx2, SincosIsa::avx512}) {
    if (!sincos_isa_available(isa)) {
      WARN(sincos_isa_name(isa) << " not on this CPU: not compared");
      continue;
    }
    INFO(sincos_isa_name(isa) << " against " << sincos_isa_name(sincos_isa()));
    std::vector<double> version(2 * x.size());
    sincos_interleaved_isa(isa, x.data(), x.size(), version.data());
    REQUIRE(test::bit_difference(version, whole) == "");
    std::vector<double> wide_version(2 * wide.size());
    sincos_interleaved_isa(isa, wide.data(), wide.size(), wide_version.data());
    REQUIRE(std::memcmp(wide_version.data(), wide_chosen.data(),
                        wide_chosen.size() * sizeof(double)) == 0);
  }
  // In a team of two threads (blocks shared out) the same bits.
  const ThreadCountScope two(2);
  std::vector<double> team(2 * x.size(), 0.0);
  in_team([&] { sincos_interleaved_team(x.data(), x.size(), team.data()); });
  CHECK(test::bit_difference(team, whole) == "");
}

TEST_CASE("sincos: pinned bits", "[sincos]") {
  // Printed once from this implementation (commit 67bf11b) and checked against cosl/sinl below: the
  // bits any build of it must give on any x86-64 CPU (no contraction, no reassociation, the same
  // four-part reduction). A compiler or flag that changes the arithmetic shows here; a deliberate
  // change of the algorithm re-pins them.
  const std::vector<double> x = {0.5, 1.0, -2.0, 3.0, 10.0, -100.0, 12345.678, 9436423.844736237};
  const std::vector<std::uint64_t> pinned = {
      0x3fec1528065b7d50ULL, 0x3fdeaee8744b05f0ULL, 0x3fe14a280fb5068cULL, 0x3feaed548f090ceeULL,
      0xbfdaa22657537205ULL, 0xbfed18f6ead1b446ULL, 0xbfefae04be85e5d2ULL, 0x3fc210386db6d55bULL,
      0xbfead9ac890c6b1fULL, 0xbfe1689ef5f34f52ULL, 0x3feb981dbf665fdfULL, 0x3fe03425b78c4db8ULL,
      0x3fe6b94c3bbe24b8ULL, 0xbfe687d5890974a5ULL, 0xbff0000000000000ULL, 0x3d140c1bc3c6f0eeULL};
  std::vector<double> cs(2 * x.size());
  sincos_interleaved(x.data(), x.size(), cs.data());
  for (std::size_t k = 0; k < cs.size(); ++k) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &cs[k], sizeof bits);
    INFO("angle " << x[k / 2] << (k % 2 == 0 ? " cos" : " sin"));
    CHECK(bits == pinned[k]);
    const auto xl = static_cast<long double>(x[k / 2]);
    CHECK(ulps(cs[k], k % 2 == 0 ? cosl(xl) : sinl(xl)) <= 1.0);  // 1 ulp: see above
  }
}
