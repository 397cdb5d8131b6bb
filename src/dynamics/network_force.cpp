#include "dynamics/network_force.hpp"

#include <cmath>
#include <stdexcept>

#include "dynamics/ordered_sum.hpp"

namespace hmfnet {

namespace {

struct RowKernelArgs {
  const EdgeOffset* row_ptr;
  const NodeIndex* cols;
  const double* weights;  // nullptr: 0/1 network
  const double* column_cs;
  const double* owned_cs;
  double inverse_n;
  double* g;
  double* y;
  double* abs_y;
  double* coupling;
};

// Replica count B fixed at compile time so the inner loops unroll and vectorise; `runtime_b`
// serves other counts. Weighted is a template flag so the 0/1 loop reads no values.
template <int B, bool Weighted>
void rows_kernel(const RowKernelArgs& a, NodeIndex rows, int runtime_b) {
  const int nb = B > 0 ? B : runtime_b;
  constexpr int kMax = 64;
#pragma omp parallel for schedule(static)
  for (NodeIndex r = 0; r < rows; ++r) {
    double yc[kMax], ys[kMax];
    for (int b = 0; b < nb; ++b) yc[b] = ys[b] = 0.0;
    for (EdgeOffset k = a.row_ptr[r]; k < a.row_ptr[r + 1]; ++k) {
      const double* q = a.column_cs + 2 * static_cast<std::ptrdiff_t>(a.cols[k]) * nb;
      const double w = Weighted ? a.weights[k] : 1.0;
      for (int b = 0; b < nb; ++b) {
        yc[b] += w * q[2 * b];
        ys[b] += w * q[2 * b + 1];
      }
    }
    const double* o = a.owned_cs + 2 * static_cast<std::ptrdiff_t>(r) * nb;
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(r) * nb;
    for (int b = 0; b < nb; ++b) {
      const double c = o[2 * b], s = o[2 * b + 1];
      a.g[base + b] = a.inverse_n * (c * ys[b] - s * yc[b]);
      a.y[2 * (base + b)] = yc[b];
      a.y[2 * (base + b) + 1] = ys[b];
      a.abs_y[base + b] = std::sqrt(yc[b] * yc[b] + ys[b] * ys[b]);
      a.coupling[base + b] = c * yc[b] + s * ys[b];
    }
  }
}

template <bool Weighted>
void dispatch(const RowKernelArgs& a, NodeIndex rows, int b) {
  switch (b) {
    case 1: rows_kernel<1, Weighted>(a, rows, b); break;
    case 2: rows_kernel<2, Weighted>(a, rows, b); break;
    case 4: rows_kernel<4, Weighted>(a, rows, b); break;
    case 8: rows_kernel<8, Weighted>(a, rows, b); break;
    default: rows_kernel<0, Weighted>(a, rows, b); break;
  }
}

}  // namespace

NetworkForce::NetworkForce(const DistributedNetwork& network)
    : m_network(network),
      m_adjacency(network.local_adjacency()),
      m_inverse_n(1.0 / static_cast<double>(network.global_size())) {}

void NetworkForce::evaluate(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  const int nb = state.replicas;
  const std::size_t cells = static_cast<std::size_t>(state.rows) * static_cast<std::size_t>(nb);
  m_owned_cs.resize(2 * cells);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < cells; ++k) {
    ::sincos(state.theta[k], &m_owned_cs[2 * k + 1], &m_owned_cs[2 * k]);  // one call: both
  }
  m_column_cs.resize(2 * static_cast<std::size_t>(m_adjacency.columns) *
                     static_cast<std::size_t>(nb));
  m_network.import_columns(m_owned_cs.data(), 2 * nb, m_column_cs.data());
  g.resize(cells);
  m_y.resize(2 * cells);
  m_abs_y.resize(cells);
  m_coupling.resize(cells);
  const RowKernelArgs args{m_adjacency.row_ptr.data(),
                           m_adjacency.cols.data(),
                           m_adjacency.weights.empty() ? nullptr : m_adjacency.weights.data(),
                           m_column_cs.data(),
                           m_owned_cs.data(),
                           m_inverse_n,
                           g.data(),
                           m_y.data(),
                           m_abs_y.data(),
                           m_coupling.data()};
  if (nb > 64) throw std::invalid_argument("at most 64 replicas per pass");
  if (args.weights == nullptr) {
    dispatch<false>(args, state.rows, nb);
  } else {
    dispatch<true>(args, state.rows, nb);
  }
  ordered_column_sums(m_abs_y, static_cast<std::size_t>(state.rows), nb, sums.order);
  ordered_column_sums(m_coupling, static_cast<std::size_t>(state.rows), nb, sums.coupling);
}

}  // namespace hmfnet
