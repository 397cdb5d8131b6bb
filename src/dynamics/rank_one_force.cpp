#include "dynamics/rank_one_force.hpp"

#include <cmath>

#include "dynamics/ordered_sum.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

bool close(double x, double y) {
  return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
}

}  // namespace

std::optional<RankOneStructure> detect_rank_one(const Network& net) {
  const NodeIndex n = net.size();
  if (n < 3) return std::nullopt;
  const bool diagonal = net.self_loops() == n;
  if (!diagonal && (net.self_loops() != 0 || net.weighted())) return std::nullopt;
  const EdgeOffset full = diagonal ? n : n - 1;
  RankOneStructure s;
  s.diagonal = diagonal;
  s.a.assign(static_cast<std::size_t>(n), 1.0);
  for (NodeIndex i = 0; i < n; ++i) {
    if (static_cast<EdgeOffset>(net.row(i).size()) != full) return std::nullopt;
    if (diagonal && net.weighted()) {
      // Row i holds column i at position i (a full, sorted row).
      s.a[static_cast<std::size_t>(i)] = std::sqrt(net.weight(net.row_begin(i) + i));
    }
  }
  if (!net.weighted()) return s;
  for (NodeIndex i = 0; i < n; ++i) {
    for (const auto [j, w] : net.row(i)) {
      const double expected = s.a[static_cast<std::size_t>(i)] * s.a[static_cast<std::size_t>(j)];
      if (!close(w, expected)) return std::nullopt;
    }
  }
  return s;
}

RankOneForce::RankOneForce(RankOneStructure structure, NodeIndex first_row, NodeIndex rows)
    : m_structure(std::move(structure)),
      m_first_row(first_row),
      m_rows(rows),
      m_inverse_n(1.0 / static_cast<double>(m_structure.a.size())) {}

void RankOneForce::evaluate(const RotorState& state, std::vector<double>& g, ForceSums& sums) {
  const int nb = state.replicas;
  const auto w = static_cast<std::size_t>(nb);
  const auto rows = static_cast<std::size_t>(state.rows);
  // Z_b = sum_m a_m e^{i theta_m}: ordered local sums, then over ranks.
  std::vector<double> terms(rows * 2 * w);
  for (std::size_t r = 0; r < rows; ++r) {
    const double a = m_structure.a[static_cast<std::size_t>(m_first_row) + r];
    for (std::size_t b = 0; b < w; ++b) {
      terms[(r * w + b) * 2] = a * std::cos(state.theta[r * w + b]);
      terms[(r * w + b) * 2 + 1] = a * std::sin(state.theta[r * w + b]);
    }
  }
  std::vector<double> z;
  ordered_column_sums(terms, rows, 2 * nb, z);
  ParallelSession::sum_in_place(z);
  g.resize(rows * w);
  m_y.resize(2 * rows * w);
  m_abs_y.resize(rows * w);
  m_coupling.resize(rows * w);
  for (std::size_t r = 0; r < rows; ++r) {
    const double a = m_structure.a[static_cast<std::size_t>(m_first_row) + r];
    for (std::size_t b = 0; b < w; ++b) {
      const double c = std::cos(state.theta[r * w + b]), s = std::sin(state.theta[r * w + b]);
      double yc = a * z[2 * b], ys = a * z[2 * b + 1];
      if (!m_structure.diagonal) {
        yc -= a * a * c;
        ys -= a * a * s;
      }
      g[r * w + b] = m_inverse_n * (c * ys - s * yc);
      m_y[2 * (r * w + b)] = yc;
      m_y[2 * (r * w + b) + 1] = ys;
      m_abs_y[r * w + b] = std::sqrt(yc * yc + ys * ys);
      m_coupling[r * w + b] = c * yc + s * ys;
    }
  }
  ordered_column_sums(m_abs_y, rows, nb, sums.order);
  ordered_column_sums(m_coupling, rows, nb, sums.coupling);
}

}  // namespace hmfnet
