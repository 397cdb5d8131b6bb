#include "theory/self_consistent_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "theory/anderson_acceleration.hpp"
#include "theory/bessel_ratio.hpp"

namespace hmfnet {

std::string solve_status_name(SolveStatus status) {
  switch (status) {
    case SolveStatus::converged:
      return "converged";
    case SolveStatus::incoherent:
      return "incoherent";
    case SolveStatus::failed:
      return "failed";
  }
  return "unknown";
}

SelfConsistentMap::SelfConsistentMap(const AdjacencyProduct& product, double offset)
    // A non-owning pointer (empty control block): the caller keeps the product alive.
    : m_product(std::shared_ptr<void>(), &product),
      m_offset(offset),
      m_v(static_cast<std::size_t>(product.size())) {
  if (product.size() < 1) throw ParameterError("self-consistent map: network", "0 nodes", "N >= 1");
}

SelfConsistentMap::SelfConsistentMap(const Network& network, double offset)
    : m_product(std::make_shared<NetworkProduct>(network)),
      m_offset(offset),
      m_v(static_cast<std::size_t>(network.size())) {
  if (network.size() < 1) throw ParameterError("self-consistent map: network", "0 nodes", "N >= 1");
}

void SelfConsistentMap::apply(const std::vector<double>& r, double eta, std::vector<double>& r_out,
                              double& eta_out) const {
  const NodeIndex n = m_product->size();
  const double inv_eta = 1.0 / eta;
  const double inv_n = 1.0 / static_cast<double>(n);
  double* v = m_v.data();
#pragma omp parallel for schedule(static)
  for (NodeIndex i = 0; i < n; ++i) v[i] = bessel_ratio(r[static_cast<std::size_t>(i)] * inv_eta);
  m_product->apply(m_v, r_out);
  for (double& x : r_out) x *= inv_n;
  double energy = 0.0;
  for (NodeIndex i = 0; i < n; ++i) energy += r[static_cast<std::size_t>(i)] * v[i];
  eta_out = m_offset + energy * inv_n;
}

namespace {

// max(|r' - r|_inf / |r'|_inf, |eta' - eta| / eta'); an exactly zero r' is the incoherent root,
// not a converged nontrivial solution, and reports an infinite residual.
double relative_residual(const std::vector<double>& r, const std::vector<double>& r_out, double eta,
                         double eta_out) {
  double diff = 0.0, size = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    diff = std::max(diff, std::abs(r_out[i] - r[i]));
    size = std::max(size, std::abs(r_out[i]));
  }
  if (!(size > 0.0)) return std::numeric_limits<double>::infinity();
  return std::max(diff / size, std::abs(eta_out - eta) / eta_out);
}

// Unknowns of the accelerated iteration: x = (log r_n for nodes with neighbours, log eta).
// In r itself Anderson's secant model is drawn to the incoherent root r = 0 (near it the map is
// linear, with that root), and near onset the relative residual there, 1 - K_c/K, is as small as
// that of a fair first guess. In logarithms the root lies at -infinity, every iterate is
// positive, and each r_n weighs by its relative change whatever its size (hubs and leaves
// alike). Extrapolated steps are shortened so that no component moves by more than
// k_max_log_step (a factor e^0.5 = 1.65), a trust region that keeps a poor first guess from being
// extrapolated far towards r = 0: on a star with a degree-shaped guess near onset, unlimited steps
// ended there (tests/theory/test_self_consistent.cpp), with 0.5 it converges in <= 46 steps.
// Nodes without neighbours have r_n = 0 exactly and are not unknowns, nor are the nodes of a
// component the guess starts at r = 0 (an incoherent component of a disconnected network, a fixed
// point of the map; self_consistent.cpp): as unknowns they would sit at the smallest normal
// double and drift there by the log of their linear growth factor, 1 - K lambda_c / (2 N mu)
// per iteration, a residual that Anderson's secant model cannot cancel (found at N = 10^4, where
// two components' lambda_c differ by 3e-4: 1000 iterations stalled at residual 1e-4). An r_n
// that underflows during the iteration is held at the smallest normal double so that its
// logarithm stays finite.
constexpr double k_max_log_step = 0.5;

// A node the guess puts at r = 0 stays there (it is not an unknown), which is a fixed point only
// if all its neighbours are 0 too, i.e. the zeros form whole components: A applied to the
// indicator of the non-zeros vanishes on every zero (one product, so it works on distributed
// rows too; with positive weights, as the theory assumes).
void require_closed_zero_set(const AdjacencyProduct& product, const std::vector<double>& r) {
  std::vector<double> nonzero(r.size()), reached;
  for (std::size_t i = 0; i < r.size(); ++i) nonzero[i] = r[i] != 0.0 ? 1.0 : 0.0;
  product.apply(nonzero, reached);
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (r[i] == 0.0 && reached[i] != 0.0) {
      throw ParameterError("self-consistent map: guess",
                           "0 at node " + std::to_string(i) + " but not at all its neighbours",
                           "zeros that cover whole components");
    }
  }
}

class LogVariables {
 public:
  LogVariables(const AdjacencyProduct& product, const std::vector<double>& guess) {
    const std::vector<double>& d = product.degrees();
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (d[i] > 0.0 && guess[i] > 0.0) m_active.push_back(i);
    }
  }
  std::size_t size() const { return m_active.size() + 1; }
  std::vector<double> pack(const std::vector<double>& r, double eta) const {
    std::vector<double> x(size());
    for (std::size_t k = 0; k < m_active.size(); ++k) {
      x[k] = std::log(std::max(r[m_active[k]], std::numeric_limits<double>::min()));
    }
    x.back() = std::log(eta);
    return x;
  }
  double unpack(const std::vector<double>& x, std::vector<double>& r) const {
    for (std::size_t k = 0; k < m_active.size(); ++k) r[m_active[k]] = std::exp(x[k]);
    return std::exp(x.back());
  }

 private:
  std::vector<std::size_t> m_active;
};

}  // namespace

MapFixedPoint iterate_self_consistent_map(const SelfConsistentMap& map,
                                          const std::vector<double>& r, double eta,
                                          const SelfConsistentOptions& options) {
  const auto n = static_cast<std::size_t>(map.size());
  if (r.size() != n) {
    throw ParameterError("self-consistent map: guess", std::to_string(r.size()) + " entries",
                         std::to_string(n) + " (one per node)");
  }
  if (!(eta > 0.0) || !std::isfinite(eta)) {
    throw ParameterError("self-consistent map: guess eta", std::to_string(eta), "0 < eta < inf");
  }
  require_closed_zero_set(map.product(), r);
  const LogVariables variables(map.product(), r);
  std::vector<double> r_in(n, 0.0), r_out(n, 0.0);
  const FixedPointMap log_map = [&](const std::vector<double>& x, std::vector<double>& gx) {
    const double eta_in = variables.unpack(x, r_in);
    double eta_out = 0.0;
    map.apply(r_in, eta_in, r_out, eta_out);
    gx = variables.pack(r_out, eta_out);
    return relative_residual(r_in, r_out, eta_in, eta_out);
  };

  AndersonOptions anderson;
  anderson.memory = options.anderson_memory;
  anderson.damping = options.damping;
  anderson.tolerance = options.tolerance;
  anderson.max_iterations = options.max_iterations;
  anderson.max_step = k_max_log_step;
  const FixedPointResult fp = anderson_fixed_point(log_map, variables.pack(r, eta), anderson);

  MapFixedPoint out;
  out.r.assign(n, 0.0);
  out.eta = variables.unpack(fp.x, out.r);
  out.converged = fp.converged;
  out.iterations = fp.iterations;
  out.residual = fp.residual;
  out.restarts = fp.restarts;
  return out;
}

double global_order_parameter(const std::vector<double>& r, double mean_degree) {
  double sum = 0.0;
  for (const double x : r) sum += x;
  return sum / mean_degree;
}

}  // namespace hmfnet
