// Leap-frog on the network: conservation laws, order, reversibility, determinism.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "dynamics/integrator.hpp"
#include "dynamics/network_force.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"

using namespace hmfnet;

namespace {

struct Fixture {
  Network net = erdos_renyi({600, 0.05, 3});
  DistributedNetwork distributed{net};
  NetworkForce force{distributed};
  RotorState initial() const {
    return initial_state(distributed.first_row(), distributed.local_size(), {{6.0, 1.0, 7}});
  }
};

double total(const std::vector<double>& local) {
  double s = 0.0;
  for (const double x : local) s += x;
  return ParallelSession::sum(s);
}

// H = sum p^2/2 - (K/2N) sum_n Re(e^{-i theta_n} y_n), from a fresh force evaluation.
double energy(const RotorState& s, NetworkForce& force, double K, double n) {
  std::vector<double> g;
  ForceSums sums;
  force.evaluate(s, g, sums);
  double kinetic = 0.0;
  for (const double p : s.p) kinetic += 0.5 * p * p;
  return ParallelSession::sum(kinetic) - K / (2 * n) * ParallelSession::sum(sums.coupling[0]);
}

double max_energy_error(Fixture& fx, double h, double T, double K) {
  RotorState s = fx.initial();
  ForceEvaluation f(fx.force);
  f.update(s);
  const double n = fx.net.size();
  const double e0 = energy(s, fx.force, K, n);
  double worst = 0.0;
  const LeapFrog lf;
  for (long k = 0; k < std::lround(T / h); ++k) {
    lf.step(s, h, {K}, f);
    worst = std::max(worst, std::abs(energy(s, fx.force, K, n) - e0));
  }
  return worst / std::abs(e0);
}

}  // namespace

TEST_CASE("Leap-frog conserves total momentum to round-off [ER N=600 K=3Kc]", "[integrator]") {
  Fixture fx;
  RotorState s = fx.initial();
  ForceEvaluation f(fx.force);
  f.update(s);
  double scale = 0.0;
  for (const double p : s.p) scale += std::abs(p);
  scale = ParallelSession::sum(scale);
  const double p0 = total(s.p);
  const LeapFrog lf;
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    lf.step(s, 0.01, {200.0}, f);
    worst = std::max(worst, std::abs(total(s.p) - p0) / scale);
  }
  INFO("max |P(t) - P(0)| / sum |p| = " << worst);
  REQUIRE(worst <= 1e-10);  // round-off; antisymmetric forces sum to zero exactly
}

TEST_CASE("Leap-frog energy error is second order [ER N=600]", "[integrator]") {
  Fixture fx;
  const double K = 300.0;  // strongly coupled, so the error is well above round-off
  const double e1 = max_energy_error(fx, 0.02, 2.0, K);
  const double e2 = max_energy_error(fx, 0.01, 2.0, K);
  const double ratio = e1 / e2;
  INFO("max energy error h=0.02: " << e1 << ", h=0.01: " << e2 << ", ratio " << ratio);
  REQUIRE(ratio >= 3.5);  // 2^2 = 4 for a second-order method (MFEM-style order test)
  REQUIRE(ratio <= 4.5);
}

TEST_CASE("Leap-frog is time reversible: forward / flip p / back returns to the start",
          "[integrator]") {
  Fixture fx;
  const RotorState s0 = fx.initial();
  RotorState s = s0;
  ForceEvaluation f(fx.force);
  f.update(s);
  const LeapFrog lf;
  for (int k = 0; k < 500; ++k) lf.step(s, 0.01, {150.0}, f);
  for (double& p : s.p) p = -p;
  for (int k = 0; k < 500; ++k) lf.step(s, 0.01, {150.0}, f);
  double worst = 0.0;
  for (std::size_t k = 0; k < s.p.size(); ++k) {
    worst = std::max({worst, std::abs(s.theta[k] - s0.theta[k]), std::abs(-s.p[k] - s0.p[k])});
  }
  INFO("max deviation from the initial state: " << worst);
  REQUIRE(worst < 1e-9);
}

TEST_CASE("Force and state are bit-identical with 1 and 2 OpenMP threads", "[integrator]") {
  Fixture fx;
  const int saved = omp_get_max_threads();
  std::vector<RotorState> finals;
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    RotorState s = fx.initial();
    ForceEvaluation f(fx.force);
    f.update(s);
    const LeapFrog lf;
    for (int k = 0; k < 300; ++k) lf.step(s, 0.01, {100.0}, f);
    finals.push_back(s);
  }
  omp_set_num_threads(saved);
  REQUIRE(finals[0].theta == finals[1].theta);
  REQUIRE(finals[0].p == finals[1].p);
}
