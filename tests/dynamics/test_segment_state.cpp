// The segment state is defined once: every member of SegmentState and RunPosition is in its field
// list, and every listed field survives capture -> checkpoint file -> restore unchanged, on any
// rank count. An old checkpoint format is refused with a message that says so.
#include <hdf5.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <type_traits>
#include <utility>

#include "dynamics/checkpoint.hpp"
#include "dynamics/segment_state.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "support/member_count.hpp"
#include "support/simulation_runs.hpp"

using namespace hmfnet;
using hmfnet::test::member_count;
using hmfnet::test::remove_on_root;
using hmfnet::test::temp_path;

namespace {

// Counts the fields a list visits, whatever their kind (every kind forwards to `count`).
struct FieldCounter {
  std::size_t fields = 0;
  template <class... Args>
  void count(const Args&...) {
    ++fields;
  }
  template <class... Args>
  void real(const Args&... a) {
    count(a...);
  }
  template <class... Args>
  void replicated(const Args&... a) {
    count(a...);
  }
  template <class... Args>
  void rows(const Args&... a) {
    count(a...);
  }
  template <class... Args>
  void batch_means(const Args&... a) {
    count(a...);
  }
  template <class... Args>
  void node_statistics(const Args&... a) {
    count(a...);
  }
};

// Distinct values in every field: 1000 * field + index, so a field restored into another's place
// or a value dropped shows.
std::vector<double> distinct(std::size_t field, std::size_t size, double offset = 0.0) {
  std::vector<double> v(size);
  for (std::size_t k = 0; k < size; ++k) v[k] = 1000.0 * double(field) + double(k) + offset;
  return v;
}

constexpr int k_replicas = 3;
constexpr int k_bins = 5;
constexpr std::int64_t k_rotor_samples = 4;

// A segment of this rank's rows with every accumulator started (node data on).
SegmentState filled_segment(const DistributedNetwork& d) {
  const auto rows = static_cast<std::size_t>(d.local_size());
  const auto first = static_cast<double>(d.first_row());
  const std::size_t w = k_replicas;
  SegmentState s;
  s.step = 17;
  s.R = BatchMeans(40, 4, k_replicas);
  for (int k = 0; k < 40; ++k) s.R.add(distinct(1, w, 0.5 * k * k));
  s.energy0 = distinct(2, w);
  s.momentum0 = distinct(3, w);
  s.momentum_scale = distinct(4, w);
  s.energy_err_max = distinct(5, w);
  s.momentum_drift_max = distinct(6, w);
  s.theta_T1 = distinct(7, rows * w, first * double(w));
  s.R_node_sum = distinct(8, rows * w, first * double(w));
  s.stats = NodeStatistics(d.first_row(), d.local_size(), 0, k_rotor_samples, k_bins, 0.25);
  std::vector<double> globals =
      distinct(9, NodeStatistics::k_shared_globals + k_bins + 2 * std::size_t(k_rotor_samples));
  s.stats.restore(
      distinct(10, rows * NodeStatistics::k_row_width, first * double(NodeStatistics::k_row_width)),
      globals, ParallelSession::rank() == 0);
  return s;
}

RunPosition filled_position(const DistributedNetwork& d) {
  const auto rows = static_cast<std::size_t>(d.local_size());
  const auto first = static_cast<double>(d.first_row()) * k_replicas;
  RunPosition p;
  p.k_index = 2;
  p.steps_total = 1234;
  p.evaluations = 5678;
  p.integration_seconds = 9.75;
  p.theta = distinct(11, rows * k_replicas, first);
  p.p = distinct(12, rows * k_replicas, first);
  return p;
}

void require_same(const CheckpointRecord& a, const CheckpointRecord& b) {
  REQUIRE(a.counts == b.counts);
  REQUIRE(a.reals == b.reals);
  REQUIRE(a.arrays.size() == b.arrays.size());
  for (std::size_t k = 0; k < a.arrays.size(); ++k) {
    INFO("field " << a.arrays[k].name);
    REQUIRE(a.arrays[k].name == b.arrays[k].name);
    REQUIRE(a.arrays[k].columns == b.arrays[k].columns);
    REQUIRE(a.arrays[k].values == b.arrays[k].values);
  }
}

}  // namespace

TEST_CASE("Every member of the segment state and the run position is in the field list",
          "[segment_state]") {
  SegmentState segment;
  RunPosition position;
  FieldCounter counter;
  visit_fields(position, segment, counter);
  INFO("a member missing from visit_fields would not be checkpointed");
  REQUIRE(counter.fields == member_count<SegmentState>() + member_count<RunPosition>());
}

TEST_CASE("Every field survives capture, the checkpoint file and restore [ER N=60, B=3]",
          "[segment_state]") {
  const Network net = erdos_renyi({60, 0.1, 3});
  const DistributedNetwork d(net);
  const std::string path = temp_path("hmfnet_test_segment_round_trip");
  const RowExchange exchange = row_exchange(d, path);

  const SegmentState segment = filled_segment(d);
  const RunPosition position = filled_position(d);
  Checkpoint written;
  written.fingerprint = "{\"test\": 1}";
  written.replicas = k_replicas;
  written.record = capture(position, segment, k_replicas, exchange);
  for (const auto& a : written.record.arrays) {
    INFO("field " << a.name << " must be exercised");
    REQUIRE_FALSE(a.values.empty());
  }
  if (ParallelSession::rank() == 0) write_checkpoint(path, written);
  ParallelSession::max(0.0);
  const Checkpoint read = read_checkpoint(path);
  require_same(written.record, read.record);

  // Restore into fresh shapes (as a resuming run builds them), then capture again: every field
  // must come back, so the second record equals the first.
  SegmentState restored;
  restored.R = BatchMeans(40, 4, k_replicas);
  restored.stats = NodeStatistics(d.first_row(), d.local_size(), 0, k_rotor_samples, k_bins, 0.0);
  RunPosition restored_position;
  restore(read.record, restored_position, restored, k_replicas, exchange);
  require_same(written.record, capture(restored_position, restored, k_replicas, exchange));
  REQUIRE(restored.R.mean() == segment.R.mean());
  REQUIRE(restored.R.standard_error() == segment.R.standard_error());
  remove_on_root(path);
}

TEST_CASE("A checkpoint whose field does not fit the run is refused naming the field",
          "[segment_state]") {
  const Network net = erdos_renyi({60, 0.1, 3});
  const DistributedNetwork d(net);
  const RowExchange exchange = row_exchange(d, "cp.h5");
  CheckpointRecord record = capture(filled_position(d), filled_segment(d), k_replicas, exchange);
  record.source = "cp.h5";
  SegmentState fresh;
  fresh.R = BatchMeans(40, 5, k_replicas);  // another batch count than the record's 4
  fresh.stats = NodeStatistics(d.first_row(), d.local_size(), 0, k_rotor_samples, k_bins, 0.0);
  RunPosition position;
  REQUIRE_THROWS_WITH(restore(record, position, fresh, k_replicas, exchange),
                      Catch::Contains("cp.h5") && Catch::Contains("batch_sums"));
}

TEST_CASE("A checkpoint of an older format version is refused with a message that says so",
          "[segment_state]") {
  const Network net = erdos_renyi({60, 0.1, 3});
  const DistributedNetwork d(net);
  const std::string path = temp_path("hmfnet_test_old_checkpoint");
  Checkpoint c;
  c.fingerprint = "{}";
  c.replicas = k_replicas;
  c.record = capture(filled_position(d), filled_segment(d), k_replicas, row_exchange(d, path));
  if (ParallelSession::rank() == 0) {
    write_checkpoint(path, c);
    // Version 3 (before the field lists) as an older hmfnet wrote it.
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    const hid_t attr = H5Aopen(file, "format_version", H5P_DEFAULT);
    const std::int64_t old_version = 3;
    REQUIRE(H5Awrite(attr, H5T_NATIVE_INT64, &old_version) >= 0);
    H5Aclose(attr);
    H5Fclose(file);
  }
  ParallelSession::max(0.0);
  REQUIRE_THROWS_WITH(read_checkpoint(path), Catch::Contains(path) &&
                                                 Catch::Contains("format version 3") &&
                                                 Catch::Contains("not supported"));
  remove_on_root(path);
}
