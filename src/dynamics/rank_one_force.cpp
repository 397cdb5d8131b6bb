#include "dynamics/rank_one_force.hpp"

#include <cmath>

#include "dynamics/ordered_sum.hpp"
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
      m_inverse_n(1.0 / static_cast<double>(m_structure.a.size())) {}

void RankOneForce::prepare(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  const auto cells =
      static_cast<std::size_t>(state.rows) * static_cast<std::size_t>(state.replicas);
  const auto w = static_cast<std::size_t>(state.replicas);
  m_cs.resize(2 * cells);
  m_scratch.resize(2 * cells);
  m_z.resize(2 * w);
  m_z_sums.prepare(static_cast<std::size_t>(state.rows), 2 * state.replicas);
  g.resize(cells);
  m_y.resize(2 * cells);
  m_term_sums.resize(2 * w);
  m_sums.prepare(static_cast<std::size_t>(state.rows), 2 * state.replicas);
  sums.order.resize(w);
  sums.coupling.resize(w);
}

void RankOneForce::evaluate(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  if (outside_team()) prepare(state, g, sums);
  const int nb = state.replicas;
  const auto w = static_cast<std::size_t>(nb);
  const auto rows = static_cast<std::size_t>(state.rows);
  // Z_b = sum_m a_m e^{i theta_m}: ordered local sums, then over ranks. The [cos, sin] blocks
  // are shared out in other blocks than the rows below, so the loop after them reads them only
  // after their worksharing barrier.
  sincos_interleaved_team(state.theta.data(), rows * w, m_cs.data());
#pragma omp for schedule(static)
  for (std::size_t r = 0; r < rows; ++r) {
    const double a = m_structure.a[static_cast<std::size_t>(m_first_row) + r];
    for (std::size_t b = 0; b < w; ++b) {
      const std::size_t k = r * w + b;
      m_scratch[2 * k] = a * m_cs[2 * k];
      m_scratch[2 * k + 1] = a * m_cs[2 * k + 1];
    }
  }
  m_z_sums.sum(m_scratch.data(), m_z.data());
  // MPI on the master thread; the barrier after it gives every thread the reduced Z. The loop
  // below overwrites m_scratch: every read of it in the sum above ended at that sum's own
  // worksharing barrier, before the master's reduction and this barrier.
  on_master([&] { ParallelSession::sum_in_place(m_z); });
#pragma omp for schedule(static)
  for (std::size_t r = 0; r < rows; ++r) {
    const double a = m_structure.a[static_cast<std::size_t>(m_first_row) + r];
    for (std::size_t b = 0; b < w; ++b) {
      const std::size_t k = r * w + b;
      const double c = m_cs[2 * k], s = m_cs[2 * k + 1];  // the first loop's, after its barrier
      double yc = a * m_z[2 * b], ys = a * m_z[2 * b + 1];
      if (!m_structure.diagonal) {
        yc -= a * a * c;
        ys -= a * a * s;
      }
      g[k] = m_inverse_n * (c * ys - s * yc);
      m_y[2 * k] = yc;
      m_y[2 * k + 1] = ys;
      m_scratch[2 * k] = std::sqrt(yc * yc + ys * ys);
      m_scratch[2 * k + 1] = c * yc + s * ys;
    }
  }
  // Both sums of every replica in one ordered pass (each column is summed on its own).
  m_sums.sum(m_scratch.data(), m_term_sums.data());
#pragma omp master
  for (std::size_t b = 0; b < w; ++b) {
    sums.order[b] = m_term_sums[2 * b];
    sums.coupling[b] = m_term_sums[2 * b + 1];
  }
}

}  // namespace hmfnet
