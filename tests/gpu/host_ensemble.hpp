#pragma once
// The CPU's step for the gpu tests, on the host: integrator.cpp's kick-drift splittings over
// network_force.cpp's rows (sparse) or rank_one_force.cpp's Z (the complete graph), each cell
// computed by the functions of dynamics/kernel_arithmetic.hpp in the CPU's order
// (tests/dynamics/test_kernel_arithmetic.cpp ties these functions to the CPU kernels). The
// device steppers are compared with it; it needs no Trilinos, so the device check's own build
// (ci/device) has it. Spread over ranks (spread_over), it sums as each of several MPI ranks
// would: the observables over each rank's rows, Z per rank and then over the ranks.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "core/random.hpp"
#include "dynamics/cuda/sparse_ensemble.hpp"
#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/splitting_coefficients.hpp"

namespace hmfnet::gpu_test {

/// Values whose bits differ (NaN only as NaN); a.size() + b.size() when the sizes differ.
inline std::size_t differing(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return a.size() + b.size();
  std::size_t n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (std::memcmp(&a[k], &b[k], sizeof(double)) != 0 && !(std::isnan(a[k]) && std::isnan(b[k])))
      ++n;
  }
  return n;
}

/// An undirected random network: each pair an edge with probability degree / (n - 1), no
/// self-loops, rows sorted (a CSR as the CPU stores it).
inline cuda::HostCsr random_network(std::int64_t n, double degree, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution edge(degree / static_cast<double>(n - 1));
  std::vector<std::vector<std::int32_t>> rows(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) {
    for (std::int64_t j = i + 1; j < n; ++j) {
      if (!edge(rng)) continue;
      rows[static_cast<std::size_t>(i)].push_back(static_cast<std::int32_t>(j));
      rows[static_cast<std::size_t>(j)].push_back(static_cast<std::int32_t>(i));
    }
  }
  cuda::HostCsr csr;
  csr.rows = n;
  csr.offsets.push_back(0);
  for (auto& r : rows) {
    std::sort(r.begin(), r.end());
    csr.columns.insert(csr.columns.end(), r.begin(), r.end());
    csr.offsets.push_back(static_cast<std::int64_t>(csr.columns.size()));
  }
  return csr;
}

/// The water-bag start of rotor_state.cpp (theta uniform on [0, 2 pi), p uniform on +-sqrt(3)
/// sigma0, stream = row of seed + replica), rows x replicas.
inline void waterbag(std::int64_t n, int replicas, double sigma0, std::uint64_t seed,
                     std::vector<double>& theta, std::vector<double>& p) {
  const auto cells = static_cast<std::size_t>(n * replicas);
  theta.assign(cells, 0.0);
  p.assign(cells, 0.0);
  const double half_width = std::sqrt(3.0) * sigma0;
  for (int b = 0; b < replicas; ++b) {
    for (std::int64_t r = 0; r < n; ++r) {
      Rng rng(seed + static_cast<std::uint64_t>(b), static_cast<std::uint64_t>(r));
      const auto k = static_cast<std::size_t>(r * replicas + b);
      theta[k] = 6.283185307179586476925286766559 * rng.uniform();
      p[k] = half_width * (2.0 * rng.uniform() - 1.0);
    }
  }
}

/// The host stepper. complete(): K_N with or without self-loops (y_n = Z - [no self-loops]
/// e^{i theta_n}, Z summed in OrderedColumnSums' 2048-row blocks: rank_one_force.cpp with a = 1);
/// otherwise the network's rows in T.
class HostEnsemble {
 public:
  HostEnsemble(cuda::HostCsr network, int replicas, bool float32)
      : m_net(std::move(network)),
        m_n(m_net.rows),
        m_b(replicas),
        m_w(static_cast<std::size_t>(replicas)),
        m_float32(float32) {
    for (const double w : m_net.weights) m_weights32.push_back(static_cast<float>(w));
  }
  static HostEnsemble complete(std::int64_t n, int replicas, bool self_loops = true) {
    return rank_one(std::vector<double>(static_cast<std::size_t>(n), 1.0), replicas, self_loops);
  }
  /// A = a a^T, with or without its diagonal (rank_one_force.hpp).
  static HostEnsemble rank_one(std::vector<double> a, int replicas, bool diagonal) {
    cuda::HostCsr none;
    none.rows = static_cast<std::int64_t>(a.size());
    HostEnsemble e(std::move(none), replicas, false);
    e.m_complete = true;
    e.m_self_loops = diagonal;
    e.m_a = std::move(a);
    return e;
  }

  std::vector<double> theta, p, K;

  /// The rows as consecutive blocks of `rank_rows[r]` rows, one a rank (they add up to N): the
  /// order sums of `advance` and `rank_sums` are each rank's, over its rows in its own 2048-row
  /// blocks, and the rank-one Z is each rank's so summed and then the ranks' added in rank order
  /// (rank_one_force.cpp's reduce_z: ParallelSession::sum_in_place, whose two addends give the
  /// same bits in either order). A sparse row's sum does not depend on it.
  void spread_over(std::vector<std::int64_t> rank_rows) { m_rank_rows = std::move(rank_rows); }

  void set_state(std::vector<double> t, std::vector<double> q) {
    theta = std::move(t);
    p = std::move(q);
    if (K.empty()) K.assign(m_w, 1.0);
    evaluate();
  }

  /// With `order`: each step's sum_n |y_n| per replica appended (SparseEnsemble::advance), one
  /// such sum a rank where spread over ranks (steps x ranks x replicas values).
  void advance(const SplittingCoefficients& c, double h, std::int64_t steps,
               std::vector<double>* order = nullptr) {
    for (std::int64_t s = 0; s < steps; ++s) {
      for (std::size_t i = 0; i < c.drifts.size(); ++i) {
        for (std::size_t k = 0; k < cells(); ++k) {
          p[k] = kicked_momentum(p[k], c.kicks[i] * h, K[k % m_w], m_g[k]);
          theta[k] = drifted_angle(theta[k], c.drifts[i] * h, p[k]);
        }
        evaluate();
      }
      for (std::size_t k = 0; k < cells(); ++k) {
        p[k] = kicked_momentum(p[k], c.kicks.back() * h, K[k % m_w], m_g[k]);
      }
      if (order != nullptr) {
        const std::vector<double> terms = order_terms();
        for (std::size_t r = 0; r < rank_count(); ++r) {
          const std::vector<double> o = ordered_sums(terms, first_row(r), first_row(r + 1));
          order->insert(order->end(), o.begin(), o.end());
        }
      }
    }
  }

  /// The record's sums at the current state in OrderedColumnSums' order (the CPU's
  /// HostStepper::sums and SparseEnsemble::sums), over every row.
  cuda::EnsembleSums sums() const { return sums_over(0, m_n); }
  /// The same over rank `rank`'s rows, where spread over ranks (each rank's SparseEnsemble::sums).
  cuda::EnsembleSums rank_sums(std::size_t rank) const {
    return sums_over(first_row(rank), first_row(rank + 1));
  }

  /// Per replica H = sum p^2 / 2 - K / (2N) sum Re(e^{-i theta_n} y_n), summed plainly.
  std::vector<double> energy() const {
    std::vector<double> e(m_w, 0.0);
    for (std::size_t k = 0; k < cells(); ++k) {
      e[k % m_w] += 0.5 * p[k] * p[k] - K[k % m_w] / (2.0 * static_cast<double>(m_n)) *
                                            coupling_term(m_cs[2 * k], m_cs[2 * k + 1], m_y[k]);
    }
    return e;
  }

  /// Z per replica as [Re, Im] (complete graph).
  const std::vector<double>& z() const { return m_z; }

  /// y_n at the current state, rows x replicas x [Re, Im] (CouplingForce::local_fields).
  std::vector<double> fields() const {
    std::vector<double> y;
    for (const LocalField& f : m_y) {
      y.push_back(f.re);
      y.push_back(f.im);
    }
    return y;
  }

 private:
  std::size_t cells() const { return static_cast<std::size_t>(m_n) * m_w; }

  // The five sums over rows [first, last) (one rank's), each from 0 in that range's blocks.
  cuda::EnsembleSums sums_over(std::int64_t first, std::int64_t last) const {
    std::vector<double> coupling(cells()), kinetic(cells()), magnitude(cells());
    for (std::size_t k = 0; k < cells(); ++k) {
      coupling[k] = coupling_term(m_cs[2 * k], m_cs[2 * k + 1], m_y[k]);
      kinetic[k] = 0.5 * p[k] * p[k];
      magnitude[k] = std::abs(p[k]);
    }
    cuda::EnsembleSums s;
    s.order = ordered_sums(order_terms(), first, last);
    s.coupling = ordered_sums(coupling, first, last);
    s.kinetic = ordered_sums(kinetic, first, last);
    s.momentum = ordered_sums(p, first, last);
    s.momentum_scale = ordered_sums(magnitude, first, last);
    return s;
  }

  std::size_t rank_count() const { return m_rank_rows.empty() ? 1 : m_rank_rows.size(); }
  // Rank r's first row; rank_count()'s is N.
  std::int64_t first_row(std::size_t rank) const {
    if (m_rank_rows.empty()) return rank == 0 ? 0 : m_n;
    std::int64_t first = 0;
    for (std::size_t r = 0; r < rank; ++r) first += m_rank_rows[r];
    return first;
  }

  std::vector<double> order_terms() const {
    std::vector<double> t(cells());
    for (std::size_t k = 0; k < cells(); ++k) t[k] = order_term(m_y[k]);
    return t;
  }

  // Column sums of rows [begin, end) of rows x replicas values as OrderedColumnSums forms them
  // on the rank that holds those rows: 2048-row blocks from `begin`, each from 0 in order, then
  // the blocks in order from 0.
  std::vector<double> ordered_sums(const std::vector<double>& values, std::int64_t begin,
                                   std::int64_t end) const {
    std::vector<double> out(m_w, 0.0);
    for (std::int64_t first = begin; first < end; first += 2048) {
      std::vector<double> block(m_w, 0.0);
      for (std::int64_t r = first; r < std::min(end, first + 2048); ++r) {
        for (std::size_t b = 0; b < m_w; ++b)
          block[b] += values[static_cast<std::size_t>(r) * m_w + b];
      }
      for (std::size_t b = 0; b < m_w; ++b) out[b] += block[b];
    }
    return out;
  }

  void evaluate() {
    m_cs.assign(2 * cells(), 0.0);
    m_cs32.assign(2 * cells(), 0.0F);
    for (std::size_t k = 0; k < cells(); ++k) {
      sincos_one(theta[k], m_cs[2 * k], m_cs[2 * k + 1]);
      m_cs32[2 * k] = static_cast<float>(m_cs[2 * k]);
      m_cs32[2 * k + 1] = static_cast<float>(m_cs[2 * k + 1]);
    }
    m_g.assign(cells(), 0.0);
    m_y.assign(cells(), LocalField{0.0, 0.0});
    if (m_complete) {
      complete_fields();
    } else {
      for (std::size_t k = 0; k < cells(); ++k) {
        const std::size_t row = k / m_w;
        const int lane = static_cast<int>(k % m_w);
        const bool weighted = !m_net.weights.empty();
        m_y[k] = m_float32 ? row_field<float, std::int64_t, std::int32_t>(
                                 m_net.offsets[row], m_net.offsets[row + 1], m_net.columns.data(),
                                 weighted ? m_weights32.data() : nullptr, m_cs32.data(), m_b, lane)
                           : row_field<double, std::int64_t, std::int32_t>(
                                 m_net.offsets[row], m_net.offsets[row + 1], m_net.columns.data(),
                                 weighted ? m_net.weights.data() : nullptr, m_cs.data(), m_b, lane);
        m_g[k] =
            coupling_force(1.0 / static_cast<double>(m_n), m_cs[2 * k], m_cs[2 * k + 1], m_y[k]);
      }
    }
  }

  // rank_one_force.cpp: Z = sum_m a_m e^{i theta_m} by 2048-row blocks of each rank's rows,
  // each from 0 in order, the blocks in order from 0 (OrderedColumnSums), the ranks' Z added in
  // rank order (spread_over), then y_n = a_n Z - [no diagonal] a_n^2 e^{i theta_n}.
  void complete_fields() {
    for (std::size_t rank = 0; rank < rank_count(); ++rank) {
      const std::vector<double> z = rank_z(first_row(rank), first_row(rank + 1));
      if (rank == 0) {
        m_z = z;
      } else {
        for (std::size_t j = 0; j < z.size(); ++j) m_z[j] += z[j];
      }
    }
    for (std::size_t k = 0; k < cells(); ++k) {
      const std::size_t b = k % m_w;
      m_y[k] = rank_one_field(m_a[k / m_w], m_z[2 * b], m_z[2 * b + 1], m_cs[2 * k],
                              m_cs[2 * k + 1], m_self_loops);
      m_g[k] = coupling_force(1.0 / static_cast<double>(m_n), m_cs[2 * k], m_cs[2 * k + 1], m_y[k]);
    }
  }

  // One rank's Z over rows [begin, end), [Re, Im] per replica.
  std::vector<double> rank_z(std::int64_t begin, std::int64_t end) const {
    std::vector<double> z(2 * m_w, 0.0);
    for (std::int64_t first = begin; first < end; first += 2048) {
      std::vector<double> block(2 * m_w, 0.0);
      for (std::int64_t r = first; r < std::min(end, first + 2048); ++r) {
        for (std::size_t b = 0; b < m_w; ++b) {
          const std::size_t k = static_cast<std::size_t>(r) * m_w + b;
          block[2 * b] += m_a[static_cast<std::size_t>(r)] * m_cs[2 * k];
          block[2 * b + 1] += m_a[static_cast<std::size_t>(r)] * m_cs[2 * k + 1];
        }
      }
      for (std::size_t j = 0; j < block.size(); ++j) z[j] += block[j];
    }
    return z;
  }

  cuda::HostCsr m_net;
  std::int64_t m_n;
  int m_b;
  std::size_t m_w;
  bool m_float32;
  bool m_complete = false;
  bool m_self_loops = true;
  std::vector<double> m_a;                // rank-one: a_n
  std::vector<std::int64_t> m_rank_rows;  // spread_over's rows a rank; empty: one rank
  std::vector<double> m_cs, m_g, m_z;
  std::vector<float> m_cs32;
  std::vector<float> m_weights32;  // the weights narrowed as network_force.cpp narrows them
  std::vector<LocalField> m_y;
};

}  // namespace hmfnet::gpu_test
