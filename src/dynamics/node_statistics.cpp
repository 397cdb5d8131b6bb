#include "dynamics/node_statistics.hpp"

#include <cmath>
#include <complex>

#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

constexpr double k_pi = 3.14159265358979323846;

double wrap(double angle) {  // into [-pi, pi)
  return angle - 2.0 * k_pi * std::floor((angle + k_pi) / (2.0 * k_pi));
}

}  // namespace

NodeStatistics::NodeStatistics(NodeIndex first_row, NodeIndex rows, NodeIndex rotor,
                               std::int64_t rotor_samples, int bins, double omega)
    : m_first_row(first_row),
      m_rows(rows),
      m_rotor(rotor),
      m_omega(omega),
      m_rows_sums(k_row_width * static_cast<std::size_t>(rows), 0.0),
      m_histogram(static_cast<std::size_t>(bins), 0.0),
      m_rotor_theta(static_cast<std::size_t>(rotor_samples), 0.0),
      m_rotor_p(static_cast<std::size_t>(rotor_samples), 0.0) {}

void NodeStatistics::add(const RotorState& state, const std::vector<double>& y, double t,
                         double n) {
  const auto w = static_cast<std::size_t>(state.replicas);
  const auto rows = static_cast<std::size_t>(m_rows);
  // The measured frame (see the header): Psi = arg of the global field of replica 0.
  std::vector<double> global{0.0, 0.0};
  for (std::size_t r = 0; r < rows; ++r) {
    global[0] += y[2 * r * w];
    global[1] += y[2 * r * w + 1];
  }
  ParallelSession::sum_in_place(global);
  const double frame = std::atan2(global[1], global[0]);
  const bool first = m_count == 0;
  if (first) m_t_first = t;
  if (!first) m_frame_turned += wrap(frame - m_frame_last);
  m_frame_last = frame;
  m_t_last = t;
  const std::complex<double> rotation = std::polar(1.0, -frame);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::complex<double> field(y[2 * r * w] / n, y[2 * r * w + 1] / n);
    const std::complex<double> back = std::polar(1.0, -state.theta[r * w]);
    const std::complex<double> a = field * back, b = back / rotation, c = field * rotation;
    double* s = &m_rows_sums[k_row_width * r];
    s[0] += a.real();
    s[1] += a.imag();
    s[2] += b.real();
    s[3] += b.imag();
    s[4] += c.real();
    s[5] += c.imag();
    const double psi = std::arg(field);
    if (!first) s[6] += wrap(psi - s[7]);
    s[7] = psi;
  }
  ++m_count;
}

void NodeStatistics::add_phase_sample(const std::vector<double>& y, int replicas) {
  const auto w = static_cast<std::size_t>(replicas);
  // psi_1 (node 0) from its owner: the others contribute 0 to the sum.
  double psi_first = 0.0;
  if (m_first_row == 0 && m_rows > 0) psi_first = std::atan2(y[1], y[0]);
  psi_first = ParallelSession::sum(psi_first);
  const auto bins = static_cast<double>(m_histogram.size());
  for (std::size_t r = 0; r < static_cast<std::size_t>(m_rows); ++r) {
    const double psi = std::atan2(y[2 * r * w + 1], y[2 * r * w]);
    const double x = (wrap(psi - psi_first) + k_pi) / (2.0 * k_pi);  // in [0, 1)
    const auto bin = std::min(static_cast<std::size_t>(x * bins), m_histogram.size() - 1);
    m_histogram[bin] += 1.0;
  }
}

void NodeStatistics::add_rotor_sample(const RotorState& state, double) {
  const auto index = static_cast<std::size_t>(m_rotor_count++);
  if (index >= m_rotor_theta.size()) return;
  if (m_rotor < m_first_row || m_rotor >= m_first_row + m_rows) return;
  const auto r =
      static_cast<std::size_t>(m_rotor - m_first_row) * static_cast<std::size_t>(state.replicas);
  m_rotor_theta[index] = wrap(state.theta[r] - m_frame_last);
  m_rotor_p[index] = state.p[r] - m_omega;
}

std::vector<double> NodeStatistics::global_state() const {
  std::vector<double> g{static_cast<double>(m_count),
                        static_cast<double>(m_rotor_count),
                        m_frame_turned,
                        m_frame_last,
                        m_t_first,
                        m_t_last,
                        m_omega};
  static_assert(k_shared_globals == 7);
  g.insert(g.end(), m_histogram.begin(), m_histogram.end());
  g.insert(g.end(), m_rotor_theta.begin(), m_rotor_theta.end());
  g.insert(g.end(), m_rotor_p.begin(), m_rotor_p.end());
  return g;
}

void NodeStatistics::restore(std::vector<double> row_state, const std::vector<double>& global,
                             bool owner_of_globals) {
  m_rows_sums = std::move(row_state);
  m_count = static_cast<std::int64_t>(global[0]);
  m_rotor_count = static_cast<std::int64_t>(global[1]);
  m_frame_turned = global[2];
  m_frame_last = global[3];
  m_t_first = global[4];
  m_t_last = global[5];
  m_omega = global[6];
  // Rank-additive parts: the summed values go to one rank, zeros elsewhere.
  const std::size_t g0 = k_shared_globals, h = m_histogram.size(), s = m_rotor_theta.size();
  for (std::size_t k = 0; k < h; ++k) m_histogram[k] = owner_of_globals ? global[g0 + k] : 0.0;
  for (std::size_t k = 0; k < s; ++k) {
    m_rotor_theta[k] = owner_of_globals ? global[g0 + h + k] : 0.0;
    m_rotor_p[k] = owner_of_globals ? global[g0 + h + s + k] : 0.0;
  }
}

NodeStatisticsResult NodeStatistics::finish(const DistributedNetwork& network) const {
  NodeStatisticsResult out;
  const double span = m_t_last > m_t_first ? m_t_last - m_t_first : 1.0;
  out.omega = m_frame_turned / span;
  out.omega_momentum = m_omega;
  const auto count = static_cast<double>(std::max<std::int64_t>(m_count, 1));
  std::vector<std::vector<double>> columns(7);
  for (std::size_t r = 0; r < static_cast<std::size_t>(m_rows); ++r) {
    for (std::size_t k = 0; k < 6; ++k) {
      columns[k].push_back(m_rows_sums[k_row_width * r + k] / count);
    }
    columns[6].push_back(m_rows_sums[k_row_width * r + 6] / span);
  }
  for (auto& c : columns) c = network.gather(c);
  out.psi_frequency = columns[6];
  const std::size_t n = columns[0].size();
  std::complex<double> total;
  for (std::size_t i = 0; i < n; ++i) total += std::complex<double>(columns[4][i], columns[5][i]);
  out.phi = std::arg(total);
  const std::complex<double> e_phi = std::polar(1.0, out.phi);
  out.r.resize(n);
  out.fluctuation.resize(n);
  out.synchronised.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::complex<double> A(columns[0][i], columns[1][i]), B(columns[2][i], columns[3][i]),
        C(columns[4][i], columns[5][i]);
    out.r[i] = (C / e_phi).real();
    out.fluctuation[i] = (A - C * B).real();
    out.synchronised[i] = out.r[i] * (e_phi * B).real();
  }
  out.phase_histogram = m_histogram;
  ParallelSession::sum_in_place(out.phase_histogram);
  out.rotor_theta_bar = m_rotor_theta;
  out.rotor_p_bar = m_rotor_p;
  ParallelSession::sum_in_place(out.rotor_theta_bar);
  ParallelSession::sum_in_place(out.rotor_p_bar);
  for (double& x : out.rotor_theta_bar) x = wrap(x - out.phi);
  return out;
}

}  // namespace hmfnet
