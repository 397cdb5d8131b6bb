// The integrator family behind one interface: measured convergence orders by halving
// the step (MFEM's ODE tests: order = log2(e_h / e_{h/2}) >= p - 0.1), Yoshida's energy order,
// RK4's secular energy drift against leap-frog's bounded error, reversibility, momentum
// conservation, the evaluation count each integrator reports and thread determinism.
//
// Regime: ER N = 400, q = 0.05 (lambda ~ Nq + 1 = 21), Gaussian momenta sigma0 = 1, so
// K_c = 2 sigma0^2 N / lambda ~ 38 (criticalKFirstOrder) and K = 300 ~ 8 K_c: strongly coupled,
// the forces are large and the step errors far above round-off. The fastest rotors oscillate
// at omega ~ sqrt(K d_max / N) ~ 5, so omega h <= 0.1 for h <= 0.02 (0.2 for Blanes-Moan's
// h = 0.04, whose error constant is ~300 times smaller): the leading error term dominates and
// the measured orders sit within 0.05 of the nominal ones. T = 2 is about one oscillation
// period: chaotic amplification of the error stays moderate and linear in the local errors.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/network_force.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;

namespace {

constexpr double k_strong = 300.0;  // ~ 8 K_c, see the header
constexpr double k_final_time = 2.0;

/// MFEM's order test margin: the measured order of a p-th order method is >= p - 0.1.
constexpr double k_order_margin = 0.1;

/// The reference solution's own error (measured against half its step) must be below 1% of the
/// smallest error it judges: it then shifts a measured order by at most log2(1.01 / 0.99) = 0.03,
/// well inside k_order_margin.
constexpr double k_reference_share = 1e-2;

/// Reference: Blanes-Moan SRKN_6^b at h = 0.002. Its error is 6e-9 at h = 0.02 and falls as
/// h^4, so ~6e-13 here, next to the round-off floor (~2e-12 measured) and 1e-4 of the smallest
/// error judged (Blanes-Moan's own, 6e-9 at h = 0.02).
constexpr double k_reference_h = 0.002;

const std::vector<std::string> k_all_names = {"leapfrog", "yoshida4", "blanes_moan", "rk4"};

/// One OpenMP thread while it lives (every Fixture holds one), restoring the count. Results do not
/// depend on the thread count (bit-identical: last test case), and at N = 400 each parallel
/// region holds microseconds of work: on a loaded 2-core machine the passive barriers of ~10^5
/// regions cost 10-30 s against ~1 s single-threaded (measured on the drift test).
class OneThread {
 public:
  OneThread() { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(m_saved); }
  OneThread(const OneThread&) = delete;
  OneThread& operator=(const OneThread&) = delete;

 private:
  int m_saved = omp_get_max_threads();
};

struct Fixture {
  OneThread serial;
  Network net = erdos_renyi({400, 0.05, 11});
  DistributedNetwork distributed{net};
  NetworkForce force{distributed};
  RotorState initial() const {
    return initial_state(distributed.first_row(), distributed.local_size(), {{6.0, 1.0, 5}});
  }
  /// The force at the phases of `s`, ready for a first step.
  ForceEvaluation force_at(const RotorState& s) {
    ForceEvaluation f(force);
    f.update(s);
    return f;
  }
};

RotorState run(const Integrator& method, Fixture& fx, double h, double T, double K) {
  RotorState s = fx.initial();
  ForceEvaluation f = fx.force_at(s);
  for (long k = 0; k < std::lround(T / h); ++k) method.step(s, h, {K}, f);
  return s;
}

/// max_n max(|theta_n - theta_n'|, |p_n - p_n'|) over all ranks.
double distance(const RotorState& a, const RotorState& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.p.size(); ++k) {
    worst = std::max({worst, std::abs(a.theta[k] - b.theta[k]), std::abs(a.p[k] - b.p[k])});
  }
  return ParallelSession::max(worst);
}

/// H = sum p^2/2 - (K/2N) sum_n Re(e^{-i theta_n} y_n) from the cached force sums, which every
/// integrator leaves at the new phases.
double energy(const RotorState& s, const ForceEvaluation& f, double K, double n) {
  double kinetic = 0.0;
  for (const double p : s.p) kinetic += 0.5 * p * p;
  return ParallelSession::sum(kinetic) - K / (2 * n) * ParallelSession::sum(f.sums().coupling[0]);
}

/// log2(e_h / e_{h/2}) of the state at k_final_time against the reference solution.
double measured_state_order(const std::string& name, double h) {
  Fixture fx;
  const KickDriftSplitting reference_method = blanes_moan4();
  const RotorState reference = run(reference_method, fx, k_reference_h, k_final_time, k_strong);
  const RotorState finer = run(reference_method, fx, k_reference_h / 2, k_final_time, k_strong);
  const auto method = make_integrator(name);
  const double e_h = distance(run(*method, fx, h, k_final_time, k_strong), reference);
  const double e_half = distance(run(*method, fx, h / 2, k_final_time, k_strong), reference);
  const double reference_error = distance(reference, finer);
  INFO(name << ": e(h=" << h << ") = " << e_h << ", e(h=" << h / 2 << ") = " << e_half
            << ", reference error ~ " << reference_error);
  REQUIRE(reference_error <= k_reference_share * e_half);
  return std::log2(e_h / e_half);
}

/// Per half of [0, T]: the largest relative energy error, and the error at the half's end.
struct EnergyHalves {
  double max_first = 0.0, max_second = 0.0, end_first = 0.0, end_second = 0.0;
};

EnergyHalves energy_halves(const Integrator& method, Fixture& fx, double h, double T, double K) {
  RotorState s = fx.initial();
  ForceEvaluation f = fx.force_at(s);
  const double n = fx.net.size();
  const double e0 = energy(s, f, K, n);
  const long steps = std::lround(T / h);
  EnergyHalves out;
  for (long k = 1; k <= steps; ++k) {
    method.step(s, h, {K}, f);
    const double error = std::abs(energy(s, f, K, n) - e0) / std::abs(e0);
    const bool first = 2 * k <= steps;
    double& worst = first ? out.max_first : out.max_second;
    worst = std::max(worst, error);
    (first ? out.end_first : out.end_second) = error;
  }
  return out;
}

}  // namespace

TEST_CASE("make_integrator builds every named method and lists the names when it fails [factory]",
          "[integrator]") {
  const std::vector<int> orders = {2, 4, 4, 4};
  const std::vector<int> evaluations = {1, 3, 6, 4};
  for (std::size_t i = 0; i < k_all_names.size(); ++i) {
    const auto method = make_integrator(k_all_names[i]);
    CHECK(method->name() == k_all_names[i]);
    CHECK(method->order() == orders[i]);
    CHECK(method->evaluations_per_step() == evaluations[i]);
  }
  // One kick short of a splitting and one whose kicks sum to 0.9 (a typo in a coefficient).
  CHECK_THROWS_AS(KickDriftSplitting("bad", 2, {0.5}, {1.0}), ParameterError);
  CHECK_THROWS_AS(KickDriftSplitting("bad", 2, {0.5, 0.4}, {1.0}), ParameterError);
  try {
    make_integrator("euler");
    FAIL("an unknown integrator name was accepted");
  } catch (const ParameterError& e) {
    const std::string message = e.what();
    INFO(message);
    for (const auto& name : k_all_names) CHECK(message.find(name) != std::string::npos);
  }
}

TEST_CASE(
    "Each integrator step costs its reported evaluations and leaves the force at the new "
    "phases [ER N=400 K=8Kc]",
    "[integrator]") {
  Fixture fx;
  for (const auto& name : k_all_names) {
    const auto method = make_integrator(name);
    RotorState s = fx.initial();
    ForceEvaluation f = fx.force_at(s);
    for (int k = 0; k < 10; ++k) method->step(s, 0.01, {k_strong}, f);
    std::vector<double> g;
    ForceSums sums;
    fx.force.evaluate(s, g, sums);
    INFO(name);
    CHECK(f.count() == 1 + 10 * method->evaluations_per_step());
    // Same phases, same deterministic kernel: the cached force must be bit-identical.
    CHECK(test::bit_difference(f.g(), g) == "");
    CHECK(test::bit_difference(f.sums().coupling, sums.coupling) == "");
  }
}

TEST_CASE("Leap-frog state error converges at second order [ER N=400 K=8Kc T=2]", "[integrator]") {
  const double order = measured_state_order("leapfrog", 0.02);
  INFO("measured order " << order);
  REQUIRE(order >= 2 - k_order_margin);
}

TEST_CASE("Yoshida4 state error converges at fourth order [ER N=400 K=8Kc T=2]", "[integrator]") {
  const double order = measured_state_order("yoshida4", 0.02);
  INFO("measured order " << order);
  REQUIRE(order >= 4 - k_order_margin);
}

TEST_CASE("RK4 state error converges at fourth order [ER N=400 K=8Kc T=2]", "[integrator]") {
  const double order = measured_state_order("rk4", 0.02);
  INFO("measured order " << order);
  REQUIRE(order >= 4 - k_order_margin);
}

TEST_CASE("Blanes-Moan state error converges at fourth order [ER N=400 K=8Kc T=2]",
          "[integrator]") {
  // h twice as large as the others: its error at h = 0.02 / 2 (4e-10) would approach the
  // reference's 1% share.
  const double order = measured_state_order("blanes_moan", 0.04);
  INFO("measured order " << order);
  REQUIRE(order >= 4 - k_order_margin);
}

TEST_CASE("Yoshida4 energy error is fourth order [ER N=400 K=8Kc T=2]", "[integrator]") {
  Fixture fx;
  const KickDriftSplitting method = yoshida4();
  const auto coarse = energy_halves(method, fx, 0.02, k_final_time, k_strong);
  const auto fine = energy_halves(method, fx, 0.01, k_final_time, k_strong);
  const double e_h = std::max(coarse.max_first, coarse.max_second);
  const double e_half = std::max(fine.max_first, fine.max_second);
  const double order = std::log2(e_h / e_half);
  INFO("max relative energy error h=0.02: " << e_h << ", h=0.01: " << e_half << ", order "
                                            << order);
  REQUIRE(order >= 4 - k_order_margin);
}

TEST_CASE(
    "RK4 energy drifts secularly while the leap-frog energy error stays bounded "
    "[ER N=400 K=8Kc T=200]",
    "[integrator]") {
  // Backward error analysis (Hairer, Lubich & Wanner, Geometric Numerical Integration, IX.8): a
  // symplectic method conserves a modified energy, so its energy error stays O(h^2) over
  // exponentially long times; RK4's modified equation is not Hamiltonian and its energy error
  // grows linearly (measured: 4.6e-7 per 50 time units here at h = 0.02).
  Fixture fx;
  const double h = 0.02;
  const double T = 200.0;
  const auto leapfrog = energy_halves(LeapFrog(), fx, h, T, k_strong);
  const auto rk4 = energy_halves(RungeKutta4(), fx, h, T, k_strong);
  INFO("leap-frog max |dE|/E first half " << leapfrog.max_first << ", second half "
                                          << leapfrog.max_second);
  INFO("RK4 |dE|/E at T/2 " << rk4.end_first << ", at T " << rk4.end_second);
  // Bounded: the second half's largest error is the same fluctuation as the first's (measured
  // ratio ~1.0); growth like RK4's would double it.
  CHECK(leapfrog.max_second <= 1.25 * leapfrog.max_first);
  // Linear growth doubles the error from T/2 to T; a bounded error would give ~1 and an
  // accumulation of random round-off sqrt(2) = 1.41, so >= 1.7 asserts the secular drift.
  CHECK(rk4.end_second >= 1.7 * rk4.end_first);
  CHECK(rk4.end_second <= 2.5 * rk4.end_first);  // and not faster than linear
}

TEST_CASE(
    "Yoshida4 and Blanes-Moan are time reversible: forward then flip p then back returns "
    "to the start [ER N=400 K=8Kc]",
    "[integrator]") {
  // Symmetric compositions are symmetric methods (Phi_{-h} = Phi_h^{-1}); with p -> -p
  // reversibility the return trip undoes the forward one up to round-off, which over 2 x 250
  // steps of 3-6 stages stays far below 1e-9 (as for leap-frog in test_integrator.cpp).
  Fixture fx;
  const RotorState s0 = fx.initial();
  for (const std::string name : {"yoshida4", "blanes_moan"}) {
    const auto method = make_integrator(name);
    RotorState s = s0;
    ForceEvaluation f = fx.force_at(s);
    for (int k = 0; k < 250; ++k) method->step(s, 0.02, {k_strong}, f);
    for (double& p : s.p) p = -p;  // the cached force depends on the phases only
    for (int k = 0; k < 250; ++k) method->step(s, 0.02, {k_strong}, f);
    for (double& p : s.p) p = -p;
    const double deviation = distance(s, s0);
    INFO(name << ": max deviation from the initial state " << deviation);
    CHECK(deviation < 1e-9);
  }
}

TEST_CASE("Every integrator conserves total momentum to round-off [ER N=400 K=8Kc]",
          "[integrator]") {
  // Each kick adds pair forces that are antisymmetric (A symmetric), and RK4 like every
  // Runge-Kutta method conserves linear invariants (Hairer, Lubich & Wanner, Sec. IV.1): the
  // total changes only by round-off, ~1e-16 relative per step.
  Fixture fx;
  for (const auto& name : k_all_names) {
    const auto method = make_integrator(name);
    RotorState s = fx.initial();
    ForceEvaluation f = fx.force_at(s);
    double scale = 0.0;
    double p0 = 0.0;
    for (const double p : s.p) {
      scale += std::abs(p);
      p0 += p;
    }
    scale = ParallelSession::sum(scale);
    p0 = ParallelSession::sum(p0);
    double worst = 0.0;
    for (int k = 0; k < 500; ++k) {
      method->step(s, 0.02, {k_strong}, f);
      double total = 0.0;
      for (const double p : s.p) total += p;
      worst = std::max(worst, std::abs(ParallelSession::sum(total) - p0) / scale);
    }
    INFO(name << ": max |P(t) - P(0)| / sum |p| = " << worst);
    CHECK(worst <= 1e-10);
  }
}

TEST_CASE("Every integrator is bit-identical with 1 and 2 OpenMP threads [ER N=400]",
          "[integrator]") {
  Fixture fx;
  const int saved = omp_get_max_threads();
  for (const auto& name : k_all_names) {
    const auto method = make_integrator(name);
    std::vector<RotorState> finals;
    for (const int threads : {1, 2}) {
      omp_set_num_threads(threads);
      finals.push_back(run(*method, fx, 0.02, 1.0, k_strong));
    }
    INFO(name);
    CHECK(test::bit_difference(finals[0].theta, finals[1].theta) == "");
    CHECK(test::bit_difference(finals[0].p, finals[1].p) == "");
  }
  omp_set_num_threads(saved);
}

TEST_CASE("Each method's linear stability bound: closed forms and Yoshida's [harmonic oscillator]",
          "[integrator]") {
  // Leap-frog as a splitting (kicks 1/2, 1/2; drift 1): |trace| = |2 - x^2| < 2 iff x < 2.
  const KickDriftSplitting leapfrog_as_splitting("leapfrog", 2, {0.5, 0.5}, {1.0});
  CHECK_THAT(leapfrog_as_splitting.stability_limit(), Catch::Matchers::WithinAbs(2.0, 1e-9));
  CHECK(LeapFrog().stability_limit() == 2.0);
  CHECK_THAT(RungeKutta4().stability_limit(),
             Catch::Matchers::WithinAbs(2.0 * std::sqrt(2.0), 1e-15));
  // Yoshida's triple jump, independently: the product of three leap-frog maps
  // [[1 - y^2/2, y], [-y (1 - y^2/4), 1 - y^2/2]] at y = w1 x, w0 x, w1 x (kicks unmerged, unlike
  // the splitting's own product); its first crossing of |trace| = 2, scanned at 1e-5, is 1.57341.
  const double c = std::cbrt(2.0), w1 = 1.0 / (2.0 - c), w0 = -c / (2.0 - c);
  const auto trace = [&](double x) {
    double a = 1.0, b = 0.0, cc = 0.0, dd = 1.0;  // running product, row-major
    for (const double y : {w1 * x, w0 * x, w1 * x}) {
      const double m00 = 1 - y * y / 2, m01 = y, m10 = -y * (1 - y * y / 4), m11 = m00;
      const double na = m00 * a + m01 * cc, nb = m00 * b + m01 * dd;
      const double nc = m10 * a + m11 * cc, nd = m10 * b + m11 * dd;
      a = na, b = nb, cc = nc, dd = nd;
    }
    return a + dd;
  };
  double first_unstable = 0.0;
  for (double x = 1e-5; x < 4.0 && first_unstable == 0.0; x += 1e-5) {
    if (std::abs(trace(x)) >= 2.0) first_unstable = x;
  }
  CHECK_THAT(yoshida4().stability_limit(), Catch::Matchers::WithinAbs(first_unstable, 1e-5));
  CHECK_THAT(yoshida4().stability_limit(), Catch::Matchers::WithinAbs(1.5734, 1e-4));
  // Every method is stable just below its bound and unstable just above it.
  for (const auto& name : {"yoshida4", "blanes_moan"}) {
    const auto method = make_integrator(name);
    INFO(name << ": " << method->stability_limit());
    CHECK(method->stability_limit() > 0.5);
    CHECK(method->stability_limit() < 8.0);
  }
}
