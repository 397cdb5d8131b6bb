#pragma once
// What the sparse kernel's row loops share (network_force.cpp, wide_rows.cpp): the CSR and the
// gathered table they read, the outputs they write, and how a row's four partial sums become
// them (eq:dMomentum_dT_orderParam: g_n = (1/N) Im(e^{-i theta_n} y_n), y_n = sum_m A_nm
// e^{i theta_m}, and the order-parameter terms |y_n| and Re(e^{-i theta_n} y_n)).
#include <cmath>
#include <cstddef>

#include "network/network.hpp"

namespace hmfnet {

/// T: the storage of the gathered [cos, sin] table and the weights, and the type of the per-row
/// accumulation (float32 halves the bytes the gather touches); the owned rows' cos and sin and
/// the outputs stay double. I: the column indices' type, std::uint16_t where every column fits
/// in 16 bits (narrow_columns.hpp), else NodeIndex.
template <typename T, typename I = NodeIndex>
struct RowKernelArgs {
  const EdgeOffset* row_ptr;
  const I* cols;
  const T* weights;  // nullptr: 0/1 network
  const T* column_cs;
  const double* owned_cs;
  double inverse_n;
  double* g;
  double* y;
  // rows x replicas x [|y_n|, Re(e^{-i theta_n} y_n)]; nullptr: not formed, for an evaluation
  // whose sums no record reads (ForceOutputs::force_only), which then skips a square root, four
  // products, two additions and two stores a row and replica: at ER N = 10^4, degree 100, float32
  // with 8 replicas, the finish took 11-15% of the row loop's samples (docs/performance.md,
  // "16-bit column indices and the terms only where the sums are read").
  double* terms;
};

/// The partials one walk of a row forms in network_force.cpp's baseline rows_kernel, for
/// records of `record_bytes`: as many as keep their accumulators within 128 bytes (8 SSE
/// registers, leaving the rest for loads and addresses).
constexpr int baseline_walk_partials(std::size_t record_bytes) {
  return record_bytes <= 32 ? 4 : record_bytes <= 64 ? 2 : 1;
}

/// Row r's outputs for replicas [first, first + count) of the run's nb from their four partial
/// sums (partial j of the group's value v at p[j * stride + v]), combined as (s0 + s1) + (s2 +
/// s3) in T: every row loop ends here, so they agree bit for bit whenever their partials do.
template <typename T, typename I>
inline void finish_replicas(const RowKernelArgs<T, I>& a, NodeIndex r, const T* p,
                            std::size_t stride, int nb, int first, int count) {
  const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(r) * nb + first;
  const double* o = a.owned_cs + 2 * base;
  for (int b = 0; b < count; ++b) {
    const std::size_t re = 2 * static_cast<std::size_t>(b), im = re + 1;
    const double yc = (p[re] + p[stride + re]) + (p[2 * stride + re] + p[3 * stride + re]);
    const double ys =
        static_cast<double>((p[im] + p[stride + im]) + (p[2 * stride + im] + p[3 * stride + im]));
    const double c = o[re], s = o[im];
    a.g[base + b] = a.inverse_n * (c * ys - s * yc);
    a.y[2 * (base + b)] = yc;
    a.y[2 * (base + b) + 1] = ys;
    if (a.terms == nullptr) continue;
    a.terms[2 * (base + b)] = std::sqrt(yc * yc + ys * ys);
    a.terms[2 * (base + b) + 1] = c * yc + s * ys;
  }
}

/// Row r's outputs for all nb replicas (finish_replicas).
template <typename T, typename I>
inline void finish_row(const RowKernelArgs<T, I>& a, NodeIndex r, const T* p, std::size_t stride,
                       int nb) {
  finish_replicas(a, r, p, stride, nb, 0, nb);
}

}  // namespace hmfnet
