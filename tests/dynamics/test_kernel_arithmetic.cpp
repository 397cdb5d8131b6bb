// The host-and-device arithmetic (dynamics/kernel_arithmetic.hpp) against the CPU kernels it must
// reproduce bit for bit, so that a device running these functions gives the CPU's bits: the
// scalar sincos against the vectorised one (random angles, the doubles nearest multiples of pi/2,
// angles beyond the reduced range and non-finite ones), and leap-frog steps of the real
// NetworkForce and LeapFrog against the same steps composed by hand from the per-element
// functions (sincos, row sums, g, the observable terms, kick, drift). And the host stepper that
// the gpu tests compare the device with (tests/gpu/host_ensemble.hpp) against the CPU's
// splittings over NetworkForce and RankOneForce, so that "the device gives the CPU's bits" is
// a chain of tests: device = host stepper (gpu label), host stepper = CPU (here).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ios>
#include <limits>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "dynamics/host_stepper.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/ordered_sum.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/sincos.hpp"
#include "dynamics/splitting_coefficients.hpp"
#include "gpu/host_ensemble.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/sincos_hard_cases.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

namespace {

std::uint64_t bits_of(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The values whose bits differ (a NaN equals only the same NaN), and the first such index.
struct BitDifference {
  std::size_t count = 0;
  std::size_t first = 0;
};

BitDifference bit_difference(const std::vector<double>& a, const std::vector<double>& b) {
  BitDifference d;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    if (bits_of(a[k]) == bits_of(b[k])) continue;
    if (d.count++ == 0) d.first = k;
  }
  if (a.size() != b.size()) ++d.count;
  return d;
}

// [cos, sin] of every angle from sincos_one, interleaved as sincos_interleaved writes them.
std::vector<double> scalar_sincos(const std::vector<double>& x) {
  std::vector<double> cs(2 * x.size());
  for (std::size_t k = 0; k < x.size(); ++k) sincos_one(x[k], cs[2 * k], cs[2 * k + 1]);
  return cs;
}

// The scalar against every vector version this CPU runs (the x86-64 baseline; AVX2 and AVX-512
// where it has them) and the chosen one.
void require_same_sincos(const std::vector<double>& x) {
  const std::vector<double> scalar = scalar_sincos(x);
  std::vector<double> vector(2 * x.size());
  for (const SincosIsa isa : {SincosIsa::baseline, SincosIsa::avx2, SincosIsa::avx512}) {
    if (!sincos_isa_available(isa)) continue;
    sincos_interleaved_isa(isa, x.data(), x.size(), vector.data());
    const BitDifference d = bit_difference(scalar, vector);
    INFO(x.size() << " angles, " << sincos_isa_name(isa) << " version: " << d.count
                  << " values differ; the first: angle " << std::hexfloat << x[d.first / 2]
                  << (d.first % 2 == 0 ? " cos " : " sin ") << scalar[d.first]
                  << " (scalar) against " << vector[d.first]);
    CHECK(d.count == 0);
  }
  sincos_interleaved(x.data(), x.size(), vector.data());
  CHECK(bit_difference(scalar, vector).count == 0);
}

}  // namespace

TEST_CASE("scalar sincos equals the vectorised one bit for bit on 10^6 random angles in +-100",
          "[kernel_arithmetic]") {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  std::vector<double> x(1000000);
  for (auto& v : x) v = u(rng);
  require_same_sincos(x);
}

TEST_CASE("scalar sincos equals the vectorised one at the doubles nearest k pi/2 up to 10^7",
          "[kernel_arithmetic]") {
  // The hard cases of tests/dynamics/test_sincos.cpp: every k up to 2000, then k growing by 1%
  // to 6.3 10^6 (|x| ~ 10^7), each with both neighbours and both signs, and the angles that were
  // 20-3900 ulp off before the reduction carried its rounding.
  std::vector<double> x = test::sincos_hard_angles();
  require_same_sincos(x);
}

TEST_CASE("scalar sincos equals the vectorised one beyond the reduced range and when not finite",
          "[kernel_arithmetic]") {
  // Both sides of k_reduced_range, the C library's range, and the values whose lanes compute
  // nothing of use and must be overwritten: infinities, NaNs of both signs; zeros and a subnormal.
  // Each value is also placed at every lane of the 4-lane vectors and the 16 lanes of the AVX-512
  // version's two registers, and in the padded tail after them (the range test is per lane).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> special = {k_reduced_range,
                                       -k_reduced_range,
                                       std::nextafter(k_reduced_range, INFINITY),
                                       -std::nextafter(k_reduced_range, INFINITY),
                                       std::nextafter(k_reduced_range, 0.0),
                                       -1e8,
                                       123456789.123,
                                       1e300,
                                       DBL_MAX,
                                       INFINITY,
                                       -INFINITY,
                                       nan,
                                       -nan,
                                       0.0,
                                       -0.0,
                                       1e-310};
  for (const double v : special) {
    std::vector<double> x(17, 0.5);
    for (std::size_t lane = 0; lane < x.size(); ++lane) {
      x[lane] = v;
      require_same_sincos(x);
      x[lane] = 0.5;
    }
  }
  require_same_sincos(special);
}

namespace {

// The network of the step test, 0/1 or with the weights of test::pair_weighted, so that both
// row sums are exercised.
Network step_network(bool weighted) {
  const Network net = erdos_renyi({300, 0.05, 29});
  return weighted ? test::pair_weighted(net) : net;
}

// NetworkForce::evaluate composed from the per-element functions, as a device backend composes
// them: [cos, sin] of the owned rotors, the column space through the network's import, each row
// and replica summed by row_field in T, then g, y and the two observable terms.
class HandForce {
 public:
  HandForce(const DistributedNetwork& network, ForcePrecision precision)
      : m_network(network), m_precision(precision) {
    for (const double w : network.local_adjacency().weights)
      m_weights_f32.push_back(static_cast<float>(w));
  }

  void evaluate(const RotorState& state) {
    const auto& adjacency = m_network.local_adjacency();
    const int nb = state.replicas;
    const std::size_t cells = state.theta.size();
    m_owned_cs.resize(2 * cells);
    for (std::size_t k = 0; k < cells; ++k)
      sincos_one(state.theta[k], m_owned_cs[2 * k], m_owned_cs[2 * k + 1]);
    m_column_cs = m_owned_cs;
    if (!m_network.columns_are_owned_rows()) {
      m_column_cs.resize(2 * static_cast<std::size_t>(adjacency.columns) *
                         static_cast<std::size_t>(nb));
      m_network.import_columns(m_owned_cs.data(), 2 * nb, m_column_cs.data());
    }
    const std::vector<float> column_f32(m_column_cs.begin(), m_column_cs.end());
    const double inverse_n = 1.0 / static_cast<double>(m_network.global_size());
    g.assign(cells, 0.0);
    y.assign(2 * cells, 0.0);
    std::vector<double> terms(2 * cells);
    for (NodeIndex r = 0; r < state.rows; ++r) {
      const EdgeOffset begin = adjacency.row_ptr[static_cast<std::size_t>(r)];
      const EdgeOffset end = adjacency.row_ptr[static_cast<std::size_t>(r) + 1];
      for (int b = 0; b < nb; ++b) {
        const std::size_t k = state.at(r, b);
        const LocalField field =
            m_precision == ForcePrecision::float64
                ? row_field(begin, end, adjacency.cols.data(),
                            adjacency.weights.empty() ? nullptr : adjacency.weights.data(),
                            m_column_cs.data(), nb, b)
                : row_field(begin, end, adjacency.cols.data(),
                            m_weights_f32.empty() ? nullptr : m_weights_f32.data(),
                            column_f32.data(), nb, b);
        const double c = m_owned_cs[2 * k], s = m_owned_cs[2 * k + 1];
        g[k] = coupling_force(inverse_n, c, s, field);
        y[2 * k] = field.re;
        y[2 * k + 1] = field.im;
        terms[2 * k] = order_term(field);
        terms[2 * k + 1] = coupling_term(c, s, field);
      }
    }
    ordered_column_sums(terms, static_cast<std::size_t>(state.rows), 2 * nb, term_sums);
  }

  std::vector<double> g;
  std::vector<double> y;
  std::vector<double> term_sums;  // replicas x [sum |y_n|, sum Re(e^{-i theta_n} y_n)]

 private:
  const DistributedNetwork& m_network;
  ForcePrecision m_precision;
  std::vector<float> m_weights_f32;
  std::vector<double> m_owned_cs;
  std::vector<double> m_column_cs;
};

std::vector<double> interleaved_sums(const ForceSums& sums) {
  std::vector<double> out;
  for (std::size_t b = 0; b < sums.order.size(); ++b) {
    out.push_back(sums.order[b]);
    out.push_back(sums.coupling[b]);
  }
  return out;
}

}  // namespace

TEST_CASE(
    "leap-frog steps composed of the per-element functions equal NetworkForce and LeapFrog "
    "bit for bit [ER N=300]",
    "[kernel_arithmetic]") {
  // Replica counts 1, 2, 4, 8 and 3 take every path of network_force.cpp's dispatch (the
  // one-replica kernel, the compiled widths: the wide loops where the CPU has AVX2, the baseline
  // ones with their partials per pass under unit.baseline_row_loops; 3: the wide loops' groups,
  // 2 + 1, and the baseline loop's run-time width under unit.baseline_row_loops), over 16-bit
  // column indices (narrow_columns.hpp) and 32-bit ones.
  constexpr double h = 0.05;
  constexpr int steps = 20;
  for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
    for (const bool weighted : {false, true}) {
      const Network net = step_network(weighted);
      const DistributedNetwork network(net);
      for (const int replicas : {1, 2, 3, 4, 8}) {
        std::vector<InitialCondition> ic;
        std::vector<double> K;
        for (int b = 0; b < replicas; ++b) {
          ic.push_back({6.0, 1.0, static_cast<std::uint64_t>(b + 41)});
          K.push_back(2.0 + 0.75 * b);
        }
        for (const bool narrow : {true, false}) {
          RotorState cpu = initial_state(network.first_row(), network.local_size(), ic);
          RotorState hand = cpu;
          NetworkForce force(network, precision, k_automatic_segments, narrow);
          ForceEvaluation f(force);
          f.update(cpu);
          HandForce by_hand(network, precision);
          by_hand.evaluate(hand);
          const LeapFrog leapfrog;
          for (int step = 0; step < steps; ++step) {
            leapfrog.step(cpu, h, K, f);
            // LeapFrog::advance: kick_drift by (h / 2, h), the force at the new phases, kick by h
            // / 2.
            const double half = 0.5 * h;
            for (NodeIndex r = 0; r < hand.rows; ++r) {
              for (int b = 0; b < replicas; ++b) {
                const std::size_t k = hand.at(r, b);
                const auto kb = static_cast<std::size_t>(b);
                hand.p[k] = kicked_momentum(hand.p[k], half, K[kb], by_hand.g[k]);
                hand.theta[k] = drifted_angle(hand.theta[k], h, hand.p[k]);
              }
            }
            by_hand.evaluate(hand);
            for (NodeIndex r = 0; r < hand.rows; ++r) {
              for (int b = 0; b < replicas; ++b) {
                const std::size_t k = hand.at(r, b);
                hand.p[k] =
                    kicked_momentum(hand.p[k], half, K[static_cast<std::size_t>(b)], by_hand.g[k]);
              }
            }
          }
          INFO(to_string(precision)
               << (weighted ? ", weighted" : ", 0/1") << ", " << replicas << " replicas, " << steps
               << " steps of h = " << h << ", " << (narrow ? 16 : 32) << "-bit column indices");
          CHECK(bit_difference(by_hand.g, f.g()).count == 0);
          CHECK(bit_difference(by_hand.y, force.local_fields()).count == 0);
          CHECK(bit_difference(by_hand.term_sums, interleaved_sums(f.sums())).count == 0);
          CHECK(bit_difference(hand.theta, cpu.theta).count == 0);
          CHECK(bit_difference(hand.p, cpu.p).count == 0);
          CHECK(force.narrow_columns() == narrow);
        }
      }
    }
  }
}

namespace {

// The rows of a one-rank network as the host stepper's CSR (0/1 entries).
cuda::HostCsr host_csr(const DistributedNetwork& network) {
  const auto& a = network.local_adjacency();
  cuda::HostCsr csr;
  csr.rows = network.local_size();
  csr.offsets.assign(a.row_ptr.begin(), a.row_ptr.end());
  for (const NodeIndex c : a.cols) csr.columns.push_back(static_cast<std::int32_t>(c));
  csr.weights = a.weights;
  return csr;
}

}  // namespace

TEST_CASE(
    "the gpu tests' host stepper equals the CPU's splittings over NetworkForce and RankOneForce "
    "bit for bit [ER N=300 0/1 and weighted, K_N N=5000]",
    "[kernel_arithmetic]") {
  if (ParallelSession::ranks() > 1) {
    SUCCEED(
        "one rank only: the host stepper holds the whole network (rank independence of the "
        "CPU step is tested by the mpi label)");
    return;
  }
  const std::vector<std::pair<KickDriftSplitting, SplittingCoefficients>> methods = {
      {KickDriftSplitting("leapfrog", 2, leap_frog_coefficients().kicks,
                          leap_frog_coefficients().drifts),
       leap_frog_coefficients()},
      {yoshida4(), yoshida4_coefficients()},
      {blanes_moan4(), blanes_moan4_coefficients()}};
  std::vector<InitialCondition> ic;
  std::vector<double> K;
  for (int b = 0; b < 3; ++b) {
    ic.push_back({0.0, 0.6, static_cast<std::uint64_t>(b + 11), MomentumDistribution::waterbag});
    K.push_back(1.0 + 2.5 * b);  // a K per replica (--K-across-replicas)
  }
  for (const bool weighted : {false, true}) {
    const Network net = step_network(weighted);
    const DistributedNetwork network(net);
    for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
      for (const auto& [method, table] : methods) {
        RotorState cpu = initial_state(network.first_row(), network.local_size(), ic);
        gpu_test::HostEnsemble host(host_csr(network), 3, precision == ForcePrecision::float32);
        host.K = K;
        host.set_state(cpu.theta, cpu.p);
        NetworkForce force(network, precision);
        ForceEvaluation f(force);
        f.update(cpu);
        for (int step = 0; step < 25; ++step) method.step(cpu, 0.05, K, f);
        host.advance(table, 0.05, 25);
        INFO(to_string(precision) << ", " << method.name() << (weighted ? ", weighted" : ""));
        CHECK(bit_difference(host.theta, cpu.theta).count == 0);
        CHECK(bit_difference(host.p, cpu.p).count == 0);
      }
    }
  }
  // K_N with and without self-loops: RankOneForce's Z in 2048-row blocks (N = 5000: three
  // blocks), and each step's order sums and a record's sums as the CPU's stepper forms them.
  for (const bool self_loops : {true, false}) {
    const CompleteGraph graph = CompleteGraph::make(5000, self_loops);
    const DistributedNetwork complete(graph);
    RankOneForce rank_one(complete_graph_structure(graph), complete.first_row(),
                          complete.local_size());
    HostStepper cpu(rank_one);
    cpu.set_state(initial_state(complete.first_row(), complete.local_size(), ic));
    auto host = gpu_test::HostEnsemble::complete(5000, 3, self_loops);
    host.K = K;
    host.set_state(cpu.state().theta, cpu.state().p);
    std::vector<double> cpu_order, host_order;
    cpu.advance(LeapFrog(), 0.1, K, 25, &cpu_order);
    host.advance(leap_frog_coefficients(), 0.1, 25, &host_order);
    INFO("K_N, self-loops " << self_loops);
    CHECK(bit_difference(host.theta, cpu.state().theta).count == 0);
    CHECK(bit_difference(host.p, cpu.state().p).count == 0);
    CHECK(bit_difference(host_order, cpu_order).count == 0);
    const StepperSums x = cpu.sums();
    const cuda::EnsembleSums y = host.sums();
    CHECK(bit_difference(y.coupling, x.coupling).count == 0);
    CHECK(bit_difference(y.kinetic, x.kinetic).count == 0);
    CHECK(bit_difference(y.momentum_scale, x.momentum_scale).count == 0);
  }
  // A = a a^T with a in [0.5, 1.5] (the disordered HMF), with and without the diagonal.
  std::vector<double> a(4500);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> spread(0.5, 1.5);
  for (double& x : a) x = spread(rng);
  for (const bool diagonal : {true, false}) {
    RankOneForce rank_one(RankOneStructure{a, diagonal}, 0, 4500);
    HostStepper cpu(rank_one);
    cpu.set_state(initial_state(0, 4500, ic));
    auto host = gpu_test::HostEnsemble::rank_one(a, 3, diagonal);
    host.K = K;
    host.set_state(cpu.state().theta, cpu.state().p);
    std::vector<double> cpu_order, host_order;
    cpu.advance(LeapFrog(), 0.1, K, 20, &cpu_order);
    host.advance(leap_frog_coefficients(), 0.1, 20, &host_order);
    INFO("a a^T, diagonal " << diagonal);
    CHECK(bit_difference(host.theta, cpu.state().theta).count == 0);
    CHECK(bit_difference(host.p, cpu.state().p).count == 0);
    CHECK(bit_difference(host_order, cpu_order).count == 0);
    CHECK(bit_difference(host.sums().coupling, cpu.sums().coupling).count == 0);
  }
}

TEST_CASE(
    "the gpu tests' host stepper's per-step order sums and record sums equal the CPU stepper's "
    "bit for bit [ER N=4500: three sum blocks]",
    "[kernel_arithmetic]") {
  if (ParallelSession::ranks() > 1) {
    SUCCEED("one rank only: the host stepper holds the whole network");
    return;
  }
  // The device's sums are compared with the host stepper's (tests/gpu), these with the CPU's
  // HostStepper, which the simulation protocol reads: per step sum_n |y_n| (the time average),
  // at a record the five sums of the observables.
  const Network net = erdos_renyi({4500, 8.0 / 4499.0, 31});
  const DistributedNetwork network(net);
  std::vector<InitialCondition> ic;
  std::vector<double> K;
  for (int b = 0; b < 3; ++b) {
    ic.push_back({0.5, 0.6, static_cast<std::uint64_t>(b + 5), MomentumDistribution::waterbag});
    K.push_back(2.0 + 1.5 * b);
  }
  for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
    NetworkForce force(network, precision);
    HostStepper cpu(force);
    cpu.set_state(initial_state(network.first_row(), network.local_size(), ic));
    gpu_test::HostEnsemble host(host_csr(network), 3, precision == ForcePrecision::float32);
    host.K = K;
    host.set_state(cpu.state().theta, cpu.state().p);
    std::vector<double> cpu_order, host_order;
    const std::unique_ptr<Integrator> yoshida = make_integrator("yoshida4");
    cpu.advance(*yoshida, 0.05, K, 7, &cpu_order);
    host.advance(yoshida4_coefficients(), 0.05, 7, &host_order);
    INFO(to_string(precision));
    REQUIRE(cpu_order.size() == 7 * 3);
    CHECK(bit_difference(host_order, cpu_order).count == 0);
    const StepperSums a = cpu.sums();
    const cuda::EnsembleSums b = host.sums();
    CHECK(bit_difference(b.order, a.order).count == 0);
    CHECK(bit_difference(b.coupling, a.coupling).count == 0);
    CHECK(bit_difference(b.kinetic, a.kinetic).count == 0);
    CHECK(bit_difference(b.momentum, a.momentum).count == 0);
    CHECK(bit_difference(b.momentum_scale, a.momentum_scale).count == 0);
    // Each step's order sums are the force's at that step's end: the last equal the record's.
    CHECK(
        bit_difference(std::vector<double>(cpu_order.end() - 3, cpu_order.end()), a.order).count ==
        0);
  }
}
