// Leap-frog on the network: conservation laws, order, reversibility, determinism.
#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "dynamics/integrator.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/thread_choice.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/bit_difference.hpp"

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
  REQUIRE(test::bit_difference(finals[0].theta, finals[1].theta) == "");
  REQUIRE(test::bit_difference(finals[0].p, finals[1].p) == "");
}

TEST_CASE("Kick and kick-drift of one replica take the general loop's operations, bit for bit",
          "[integrator]") {
  // One replica runs a flat loop of its own; these are the operations of the loop over rows and
  // replicas written out: p += (c K) g, then theta += c_drift p. Values of mixed magnitude, so
  // that forming c (K g) instead changes bits.
  const NodeIndex rows = 1000;
  RotorState state;
  state.rows = rows;
  state.theta.resize(rows);
  state.p.resize(rows);
  std::vector<double> g(rows);
  for (NodeIndex r = 0; r < rows; ++r) {
    const auto k = static_cast<std::size_t>(r);
    state.theta[k] = 0.1 + 1e-3 * static_cast<double>(r % 97);
    state.p[k] = 6.0 + std::sin(static_cast<double>(r));
    g[k] = std::cos(0.7 * static_cast<double>(r)) * std::pow(10.0, static_cast<double>(r % 9) - 4);
  }
  const std::vector<double> K{1.3 / 3.0};
  const double c_kick = 0.05 / 3.0, c_drift = 0.1 / 7.0;
  RotorState expected = state;
  for (std::size_t k = 0; k < g.size(); ++k) {
    const double cK = c_kick * K[0];
    expected.p[k] = expected.p[k] + cK * g[k];
    expected.theta[k] = expected.theta[k] + c_drift * expected.p[k];
  }
  for (const int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    RotorState s = state;
#pragma omp parallel
    kick_drift(s, c_kick, K, g, c_drift);
    CHECK(test::bit_difference(s.p, expected.p) == "");
    CHECK(test::bit_difference(s.theta, expected.theta) == "");
    RotorState kicked = state;
#pragma omp parallel
    kick(kicked, c_kick, K, g);
    std::vector<double> p_expected = state.p;
    for (std::size_t k = 0; k < g.size(); ++k) p_expected[k] += c_kick * K[0] * g[k];
    CHECK(test::bit_difference(kicked.p, p_expected) == "");
    CHECK(test::bit_difference(kicked.theta, state.theta) == "");
  }
}

namespace {

// steps() joins each step's closing kick to the next step's first pass and runs all steps in one
// team; the same operations on every cell in the same order, so theta, p, g, every step's order
// sums and the evaluation count must equal those of single steps bit for bit, for every method,
// step count and thread count.
void check_steps_against_step(CouplingForce& force, NodeIndex first_row, NodeIndex rows,
                              std::size_t replicas) {
  std::vector<InitialCondition> nine{
      {6.0, 1.0, 7}, {5.0, 0.5, 8}, {4.0, 2.0, 9}, {0.0, 0.3, 10}, {-1.0, 0.7, 11}};
  for (std::uint64_t seed = 12; seed < 16; ++seed) nine.push_back({1.0, 0.4, seed});
  const std::vector<InitialCondition> ics(nine.begin(), nine.begin() + static_cast<long>(replicas));
  const std::vector<double> K(replicas, 100.0);
  for (const std::string name : {"leapfrog", "yoshida4", "blanes_moan", "rk4"}) {
    for (const int n : {0, 1, 23}) {
      for (const int threads : {1, 2}) {
        INFO(name << ", " << replicas << " replicas, " << n << " steps, " << threads << " threads");
        const ThreadCountScope scope(threads);
        const auto method = make_integrator(name);
        RotorState one = initial_state(first_row, rows, ics);
        RotorState many = one;
        ForceEvaluation f_one(force);
        f_one.update(one);
        std::vector<double> order_one;
        for (int k = 0; k < n; ++k) {
          method->step(one, 0.01, K, f_one);
          order_one.insert(order_one.end(), f_one.sums().order.begin(), f_one.sums().order.end());
        }
        ForceEvaluation f_many(force);
        f_many.update(many);
        std::vector<double> order_many;
        method->steps(many, 0.01, K, f_many, n, [&] {
          order_many.insert(order_many.end(), f_many.sums().order.begin(),
                            f_many.sums().order.end());
        });
        CHECK(test::bit_difference(many.theta, one.theta) == "");
        CHECK(test::bit_difference(many.p, one.p) == "");
        CHECK(test::bit_difference(f_many.g(), f_one.g()) == "");
        CHECK(test::bit_difference(order_many, order_one) == "");
        CHECK(f_many.count() == f_one.count());
        // Without after_step only the last step forms the sums (coupling_force.hpp:
        // ForceOutputs): the same state and the same last sums.
        RotorState quiet = initial_state(first_row, rows, ics);
        ForceEvaluation f_quiet(force);
        f_quiet.update(quiet);
        method->steps(quiet, 0.01, K, f_quiet, n, {});
        CHECK(test::bit_difference(quiet.theta, one.theta) == "");
        CHECK(test::bit_difference(quiet.p, one.p) == "");
        CHECK(f_quiet.sums_current());
        CHECK(test::bit_difference(f_quiet.sums().order, f_one.sums().order) == "");
        CHECK(test::bit_difference(f_quiet.sums().coupling, f_one.sums().coupling) == "");
        CHECK(test::bit_difference(f_many.sums().coupling, f_one.sums().coupling) == "");
      }
    }
  }
}

}  // namespace

TEST_CASE("steps() gives the bits of step() after step(), with each step's sums to after_step",
          "[integrator]") {
  SECTION("the sparse force, ER N = 600") {
    Fixture fx;
    for (const std::size_t replicas : {std::size_t{1}, std::size_t{3}}) {
      check_steps_against_step(fx.force, fx.distributed.first_row(), fx.distributed.local_size(),
                               replicas);
    }
  }
  SECTION(
      "the rank-one force, K_N N = 3000 (one replica: several blocks of cells a thread; 9: a "
      "group of 8 in AVX-512 or AVX2 and one in the baseline loops)") {
    const NodeIndex n = 3000;
    RankOneForce force(RankOneStructure{std::vector<double>(n, 1.0), false}, 0, n);
    for (const std::size_t replicas : {std::size_t{1}, std::size_t{5}, std::size_t{9}}) {
      check_steps_against_step(force, 0, n, replicas);
    }
  }
}
