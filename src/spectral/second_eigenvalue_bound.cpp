#include "spectral/second_eigenvalue_bound.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "core/random.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

using Local = std::vector<double>;

double dot(const Local& a, const Local& b) {
  double local = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) local += a[k] * b[k];
  return ParallelSession::sum(local);
}

void axpy(double alpha, const Local& x, Local& y) {
  for (std::size_t k = 0; k < y.size(); ++k) y[k] += alpha * x[k];
}

// v <- P v = v - u (u^T v).
void deflate(const Local& u, Local& v) { axpy(-dot(u, v), u, v); }

// Largest eigenvalue of the k x k tridiagonal matrix (alpha, beta).
double largest_ritz_value(const std::vector<double>& alpha, const std::vector<double>& beta) {
  const auto k = static_cast<Eigen::Index>(alpha.size());
  Eigen::VectorXd diagonal = Eigen::Map<const Eigen::VectorXd>(alpha.data(), k);
  Eigen::VectorXd off = Eigen::VectorXd::Zero(std::max<Eigen::Index>(k - 1, 0));
  for (Eigen::Index j = 0; j + 1 < k; ++j) off[j] = beta[static_cast<std::size_t>(j)];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off, Eigen::EigenvaluesOnly);
  return solver.eigenvalues()[k - 1];
}

}  // namespace

SecondEigenvalueBound bound_second_eigenvalue(const DistributedNetwork& network,
                                              const std::vector<double>& u, double lambda,
                                              const std::function<bool(double, double)>& decided,
                                              int max_steps, double failure_probability,
                                              std::uint64_t seed) {
  const auto first = static_cast<std::size_t>(network.first_row());
  const auto rows = static_cast<std::size_t>(network.local_size());
  const Local u_local(u.begin() + static_cast<std::ptrdiff_t>(first),
                      u.begin() + static_cast<std::ptrdiff_t>(first + rows));
  Local v(rows), previous(rows, 0.0), w;
  for (std::size_t k = 0; k < rows; ++k) v[k] = Rng(seed, first + k).normal();
  deflate(u_local, v);
  const double norm = std::sqrt(dot(v, v));
  for (double& x : v) x /= norm;

  const double shift = lambda * (1.0 + 1e-6);
  // sqrt(eps_k) (2k - 1) = log(1.648 sqrt(n) / delta_k), delta_k = 6 delta / (pi^2 k^2).
  const double pi = std::acos(-1.0);
  const double log_factor = std::log(1.648 * std::sqrt(static_cast<double>(network.global_size())) *
                                     pi * pi / (6.0 * failure_probability));
  SecondEigenvalueBound bound;
  bound.failure_probability = failure_probability;
  bound.lower = -std::numeric_limits<double>::infinity();
  bound.upper = std::numeric_limits<double>::infinity();
  std::vector<double> alpha, beta;
  double beta_previous = 0.0;
  for (int k = 1; k <= max_steps; ++k) {
    network.apply(v, w);
    deflate(u_local, w);
    alpha.push_back(dot(w, v));
    axpy(-alpha.back(), v, w);
    axpy(-beta_previous, previous, w);
    const double theta = largest_ritz_value(alpha, beta);
    bound.steps = k;
    bound.lower = std::max(bound.lower, theta);
    const double root_eps = (log_factor + 2.0 * std::log(static_cast<double>(k))) / (2.0 * k - 1.0);
    const double eps = root_eps * root_eps;
    if (eps < 1.0) {
      bound.upper = std::min(bound.upper, (bound.lower + shift) / (1.0 - eps) - shift);
    }
    const double b = std::sqrt(dot(w, w));
    // Breakdown, relative to the scale of B: the Krylov space is invariant.
    if (!(b > 1e-12 * std::max(shift, 1.0)) ||
        static_cast<std::int64_t>(k) + 1 >= network.global_size()) {
      bound.exact = true;
      bound.upper = bound.lower;
      return bound;
    }
    if (decided(bound.lower, bound.upper)) return bound;
    beta.push_back(b);
    previous.swap(v);
    for (std::size_t j = 0; j < rows; ++j) v[j] = w[j] / b;
    beta_previous = b;
  }
  return bound;
}

}  // namespace hmfnet
