#include "dynamics/sincos.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>

#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/vector_lanes.hpp"

namespace hmfnet {

namespace {

using simd::Lanes4;
using simd::Lanes8Twice;
using simd::store_interleaved;

template <typename Lanes>
HMFNET_INLINE void sincos_block(const double* x, std::size_t n, double* cs) {
  using Real = typename Lanes::Real;
  constexpr std::size_t lanes = Lanes::k_lanes;
  const std::uint64_t range_bits = ScalarLane::bits(k_reduced_range);
  // All ones in a lane while every angle it saw was within the reduced range (sincos_reduces'
  // test, lane by lane): the C library's pass below runs only when one was not.
  typename Lanes::Mask inside = ~typename Lanes::Mask{};
  Real c;
  Real s;
  const std::size_t body = n - n % lanes;
  for (std::size_t k = 0; k < body; k += lanes) {
    Real v;
    std::memcpy(&v, x + k, sizeof v);
    sincos_lanes<Lanes>(v, c, s);
    inside &= Lanes::at_most(Lanes::bits(v) & sincos_constants::k_abs_mask, range_bits);
    store_interleaved(c, s, cs + 2 * k);
  }
  if (body < n) {
    Real v = Real{};
    std::memcpy(&v, x + body, (n - body) * sizeof(double));
    sincos_lanes<Lanes>(v, c, s);
    inside &= Lanes::at_most(Lanes::bits(v) & sincos_constants::k_abs_mask, range_bits);
    double tail[2 * lanes];
    store_interleaved(c, s, tail);
    std::memcpy(cs + 2 * body, tail, 2 * (n - body) * sizeof(double));
  }
  std::uint64_t all_inside = ~std::uint64_t{0};
  for (std::size_t l = 0; l < lanes; ++l) all_inside &= static_cast<std::uint64_t>(inside[l]);
  if (all_inside != 0) return;
  // The rare angles beyond the reduced range, and non-finite ones, from the C library.
  for (std::size_t k = 0; k < n; ++k) {
    if (!sincos_reduces(x[k])) ::sincos(x[k], &cs[2 * k + 1], &cs[2 * k]);
  }
}

void sincos_block_baseline(const double* x, std::size_t n, double* cs) {
  sincos_block<Lanes4>(x, n, cs);
}

// The same code for AVX2 (4 lanes in one register) and AVX-512 (16 lanes in two registers side by
// side, simd::TwiceLanes: two chains in flight, 1.16-1.20x one register on the AMD EPYC family 25
// model 17, where two AVX2 registers ran 0.72x one (3.8-3.9 against 2.7-2.8 ns) for want of
// registers and four AVX-512 ones 1.08-1.13x; docs/performance.md, "The AVX-512 sincos in two
// registers"): the same IEEE operations in the same order and no FMA (contraction is off for this
// file, whatever the target brings), so the same bits; tests/dynamics/test_sincos.cpp compares
// every version this CPU runs with the baseline and with sincos_one. GCC and Clang on x86-64 only.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HMFNET_SINCOS_X86 1
__attribute__((target("avx2"))) void sincos_block_avx2(const double* x, std::size_t n, double* cs) {
  sincos_block<Lanes4>(x, n, cs);
}
__attribute__((target("avx512f,avx512dq"))) void sincos_block_avx512(const double* x, std::size_t n,
                                                                     double* cs) {
  sincos_block<Lanes8Twice>(x, n, cs);
}
#endif

bool cpu_runs(SincosIsa isa) {
#ifdef HMFNET_SINCOS_X86
  __builtin_cpu_init();
  switch (isa) {
    case SincosIsa::baseline:
      return true;
    case SincosIsa::avx2:
      return __builtin_cpu_supports("avx2") != 0;
    case SincosIsa::avx512:
      return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512dq") != 0;
  }
  return false;
#else
  return isa == SincosIsa::baseline;
#endif
}

SincosIsa widest_below(SincosIsa isa) {
  for (const SincosIsa candidate : {SincosIsa::avx512, SincosIsa::avx2}) {
    if (candidate <= isa && cpu_runs(candidate)) return candidate;
  }
  return SincosIsa::baseline;
}

// Chosen once, on first use (a namespace-scope initialiser could run before the runtime's own
// CPU detection; __builtin_cpu_init makes that order irrelevant).
SincosIsa chosen_isa() {
  static const SincosIsa isa = [] {
    const char* asked = std::getenv("HMFNET_SINCOS_ISA");
    const std::string name = asked != nullptr ? asked : "";
    SincosIsa limit = SincosIsa::avx512;
    if (name == "baseline") limit = SincosIsa::baseline;
    if (name == "avx2") limit = SincosIsa::avx2;
    return widest_below(limit);
  }();
  return isa;
}

// sincos_block in `isa`, which this CPU runs.
void run(SincosIsa isa, const double* x, std::size_t n, double* cs) {
#ifdef HMFNET_SINCOS_X86
  if (isa == SincosIsa::avx512) {
    sincos_block_avx512(x, n, cs);
    return;
  }
  if (isa == SincosIsa::avx2) {
    sincos_block_avx2(x, n, cs);
    return;
  }
#endif
  (void)isa;
  sincos_block_baseline(x, n, cs);
}

}  // namespace

SincosIsa sincos_isa() { return chosen_isa(); }

bool sincos_isa_available(SincosIsa isa) { return cpu_runs(isa); }

SincosIsa sincos_isa_up_to(SincosIsa isa) { return widest_below(isa); }

const char* sincos_isa_name(SincosIsa isa) {
  switch (isa) {
    case SincosIsa::baseline:
      return "baseline";
    case SincosIsa::avx2:
      return "avx2";
    case SincosIsa::avx512:
      return "avx512";
  }
  return "unknown";
}

void sincos_interleaved_isa(SincosIsa isa, const double* x, std::size_t n, double* cs) {
  run(widest_below(isa), x, n, cs);
}

void sincos_interleaved(const double* x, std::size_t n, double* cs) { run(chosen_isa(), x, n, cs); }

void sincos_interleaved_baseline(const double* x, std::size_t n, double* cs) {
  sincos_block_baseline(x, n, cs);
}

void sincos_interleaved_team(const double* x, std::size_t n, double* cs) {
  // Blocks of 512 angles (8 KiB of output): long enough for the vector loop, short enough to
  // share out.
  constexpr std::size_t k_block = 512;
  const std::size_t blocks = (n + k_block - 1) / k_block;
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < blocks; ++i) {
    const std::size_t begin = i * k_block;
    const std::size_t count = begin + k_block <= n ? k_block : n - begin;
    sincos_interleaved(x + begin, count, cs + 2 * begin);
  }
}

}  // namespace hmfnet
