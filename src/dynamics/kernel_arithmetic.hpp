#pragma once
// The per-element arithmetic of a force evaluation and a step, written once for the host and a
// CUDA device: the [cos, sin] of an angle (sincos.hpp), the leap-frog kick and drift
// (kick_drift_lanes.cpp, which integrator.cpp's passes run) and the sum over one CSR row of the
// neighbours' [cos, sin] (network_force.cpp: rows_kernel, rows_kernel_single; wide_rows.cpp),
// with g_n and the observable terms of coupling_force.hpp. The CPU kernels and a device backend
// compute the same IEEE operations in the same order, so a device reproduces the CPU's bits;
// tests/dynamics/test_kernel_arithmetic.cpp checks these functions against the CPU kernels bit
// for bit, and the gpu test label (tests/gpu) checks the device against these functions.
//
// No fused multiply-add may be formed anywhere here. The CPU code is compiled for the x86-64
// baseline, which has none, and sincos.cpp and the sparse row loops (network_force.cpp,
// segment_runs.cpp, wide_rows.cpp, whose AVX-512 and AVX2 versions have FMA) also with
// -ffp-contract=off (a build adding an -march with FMA would let GCC contract integrator.cpp,
// and the CPU would then leave these bits). nvcc contracts a * b + c into an FMA by default: every
// CUDA file that includes this header is compiled with --fmad=false (HMFNET_CUDA_OPTIONS,
// cmake/HmfnetCuda.cmake, on the hmfnet_cuda target). nvcc then emits mul.rn and add.rn, whose
// explicit rounding forbids ptxas and the driver's PTX JIT to fuse them (PTX ISA, "add", "mul");
// checked on the PTX of dynamics/cuda/device_arithmetic_check.cu: no fma.rn.f64 from these
// functions, 17 from CUDA's own sincos (the path beyond k_reduced_range), against 33 with nvcc's
// default. The flag and not __dmul_rn / __dadd_rn, because the sincos below is one template
// shared with sincos.cpp's vector lanes, whose operators are the arithmetic. nvcc has no macro that
// reveals --fmad, so the gpu test is what catches a CUDA file compiled without it.
#include <cmath>  // ::sincos: glibc's (a GNU extension) on the host, CUDA's on the device
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "dynamics/sincos.hpp"

#if defined(__CUDACC__)
#define HMFNET_HD __host__ __device__
#define HMFNET_HD_INLINE __host__ __device__ __forceinline__
#else
#define HMFNET_HD
// Always inlined on the host: sincos.cpp instantiates the sincos template on vectors of lanes
// inside functions compiled for different instruction sets (sincos.cpp: sincos_block).
#define HMFNET_HD_INLINE inline __attribute__((always_inline))
#endif

namespace hmfnet {

namespace sincos_constants {

// pi/2 = k_pio2_0 + k_pio2_1 + k_pio2_2 + k_pio2_3 to ~2^-135; the first three have 26 significant
// bits, so q kPio2_i is exact for |q| < 2^27 (computed with mpmath at 300 bits). Separate scalars
// rather than an array: a constexpr array cannot be indexed in CUDA device code.
constexpr double k_pio2_0 = 0x1.921fb50000000p+0;
constexpr double k_pio2_1 = 0x1.110b460000000p-26;
constexpr double k_pio2_2 = 0x1.1a62630000000p-54;
constexpr double k_pio2_3 = 0x1.8a2e03707344ap-81;
constexpr double k_two_over_pi = 0x1.45f306dc9c883p-1;
// Adding and subtracting 1.5 2^52 rounds a double below 2^51 to the nearest integer (ties to
// even), and the sum's low mantissa bits then hold that integer in two's complement.
constexpr double k_round_shift = 0x1.8p52;
constexpr std::uint64_t k_abs_mask = 0x7fffffffffffffffULL;
constexpr std::uint64_t k_sign_bit = 0x8000000000000000ULL;
// Minimax polynomials on [-pi/4, pi/4] (Cephes' sin.c coefficients):
// sin r = r + r^3 S(r^2), cos r = 1 - r^2 / 2 + r^4 C(r^2), highest degree first.
constexpr double k_sin0 = 1.58962301576546568060e-10;
constexpr double k_sin1 = -2.50507477628578072866e-8;
constexpr double k_sin2 = 2.75573136213857245213e-6;
constexpr double k_sin3 = -1.98412698295895385996e-4;
constexpr double k_sin4 = 8.33333333332211858878e-3;
constexpr double k_sin5 = -1.66666666666666307295e-1;
constexpr double k_cos0 = -1.13585365213876817300e-11;
constexpr double k_cos1 = 2.08757008419747316778e-9;
constexpr double k_cos2 = -2.75573141792967388112e-7;
constexpr double k_cos3 = 2.48015872888517045348e-5;
constexpr double k_cos4 = -1.38888888888730564116e-3;
constexpr double k_cos5 = 4.16666666666665929218e-2;

}  // namespace sincos_constants

/// One double as a lane of the sincos template below (sincos.cpp has the vector ones): Real and
/// Bits, a value's bits and back, the masks where a <= b and where a is odd, and a selection.
struct ScalarLane {
  using Real = double;
  using Bits = std::uint64_t;
  using Mask = std::uint64_t;  // all ones (true) or zero (false)
  HMFNET_HD_INLINE static Bits bits(Real x) {
#if defined(__CUDA_ARCH__)
    return static_cast<Bits>(__double_as_longlong(x));
#else
    Bits b;
    std::memcpy(&b, &x, sizeof b);
    return b;
#endif
  }
  HMFNET_HD_INLINE static Real real(Bits b) {
#if defined(__CUDA_ARCH__)
    return __longlong_as_double(static_cast<long long>(b));
#else
    Real x;
    std::memcpy(&x, &b, sizeof x);
    return x;
#endif
  }
  HMFNET_HD_INLINE static Mask at_most(Bits a, std::uint64_t b) {
    return Mask{0} - static_cast<Mask>(a <= b);
  }
  HMFNET_HD_INLINE static Mask odd(Bits a) { return Mask{0} - (a & 1U); }
  /// `a` where `m` is true, else `b`.
  HMFNET_HD_INLINE static Bits select(Mask m, Bits a, Bits b) { return (a & m) | (b & ~m); }
};

/// cos and sin of each lane's angle (Lanes: ScalarLane, or sincos.cpp's vectors): Cody-Waite
/// reduction by pi/2 in four parts with the rounding of the reduced angle carried, then Cephes'
/// polynomials; below 1 ulp up to |x| = k_reduced_range (tests/dynamics/test_sincos.cpp). A lane
/// whose |x| exceeds k_reduced_range (or is not finite) computes values of no meaning (NaN for a
/// non-finite angle and for huge ones, whose reduced angle's square overflows); the caller
/// overwrites them (sincos_block in sincos.cpp, the rank-one pass's outside_range in
/// rank_one_fused.cpp, sincos_one below).
template <typename Lanes>
HMFNET_HD_INLINE void sincos_lanes(const typename Lanes::Real& angle, typename Lanes::Real& c,
                                   typename Lanes::Real& s) {
  using namespace sincos_constants;
  using Real = typename Lanes::Real;
  using Bits = typename Lanes::Bits;
  // Every lane reduces its own angle, one beyond the range too: its arithmetic then raises IEEE
  // flags at most (hmfnet enables no trap; a host program that enables FE_INVALID or FE_OVERFLOW
  // traps gets them for infinite and huge angles here, where glibc's sincos traps on infinities
  // only), and its values are overwritten. Selecting 0 for such lanes first put four integer
  // operations at the head of every lane's chain of dependent operations, which bounds this
  // code's rate (llvm-mca -mcpu=znver3: 45 cycles a 4-lane vector against a throughput bound of
  // 14.5): the AVX2 version ran ~1.1x faster without them on the AMD EPYC family 25 model 1, the
  // same bits (docs/performance.md, "The sincos's chain").
  const Real& x = angle;
  const Real t = x * k_two_over_pi + k_round_shift;
  const Real q = t - k_round_shift;
  const Bits j = Lanes::bits(t);  // q mod 4 = j & 3
  // r + r_lo = x - q pi/2 to ~2^-105 |x|: x - q k_pio2_0 and the next subtraction are exact;
  // b = q k_pio2_2 + q k_pio2_3 with its rounding error eb (Fast2Sum, |p2| >= |p3|); r = a - b
  // rounded once, and r_lo the rounding of r (Fast2Sum: exact because a is a multiple of a unit
  // at least ulp(b), also where |a| < |b|) less eb. Without r_lo the rounding of r costs 1 ulp
  // where |sin| or |cos| is just below 1/2 and |r| just above (measured 1.5 ulp); without eb,
  // angles within ~10^-10 of a multiple of pi/2 (|r| tiny) lose up to thousands of ulp.
  const Real a = (x - q * k_pio2_0) - q * k_pio2_1;
  const Real p2 = q * k_pio2_2;
  const Real p3 = q * k_pio2_3;
  const Real b = p2 + p3;
  const Real eb = p3 - (b - p2);
  const Real r = a - b;
  const Real r_lo = ((a - r) - b) - eb;
  const Real z = r * r;
  const Real ps = ((((k_sin0 * z + k_sin1) * z + k_sin2) * z + k_sin3) * z + k_sin4) * z + k_sin5;
  const Real pc = ((((k_cos0 * z + k_cos1) * z + k_cos2) * z + k_cos3) * z + k_cos4) * z + k_cos5;
  // sin(r + r_lo) = sin r + r_lo cos r, cos(r + r_lo) = cos r - r_lo sin r, to first order in
  // r_lo (|r_lo| <= 2^-54 |r|); cos r = w + ((1 - w) - z / 2 + z^2 C) with w = 1 - z / 2: the
  // parenthesis recovers the rounding of w (fdlibm's kernel_cos).
  const Real half_z = 0.5 * z;
  const Real sin_r = r + (r * z * ps + r_lo * (1.0 - half_z));
  const Real w = 1.0 - half_z;
  const Real cos_r = w + (((1.0 - w) - half_z) + (z * z * pc - r * r_lo));
  // Quadrant j: (cos, sin)(x) = (cos r, sin r), (-sin r, cos r), (-cos r, -sin r), (sin r,
  // -cos r) for j = 0, 1, 2, 3: swap when j is odd, then flip the sign bits.
  const typename Lanes::Mask swap = Lanes::odd(j);
  const Bits sin_bits = Lanes::select(swap, Lanes::bits(cos_r), Lanes::bits(sin_r));
  const Bits cos_bits = Lanes::select(swap, Lanes::bits(sin_r), Lanes::bits(cos_r));
  s = Lanes::real(sin_bits ^ ((j << 62) & k_sign_bit));
  c = Lanes::real(cos_bits ^ (((j + 1U) << 62) & k_sign_bit));
}

/// Whether sincos_lanes computes x itself: |x| <= k_reduced_range (false for NaN).
HMFNET_HD_INLINE bool sincos_reduces(double x) {
  return (ScalarLane::bits(x) & sincos_constants::k_abs_mask) <= ScalarLane::bits(k_reduced_range);
}

/// c = cos x, s = sin x with the bits of sincos_interleaved for |x| <= k_reduced_range (the same
/// template). Beyond that, and for non-finite x, the C library's sincos: on the host glibc's, as
/// sincos_interleaved calls it (the same bits again); on a device CUDA's, which is not glibc's:
/// within CUDA's documented 2 ulp for sin and cos instead of the CPU's bits (NaN for inf and NaN,
/// as on the CPU). Unwrapped phases reach 10^7 after ~1.7 10^6 time units at omega = 6.
HMFNET_HD_INLINE void sincos_one(double x, double& c, double& s) {
  sincos_lanes<ScalarLane>(x, c, s);
  if (!sincos_reduces(x)) ::sincos(x, &s, &c);
}

/// The kick p += c K g of one rotor and replica, as integrator.cpp's kick and kick_drift form it:
/// (c K) g rounded, then added to p (c is the step fraction times h, K the replica's coupling).
HMFNET_HD inline double kicked_momentum(double p, double c, double coupling, double g) {
  return p + c * coupling * g;
}

/// The drift theta += c p of one rotor and replica (integrator.cpp: kick_drift, with the p the
/// kick of the same pass has just updated).
HMFNET_HD inline double drifted_angle(double theta, double c, double p) { return theta + c * p; }

/// y_n = sum_m A_nm e^{i theta_m} of one row and replica (eq:localOrderParam), as [Re, Im].
struct LocalField {
  double re;
  double im;
};

/// y_n of replica `lane` for the CSR row [begin, end) summed exactly as the sparse force's row
/// loops (network_force.cpp, wide_rows.cpp) sum it, whatever their replica count: four partial sums
/// in T, partial j over the entries begin + j, begin + j + 4, ... of the first 4 floor(d / 4), the
/// last d mod 4 added to partial 0, each entry adding w [cos, sin] (w = 1 without weights),
/// combined as (s0 + s1) + (s2 + s3) and then widened to double. column_cs holds the column space x
/// replicas x [cos, sin] in T, weights the row's entries in T (nullptr: a 0/1 network). T is double
/// (float64) or float (ForcePrecision::float32).
template <typename T, typename Offset, typename Index>
HMFNET_HD inline LocalField row_field(Offset begin, Offset end, const Index* cols, const T* weights,
                                      const T* column_cs, int replicas, int lane) {
  T cos_part[4] = {T(0), T(0), T(0), T(0)};
  T sin_part[4] = {T(0), T(0), T(0), T(0)};
  const auto record = [&](Offset k) {
    return column_cs + 2 * static_cast<std::ptrdiff_t>(cols[k]) * replicas + 2 * lane;
  };
  const Offset full = begin + (end - begin) / 4 * 4;
  for (Offset k = begin; k < full; k += 4) {
    for (int j = 0; j < 4; ++j) {
      const T* q = record(k + j);
      const T w = weights != nullptr ? weights[k + j] : T(1);
      cos_part[j] += w * q[0];
      sin_part[j] += w * q[1];
    }
  }
  for (Offset k = full; k < end; ++k) {
    const T* q = record(k);
    const T w = weights != nullptr ? weights[k] : T(1);
    cos_part[0] += w * q[0];
    sin_part[0] += w * q[1];
  }
  return {static_cast<double>((cos_part[0] + cos_part[1]) + (cos_part[2] + cos_part[3])),
          static_cast<double>((sin_part[0] + sin_part[1]) + (sin_part[2] + sin_part[3]))};
}

/// g_n = (cos theta_n Im y_n - sin theta_n Re y_n) / N (coupling_force.hpp), with c, s the row's
/// own [cos, sin] and inverse_n = 1 / N.
HMFNET_HD inline double coupling_force(double inverse_n, double c, double s, LocalField y) {
  return inverse_n * (c * y.im - s * y.re);
}

/// y_n = a_n Z - [no diagonal] a_n^2 e^{i theta_n} of a rank-one coupling A = a a^T
/// (rank_one_force.hpp), with Z = sum_m a_m e^{i theta_m} and c, s the row's own [cos, sin].
HMFNET_HD inline LocalField rank_one_field(double a, double z_re, double z_im, double c, double s,
                                           bool diagonal) {
  LocalField y{a * z_re, a * z_im};
  if (!diagonal) {
    y.re -= a * a * c;
    y.im -= a * a * s;
  }
  return y;
}

/// |y_n|, the row's term of sum_n |y_n| (the order parameter R).
HMFNET_HD inline double order_term(LocalField y) { return std::sqrt(y.re * y.re + y.im * y.im); }

/// Re(e^{-i theta_n} y_n), the row's term of the potential energy's sum.
HMFNET_HD inline double coupling_term(double c, double s, LocalField y) {
  return c * y.re + s * y.im;
}

}  // namespace hmfnet
