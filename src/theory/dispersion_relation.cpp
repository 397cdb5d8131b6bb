#include "theory/dispersion_relation.hpp"

#include <Eigen/Dense>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace hmfnet {

namespace {

using Complex = std::complex<double>;
constexpr Complex k_i{0.0, 1.0};
constexpr int k_max_dense_nodes = 2000;

void check_inputs(double K, const std::vector<double>& p, Complex s0) {
  if (!(K > 0.0) || !std::isfinite(K)) throw ParameterError("K", std::to_string(K), "0 < K < inf");
  if (p.empty()) throw ParameterError("momenta", "empty", "one per node");
  if (!(s0.real() > 0.0)) {
    throw ParameterError("initial s", std::to_string(s0.real()), "Re s > 0 (a growing mode)");
  }
}

// One Newton step s - F/F' that keeps Re s > 0 (the relation holds only for growing modes).
Complex guarded_step(Complex s, Complex step) {
  Complex next = s - step;
  for (int k = 0; k < 60 && !(next.real() > 0.0); ++k) {
    step *= 0.5;
    next = s - step;
  }
  return next;
}

}  // namespace

DispersionRoot solve_independent_dispersion(double K, double lambda, const std::vector<double>& p,
                                            Complex s0, const DispersionOptions& options) {
  check_inputs(K, p, s0);
  const double n = static_cast<double>(p.size());
  const double scale = K * lambda / (2.0 * n * n);  // (K lambda / 2N) times the 1/N of ||.||
  DispersionRoot out;
  out.s = s0;
  for (out.iterations = 0; out.iterations <= options.max_iterations; ++out.iterations) {
    Complex f = -1.0, df = 0.0;
    for (const double pn : p) {
      const Complex w = 1.0 / (out.s - k_i * pn);
      f += scale * w * w;
      df -= 2.0 * scale * w * w * w;
    }
    out.residual = std::abs(f);
    if (out.residual <= options.tolerance) {
      out.converged = true;
      break;
    }
    if (out.iterations == options.max_iterations) break;
    out.s = guarded_step(out.s, f / df);
  }
  return out;
}

namespace {

// The eigenpair of the complex symmetric S nearest `shift` by inverse iteration from x (updated in
// place, unit 2-norm): one LU of S - shift I, then solves until the eigen-residual
// |S x - mu x| / |mu| falls below 1e-12. Returns false if it does not within 200 solves.
bool nearest_eigenpair(const Eigen::MatrixXcd& S, Complex shift, Eigen::VectorXcd& x, Complex& mu) {
  const Eigen::MatrixXcd identity = Eigen::MatrixXcd::Identity(S.rows(), S.cols());
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(S - shift * identity);
  for (int k = 0; k < 200; ++k) {
    x = lu.solve(x);
    x /= x.norm();
    const Eigen::VectorXcd sx = S * x;
    mu = (x.transpose() * sx)(0) / (x.transpose() * x)(0);  // bilinear Rayleigh quotient
    if ((sx - mu * x).norm() <= 1e-12 * std::abs(mu)) return true;
  }
  return false;
}

// Newton's method on mu(s) = 2N/K for the eigenvalue mu of S(s) = D A D nearest 2N/K (inverse
// iteration from the previous eigenvector x). False if it does not converge.
bool newton_on_branch(const Eigen::MatrixXcd& a, double K, const std::vector<double>& p,
                      const DispersionOptions& options, Complex& s, Eigen::VectorXcd& x,
                      double& residual, int& steps) {
  const auto n = static_cast<Eigen::Index>(p.size());
  const double target = 2.0 * static_cast<double>(n) / K;
  for (int it = 0; it <= options.max_iterations; ++it) {
    Eigen::VectorXcd d(n);
    for (Eigen::Index i = 0; i < n; ++i) d(i) = 1.0 / (s - k_i * p[static_cast<std::size_t>(i)]);
    Complex mu;
    if (!nearest_eigenpair(d.asDiagonal() * a * d.asDiagonal(), target, x, mu)) return false;
    residual = std::abs(mu - target) / target;
    if (residual <= options.tolerance) return true;
    const Complex xdx = (x.array().square() * d.array()).sum();
    const Complex dmu = -2.0 * mu * xdx / x.array().square().sum();
    s = guarded_step(s, (mu - target) / dmu);
    ++steps;
  }
  return false;
}

}  // namespace

DispersionRoot solve_dispersion(const Network& network, double K, const std::vector<double>& p,
                                const DispersionOptions& options) {
  check_inputs(K, p, Complex(1.0, 0.0));
  const NodeIndex n = network.size();
  if (n > k_max_dense_nodes) {
    throw ParameterError("N", std::to_string(n), "N <= 2000 for the dense dispersion solver");
  }
  if (static_cast<std::size_t>(n) != p.size()) {
    throw ParameterError("momenta", std::to_string(p.size()) + " entries",
                         std::to_string(n) + " (one per node)");
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (NodeIndex i = 0; i < n; ++i)
    for (const auto [j, w] : network.row(i)) a(i, j) = w;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(a);
  const double lambda = eigen.eigenvalues()(n - 1);
  double mean_p = 0.0;
  for (const double x : p) mean_p += x / static_cast<double>(n);

  // Start at K_start = k_homotopy_start K, where every w_n ~ 1/s^2 alike: the Perron mode's root
  // is s = sqrt(K_start lambda / 2N) + i mean(p) with eigenvector u. Then lower K geometrically,
  // halving the step when Newton fails.
  const Eigen::MatrixXcd ac = a.cast<Complex>();
  double factor = options.homotopy_start;
  Complex s(std::sqrt(factor * K * lambda / (2.0 * n)), mean_p);
  Eigen::VectorXcd x = eigen.eigenvectors().col(n - 1).cast<Complex>();
  DispersionRoot out;
  double ratio = options.homotopy_ratio;
  bool on_branch = false;
  while (ratio > 1.0 + 1e-6) {
    Complex trial_s = s;
    Eigen::VectorXcd trial_x = x;
    const double next = on_branch ? std::max(1.0, factor / ratio) : factor;
    if (newton_on_branch(ac, next * K, p, options, trial_s, trial_x, out.residual,
                         out.iterations)) {
      s = trial_s;
      x = trial_x;
      factor = next;
      on_branch = true;
      if (factor == 1.0) break;
    } else {
      ratio = std::sqrt(ratio);
    }
  }
  out.s = s;
  out.converged = on_branch && factor == 1.0 && out.residual <= options.tolerance;
  return out;
}

Complex gaussian_dispersion_integral(Complex s, double Omega, double sigma0) {
  if (!(sigma0 > 0.0)) throw ParameterError("sigma0", std::to_string(sigma0), "sigma0 > 0");
  if (!(s.real() > 0.0)) throw ParameterError("Re s", std::to_string(s.real()), "Re s > 0");
  // p = Omega + sigma0 t, g(p) dp = exp(-t^2/2) dt / sqrt(2 pi).
  const double norm = 1.0 / std::sqrt(2.0 * 3.14159265358979323846);
  auto part = [&](bool imaginary) {
    auto f = [&](double t) {
      const Complex w = 1.0 / (s - k_i * (Omega + sigma0 * t));
      const Complex value = norm * std::exp(-0.5 * t * t) * w * w;
      return imaginary ? value.imag() : value.real();
    };
    const double inf = std::numeric_limits<double>::infinity();
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, -inf, inf, 20, 1e-13);
  };
  return {part(false), part(true)};
}

}  // namespace hmfnet
