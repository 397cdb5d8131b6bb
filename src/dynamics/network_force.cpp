#include "dynamics/network_force.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "dynamics/ordered_sum.hpp"

namespace hmfnet {

namespace {

// T: the storage of the gathered [cos, sin] table and the weights, and the type of the per-row
// accumulation (float32 halves the bytes the gather touches); the owned rows' cos and sin and
// the outputs stay double.
template <typename T>
struct RowKernelArgs {
  const EdgeOffset* row_ptr;
  const NodeIndex* cols;
  const T* weights;  // nullptr: 0/1 network
  const T* column_cs;
  const double* owned_cs;
  double inverse_n;
  double* g;
  double* y;
  double* abs_y;
  double* coupling;
};

// Replica count B fixed at compile time so the inner loops unroll and vectorise; `runtime_b`
// serves other counts. Weighted is a template flag so the 0/1 loop reads no values. Each replica
// is summed exactly as rows_kernel_single sums one (four accumulators by k mod 4, combined as
// (a0 + a1) + (a2 + a3)), so B replicas in one pass equal B separate runs bit for bit.
template <typename T, int B, bool Weighted>
void rows_kernel(const RowKernelArgs<T>& a, NodeIndex rows, int runtime_b) {
  const int nb = B > 0 ? B : runtime_b;
  constexpr int kMax = 64;
#pragma omp parallel for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    T acc[4][2 * kMax];
    for (int j = 0; j < 4; ++j)
      for (int b = 0; b < 2 * nb; ++b) acc[j][b] = T(0);
    const EdgeOffset end = a.row_ptr[r + 1];
    EdgeOffset k = a.row_ptr[r];
    for (; k + 4 <= end; k += 4) {
      for (int j = 0; j < 4; ++j) {
        const T* q = a.column_cs + 2 * static_cast<std::ptrdiff_t>(a.cols[k + j]) * nb;
        const T w = Weighted ? a.weights[k + j] : T(1);
        for (int b = 0; b < 2 * nb; ++b) acc[j][b] += w * q[b];
      }
    }
    for (; k < end; ++k) {
      const T* q = a.column_cs + 2 * static_cast<std::ptrdiff_t>(a.cols[k]) * nb;
      const T w = Weighted ? a.weights[k] : T(1);
      for (int b = 0; b < 2 * nb; ++b) acc[0][b] += w * q[b];
    }
    const double* o = a.owned_cs + 2 * static_cast<std::ptrdiff_t>(r) * nb;
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(r) * nb;
    for (int b = 0; b < nb; ++b) {
      const double yc = (acc[0][2 * b] + acc[1][2 * b]) + (acc[2][2 * b] + acc[3][2 * b]);
      const double ys = static_cast<double>((acc[0][2 * b + 1] + acc[1][2 * b + 1]) +
                                            (acc[2][2 * b + 1] + acc[3][2 * b + 1]));
      // 2 * b < 2 * kMax cannot overflow int. Casting it to ptrdiff_t (the check's fix) changes
      // GCC's instruction order in this loop, so the implicit widening stays.
      // NOLINTNEXTLINE(bugprone-implicit-widening-of-multiplication-result)
      const double c = o[2 * b], s = o[2 * b + 1];
      a.g[base + b] = a.inverse_n * (c * ys - s * yc);
      a.y[2 * (base + b)] = yc;
      a.y[2 * (base + b) + 1] = ys;
      a.abs_y[base + b] = std::sqrt(yc * yc + ys * ys);
      a.coupling[base + b] = c * yc + s * ys;
    }
  }
}

// One replica: four independent [cos, sin] accumulators per row break the floating-point add
// dependency chain (one add latency per neighbour otherwise). The order of the additions is
// fixed by the CSR row, so results remain identical for any thread or rank count.
template <typename T, bool Weighted>
void rows_kernel_single(const RowKernelArgs<T>& a, NodeIndex rows) {
#pragma omp parallel for schedule(static)
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
    a.abs_y[r] = std::sqrt(yc * yc + ys * ys);
    a.coupling[r] = c * yc + s * ys;
  }
}

template <typename T, bool Weighted>
void dispatch(const RowKernelArgs<T>& a, NodeIndex rows, int b) {
  switch (b) {
    case 1:
      rows_kernel_single<T, Weighted>(a, rows);
      break;
    case 2:
      rows_kernel<T, 2, Weighted>(a, rows, b);
      break;
    case 4:
      rows_kernel<T, 4, Weighted>(a, rows, b);
      break;
    case 8:
      rows_kernel<T, 8, Weighted>(a, rows, b);
      break;
    default:
      rows_kernel<T, 0, Weighted>(a, rows, b);
      break;
  }
}

template <typename T>
void run_kernel(const RowKernelArgs<T>& a, NodeIndex rows, int b) {
  if (a.weights == nullptr) {
    dispatch<T, false>(a, rows, b);
  } else {
    dispatch<T, true>(a, rows, b);
  }
}

void narrow(const std::vector<double>& from, std::vector<float>& to) {
  to.resize(from.size());
  const std::size_t n = from.size();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) to[k] = static_cast<float>(from[k]);
}

}  // namespace

NetworkForce::NetworkForce(const DistributedNetwork& network, ForcePrecision precision)
    : m_network(network),
      m_adjacency(network.local_adjacency()),
      m_inverse_n(1.0 / static_cast<double>(network.global_size())),
      m_identity_import(network.columns_are_owned_rows()),
      m_precision(precision) {
  if (m_precision == ForcePrecision::float32) narrow(m_adjacency.weights, m_weights_f32);
}

template <typename T>
void NetworkForce::run_rows(const T* weights, const T* column_cs, NodeIndex rows, int replicas,
                            std::vector<double>& g) {
  const RowKernelArgs<T> args{m_adjacency.row_ptr.data(),
                              m_adjacency.cols.data(),
                              weights,
                              column_cs,
                              m_owned_cs.data(),
                              m_inverse_n,
                              g.data(),
                              m_y.data(),
                              m_abs_y.data(),
                              m_coupling.data()};
  run_kernel(args, rows, replicas);
}

void NetworkForce::evaluate(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  const int nb = state.replicas;
  const std::size_t cells = static_cast<std::size_t>(state.rows) * static_cast<std::size_t>(nb);
  m_owned_cs.resize(2 * cells);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < cells; ++k) {
    ::sincos(state.theta[k], &m_owned_cs[2 * k + 1], &m_owned_cs[2 * k]);  // one call: both
  }
  const double* column_cs = m_owned_cs.data();
  if (!m_identity_import) {
    m_column_cs.resize(2 * static_cast<std::size_t>(m_adjacency.columns) *
                       static_cast<std::size_t>(nb));
    m_network.import_columns(m_owned_cs.data(), 2 * nb, m_column_cs.data());
    column_cs = m_column_cs.data();
  }
  g.resize(cells);
  m_y.resize(2 * cells);
  m_abs_y.resize(cells);
  m_coupling.resize(cells);
  if (nb > 64) throw ParameterError("replicas per pass", std::to_string(nb), "1 to 64");
  if (m_precision == ForcePrecision::float64) {
    run_rows(m_adjacency.weights.empty() ? nullptr : m_adjacency.weights.data(), column_cs,
             state.rows, nb, g);
  } else {
    // The gathered table in float32 (one narrowing pass over the columns, O(columns x B), next
    // to the O(nnz x B) gather it halves).
    narrow(m_identity_import ? m_owned_cs : m_column_cs, m_column_f32);
    run_rows(m_weights_f32.empty() ? nullptr : m_weights_f32.data(), m_column_f32.data(),
             state.rows, nb, g);
  }
  ordered_column_sums(m_abs_y, static_cast<std::size_t>(state.rows), nb, sums.order);
  ordered_column_sums(m_coupling, static_cast<std::size_t>(state.rows), nb, sums.coupling);
}

}  // namespace hmfnet
