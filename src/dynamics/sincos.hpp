#pragma once
// The cosine and sine of every rotor's angle, the one transcendental step of a force evaluation:
// eq:localOrderParam sums e^{i theta_m} over the neighbours, and eq:dMomentum_dT is the product
// of that sum with e^{-i theta_n}.
//
// glibc's scalar sincos costs ~15-24 ns per angle on the development machine: ~16% of a leap-frog
// step on ER N = 10^4, degree 100, more than the gathers at degree <= 20, and ~70% of the
// rank-one force on the complete graph. This one computes four or sixteen angles at once with no
// branch (GCC/Clang vector types: two SSE2 registers on the x86-64 baseline, one AVX2 register, or
// two AVX-512 registers of eight lanes side by side, chosen at run time): Cody-Waite reduction by
// pi/2 in four parts with the rounding of the reduced angle carried, then minimax polynomials on
// [-pi/4, pi/4]. Its error is below 1 ulp up to |x| = 10^7, also at the doubles nearest multiples
// of pi/2 (tests/dynamics/test_sincos.cpp); angles beyond k_reduced_range, and non-finite ones, go
// to the C library. The per-lane arithmetic is kernel_arithmetic.hpp's sincos_lanes, one template
// that these vectors, the scalar sincos_one and a CUDA device instantiate alike.
// bench/ensemble_table.sh prints its time per angle beside glibc's; bench/sincos_table.sh each
// version's beside SLEEF's and numpy's (docs/performance.md "sincos").
//
// Reproducibility: for |x| <= k_reduced_range an angle's [cos, sin] depends on its value only,
// never on where it sits in the array (vector body or padded tail), on the thread that computes
// it or on the CPU: the same IEEE additions and multiplications in the same order in every lane
// and in every instruction set, compiled without floating-point contraction
// (src/CMakeLists.txt); the test pins some of its bits. So runs stay bit-identical across thread
// and rank counts, as the force kernels promise. Beyond that range (the angles are not wrapped,
// so a long run's can grow) the C library's sincos decides, and glibc picks its own version by
// CPU.
#include <cstddef>

namespace hmfnet {

// |x| up to which the four-part reduction keeps the reduced angle exact to ~2^-105 |x|: the
// quadrant count q stays below 2^26, so q times each 26-bit part of pi/2 is exact.
inline constexpr double k_reduced_range = 1e7;

/// The instruction sets sincos_interleaved has a version for, narrowest first: the x86-64
/// baseline (SSE2, 4 lanes in two registers), AVX2 (4 lanes in one) and AVX-512F/DQ (16 lanes in
/// two, side by side). All give the same bits (see above).
enum class SincosIsa { baseline, avx2, avx512 };

/// The version sincos_interleaved runs: the widest this CPU has, or, where the environment
/// variable HMFNET_SINCOS_ISA names a narrower one (baseline, avx2), the widest up to that, so
/// that a whole run can be repeated in another instruction set (`HMFNET_SINCOS_ISA=baseline
/// ctest -L regression`). Chosen on first use.
SincosIsa sincos_isa();

/// Whether this CPU runs `isa` (the baseline: always).
bool sincos_isa_available(SincosIsa isa);

/// `isa` where this CPU runs it, else the widest set below it that it runs.
SincosIsa sincos_isa_up_to(SincosIsa isa);

/// "baseline", "avx2" or "avx512".
const char* sincos_isa_name(SincosIsa isa);

/// cs[2k] = cos(x[k]), cs[2k + 1] = sin(x[k]) for k < n, in sincos_isa().
void sincos_interleaved(const double* x, std::size_t n, double* cs);

/// The same in `isa`, or the widest set below it that this CPU runs: for the tests and
/// benchmarks that compare the versions.
void sincos_interleaved_isa(SincosIsa isa, const double* x, std::size_t n, double* cs);

/// The same in the x86-64 baseline instructions whatever the CPU (sincos_interleaved_isa with
/// SincosIsa::baseline).
void sincos_interleaved_baseline(const double* x, std::size_t n, double* cs);

// The same angles over the threads of the current team (an orphaned `omp for` in blocks; outside
// a parallel region one thread does all): every thread must call it.
void sincos_interleaved_team(const double* x, std::size_t n, double* cs);

}  // namespace hmfnet
