#include "support/dense_spectrum.hpp"

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace hmfnet::test {

DenseSpectrum dense_spectrum(const Network& network) {
  const NodeIndex n = network.size();
  if (n > 4000) {
    throw ParameterError("dense spectrum: N", std::to_string(n), "N <= 4000 (O(N^3) work)");
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (NodeIndex i = 0; i < n; ++i)
    for (const auto [j, w] : network.row(i)) a(i, j) = w;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(a);
  if (solver.info() != Eigen::Success) throw std::runtime_error("Eigen eigensolver failed");
  DenseSpectrum s;
  s.eigenvalues.assign(solver.eigenvalues().data(), solver.eigenvalues().data() + n);
  Eigen::VectorXd u = solver.eigenvectors().col(n - 1);
  if (u.sum() < 0.0) u = -u;
  s.perron.assign(u.data(), u.data() + n);
  return s;
}

}  // namespace hmfnet::test
