// The simulation protocol: agreement with a serial reference on any rank count, replicas,
// checkpoint/resume, the rank-one fast path, the blow-up guard.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/run_file.hpp"
#include "dynamics/simulation.hpp"
#include "io/hdf5_file.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/simulation_runs.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;
using hmfnet::test::short_run;
using hmfnet::test::temp_path;

namespace {

// Plain serial leap-frog on the whole network, written from eq:dMomentum_dT directly.
void reference_steps(const Network& net, std::vector<double>& theta, std::vector<double>& p,
                     double K, double h, int steps) {
  const auto n = static_cast<std::size_t>(net.size());
  std::vector<double> g(n);
  const auto force = [&] {
    for (NodeIndex i = 0; i < net.size(); ++i) {
      double sum = 0.0;
      for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) {
        sum += net.weight(k) * std::sin(theta[std::size_t(net.col(k))] - theta[std::size_t(i)]);
      }
      g[std::size_t(i)] = sum / static_cast<double>(n);
    }
  };
  force();
  for (int s = 0; s < steps; ++s) {
    for (std::size_t i = 0; i < n; ++i) p[i] += 0.5 * h * K * g[i];
    for (std::size_t i = 0; i < n; ++i) theta[i] += h * p[i];
    force();
    for (std::size_t i = 0; i < n; ++i) p[i] += 0.5 * h * K * g[i];
  }
}

RotorState run_steps(CouplingForce& force, RotorState s, double K, double h, int steps) {
  ForceEvaluation f(force);
  f.update(s);
  const LeapFrog lf;
  for (int k = 0; k < steps; ++k) lf.step(s, h, {K}, f);
  return s;
}

}  // namespace

TEST_CASE("Distributed leap-frog matches a serial reference to 1e-12 on any rank count [ER N=400]",
          "[simulation]") {
  const Network net = erdos_renyi({400, 0.05, 2});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  const RotorState s0 = initial_state(d.first_row(), d.local_size(), {{6.0, 1.0, 5}});
  const RotorState s = run_steps(force, s0, 80.0, 0.01, 200);
  const RotorState all0 = initial_state(0, net.size(), {{6.0, 1.0, 5}});
  std::vector<double> theta = all0.theta, p = all0.p;
  reference_steps(net, theta, p, 80.0, 0.01, 200);
  const std::vector<double> got_theta = d.gather(s.theta), got_p = d.gather(s.p);
  double worst = 0.0;
  for (std::size_t k = 0; k < theta.size(); ++k) {
    worst = std::max({worst, std::abs(got_theta[k] - theta[k]), std::abs(got_p[k] - p[k])});
  }
  INFO("ranks " << ParallelSession::ranks() << ": max deviation " << worst);
  REQUIRE(worst < 1e-12);
}

TEST_CASE("Rank-one fast path equals the sparse path to 1e-12 [weighted a a^T and K_N]",
          "[simulation]") {
  const NodeIndex n = 120;
  std::vector<double> a(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = 0.5 + 0.01 * double(i % 37);
  const Network full = test::complete(n, true);
  std::vector<double> w(std::size_t(full.nnz()));
  for (NodeIndex i = 0; i < n; ++i)
    for (EdgeOffset k = full.row_begin(i); k < full.row_end(i); ++k)
      w[std::size_t(k)] = a[std::size_t(i)] * a[std::size_t(full.col(k))];
  const Network weighted = Network::from_csr(n, full.row_ptr(), full.cols(), w);
  const Network unweighted = test::complete(n, false);
  for (const Network* net : {&weighted, &unweighted}) {
    const DistributedNetwork d(*net);
    auto structure = detect_rank_one(d);
    REQUIRE(structure.has_value());
    NetworkForce sparse(d);
    RankOneForce fast(*structure, d.first_row(), d.local_size());
    const RotorState s0 = initial_state(d.first_row(), d.local_size(), {{6.0, 1.0, 3}});
    const RotorState a1 = run_steps(sparse, s0, 30.0, 0.01, 300);
    const RotorState a2 = run_steps(fast, s0, 30.0, 0.01, 300);
    double worst = 0.0;
    for (std::size_t k = 0; k < a1.p.size(); ++k) {
      worst = std::max({worst, std::abs(a1.theta[k] - a2.theta[k]), std::abs(a1.p[k] - a2.p[k])});
    }
    INFO("max |sparse - rank-one| = " << worst);
    REQUIRE(worst < 1e-12);
  }
  REQUIRE_FALSE(detect_rank_one(DistributedNetwork(erdos_renyi({100, 0.5, 1}))).has_value());
  // Full rows whose weights are not a_i a_j: rejected on every rank (the weighted check is
  // collective).
  std::vector<double> skewed(std::size_t(full.nnz()), 1.0);
  skewed.front() = 4.0;  // A_00 = 4 makes a_0 = 2, so A_01 = 1 != a_0 a_1 = 2
  const Network not_rank_one = Network::from_csr(n, full.row_ptr(), full.cols(), skewed);
  REQUIRE_FALSE(detect_rank_one(DistributedNetwork(not_rank_one)).has_value());
}

TEST_CASE("B replicas in one pass equal B separate runs bit for bit [ER N=300 B=3]",
          "[simulation]") {
  const Network net = erdos_renyi({300, 0.05, 4});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters together = short_run();
  together.replicas = {{6.0, 1.0, 11}, {6.0, 0.5, 12}, {5.0, 1.0, 13}};
  const SimulationResult joint = simulate(d, net.degrees(), force, together);
  for (std::size_t b = 0; b < 3; ++b) {
    SimulationParameters alone = together;
    alone.replicas = {together.replicas[b]};
    const SimulationResult single = simulate(d, net.degrees(), force, alone);
    for (std::size_t k = 0; k < single.points.size(); ++k) {
      REQUIRE(single.points[k].R_mean[0] == joint.points[k].R_mean[b]);
      REQUIRE(single.points[k].R_sem[0] == joint.points[k].R_sem[b]);
      REQUIRE(single.points[k].energy_rel_error_max[0] == joint.points[k].energy_rel_error_max[b]);
    }
    for (std::size_t r = 0; r < single.series.t.size(); ++r) {
      REQUIRE(single.series.energy[r] == joint.series.energy[r * 3 + b]);
    }
  }
}

TEST_CASE("Checkpoint and resume end bit-identical to an uninterrupted run [ER N=300]",
          "[simulation]") {
  const Network net = erdos_renyi({300, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = short_run();
  p.node_data = true;
  const SimulationResult whole = simulate(d, net.degrees(), force, p);

  p.checkpoint_path = temp_path("hmfnet_test_checkpoint");
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
  ParallelSession::max(0.0);
  p.checkpoint_seconds = 0.0;                      // a checkpoint at every record
  for (const std::int64_t stop : {170, 260, 0}) {  // interrupted twice, then to the end
    p.stop_after_steps = stop;
    p.resume = true;
    const SimulationResult part = simulate(d, net.degrees(), force, p);
    REQUIRE(part.interrupted == (stop != 0));
    if (stop != 0) continue;
    REQUIRE(part.resumed);
    REQUIRE(part.points.size() == whole.points.size());
    for (std::size_t k = 0; k < whole.points.size(); ++k) {
      REQUIRE(part.points[k].R_mean == whole.points[k].R_mean);
      REQUIRE(part.points[k].R_sem == whole.points[k].R_sem);
      REQUIRE(part.points[k].energy_rel_error_max == whole.points[k].energy_rel_error_max);
      REQUIRE(part.points[k].omega_node == whole.points[k].omega_node);
      REQUIRE(part.points[k].R_node == whole.points[k].R_node);
      REQUIRE(part.points[k].r_node == whole.points[k].r_node);
      REQUIRE(part.points[k].fluctuation == whole.points[k].fluctuation);
      REQUIRE(part.points[k].phase_histogram == whole.points[k].phase_histogram);
      REQUIRE(part.points[k].rotor_theta_bar == whole.points[k].rotor_theta_bar);
      REQUIRE(part.points[k].rotor_p_bar == whole.points[k].rotor_p_bar);
    }
    REQUIRE(part.series.t == whole.series.t);
    REQUIRE(part.series.energy == whole.series.energy);
    REQUIRE(part.steps == whole.steps);
    REQUIRE(part.force_evaluations == whole.force_evaluations);
  }
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
}

TEST_CASE("A checkpoint of other parameters is refused with the reason", "[simulation]") {
  const Network net = erdos_renyi({200, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = short_run();
  p.checkpoint_path = temp_path("hmfnet_test_foreign_checkpoint");
  p.checkpoint_seconds = 0.0;
  p.stop_after_steps = 50;
  simulate(d, net.degrees(), force, p);
  p.stop_after_steps = 0;
  p.resume = true;
  p.K = {25.0};
  REQUIRE_THROWS_WITH(simulate(d, net.degrees(), force, p),
                      Catch::Contains("checkpoint belongs to another run (K: ["));
  ParallelSession::max(0.0);
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
}

TEST_CASE("A step far too large for K stops the run naming K / t and the stable step",
          "[simulation]") {
  const Network net = erdos_renyi({200, 0.1, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = short_run();
  p.h = 0.5;
  p.duration = 100.0;
  p.transient = 10.0;
  p.K = {4000.0};
  REQUIRE_THROWS_AS(simulate(d, net.degrees(), force, p), SimulationBlowUp);
  try {
    simulate(d, net.degrees(), force, p);
  } catch (const SimulationBlowUp& e) {
    INFO(e.what());
    REQUIRE_THAT(e.what(), Catch::Contains("K = 4000") && Catch::Contains("h < "));
  }
}

TEST_CASE("Simulation parameters are range-checked with the allowed range", "[simulation]") {
  const SimulationParameters base = short_run();
  SimulationParameters p = base;
  p.h = 0.0;
  REQUIRE_THROWS_WITH(validate(p), Catch::Contains("h > 0"));
  p = base;
  p.transient = p.duration;
  REQUIRE_THROWS_WITH(validate(p), Catch::Contains("T > transient"));
  p = base;
  p.K = {-1.0};
  REQUIRE_THROWS_AS(validate(p), ParameterError);
  p = base;
  p.replicas[0].sigma0 = 0.0;
  REQUIRE_THROWS_AS(validate(p), ParameterError);
}

TEST_CASE("Node statistics are consistent: r_n <= <R_n>_t / full histograms / all rotor samples",
          "[simulation]") {
  const Network net = erdos_renyi({400, 0.05, 8});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = short_run();
  p.node_data = true;
  p.rotor_node = 7;
  p.K = {200.0};  // well above K_c = 2 N / lambda ~ 38 for sigma0 = 1
  p.duration = 20.0;
  p.transient = 10.0;
  const SimulationResult r = simulate(d, net.degrees(), force, p);
  const PointResult& pt = r.points[0];
  REQUIRE(pt.r_node.size() == 400);
  // |<R_n e^{i(psi_n - Omega t)}>| <= <R_n> (triangle inequality), both over the same samples.
  for (std::size_t n = 0; n < pt.r_node.size(); ++n) REQUIRE(pt.r_node[n] <= pt.R_node[n] + 1e-12);
  double counts = 0.0;
  for (const double c : pt.phase_histogram) counts += c;
  REQUIRE(counts == 400.0 * 10.0);           // N nodes x one sample per time unit over T2 - T1 = 10
  REQUIRE(pt.rotor_theta_bar.size() == 50);  // (T2 - T1) / (h * stride) = 10 / 0.2 records
  for (const double x : pt.rotor_theta_bar) REQUIRE(std::abs(x) <= 3.14159265358979);
  // sum_n Omega_n (T2 - T1) = sum_n (theta_n(T2) - theta_n(T1)) = h sum_steps P (leap-frog drifts
  // with the conserved total momentum), so the node average of Omega_n is Omega = P/N.
  double mean_omega = 0.0;
  for (const double w : pt.omega_node) mean_omega += w / 400.0;
  INFO("mean Omega_n " << mean_omega << ", P/N " << pt.frame[2]);
  REQUIRE(std::abs(mean_omega - pt.frame[2]) < 1e-9);
  // The measured frame turns with the global order parameter, so phi = arg sum_n C_n = 0 up to
  // round-off, and in this strongly locked state (K ~ 5 K_c) the synchronised term dominates the
  // fluctuation term of eq:timeAveragedHV2 on the node average (Assumption 3).
  REQUIRE(std::abs(pt.frame[1]) < 1e-9);
  double sync = 0.0, fluct = 0.0;
  for (std::size_t n = 0; n < 400; ++n) {
    sync += pt.synchronised[n] / 400.0;
    fluct += std::abs(pt.fluctuation[n]) / 400.0;
  }
  INFO("frame " << pt.frame[0] << ", <r cos> " << sync << ", |<Re z e^-i theta>| " << fluct);
  REQUIRE(sync > 3.0 * fluct);
}

TEST_CASE("A per-K step list equal to the single step reproduces the run bit for bit",
          "[simulation]") {
  const Network net = erdos_renyi({300, 0.05, 7});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters plain = short_run();
  SimulationParameters listed = plain;
  listed.steps.assign(plain.K.size(), StepChoice{plain.integrator, plain.h});
  const SimulationResult a = simulate(d, net.degrees(), force, plain);
  const SimulationResult b = simulate(d, net.degrees(), force, listed);
  for (std::size_t k = 0; k < a.points.size(); ++k)
    REQUIRE(a.points[k].R_mean == b.points[k].R_mean);
  REQUIRE(a.series.t == b.series.t);
  REQUIRE(a.series.energy == b.series.energy);
  REQUIRE(a.force_evaluations == b.force_evaluations);
}

TEST_CASE("Per-K steps: each segment runs its own method and step from the state left before",
          "[simulation]") {
  const Network net = erdos_renyi({300, 0.05, 8});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters mixed = short_run();
  mixed.K = {20.0, 60.0};
  mixed.steps = {{"leapfrog", 0.02}, {"blanes_moan", 0.04}};
  const SimulationResult r = simulate(d, net.degrees(), force, mixed);
  // The first segment is the plain leap-frog run of its K, bit for bit.
  SimulationParameters first = short_run();
  first.K = {20.0};
  const SimulationResult f = simulate(d, net.degrees(), force, first);
  REQUIRE(r.points[0].R_mean == f.points[0].R_mean);
  REQUIRE(r.points[0].energy_rel_error_max == f.points[0].energy_rel_error_max);
  // Cost: the second segment is 4 / 0.04 = 100 steps of 6 evaluations (integrator.hpp).
  REQUIRE(r.force_evaluations == f.force_evaluations + 100 * 6);
  REQUIRE(r.steps == f.steps + 100);
  // Recorded times: every 10 steps of the segment's own h, ending at 2 T.
  const auto& t = r.series.t;
  REQUIRE(t.back() == Approx(8.0).epsilon(1e-12));
  REQUIRE(t[t.size() - 1] - t[t.size() - 2] == Approx(10 * 0.04).epsilon(1e-12));
  REQUIRE(t[0] == Approx(10 * 0.02).epsilon(1e-12));
  for (std::size_t k = 1; k < t.size(); ++k) REQUIRE(t[k] > t[k - 1]);
  // Fourth order at h = 0.04 keeps the energy error below leap-frog's at 0.02 on this segment.
  SimulationParameters leapfrog = mixed;
  leapfrog.steps[1] = {"leapfrog", 0.02};
  const SimulationResult l = simulate(d, net.degrees(), force, leapfrog);
  REQUIRE(r.points[1].energy_rel_error_max[0] < l.points[1].energy_rel_error_max[0]);
}

TEST_CASE("Checkpoint and resume inside a segment of another step end bit-identical",
          "[simulation]") {
  const Network net = erdos_renyi({300, 0.05, 9});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = short_run();
  p.steps = {{"leapfrog", 0.02}, {"yoshida4", 0.04}, {"leapfrog", 0.01}};
  const SimulationResult whole = simulate(d, net.degrees(), force, p);
  p.checkpoint_path = temp_path("hmfnet_test_checkpoint_steps");
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
  ParallelSession::max(0.0);
  p.checkpoint_seconds = 0.0;
  for (const std::int64_t stop : {230, 250, 0}) {  // stops in segments 2 and 3, then the end
    p.stop_after_steps = stop;
    p.resume = true;
    const SimulationResult part = simulate(d, net.degrees(), force, p);
    if (stop != 0) continue;
    REQUIRE(part.resumed);
    for (std::size_t k = 0; k < whole.points.size(); ++k)
      REQUIRE(part.points[k].R_mean == whole.points[k].R_mean);
    REQUIRE(part.series.t == whole.series.t);
    REQUIRE(part.series.energy == whole.series.energy);
    REQUIRE(part.force_evaluations == whole.force_evaluations);
  }
  if (ParallelSession::rank() == 0) std::filesystem::remove(p.checkpoint_path);
}

TEST_CASE("A per-K step list is range-checked naming the entry", "[simulation]") {
  SimulationParameters p = short_run();
  p.steps = {{"leapfrog", 0.02}};
  REQUIRE_THROWS_WITH(validate(p), Catch::Contains("one per K (3)"));
  p.steps = {{"leapfrog", 0.02}, {"leapfrog", 0.0}, {"leapfrog", 0.02}};
  REQUIRE_THROWS_WITH(validate(p), Catch::Contains("steps[1].h"));
  p.steps = {{"leapfrog", 0.02}, {"leapfrog", 0.02}, {"euler", 0.02}};
  REQUIRE_THROWS_WITH(validate(p), Catch::Contains("euler"));
  p.steps = {{"leapfrog", 0.02}, {"leapfrog", 2.0}, {"leapfrog", 0.02}};
  REQUIRE_THROWS_WITH(validate(p), Catch::Contains("h = 2"));
}

// Bugs found by a review of the run loop, each reproduced before its fix.

namespace {

// ER N = 200 (seed 6) with its distributed form and sparse force, and the short schedule.
struct ErRun {
  explicit ErRun(double q) : net(erdos_renyi({200, q, 6})), d(net), force(d) {}
  SimulationResult run() { return simulate(d, net.degrees(), force, p); }
  Network net;
  DistributedNetwork d;
  NetworkForce force;
  SimulationParameters p = short_run();
};

}  // namespace

TEST_CASE("A run stopped by stop_after_steps reports its wall time and force evaluations",
          "[simulation][bug]") {
  // Before the fix the stop returned without finish: integration_seconds stayed 0 and the
  // evaluation count missed this session's evaluations.
  ErRun e(0.05);
  e.p.stop_after_steps = 25;
  const SimulationResult r = e.run();
  REQUIRE(r.interrupted);
  REQUIRE(r.steps == 25);
  // Leap-frog: the initial force, then one evaluation per step.
  REQUIRE(r.force_evaluations == 26);
  REQUIRE(r.integration_seconds > 0.0);
  REQUIRE(r.force_name == e.force.name());
}

TEST_CASE("The blow-up message names the running method and its own stability bound [yoshida4]",
          "[simulation][bug]") {
  // Before the fix the message quoted leap-frog's bound h omega < 2 whatever ran.
  ErRun e(0.1);
  e.p.integrator = "yoshida4";
  e.p.h = 0.5;
  e.p.duration = 100.0;
  e.p.transient = 10.0;
  e.p.K = {4000.0};
  try {
    e.run();
    FAIL("no SimulationBlowUp");
  } catch (const SimulationBlowUp& blow_up) {
    const char* message = blow_up.what();
    INFO(message);
    const std::string limit = std::to_string(yoshida4().stability_limit()).substr(0, 5);
    REQUIRE_THAT(message, Catch::Contains("yoshida4 is stable for h * omega_max < " + limit));
    REQUIRE_THAT(message, !Catch::Contains("leap-frog") && !Catch::Contains("leapfrog"));
  }
}

TEST_CASE("The guard stops on the same energy error the run records [ER N=200]",
          "[simulation][bug]") {
  // The error used to be computed twice per record (once for the record, once in the guard);
  // now one value serves both, so a tolerance equal to the recorded maximum passes and the next
  // double below it stops the run.
  ErRun e(0.1);
  e.p.h = 0.05;
  double worst = 0.0;
  for (const auto& point : e.run().points) {
    for (const double err : point.energy_rel_error_max) worst = std::max(worst, err);
  }
  REQUIRE(worst > 0.0);
  e.p.energy_tolerance = worst;
  REQUIRE_NOTHROW(e.run());
  e.p.energy_tolerance = std::nextafter(worst, 0.0);
  REQUIRE_THROWS_AS(e.run(), SimulationBlowUp);
}

TEST_CASE("The results file records each K's integrator and step [per-K steps]",
          "[simulation][bug]") {
  // Before the fix the file's integrator and h attributes were those of SimulationParameters,
  // whatever the per-K steps ran.
  ErRun e(0.05);
  e.p.steps = {{"leapfrog", 0.02}, {"yoshida4", 0.05}, {"blanes_moan", 0.1}};
  const SimulationResult r = e.run();
  const std::string path = temp_path("hmfnet_test_per_k_steps");
  if (ParallelSession::rank() == 0) write_run_file(path, r, e.p, {});
  ParallelSession::max(0.0);
  {
    const Hdf5File f(path, Hdf5File::Mode::read);
    const H5Id points = f.open_group("points");
    REQUIRE(f.read_strings(points.get(), "integrator") ==
            std::vector<std::string>{"leapfrog", "yoshida4", "blanes_moan"});
    REQUIRE(f.read_double(points.get(), "h") == std::vector<double>{0.02, 0.05, 0.1});
    REQUIRE_THAT(f.string_attribute(f.id(), "integrator"), Catch::Contains("per K"));
    REQUIRE(std::isnan(f.double_attribute(f.id(), "h")));
    const auto parameters = nlohmann::json::parse(f.string_attribute(f.id(), "parameters"));
    REQUIRE(parameters == to_json(e.p));
  }
  ParallelSession::max(0.0);
  if (ParallelSession::rank() == 0) std::filesystem::remove(path);
}

TEST_CASE("One serialisation: the fingerprint is to_json less the energy tolerance",
          "[simulation]") {
  SimulationParameters p = short_run();
  const RunIdentity identity{10, 40, 0x0123456789abcdefULL, "sparse"};
  nlohmann::json expected = to_json(p);
  expected.erase("energy_tolerance");
  expected["n"] = 10;
  expected["nnz"] = 40;
  expected["network_hash"] = "0123456789abcdef";
  expected["force"] = "sparse";
  REQUIRE(nlohmann::json::parse(fingerprint(p, identity)) == expected);
  SimulationParameters looser = p;
  looser.energy_tolerance = 0.5;
  REQUIRE(fingerprint(looser, identity) == fingerprint(p, identity));
  REQUIRE(fingerprint_difference(fingerprint(p, identity), fingerprint(p, identity)).empty());
  SimulationParameters other_seed = p;
  other_seed.replicas[0].seed += 1;
  REQUIRE(fingerprint(other_seed, identity) != fingerprint(p, identity));
}

TEST_CASE("A fingerprint mismatch names the network first, then the force, then a parameter",
          "[simulation]") {
  const SimulationParameters p = short_run();
  const RunIdentity identity{10, 40, 0x0123456789abcdefULL, "sparse"};
  const auto difference = [&](const SimulationParameters& q, const RunIdentity& id) {
    return fingerprint_difference(fingerprint(p, identity), fingerprint(q, id));
  };
  RunIdentity other_network = identity;
  other_network.network_hash += 1;
  SimulationParameters other_h = p;
  other_h.h = 0.01;
  CHECK_THAT(difference(other_h, other_network),
             Catch::StartsWith("network (hash of its stored entries): \"0123456789abcdef\" in the "
                               "checkpoint, \"0123456789abcdf0\" in this run"));
  RunIdentity float32 = identity;
  float32.force = "sparse-float32";
  CHECK_THAT(difference(other_h, float32),
             Catch::StartsWith("force: \"sparse\" in the checkpoint"));
  CHECK_THAT(difference(other_h, identity), Catch::StartsWith("h: 0.02 in the checkpoint, 0.01"));
  SimulationParameters long_K = p;
  long_K.K.assign(100, 1.0 / 3.0);
  INFO(difference(long_K, identity));
  CHECK(difference(long_K, identity).size() < 200);
}

TEST_CASE("K_N held implicitly runs the protocol as the stored graph does [N = 300, 3 K]",
          "[simulation][complete]") {
  const CompleteGraph graph = CompleteGraph::make(300, false);
  const Network stored = graph.materialise();
  const std::vector<double> degrees(300, graph.degree());
  SimulationParameters params = test::short_run();
  params.K = {1.0, 3.0, 6.0};  // K_c = 2 sigma0^2 N / lambda = 2.007: 0.5, 1.5 and 3 K_c

  const DistributedNetwork implicit(graph);
  RankOneForce implicit_force({std::vector<double>(300, 1.0), false}, implicit.first_row(),
                              implicit.local_size());
  const SimulationResult a = simulate(implicit, degrees, implicit_force, params);

  const DistributedNetwork rows(stored);
  auto structure = detect_rank_one(rows);
  REQUIRE(structure.has_value());
  RankOneForce detected(*structure, rows.first_row(), rows.local_size());
  const SimulationResult b = simulate(rows, degrees, detected, params);
  NetworkForce sparse(rows);
  const SimulationResult c = simulate(rows, degrees, sparse, params);

  REQUIRE(a.points.size() == 3);
  for (std::size_t k = 0; k < a.points.size(); ++k) {
    INFO("K = " << a.points[k].K << ", ranks " << ParallelSession::ranks());
    // The same force on the same rows: the same bits.
    CHECK(a.points[k].R_mean == b.points[k].R_mean);
    CHECK(a.points[k].energy_rel_error_max == b.points[k].energy_rel_error_max);
    // Against the sparse kernel: the same terms summed in another order.
    CHECK(std::abs(a.points[k].R_mean[0] - c.points[k].R_mean[0]) < 1e-12);
  }
  CHECK(a.nnz_per_evaluation == b.nnz_per_evaluation);
}
