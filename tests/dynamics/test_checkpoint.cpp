// Checkpoints under faults: a corrupted file is refused by its checksum, and a stop requested by
// SIGINT/SIGTERM (interrupt.hpp) writes a final checkpoint from which --resume ends
// bit-identical to an uninterrupted run.
#include <hdf5.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "dynamics/checkpoint.hpp"
#include "dynamics/interrupt.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/run_file.hpp"
#include "dynamics/simulation.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/simulation_runs.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;
using hmfnet::test::checkpointed_run;
using hmfnet::test::remove_on_root;
using hmfnet::test::short_run;
using hmfnet::test::temp_path;

namespace {

// Changes one stored angle in place, as a bit flip on disk would (the file stays valid HDF5).
void corrupt_theta(const std::string& path) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t set = H5Dopen2(file, "theta", H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  std::vector<double> theta(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  REQUIRE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, theta.data()) >= 0);
  theta[theta.size() / 2] = std::nextafter(theta[theta.size() / 2], 10.0);
  REQUIRE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, theta.data()) >= 0);
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
}

}  // namespace

TEST_CASE("A checkpoint changed on disk is refused by its checksum [ER N=200]", "[checkpoint]") {
  const Network net = erdos_renyi({200, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p =
      checkpointed_run(d, net.degrees(), force, "hmfnet_test_corrupt_checkpoint", 50);
  ParallelSession::max(0.0);
  REQUIRE_NOTHROW(read_checkpoint(p.checkpoint_path));  // intact: accepted
  ParallelSession::max(0.0);  // every rank has closed it before the root changes it
  if (ParallelSession::rank() == 0) corrupt_theta(p.checkpoint_path);
  ParallelSession::max(0.0);
  REQUIRE_THROWS_WITH(read_checkpoint(p.checkpoint_path), Catch::Contains("checksum mismatch"));
  p.resume = true;
  REQUIRE_THROWS_AS(simulate(d, net.degrees(), force, p), InputError);
  remove_on_root(p.checkpoint_path);
}

TEST_CASE("A signal stops the run with a final checkpoint that resumes bit-identically [ER N=300]",
          "[checkpoint]") {
  const Network net = erdos_renyi({300, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = short_run();
  const SimulationResult whole = simulate(d, net.degrees(), force, p);

  p.checkpoint_path = temp_path("hmfnet_test_signal_checkpoint");
  remove_on_root(p.checkpoint_path);
  p.checkpoint_seconds = 1e9;  // only the forced ones: the stop must write its own
  set_interrupt_signal(SIGTERM);
  const SimulationResult stopped = simulate(d, net.degrees(), force, p);
  set_interrupt_signal(0);
  REQUIRE(stopped.interrupted);
  REQUIRE(stopped.steps == p.record_stride);  // stopped at the first record
  ParallelSession::max(0.0);
  REQUIRE(read_checkpoint(p.checkpoint_path).record.count("steps_total") == p.record_stride);

  p.resume = true;
  const SimulationResult resumed = simulate(d, net.degrees(), force, p);
  REQUIRE(resumed.resumed);
  REQUIRE_FALSE(resumed.interrupted);
  REQUIRE(resumed.points.size() == whole.points.size());
  for (std::size_t k = 0; k < whole.points.size(); ++k) {
    REQUIRE(resumed.points[k].R_mean == whole.points[k].R_mean);
    REQUIRE(resumed.points[k].energy_rel_error_max == whole.points[k].energy_rel_error_max);
  }
  REQUIRE(resumed.series.energy == whole.series.energy);
  REQUIRE(resumed.steps == whole.steps);
  remove_on_root(p.checkpoint_path);
}

TEST_CASE("The output size estimates bound the files a run writes [ER N=200]", "[checkpoint]") {
  const Network net = erdos_renyi({200, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p = short_run();
  p.node_data = true;
  p.checkpoint_path = temp_path("hmfnet_test_size_checkpoint");
  remove_on_root(p.checkpoint_path);
  p.checkpoint_seconds = 0.0;
  const SimulationResult r = simulate(d, net.degrees(), force, p);
  const std::string results = temp_path("hmfnet_test_size_results");
  if (ParallelSession::rank() == 0) write_run_file(results, r, p, {});
  ParallelSession::max(0.0);
  const auto run_bytes = std::filesystem::file_size(results);
  const auto checkpoint_bytes = std::filesystem::file_size(p.checkpoint_path);
  INFO("results " << run_bytes << " <= " << estimated_run_file_bytes(p, net.size())
                  << ", checkpoint " << checkpoint_bytes
                  << " <= " << estimated_checkpoint_bytes(p, net.size()));
  REQUIRE(run_bytes <= estimated_run_file_bytes(p, net.size()));
  REQUIRE(checkpoint_bytes <= estimated_checkpoint_bytes(p, net.size()));
  // Not absurdly loose either: within the 1 MiB metadata allowance plus 2x the data.
  REQUIRE(estimated_run_file_bytes(p, net.size()) <= 2 * run_bytes + (1u << 20));
  remove_on_root(p.checkpoint_path);
  remove_on_root(results);
}

namespace {

using Edges = std::vector<std::pair<NodeIndex, NodeIndex>>;

using test::upper_edges;

// Edge `which` moved to the first free partner of its first end: N and nnz stay the same.
Network moved_edge(const Network& net, std::size_t which) {
  Edges e = upper_edges(net);
  const NodeIndex a = e[which].first;
  NodeIndex c = 0;
  for (;; ++c) {
    bool taken = c == a;
    for (const auto& [i, j] : e) taken = taken || (i == a && j == c) || (i == c && j == a);
    if (!taken) break;
  }
  e[which].second = c;
  return Network::from_undirected_edges(net.size(), e);
}

// Entry (i, j) and its mirror given weight 2: a weighted network of the same pattern.
Network reweighted(const Network& net, std::size_t which) {
  const auto [a, b] = upper_edges(net)[which];
  std::vector<EdgeOffset> row_ptr;
  std::vector<NodeIndex> cols;
  std::vector<double> weights;
  for (NodeIndex i = 0; i <= net.size(); ++i) row_ptr.push_back(net.row_begin(i));
  for (NodeIndex i = 0; i < net.size(); ++i) {
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) {
      cols.push_back(net.col(k));
      const bool hit = (i == a && net.col(k) == b) || (i == b && net.col(k) == a);
      weights.push_back(hit ? 2.0 : 1.0);
    }
  }
  return Network::from_csr(net.size(), row_ptr, cols, weights);
}

// Resumes `p`'s checkpoint with what `change` alters; requires a refusal naming `field`.
struct Perturbation {
  std::string field;
  std::function<void(SimulationParameters&)> change;
};

}  // namespace

TEST_CASE("A resume on a changed network, force or parameter is refused naming it [ER N=200]",
          "[checkpoint]") {
  const Network net = erdos_renyi({200, 0.05, 6});
  const DistributedNetwork d(net);
  NetworkForce force(d);
  SimulationParameters p =
      checkpointed_run(d, net.degrees(), force, "hmfnet_test_foreign_resume", 50);
  p.resume = true;
  const auto refused = [&](const Network& other, CouplingForce& f, const SimulationParameters& q,
                           const std::string& field) {
    const DistributedNetwork od(other);
    INFO("changed: " << field);
    REQUIRE_THROWS_WITH(simulate(od, other.degrees(), f, q),
                        Catch::Contains("checkpoint belongs to another run (" + field + ": "));
  };

  SECTION("one entry moved or one weight changed, at random places (fixed seed)") {
    std::mt19937_64 rng(2024);
    const std::size_t edges = upper_edges(net).size();
    for (int trial = 0; trial < 5; ++trial) {
      const std::size_t which = std::uniform_int_distribution<std::size_t>(0, edges - 1)(rng);
      const Network moved = moved_edge(net, which), heavier = reweighted(net, which);
      const DistributedNetwork dm(moved), dh(heavier);
      NetworkForce fm(dm), fh(dh);
      refused(moved, fm, p, "network (hash of its stored entries)");
      refused(heavier, fh, p, "network (hash of its stored entries)");
    }
  }
  SECTION("the force's precision") {
    NetworkForce float32(d, ForcePrecision::float32);
    refused(net, float32, p, "force");
  }
  SECTION("every parameter that changes the trajectory") {
    const std::vector<Perturbation> changes{
        {"K", [](SimulationParameters& q) { q.K[1] += 1.0; }},
        {"h", [](SimulationParameters& q) { q.h = 0.01; }},
        {"T", [](SimulationParameters& q) { q.duration = 5.0; }},
        {"transient", [](SimulationParameters& q) { q.transient = 0.5; }},
        {"replicas", [](SimulationParameters& q) { q.replicas[0].seed += 1; }},
        {"replicas", [](SimulationParameters& q) { q.replicas[0].sigma0 = 0.5; }},
        {"replicas", [](SimulationParameters& q) { q.replicas[0].omega = 0.0; }},
        {"replicas",
         [](SimulationParameters& q) { q.replicas[0].momenta = MomentumDistribution::waterbag; }},
        {"replicas",
         [](SimulationParameters& q) {
           q.replicas.push_back({6.0, 1.0, 12});
         }},
        {"integrator", [](SimulationParameters& q) { q.integrator = "yoshida4"; }},
        {"continue_state", [](SimulationParameters& q) { q.continue_state = false; }},
        {"node_data", [](SimulationParameters& q) { q.node_data = true; }},
        {"record_stride", [](SimulationParameters& q) { q.record_stride = 20; }},
        {"batches", [](SimulationParameters& q) { q.batches = 10; }},
    };
    for (const Perturbation& c : changes) {
      SimulationParameters q = p;
      c.change(q);
      refused(net, force, q, c.field);
    }
  }
  remove_on_root(p.checkpoint_path);
}
