#include "dynamics/network_force.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>

#include "core/cpu_caches.hpp"
#include "core/error.hpp"
#include "dynamics/ordered_sum.hpp"
#include "dynamics/row_kernel_args.hpp"
#include "dynamics/segment_runs.hpp"
#include "dynamics/sincos.hpp"
#include "dynamics/team.hpp"
#include "dynamics/thread_choice.hpp"
#include "dynamics/wide_rows.hpp"

namespace hmfnet {

namespace {

// The baseline row loop: x86-64 baseline instructions (SSE2), for every replica count where the
// wide loops of wide_rows.hpp do not serve (HMFNET_SINCOS_ISA=baseline, a CPU without AVX2,
// float32 B = 2); the same bits as they.
// Replica count B fixed at compile time so the inner loops unroll and vectorise; `runtime_b`
// serves other counts. Weighted is a template flag so the 0/1 loop reads no values.
// Each replica is summed exactly as rows_kernel_single sums one, so B replicas in one pass equal
// B separate runs bit for bit: four partial sums, partial j over the entries begin + j,
// begin + j + 4, ... of the row's first 4 floor(d / 4), the last d mod 4 added to partial 0,
// combined as (s0 + s1) + (s2 + s3). The partials are independent sums, so they may be formed
// one after another: the row is walked 4 / C times, C partials at a time, so that the live
// accumulators (C x 2B values of T) fit in the 16 vector registers of x86-64 instead of spilling
// to the stack at every neighbour. Replicas then add 2B independent chains per neighbour, and one
// gathered neighbour brings all their [cos, sin] in 2B adjacent values (one or two cache lines).
template <typename T, int B, std::size_t C, bool Weighted, typename I>
void rows_kernel(const RowKernelArgs<T, I>& a, NodeIndex rows, int runtime_b) {
  static_assert(C == 1 || C == 2 || C == 4, "the partials per pass divide 4");
  const int nb = B > 0 ? B : runtime_b;
  constexpr int k_max = 64;
  constexpr std::size_t k_width = 2 * static_cast<std::size_t>(B > 0 ? B : k_max);
  constexpr int k_passes = 4 / static_cast<int>(C);
#pragma omp for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    const EdgeOffset begin = a.row_ptr[r], end = a.row_ptr[r + 1];
    const EdgeOffset full = begin + (end - begin) / 4 * 4;
    T partial[4][k_width];
    for (int step = 0; step < k_passes; ++step) {
      const int pass = step * static_cast<int>(C);
      T acc[C][k_width];
      for (std::size_t c = 0; c < C; ++c)
        for (int b = 0; b < 2 * nb; ++b) acc[c][b] = T(0);
      for (EdgeOffset k = begin; k < full; k += 4) {
        for (std::size_t c = 0; c < C; ++c) {
          const EdgeOffset e = k + pass + static_cast<EdgeOffset>(c);
          const T* q = a.column_cs + 2 * static_cast<std::ptrdiff_t>(a.cols[e]) * nb;
          const T w = Weighted ? a.weights[e] : T(1);
          add_record(acc[c], q, w, 2 * nb);
        }
      }
      if (pass == 0) {
        for (EdgeOffset k = full; k < end; ++k) {
          const T* q = a.column_cs + 2 * static_cast<std::ptrdiff_t>(a.cols[k]) * nb;
          const T w = Weighted ? a.weights[k] : T(1);
          add_record(acc[0], q, w, 2 * nb);
        }
      }
      for (std::size_t c = 0; c < C; ++c)
        for (int b = 0; b < 2 * nb; ++b) partial[static_cast<std::size_t>(pass) + c][b] = acc[c][b];
    }
    finish_row(a, r, &partial[0][0], k_width, nb);
  }
}

// The partials formed per pass of rows_kernel (row_kernel_args.hpp: baseline_walk_partials).
template <typename T, int B>
constexpr std::size_t partials_per_pass() {
  return static_cast<std::size_t>(
      baseline_walk_partials(2 * static_cast<std::size_t>(B) * sizeof(T)));
}

// One replica: four independent [cos, sin] accumulators per row break the floating-point add
// dependency chain (one add latency per neighbour otherwise). The order of the additions is
// fixed by the CSR row, so results remain identical for any thread or rank count.
template <typename T, bool Weighted, typename I>
void rows_kernel_single(const RowKernelArgs<T, I>& a, NodeIndex rows) {
#pragma omp for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    T c0 = 0, s0 = 0, c1 = 0, s1 = 0, c2 = 0, s2 = 0, c3 = 0, s3 = 0;
    EdgeOffset k = a.row_ptr[r];
    const EdgeOffset end = a.row_ptr[r + 1];
    const auto at = [&](EdgeOffset j) {
      return a.column_cs + 2 * static_cast<std::ptrdiff_t>(a.cols[j]);
    };
    const auto w = [&](EdgeOffset j) { return Weighted ? a.weights[j] : T(1); };
    for (; k + 4 <= end; k += 4) {
      const T *q0 = at(k), *q1 = at(k + 1), *q2 = at(k + 2), *q3 = at(k + 3);
      c0 += w(k) * q0[0];
      s0 += w(k) * q0[1];
      c1 += w(k + 1) * q1[0];
      s1 += w(k + 1) * q1[1];
      c2 += w(k + 2) * q2[0];
      s2 += w(k + 2) * q2[1];
      c3 += w(k + 3) * q3[0];
      s3 += w(k + 3) * q3[1];
    }
    for (; k < end; ++k) {
      c0 += w(k) * at(k)[0];
      s0 += w(k) * at(k)[1];
    }
    const double yc = (c0 + c1) + (c2 + c3), ys = static_cast<double>((s0 + s1) + (s2 + s3));
    const double c = a.owned_cs[2 * r], s = a.owned_cs[2 * r + 1];
    a.g[r] = a.inverse_n * (c * ys - s * yc);
    a.y[2 * r] = yc;
    a.y[2 * r + 1] = ys;
    if (a.terms == nullptr) continue;
    a.terms[2 * r] = std::sqrt(yc * yc + ys * ys);
    a.terms[2 * r + 1] = c * yc + s * ys;
  }
}

// The segmented kernel (column_segments.hpp) keeps each row's four partial sums of every
// replica between segments in `carry` (carried_rows(rows) x 4 x 2B values of T: one panel) and
// where its run of entries stopped in `cursor` (carried_rows(rows)). An entry's partial is fixed by
// its place in the row as in the unblocked kernels (place mod 4, the last d mod 4 entries in
// partial 0), and the runs of a row arrive in CSR order, so every partial receives the same
// additions in the same order.
template <typename T>
struct SegmentArgs {
  const ColumnSegments* segments;
  T* carry;
  std::uint32_t* cursor;
};

// The rows in k_carry_panels panels, each walked once per segment before the next panel, so the
// carry holds one panel's partials (column_segments.hpp). Within a panel each thread walks the
// same block of rows in every segment, so the carry needs no barrier between segments; one
// barrier after each panel (the next panel reuses the carry), as the unblocked loop has one.
// I: the segments' index type (ColumnSegments::narrow()).
template <typename T, int B, bool Weighted, typename I>
void segmented_rows_kernel(const RowKernelArgs<T>& a, const SegmentArgs<T>& sa, NodeIndex rows,
                           int runtime_b) {
  const int nb = B > 0 ? B : runtime_b;
  const std::size_t record = 2 * static_cast<std::size_t>(nb), stride = 4 * record;
  const int count = sa.segments->count();
  const auto threads = static_cast<std::int64_t>(omp_get_num_threads());
  const auto thread = static_cast<std::int64_t>(omp_get_thread_num());
  const NodeIndex panel = carried_rows(rows);
  const SincosIsa isa = sincos_isa();
  const bool wide = wide_loops_serve<T>(nb, isa);
  for (std::int64_t p0 = 0; p0 < rows; p0 += panel) {
    const std::int64_t panel_rows = std::min<std::int64_t>(panel, rows - p0);
    const auto r0 = static_cast<NodeIndex>(p0 + panel_rows * thread / threads);
    const auto r1 = static_cast<NodeIndex>(p0 + panel_rows * (thread + 1) / threads);
    for (int seg = 0; seg < count; ++seg) {
      const T* table =
          a.column_cs + static_cast<std::ptrdiff_t>(record) *
                            static_cast<std::ptrdiff_t>(sa.segments->first_column(seg));
      const SegmentPass<T, I> pass{a.row_ptr,
                                   &sa.segments->runs(),
                                   seg,
                                   sa.segments->template cols<I>(seg),
                                   table,
                                   sa.carry,
                                   sa.cursor,
                                   seg == 0,
                                   seg + 1 == count,
                                   static_cast<NodeIndex>(p0)};
      if constexpr (B == 0 || B == 2 || B == 4 || B == 8) {
        if (wide) {
          wide_segment_runs(pass, a.weights, nb, r0, r1, isa);
          continue;
        }
      }
      if constexpr (!Weighted && (B == 1 || B == 2)) {
        add_segment_runs(pass, nb, r0, r1, true);
      } else {
        scalar_segment_runs<T, B, Weighted, I>(pass, a.weights, nb, r0, r1);
      }
    }
    for (NodeIndex r = r0; r < r1; ++r)
      finish_row(a, r, sa.carry + static_cast<std::size_t>(r - p0) * stride, record, nb);
#pragma omp barrier
  }
}

template <typename T, bool Weighted, typename I>
void dispatch_segmented(const RowKernelArgs<T>& a, const SegmentArgs<T>& sa, NodeIndex rows,
                        int b) {
  switch (b) {
    case 1:
      segmented_rows_kernel<T, 1, Weighted, I>(a, sa, rows, b);
      break;
    case 2:
      segmented_rows_kernel<T, 2, Weighted, I>(a, sa, rows, b);
      break;
    case 4:
      segmented_rows_kernel<T, 4, Weighted, I>(a, sa, rows, b);
      break;
    case 8:
      segmented_rows_kernel<T, 8, Weighted, I>(a, sa, rows, b);
      break;
    default:
      segmented_rows_kernel<T, 0, Weighted, I>(a, sa, rows, b);
      break;
  }
}

template <typename T, bool Weighted>
void dispatch_segmented_index(const RowKernelArgs<T>& a, const SegmentArgs<T>& sa, NodeIndex rows,
                              int b) {
  if (sa.segments->narrow()) {
    dispatch_segmented<T, Weighted, std::uint16_t>(a, sa, rows, b);
  } else {
    dispatch_segmented<T, Weighted, NodeIndex>(a, sa, rows, b);
  }
}

template <typename T, bool Weighted, typename I>
void dispatch(const RowKernelArgs<T, I>& a, NodeIndex rows, int b) {
  switch (b) {
    case 1:
      rows_kernel_single<T, Weighted>(a, rows);
      break;
    case 2:
      rows_kernel<T, 2, partials_per_pass<T, 2>(), Weighted>(a, rows, b);
      break;
    case 4:
      rows_kernel<T, 4, partials_per_pass<T, 4>(), Weighted>(a, rows, b);
      break;
    case 8:
      rows_kernel<T, 8, partials_per_pass<T, 8>(), Weighted>(a, rows, b);
      break;
    default:  // accumulators on the stack whatever C: walk the row once
      rows_kernel<T, 0, 4, Weighted>(a, rows, b);
      break;
  }
}

template <typename T, typename I>
void run_kernel(const RowKernelArgs<T, I>& a, NodeIndex rows, int b) {
  const SincosIsa isa = sincos_isa();
  if (wide_loops_serve<T>(b, isa)) {
    wide_rows(a, rows, b, isa);
    return;
  }
  if (a.weights == nullptr) {
    dispatch<T, false>(a, rows, b);
  } else {
    dispatch<T, true>(a, rows, b);
  }
}

// Kept out of run_rows: with the segmented kernels inlined there too, GCC 12 stopped inlining
// the unblocked ones into it, and ER N = 10^4 with 8 float64 replicas ran 1.25x slower (perf:
// rows_kernel<double, 8> called instead of inlined; bench/segmented_rows_table.sh).
template <typename T>
[[gnu::noinline]] void run_segmented_kernel(const RowKernelArgs<T>& a, const SegmentArgs<T>& sa,
                                            NodeIndex rows, int b) {
  if (a.weights == nullptr) {
    dispatch_segmented_index<T, false>(a, sa, rows, b);
  } else {
    dispatch_segmented_index<T, true>(a, sa, rows, b);
  }
}

// to[0, n) = from[0, n) in float32; `to` sized by the caller (team.hpp: no allocation inside a
// team).
void narrow(const double* from, std::size_t n, float* to) {
#pragma omp for schedule(static)
  for (std::size_t k = 0; k < n; ++k) to[k] = static_cast<float>(from[k]);
}

}  // namespace

NetworkForce::NetworkForce(const DistributedNetwork& network, ForcePrecision precision,
                           NodeIndex segment_width, bool allow_narrow)
    : m_network(network),
      m_adjacency(network.local_adjacency()),
      m_nnz(static_cast<EdgeOffset>(m_adjacency.cols.size())),
      m_inverse_n(1.0 / static_cast<double>(network.global_size())),
      m_identity_import(network.columns_are_owned_rows()),
      m_precision(precision),
      m_segment_request(segment_width),
      m_allow_narrow(allow_narrow) {
  if (m_precision == ForcePrecision::float32) {
    m_weights_f32.resize(m_adjacency.weights.size());
#pragma omp parallel
    narrow(m_adjacency.weights.data(), m_adjacency.weights.size(), m_weights_f32.data());
  }
}

template <typename T>
void NetworkForce::run_rows(const T* weights, const T* column_cs, NodeIndex rows, int replicas,
                            std::vector<double>& g, ForceOutputs outputs) {
  const auto args_with = [&](const auto* cols) {
    using I = std::remove_const_t<std::remove_pointer_t<decltype(cols)>>;
    return RowKernelArgs<T, I>{m_adjacency.row_ptr.data(),
                               cols,
                               weights,
                               column_cs,
                               m_owned_cs.data(),
                               m_inverse_n,
                               g.data(),
                               m_y.data(),
                               outputs == ForceOutputs::force_only ? nullptr : m_terms.data()};
  };
  const RowKernelArgs<T> args = args_with(csr_cols().data());
  if (m_segments.count() == 1) {
    if (m_narrow_cols.empty()) {
      run_kernel(args, rows, replicas);
    } else {
      run_kernel(args_with(m_narrow_cols.data()), rows, replicas);
    }
    return;
  }
  T* carry = nullptr;
  if constexpr (sizeof(T) == sizeof(float)) {
    carry = m_carry_f32.data();
  } else {
    carry = m_carry.data();
  }
  run_segmented_kernel(args, SegmentArgs<T>{&m_segments, carry, m_cursor.data()}, rows, replicas);
}

double NetworkForce::lane_gather_cost(int lanes) const {
  const bool float32 = m_precision == ForcePrecision::float32;
  const SincosIsa isa = sincos_isa();
  const bool wide =
      float32 ? wide_rows_serve<float>(lanes, isa) : wide_rows_serve<double>(lanes, isa);
  if (wide) return wide_lane_gather_cost(float32, lanes);
  const bool grouped =
      float32 ? wide_groups_serve<float>(lanes, isa) : wide_groups_serve<double>(lanes, isa);
  return grouped ? grouped_lane_gather_cost(float32, lanes) : 1.0;
}

void NetworkForce::take_columns(DistributedNetwork& network) {
  if (&network != &m_network) {
    throw ParameterError("NetworkForce::take_columns", "another network than the force's",
                         "the network the force was made with");
  }
  m_column_owner = &network;
}

void NetworkForce::cut(NodeIndex width) {
  const bool segmented = width < m_adjacency.columns;
  const bool narrow = !segmented && m_allow_narrow && NarrowColumns::fits(m_adjacency.columns);
  // Taken before this cut, the indices live only in this force's copies; taken now, the
  // network's own arrive in m_own_cols and a 16-bit copy made before is a copy of them.
  const bool took_before = m_took_columns;
  if (m_column_owner != nullptr && !m_took_columns && (segmented || narrow)) {
    m_own_cols = m_column_owner->release_columns();
    m_took_columns = true;
  }
  // Taken, the indices are in the segments, in the 16-bit copy or in m_own_cols: back in
  // m_own_cols first, each copy freed before the next is made.
  if (!m_narrow_cols.empty()) {
    if (took_before) m_own_cols = m_narrow_cols.widened();
    m_narrow_cols = NarrowColumns();
  }
  if (!m_took_columns) {
    m_segments = ColumnSegments(m_adjacency.row_ptr, m_adjacency.cols, m_adjacency.columns, width);
    if (narrow && narrow_copy_fits()) {
      m_narrow_cols = NarrowColumns(m_adjacency.cols, m_adjacency.columns);
    }
    return;
  }
  if (m_own_cols.empty()) {
    m_own_cols = m_segments.csr_columns();
    m_segments = ColumnSegments();
  }
  m_segments = ColumnSegments::taking(m_adjacency.row_ptr, m_own_cols, m_adjacency.columns, width);
  if (narrow) m_narrow_cols = NarrowColumns::taking(m_own_cols, m_adjacency.columns);
}

bool NetworkForce::narrow_copy_fits() const {
  const auto bytes = static_cast<std::size_t>(m_nnz) * sizeof(std::uint16_t);
  return bytes <= available_memory_bytes() / 2;
}

void NetworkForce::prepare_segments(NodeIndex rows, int replicas) {
  // Another force (or this one's network) took the indices this force was made to read.
  if (!m_took_columns && m_adjacency.cols.size() != static_cast<std::size_t>(m_nnz)) {
    throw ParameterError("the sparse force", "the network's column indices were given to another",
                         "a network whose column indices this force reads or took");
  }
  // prepare runs before every evaluation outside a team (each step on one thread), and the
  // automatic rule reads /proc/meminfo and the cache size: decided once per shape (14 us a step
  // measured on ER N = 1000, degree 4, where a whole step took 10 us before the rule).
  const int threads = omp_get_max_threads();  // the team of the evaluations that follow
  if (rows == m_segmented_rows && replicas == m_segmented_replicas &&
      threads == m_segmented_threads) {
    return;
  }
  const bool float64 = m_precision == ForcePrecision::float64;
  const std::size_t value_bytes = float64 ? sizeof(double) : sizeof(float);
  const SincosIsa isa = sincos_isa();
  const bool registers =
      float64 ? wide_loops_serve<double>(replicas, isa) : wide_loops_serve<float>(replicas, isa);
  NodeIndex width = m_segment_request;
  m_trial_width = k_unsegmented;
  if (m_segment_request == k_automatic_segments) {
    const std::size_t record = 2 * static_cast<std::size_t>(replicas) * value_bytes;
    CacheSizes caches = this_cpu_caches(threads);
    if (m_caches)
      caches = CacheSizes{m_caches->l2, m_caches->l3, threads, m_caches->l3_core_complex};
    const std::size_t memory = available_memory_bytes();
    width = automatic_segment_width(m_adjacency.columns, m_nnz, rows, record, caches, memory,
                                    registers);
    m_trial_width =
        trial_segment_width(m_adjacency.columns, m_nnz, rows, record, caches, memory, registers);
    if (m_use_trial_width && m_trial_width != k_unsegmented) width = m_trial_width;
  }
  if (width != m_segment_width) {
    cut(width);
    m_segment_width = width;
  }
  const auto panel = static_cast<std::size_t>(m_segments.count() > 1 ? carried_rows(rows) : 0);
  const std::size_t carried = 8 * panel * static_cast<std::size_t>(replicas);
  m_carry.resize(m_precision == ForcePrecision::float64 ? carried : 0);
  m_carry_f32.resize(m_precision == ForcePrecision::float32 ? carried : 0);
  m_cursor.resize(panel);
  // Only once all of it is in place: a throw above leaves the next call to decide again.
  m_segmented_rows = rows;
  m_segmented_replicas = replicas;
  m_segmented_threads = threads;
}

std::vector<int> NetworkForce::segment_candidates() const {
  if (m_trial_width == k_unsegmented) return {};
  const std::int64_t columns = m_adjacency.columns;
  return {1, static_cast<int>((columns + m_trial_width - 1) / m_trial_width)};
}

void NetworkForce::use_segments(int count) {
  const bool trial = count != 1;
  if (trial != m_use_trial_width) m_segmented_rows = -1;  // the next prepare decides again
  m_use_trial_width = trial;
}

void NetworkForce::prepare(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  const int nb = state.replicas;
  if (nb > 64) throw ParameterError("replicas per pass", std::to_string(nb), "1 to 64");
  const std::size_t cells = static_cast<std::size_t>(state.rows) * static_cast<std::size_t>(nb);
  m_owned_cs.resize(2 * cells);
  const std::size_t columns =
      2 * static_cast<std::size_t>(m_adjacency.columns) * static_cast<std::size_t>(nb);
  if (!m_identity_import) m_column_cs.resize(columns);
  if (m_precision == ForcePrecision::float32) m_column_f32.resize(columns);
  g.resize(cells);
  m_y.resize(2 * cells);
  m_terms.resize(2 * cells);
  m_term_sums.resize(2 * static_cast<std::size_t>(nb));
  m_sums.prepare(static_cast<std::size_t>(state.rows), 2 * nb);
  sums.order.resize(static_cast<std::size_t>(nb));
  sums.coupling.resize(static_cast<std::size_t>(nb));
  prepare_segments(state.rows, nb);
}

void NetworkForce::compute(const RotorState& state, std::vector<double>& g, ForceSums& sums,
                           ForceOutputs outputs) {
  if (outside_team()) prepare(state, g, sums);
  const int nb = state.replicas;
  const std::size_t cells = static_cast<std::size_t>(state.rows) * static_cast<std::size_t>(nb);
  sincos_interleaved_team(state.theta.data(), cells, m_owned_cs.data());
  const double* column_cs = m_owned_cs.data();
  if (!m_identity_import) {
    // Tpetra and MPI on one thread; the barrier after it publishes the ghost values.
    on_master([&] { m_network.import_columns(m_owned_cs.data(), 2 * nb, m_column_cs.data()); });
    column_cs = m_column_cs.data();
  }
  if (m_precision == ForcePrecision::float64) {
    run_rows(m_adjacency.weights.empty() ? nullptr : m_adjacency.weights.data(), column_cs,
             state.rows, nb, g, outputs);
  } else {
    // The gathered table in float32 (one narrowing pass over the columns, O(columns x B), next
    // to the O(nnz x B) gather it halves).
    const auto& wide = m_identity_import ? m_owned_cs : m_column_cs;
    narrow(wide.data(), wide.size(), m_column_f32.data());
    run_rows(m_weights_f32.empty() ? nullptr : m_weights_f32.data(), m_column_f32.data(),
             state.rows, nb, g, outputs);
  }
  // The rows' terms (formed in their finish) and the ordered pass over them only where the sums
  // are read.
  if (outputs == ForceOutputs::force_only) return;
  // Both sums of every replica in one ordered pass (each column is summed on its own, so this
  // equals two separate passes bit for bit).
  m_sums.sum(m_terms.data(), m_term_sums.data());
#pragma omp master
  for (std::size_t b = 0; b < static_cast<std::size_t>(nb); ++b) {
    sums.order[b] = m_term_sums[2 * b];
    sums.coupling[b] = m_term_sums[2 * b + 1];
  }
}

}  // namespace hmfnet
