#include "dynamics/rank_one_force.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include <immintrin.h>
#define HMFNET_RANK_ONE_X86 1
#endif

#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/ordered_sum.hpp"
#include "dynamics/rank_one_fused.hpp"
#include "dynamics/sincos.hpp"
#include "dynamics/team.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

bool close(double x, double y) {
  return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
}

}  // namespace

RankOneStructure complete_graph_structure(const CompleteGraph& graph) {
  return {std::vector<double>(static_cast<std::size_t>(graph.n), 1.0), graph.self_loops};
}

std::optional<RankOneStructure> detect_rank_one(const DistributedNetwork& net) {
  const NodeIndex n = net.global_size();
  if (n < 3 || !net.stores_rows()) return std::nullopt;
  // Every decision up to the weights uses global counts only, so all ranks take the same path.
  const bool diagonal = net.global_self_loops() == n;
  if (!diagonal && (net.global_self_loops() != 0 || net.weighted())) return std::nullopt;
  const EdgeOffset full = diagonal ? n : n - 1;
  // A row holds at most `full` entries (distinct columns; no diagonal when there are no
  // self-loops), so n full rows are exactly nnz = n full; then every rank's column space is all
  // n nodes and a local column index is the global one.
  if (net.global_nnz() != full * static_cast<EdgeOffset>(n)) return std::nullopt;
  RankOneStructure s;
  s.diagonal = diagonal;
  s.a.assign(static_cast<std::size_t>(n), 1.0);
  if (!net.weighted()) return s;
  const auto& rows = net.local_adjacency();
  const auto own = static_cast<std::size_t>(net.local_size());
  std::vector<double> a_local(own);
  for (std::size_t r = 0; r < own; ++r) {
    const auto i = static_cast<std::size_t>(net.first_row()) + r;
    a_local[r] = std::sqrt(rows.weights[static_cast<std::size_t>(rows.row_ptr[r]) + i]);
  }
  s.a = net.gather(a_local);
  double mismatches = 0.0;
  for (std::size_t r = 0; r < own; ++r) {
    const double ai = a_local[r];
    for (auto k = static_cast<std::size_t>(rows.row_ptr[r]);
         k < static_cast<std::size_t>(rows.row_ptr[r + 1]); ++k) {
      const double expected = ai * s.a[static_cast<std::size_t>(rows.cols[k])];
      if (!close(rows.weights[k], expected)) mismatches += 1.0;
    }
  }
  if (ParallelSession::sum(mismatches) > 0.0) return std::nullopt;
  return s;
}

RankOneForce::RankOneForce(RankOneStructure structure, NodeIndex first_row, NodeIndex rows)
    : m_structure(std::move(structure)),
      m_first_row(first_row),
      m_rows(rows),
      m_inverse_n(1.0 / static_cast<double>(m_structure.a.size())),
      m_unit_a(std::all_of(m_structure.a.begin() + first_row,
                           m_structure.a.begin() + first_row + rows,
                           [](double a) { return a == 1.0; })) {}

void RankOneForce::prepare(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  const auto cells =
      static_cast<std::size_t>(state.rows) * static_cast<std::size_t>(state.replicas);
  const auto w = static_cast<std::size_t>(state.replicas);
  m_cs.resize(2 * cells);
  m_z.resize(2 * w);
  m_z_sums.prepare(static_cast<std::size_t>(state.rows), 2 * state.replicas);
  g.resize(cells);
  m_y.resize(2 * cells);
  m_y_current = false;
  m_term_sums.resize(2 * w);
  m_sums.prepare(static_cast<std::size_t>(state.rows), 2 * state.replicas);
  sums.order.resize(w);
  sums.coupling.resize(w);
}

namespace {

// Replicas summed by one work item: 16 accumulators, on the stack and not in the shared block
// sums (which the compiler must assume the inputs may alias). The lanes are independent sums,
// so how the replicas are grouped changes no bit; groups share a block out between threads when
// there are few blocks (N = 2000 is one block of the ordered sums).
constexpr std::size_t k_group = k_fused_group;

// One work item: rows [r0, r1) of block `block` of the ordered sums, replicas [b0, b0 + nb).
struct Item {
  std::size_t block, r0, r1, b0, nb;
};

std::size_t groups(std::size_t w) { return (w + k_group - 1) / k_group; }

// Work item `i` of the blocks of `sums` x the replica groups.
Item item(const OrderedColumnSums& sums, std::size_t i, std::size_t w) {
  const std::size_t block = i / groups(w), b0 = i % groups(w) * k_group;
  return {block, sums.first_row(block), sums.first_row(block + 1), b0, std::min(k_group, w - b0)};
}

// The calling thread's share of `items` work items, as schedule(static) shares a loop: one
// contiguous range a thread, the first items % threads ranges one item longer.
struct ItemRange {
  std::size_t begin, end;
};

ItemRange thread_items(std::size_t items) {
  const auto threads = static_cast<std::size_t>(omp_get_num_threads());
  const auto t = static_cast<std::size_t>(omp_get_thread_num());
  const std::size_t base = items / threads, extra = items % threads;
  const std::size_t begin = t * base + std::min(t, extra);
  return {begin, begin + base + (t < extra ? 1 : 0)};
}

// kernel(std::integral_constant<std::size_t, NB>) with the item's replica count fixed at compile
// time where it is common (one replica; a whole group), NB = 0 otherwise.
template <typename Kernel>
void with_group_size(const Item& it, std::size_t w, Kernel&& kernel) {
  if (w == 1) {
    kernel(std::integral_constant<std::size_t, 1>{});
  } else if (it.nb == k_group) {
    kernel(std::integral_constant<std::size_t, k_group>{});
  } else {
    kernel(std::integral_constant<std::size_t, 0>{});
  }
}

// The block's share of Z_b = sum_m a_m e^{i theta_m}: out[2b], out[2b + 1] summed from 0 over the
// rows in order, exactly as OrderedColumnSums::sum sums stored a [cos, sin] (same bits).
// NB > 0 fixes the group's replica count at compile time (one replica: two scalars in registers).
template <std::size_t NB>
void z_block(const Item& it, std::size_t w, const double* a, const double* cs, double* out) {
  const std::size_t nb = NB > 0 ? NB : it.nb;
  double acc[2 * (NB > 0 ? NB : k_group)] = {};
  for (std::size_t r = it.r0; r < it.r1; ++r) {
    const double* q = cs + 2 * (r * w + it.b0);
    for (std::size_t j = 0; j < 2 * nb; ++j) acc[j] += a[r] * q[j];
  }
  for (std::size_t j = 0; j < 2 * nb; ++j) out[2 * it.b0 + j] = acc[j];
}

struct FieldArgs {
  const double* a;   // this rank's a_n
  const double* cs;  // rows x replicas x [cos, sin]
  const double* z;   // replicas x [Re Z, Im Z], reduced over ranks
  double inverse_n;
  bool diagonal;
  double* g;
};

// y_n = a_n Z - [no diagonal] a_n^2 e^{i theta_n} of cell k (replica b); the one formula for
// the force below, for local_fields() and for the device (kernel_arithmetic.hpp).
inline void field(const FieldArgs& f, double a, std::size_t k, std::size_t b, double& yc,
                  double& ys) {
  const LocalField y =
      rank_one_field(a, f.z[2 * b], f.z[2 * b + 1], f.cs[2 * k], f.cs[2 * k + 1], f.diagonal);
  yc = y.re;
  ys = y.im;
}

// g_n of cell k (replica b), with (Sums) the cell's terms of the order and coupling sums, |y_n|
// and Re(e^{-i theta_n} y_n), added to acc.
template <bool Sums>
inline void field_one(const FieldArgs& f, double a, std::size_t k, std::size_t b, double* acc) {
  const double c = f.cs[2 * k], s = f.cs[2 * k + 1];
  double yc = 0.0, ys = 0.0;
  field(f, a, k, b, yc, ys);
  f.g[k] = f.inverse_n * (c * ys - s * yc);
  if constexpr (Sums) {
    acc[0] += std::sqrt(yc * yc + ys * ys);
    acc[1] += c * yc + s * ys;
  }
}

#if defined(__SSE2__)
// field_one for the cells k, k + 1 (replicas b, b + 1) in the two lanes of SSE2 registers: every
// lane does field_one's IEEE operations in its order (sqrtpd rounds as sqrtsd), so the same bits,
// with (Sums) the sums' [order, coupling] of the two replicas kept as order[2] and coupling[2].
template <bool Sums>
inline void field_pair(const FieldArgs& f, double a, std::size_t k, std::size_t b, __m128d& order,
                       __m128d& coupling) {
  const __m128d v0 = _mm_loadu_pd(f.cs + 2 * k), v1 = _mm_loadu_pd(f.cs + 2 * k + 2);
  const __m128d c = _mm_unpacklo_pd(v0, v1), s = _mm_unpackhi_pd(v0, v1);
  const __m128d z0 = _mm_loadu_pd(f.z + 2 * b), z1 = _mm_loadu_pd(f.z + 2 * b + 2);
  const __m128d va = _mm_set1_pd(a);
  __m128d yc = _mm_mul_pd(va, _mm_unpacklo_pd(z0, z1));
  __m128d ys = _mm_mul_pd(va, _mm_unpackhi_pd(z0, z1));
  if (!f.diagonal) {
    const __m128d aa = _mm_set1_pd(a * a);
    yc = _mm_sub_pd(yc, _mm_mul_pd(aa, c));
    ys = _mm_sub_pd(ys, _mm_mul_pd(aa, s));
  }
  const __m128d torque = _mm_sub_pd(_mm_mul_pd(c, ys), _mm_mul_pd(s, yc));
  _mm_storeu_pd(f.g + k, _mm_mul_pd(_mm_set1_pd(f.inverse_n), torque));
  if constexpr (Sums) {
    order = _mm_add_pd(order, _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(yc, yc), _mm_mul_pd(ys, ys))));
    coupling = _mm_add_pd(coupling, _mm_add_pd(_mm_mul_pd(c, yc), _mm_mul_pd(s, ys)));
  }
}
#endif

// The fields of one work item and (Sums) its block's share of the order and coupling sums
// (sum |y_n|, sum Re(e^{-i theta_n} y_n)), summed as z_block sums: the same bits as storing the
// terms and summing them with OrderedColumnSums::sum. Without Sums, g alone (the same bits).
template <std::size_t NB, bool Sums>
void field_block(const Item& it, std::size_t w, const FieldArgs& f, double* out) {
  const std::size_t nb = NB > 0 ? NB : it.nb;
  double acc[2 * (NB > 0 ? NB : k_group)] = {};
  std::size_t pairs = 0;
#if defined(__SSE2__)
  pairs = nb / 2;
  __m128d order[k_group / 2], coupling[k_group / 2];
  for (std::size_t p = 0; p < pairs; ++p) order[p] = coupling[p] = _mm_setzero_pd();
#endif
  for (std::size_t r = it.r0; r < it.r1; ++r) {
    const double a = f.a[r];
    const std::size_t k = r * w + it.b0;
#if defined(__SSE2__)
    for (std::size_t p = 0; p < pairs; ++p)
      field_pair<Sums>(f, a, k + 2 * p, it.b0 + 2 * p, order[p], coupling[p]);
#endif
    for (std::size_t j = 2 * pairs; j < nb; ++j)
      field_one<Sums>(f, a, k + j, it.b0 + j, acc + 2 * j);
  }
  if constexpr (!Sums) return;
#if defined(__SSE2__)
  for (std::size_t p = 0; p < pairs; ++p) {
    _mm_storeu_pd(acc + 4 * p, _mm_unpacklo_pd(order[p], coupling[p]));
    _mm_storeu_pd(acc + 4 * p + 2, _mm_unpackhi_pd(order[p], coupling[p]));
  }
#endif
  for (std::size_t j = 0; j < 2 * nb; ++j) out[2 * it.b0 + j] = acc[j];
}

#if defined(HMFNET_RANK_ONE_X86)
// A whole group of 8 replicas in the lanes of one AVX-512 register (chosen at run time with the
// sincos's instruction set, sincos.hpp): every lane does z_block's and field_one's IEEE
// operations in their order (no contraction: -ffp-contract=off; vsqrtpd rounds as sqrtsd), so
// the same bits as the baseline code, 4 times as many cells an instruction as field_pair
// (tests/cli/instruction_sets_agree.sh).
#define HMFNET_AVX512 __attribute__((target("avx512f,avx512dq")))

// [c0 s0 c1 s1 ... c7 s7] at p as (c, s) of 8 lanes.
HMFNET_AVX512 inline void split_pairs(const double* p, __m512d& c, __m512d& s) {
  const __m512d v0 = _mm512_loadu_pd(p), v1 = _mm512_loadu_pd(p + 8);
  c = _mm512_permutex2var_pd(v0, _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), v1);
  s = _mm512_permutex2var_pd(v0, _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15), v1);
}

// (x, y) of 8 lanes stored as [x0 y0 x1 y1 ... x7 y7] at p.
HMFNET_AVX512 inline void store_pairs(double* p, __m512d x, __m512d y) {
  _mm512_storeu_pd(p, _mm512_permutex2var_pd(x, _mm512_setr_epi64(0, 8, 1, 9, 2, 10, 3, 11), y));
  _mm512_storeu_pd(p + 8,
                   _mm512_permutex2var_pd(x, _mm512_setr_epi64(4, 12, 5, 13, 6, 14, 7, 15), y));
}

// z_block for a group of k_group = 8 replicas.
HMFNET_AVX512 void z_block_avx512(const Item& it, std::size_t w, const double* a, const double* cs,
                                  double* out) {
  __m512d acc0 = _mm512_setzero_pd(), acc1 = _mm512_setzero_pd();
  for (std::size_t r = it.r0; r < it.r1; ++r) {
    const double* q = cs + 2 * (r * w + it.b0);
    const __m512d va = _mm512_set1_pd(a[r]);
    acc0 = _mm512_add_pd(acc0, _mm512_mul_pd(va, _mm512_loadu_pd(q)));
    acc1 = _mm512_add_pd(acc1, _mm512_mul_pd(va, _mm512_loadu_pd(q + 8)));
  }
  _mm512_storeu_pd(out + 2 * it.b0, acc0);
  _mm512_storeu_pd(out + 2 * it.b0 + 8, acc1);
}

// field_block for a group of 8 replicas.
template <bool Sums>
HMFNET_AVX512 void field_block_avx512(const Item& it, std::size_t w, const FieldArgs& f,
                                      double* out) {
  __m512d zc, zs;
  split_pairs(f.z + 2 * it.b0, zc, zs);
  const __m512d inverse_n = _mm512_set1_pd(f.inverse_n);
  __m512d order = _mm512_setzero_pd(), coupling = _mm512_setzero_pd();
  for (std::size_t r = it.r0; r < it.r1; ++r) {
    const std::size_t k = r * w + it.b0;
    __m512d c, s;
    split_pairs(f.cs + 2 * k, c, s);
    const double a = f.a[r];
    const __m512d va = _mm512_set1_pd(a);
    __m512d yc = _mm512_mul_pd(va, zc), ys = _mm512_mul_pd(va, zs);
    if (!f.diagonal) {
      const __m512d aa = _mm512_set1_pd(a * a);
      yc = _mm512_sub_pd(yc, _mm512_mul_pd(aa, c));
      ys = _mm512_sub_pd(ys, _mm512_mul_pd(aa, s));
    }
    const __m512d torque = _mm512_sub_pd(_mm512_mul_pd(c, ys), _mm512_mul_pd(s, yc));
    _mm512_storeu_pd(f.g + k, _mm512_mul_pd(inverse_n, torque));
    if constexpr (!Sums) continue;
    // All lanes of the masked form (GCC 12's unmasked one reads an undefined pass-through).
    const __m512d norm2 = _mm512_add_pd(_mm512_mul_pd(yc, yc), _mm512_mul_pd(ys, ys));
    order = _mm512_add_pd(order, _mm512_mask_sqrt_pd(norm2, 0xFF, norm2));
    coupling = _mm512_add_pd(coupling, _mm512_add_pd(_mm512_mul_pd(c, yc), _mm512_mul_pd(s, ys)));
  }
  if constexpr (Sums) store_pairs(out + 2 * it.b0, order, coupling);
}
#undef HMFNET_AVX512

// The same group of 8 replicas in two halves of four AVX2 lanes, where the sincos runs in AVX2
// (the AMD EPYC of docs/performance.md has no AVX-512): the same IEEE operations in every lane,
// the same bits. Without it those machines ran both loops in field_pair's two lanes: K_N N = 2000,
// 16 replicas, 1.52x slower a step than in AVX-512 on the Intel Xeon, of which the sincos
// explains half.
#define HMFNET_AVX2 __attribute__((target("avx2")))

// [c0 s0 c1 s1 c2 s2 c3 s3] at p as (c, s) of 4 lanes in replica order.
HMFNET_AVX2 inline void split_quad(const double* p, __m256d& c, __m256d& s) {
  const __m256d v0 = _mm256_loadu_pd(p), v1 = _mm256_loadu_pd(p + 4);
  // unpack works within 128-bit halves: lanes (0, 2, 1, 3), put back in order.
  c = _mm256_permute4x64_pd(_mm256_unpacklo_pd(v0, v1), 0xD8);
  s = _mm256_permute4x64_pd(_mm256_unpackhi_pd(v0, v1), 0xD8);
}

// z_block for a group of k_group = 8 replicas: 16 values in four registers.
HMFNET_AVX2 void z_block_avx2(const Item& it, std::size_t w, const double* a, const double* cs,
                              double* out) {
  __m256d acc[4] = {_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd(),
                    _mm256_setzero_pd()};
  for (std::size_t r = it.r0; r < it.r1; ++r) {
    const double* q = cs + 2 * (r * w + it.b0);
    const __m256d va = _mm256_set1_pd(a[r]);
    for (std::size_t j = 0; j < 4; ++j)
      acc[j] = _mm256_add_pd(acc[j], _mm256_mul_pd(va, _mm256_loadu_pd(q + 4 * j)));
  }
  for (std::size_t j = 0; j < 4; ++j) _mm256_storeu_pd(out + 2 * it.b0 + 4 * j, acc[j]);
}

// field_block for a group of 8 replicas, replicas b0 + 4h .. b0 + 4h + 3 in half h.
template <bool Sums>
HMFNET_AVX2 void field_block_avx2(const Item& it, std::size_t w, const FieldArgs& f, double* out) {
  __m256d zc[2], zs[2], order[2], coupling[2];
  for (std::size_t h = 0; h < 2; ++h) {
    split_quad(f.z + 2 * (it.b0 + 4 * h), zc[h], zs[h]);
    order[h] = coupling[h] = _mm256_setzero_pd();
  }
  const __m256d inverse_n = _mm256_set1_pd(f.inverse_n);
  for (std::size_t r = it.r0; r < it.r1; ++r) {
    const double a = f.a[r];
    const __m256d va = _mm256_set1_pd(a), aa = _mm256_set1_pd(a * a);
    for (std::size_t h = 0; h < 2; ++h) {
      const std::size_t k = r * w + it.b0 + 4 * h;
      __m256d c, s;
      split_quad(f.cs + 2 * k, c, s);
      __m256d yc = _mm256_mul_pd(va, zc[h]), ys = _mm256_mul_pd(va, zs[h]);
      if (!f.diagonal) {
        yc = _mm256_sub_pd(yc, _mm256_mul_pd(aa, c));
        ys = _mm256_sub_pd(ys, _mm256_mul_pd(aa, s));
      }
      const __m256d torque = _mm256_sub_pd(_mm256_mul_pd(c, ys), _mm256_mul_pd(s, yc));
      _mm256_storeu_pd(f.g + k, _mm256_mul_pd(inverse_n, torque));
      if constexpr (!Sums) continue;
      const __m256d norm2 = _mm256_add_pd(_mm256_mul_pd(yc, yc), _mm256_mul_pd(ys, ys));
      order[h] = _mm256_add_pd(order[h], _mm256_sqrt_pd(norm2));
      coupling[h] =
          _mm256_add_pd(coupling[h], _mm256_add_pd(_mm256_mul_pd(c, yc), _mm256_mul_pd(s, ys)));
    }
  }
  if constexpr (!Sums) return;
  for (std::size_t h = 0; h < 2; ++h) {
    double o[4], c[4];
    _mm256_storeu_pd(o, order[h]);
    _mm256_storeu_pd(c, coupling[h]);
    for (std::size_t j = 0; j < 4; ++j) {
      out[2 * (it.b0 + 4 * h + j)] = o[j];
      out[2 * (it.b0 + 4 * h + j) + 1] = c[j];
    }
  }
}
#undef HMFNET_AVX2

// The instruction set a work item runs in: a whole group in AVX-512 or AVX2, whichever the
// sincos runs in (sincos.hpp; HMFNET_SINCOS_ISA chooses both), else the baseline code.
SincosIsa item_isa(const Item& it) { return it.nb == k_group ? sincos_isa() : SincosIsa::baseline; }
#endif

// z_block of one work item in its instruction set.
void z_item(const Item& it, std::size_t w, const double* a, const double* cs, double* out) {
#if defined(HMFNET_RANK_ONE_X86)
  const SincosIsa isa = item_isa(it);
  if (isa == SincosIsa::avx512) return z_block_avx512(it, w, a, cs, out);
  if (isa == SincosIsa::avx2) return z_block_avx2(it, w, a, cs, out);
#endif
  with_group_size(it, w, [&](auto nb) { z_block<decltype(nb)::value>(it, w, a, cs, out); });
}

// field_block of one work item in its instruction set.
template <bool Sums>
void field_item(const Item& it, std::size_t w, const FieldArgs& f, double* out) {
#if defined(HMFNET_RANK_ONE_X86)
  const SincosIsa isa = item_isa(it);
  if (isa == SincosIsa::avx512) return field_block_avx512<Sums>(it, w, f, out);
  if (isa == SincosIsa::avx2) return field_block_avx2<Sums>(it, w, f, out);
#endif
  with_group_size(it, w, [&](auto nb) { field_block<decltype(nb)::value, Sums>(it, w, f, out); });
}

}  // namespace

void RankOneForce::compute(const RotorState& state, std::vector<double>& g, ForceSums& sums,
                           ForceOutputs outputs) {
  if (outputs == ForceOutputs::force_only) {
    evaluate_passes<false>(state, g, sums);
  } else {
    evaluate_passes<true>(state, g, sums);
  }
}

template <bool Sums>
void RankOneForce::evaluate_passes(const RotorState& state, std::vector<double>& g,
                                   ForceSums& sums) {
  if (outside_team()) prepare(state, g, sums);
  const auto w = static_cast<std::size_t>(state.replicas);
  const auto rows = static_cast<std::size_t>(state.rows);
  const double* a = m_structure.a.data() + m_first_row;
  const std::size_t items = m_z_sums.blocks() * groups(w);
#pragma omp master
  m_y_current = false;  // read and written by the master only (local_fields: outside a team)
  // The [cos, sin] blocks are shared out in other blocks than the items below, which read them
  // only after their worksharing barrier.
  sincos_interleaved_team(state.theta.data(), rows * w, m_cs.data());
  // Z_b = sum_m a_m e^{i theta_m}: each block's ordered sum, then the blocks in order, then over
  // ranks. Formed as they are summed, never stored: one replica costs ~17 ns a rotor when a
  // [cos, sin] table scaled by a_n was written, summed, then overwritten by the terms and summed
  // again.
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < items; ++i) {
    const Item it = item(m_z_sums, i, w);
    z_item(it, w, a, m_cs.data(), m_z_sums.partial(it.block));
  }
  reduce_z(state, g.data());
  field_pass<Sums>(state, g, sums);
}

void RankOneForce::reduce_z(const RotorState& state, const double* g_formed) {
  // MPI on the master thread; the barrier after it gives every thread the reduced Z, and what it
  // belongs to (read by the next fused pass's threads before the master writes them again).
  on_master([&] {
    m_z_sums.add_blocks(m_z.data());
    ParallelSession::sum_in_place(m_z);
    m_evaluated_theta = state.theta.data();
    m_formed_g = g_formed;
  });
}

template <bool Sums>
void RankOneForce::field_pass(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  const auto w = static_cast<std::size_t>(state.replicas);
  const double* a = m_structure.a.data() + m_first_row;
  const std::size_t items = m_sums.blocks() * groups(w);
  const FieldArgs f{a, m_cs.data(), m_z.data(), m_inverse_n, m_structure.diagonal, g.data()};
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < items; ++i) {
    const Item it = item(m_sums, i, w);
    field_item<Sums>(it, w, f, m_sums.partial(it.block));
  }
  // The loop's barrier above makes every block's sums visible to the master.
  if constexpr (!Sums) return;
#pragma omp master
  collect_sums(w, sums);
}

void RankOneForce::collect_sums(std::size_t w, ForceSums& sums) {
  m_sums.add_blocks(m_term_sums.data());
  for (std::size_t b = 0; b < w; ++b) {
    sums.order[b] = m_term_sums[2 * b];
    sums.coupling[b] = m_term_sums[2 * b + 1];
  }
}

void RankOneForce::compute_sums(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  // [cos, sin] and Z of the last evaluation are `state`'s (also after a force_only one); else
  // evaluate again.
  if (state.theta.data() != m_evaluated_theta) {
    compute(state, g, sums, ForceOutputs::force_and_sums);
    return;
  }
  field_pass<true>(state, g, sums);
}

bool RankOneForce::fuses_kick_drift(const RotorState& state) const {
  const auto w = static_cast<std::size_t>(state.replicas);
  if (w == 0 || w % k_fused_group != 0) return false;
  // The pass forms the last evaluation's field from this force's own [cos, sin] and Z: they
  // must be those of `state` (not of another state this force evaluated since), as g is.
  if (state.theta.data() != m_evaluated_theta) return false;
  const auto rows = static_cast<std::size_t>(state.rows);
  const std::size_t blocks =
      (rows + OrderedColumnSums::k_block_rows - 1) / OrderedColumnSums::k_block_rows;
  const std::size_t items = blocks * groups(w);
  const auto threads = static_cast<std::size_t>(omp_get_num_threads());
  if (threads == 1) return true;
  // Measured on K_N N = 2000 (one block), 2 threads: 24 replicas (3 items) 0.78x the separate
  // passes, 16 (2 items, two threads writing the cache lines where the groups meet) 0.94x.
  // With a block or more a thread, and the items shared evenly or at least 4 a thread (the last
  // round's idle share <= 1/5), the threads' cells are mostly whole rows apart.
  return blocks >= threads && (items % threads == 0 || items >= 4 * threads);
}

void RankOneForce::compute_kick_drift(RotorState& state, const std::vector<double>& K,
                                      const KickDriftCoefficients& c, std::vector<double>& g,
                                      ForceSums& sums, ForceOutputs outputs) {
  if (outside_team()) prepare(state, g, sums);
  const auto w = static_cast<std::size_t>(state.replicas);
  const double* a = m_structure.a.data() + m_first_row;
  const std::size_t items = m_z_sums.blocks() * groups(w);
#pragma omp master
  m_y_current = false;
  // fuses_kick_drift(state) is the caller's to check: a tail group would run past the rows.
  // Outside a team a wrong call can throw; inside one an exception would end the process anyway.
  if (w % k_fused_group != 0) {
    if (outside_team()) throw std::logic_error("RankOneForce: a fused pass needs whole groups");
    std::abort();
  }
  // Every item reads the last evaluation's Z and its own cells' [cos, sin] before it overwrites
  // them, and the master writes the new Z only after the loop's barrier.
  // The last evaluation's g where it formed it into this g (a sampled step's field pass); with
  // the start's sums the pass forms the field instead (rank_one_fused_groups).
  const bool start_sums = outputs == ForceOutputs::start_sums_and_force;
  const RankOneFusedCells fused{a,
                                m_cs.data(),
                                m_z.data(),
                                m_formed_g == g.data() ? g.data() : nullptr,
                                m_inverse_n,
                                m_structure.diagonal,
                                state.p.data(),
                                state.theta.data(),
                                K.data(),
                                w,
                                m_unit_a};
  // Each thread's items as a static schedule shares them (one contiguous range, the same work a
  // thread as before), and the items of one block in that range in one call: its groups then
  // take each stage of rows side by side (rank_one_fused.cpp: fused_rows).
  const ItemRange mine = thread_items(items);
  for (std::size_t i = mine.begin; i < mine.end;) {
    const Item it = item(m_z_sums, i, w);
    std::size_t next = i + 1;
    while (next < mine.end && next / groups(w) == it.block) ++next;
    const std::size_t b1 = it.b0 + (next - i) * k_group;
    rank_one_fused_groups(sincos_isa(), fused, c, it.r0, it.r1, it.b0, b1,
                          m_z_sums.partial(it.block),
                          start_sums ? m_sums.partial(it.block) : nullptr);
    i = next;
  }
#pragma omp barrier
  // The sums at the start phases, before reduce_z's barrier (after which the next pass may
  // write the blocks' partials again).
  if (start_sums) {
#pragma omp master
    collect_sums(w, sums);
  }
  reduce_z(state, outputs == ForceOutputs::force_and_sums ? g.data() : nullptr);
  // g at the new phases only where the sums are formed: a force_only call leaves the last
  // evaluation's g (coupling_force.hpp), which the next fused call forms again from its own data.
  if (outputs == ForceOutputs::force_and_sums) field_pass<true>(state, g, sums);
}

const std::vector<double>& RankOneForce::local_fields() const {
  // Formed on demand from the last evaluation's [cos, sin] and Z (the same bits as forming them
  // there): only the samples with node data and the blow-up guard read them, and writing them
  // at every evaluation was 16 of the ~100 bytes a rotor and replica step moves.
  if (m_y_current) return m_y;
  const auto w = m_z.size() / 2;
  const auto cells = m_cs.size() / 2;
  const FieldArgs f{m_structure.a.data() + m_first_row,
                    m_cs.data(),
                    m_z.data(),
                    m_inverse_n,
                    m_structure.diagonal,
                    nullptr};
  for (std::size_t k = 0; k < cells; ++k)
    field(f, f.a[k / w], k, k % w, m_y[2 * k], m_y[2 * k + 1]);
  m_y_current = true;
  return m_y;
}

}  // namespace hmfnet
