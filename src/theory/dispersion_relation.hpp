#pragma once
// The dispersion relation of the incoherent state (Sec. dispersion and App. dispersion): a
// perturbation growing like e^{s t}, s = gamma + i omega with gamma > 0, exists when
//   eq:dispersion   b_k = (K / 2N) sum_n A_kn b_n / (s - i p_n)^2,
// i.e. when 2N/K is an eigenvalue of A diag((s - i p_n)^-2). If the momenta are independent of A
// (eq:bkApprox), b is the Perron vector and the condition becomes the scalar
//   eq:lambdaHat    1 = (K lambda / 2N) ||(s - i p)^-2||      (||.|| the node average),
// whose N -> infinity limit for Gaussian momenta is eq:gammaKKc (growth_rate.hpp). This file
// solves the first two on a finite network and sample of momenta, and evaluates the integral of
// the third by quadrature, to check the approximations against each other.
#include <complex>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

struct DispersionRoot {
  std::complex<double> s;  ///< gamma + i omega
  bool converged = false;
  int iterations = 0;     ///< Newton steps
  double residual = 0.0;  ///< relative: |mu(s) - 2N/K| / (2N/K) (eq:lambdaHat: |F(s)|)
};

struct DispersionOptions {
  double tolerance = 1e-12;       ///< on the relative residual
  int max_iterations = 50;        ///< Newton steps per solve (per continuation step)
  double homotopy_start = 100.0;  ///< solve_dispersion: K_start / K
  double homotopy_ratio = 1.5;    ///< solve_dispersion: first ratio of successive K
};

/// eq:lambdaHat for the sample p (N = p.size() >= 1), K > 0, lambda > 0, by Newton's method in
/// complex s from s0 (Re s0 > 0); steps that would leave Re s > 0 are halved.
DispersionRoot solve_independent_dispersion(double K, double lambda, const std::vector<double>& p,
                                            std::complex<double> s0,
                                            const DispersionOptions& options = {});

/// eq:dispersion on a network of N = p.size() <= 2000 nodes (dense: O(N^3) per Newton step;
/// throws ParameterError above). The relation has many roots (most with small Re s, near the
/// poles i p_n); the one wanted is the Perron mode. It is followed by continuation in K from
/// homotopy_start K, where all w_n = (s - i p_n)^-2 are nearly equal and the Perron mode's root is
/// s = sqrt(K lambda / 2N) + i mean(p) with eigenvector u, down to K in geometric steps (the ratio
/// square-rooted when Newton fails). At each K, Newton's method on the eigenvalue mu(s) of the
/// complex symmetric D A D, D = diag(1/(s - i p_n)), nearest 2N/K (inverse iteration from the
/// previous eigenvector x), with d mu/ds = -2 mu (x^T D x) / (x^T x) from D' = -D^2.
/// A branch followed this way is not guaranteed to stay the fastest-growing one on every network;
/// iterations counts Newton steps over the whole path.
DispersionRoot solve_dispersion(const Network& network, double K, const std::vector<double>& p,
                                const DispersionOptions& options = {});

/// The N -> infinity average of eq:lambdaHat for Gaussian momenta (mean Omega, std sigma0 > 0):
///   I(s) = int g(p) dp / (s - i p)^2,  Re s > 0,
/// by adaptive Gauss-Kronrod quadrature over the whole line (relative error ~1e-12 unless
/// Re s << sigma0, where the integrand peaks sharply). eq:gammaKKc is the closed form of
/// I(gamma + i Omega) = 2N / (K lambda) = K_c / (K sigma0^2).
std::complex<double> gaussian_dispersion_integral(std::complex<double> s, double Omega,
                                                  double sigma0);

}  // namespace hmfnet
