// The results are declared once (point_result.hpp): every member of PointResult and TimeSeries
// is in its field list, and every listed field reaches each consumer of the lists: the results
// file (written and read back equal), the checkpoint checksum (changed by any one field), the
// split of a run across replicas (each field lands in K_m's point) and the Python module (its
// own test, tests/python/test_commands.py, compares its keys with the list).
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/checkpoint.hpp"
#include "dynamics/point_result.hpp"
#include "dynamics/replica_lanes.hpp"
#include "dynamics/run_file.hpp"
#include "io/hdf5_file.hpp"
#include "support/member_count.hpp"

using namespace hmfnet;
using hmfnet::test::member_count;

namespace {

constexpr std::size_t k_replicas = 2;
constexpr std::size_t k_nodes = 3;

// Counts the fields a list visits, whatever their kind.
struct FieldCounter {
  std::size_t fields = 0;
  template <class... T>
  void count(const T&...) {
    ++fields;
  }
  template <class... T>
  void scalar(const char*, const T&... x) {
    count(x...);
  }
  template <class... T>
  void text(const char*, const T&... x) {
    count(x...);
  }
  template <class... T>
  void per_replica(const char*, const T&... x) {
    count(x...);
  }
  template <class... T>
  void per_node_replica(const char*, const T&... x) {
    count(x...);
  }
  template <class... T>
  void node_vector(const char*, const T&... x) {
    count(x...);
  }
  template <class... T>
  void per_record(const char*, const T&... x) {
    count(x...);
  }
  template <class... T>
  void per_record_replica(const char*, const T&... x) {
    count(x...);
  }
};

// Distinct values in every field (1000 * field + 100 * item + index), each with its kind's shape:
// `width` replicas, k_nodes nodes, `records` records.
class Filler {
 public:
  Filler(std::size_t width, std::size_t records, bool node_data, double item)
      : m_width(width), m_records(records), m_node_data(node_data), m_item(item) {}
  void scalar(const char*, double& x) { x = next(1)[0]; }
  void text(const char*, std::string& s) { s = "method" + std::to_string(m_field++); }
  void per_replica(const char*, std::vector<double>& v) { v = next(m_width); }
  void per_node_replica(const char*, std::vector<double>& v) {
    v = next(m_node_data ? k_nodes * m_width : 0);
  }
  void node_vector(const char*, std::vector<double>& v) { v = next(m_node_data ? k_nodes : 0); }
  void per_record(const char*, std::vector<double>& v) { v = next(m_records); }
  void per_record_replica(const char*, std::vector<double>& v) { v = next(m_records * m_width); }

 private:
  std::vector<double> next(std::size_t size) {
    std::vector<double> v(size);
    for (std::size_t k = 0; k < size; ++k) {
      v[k] = 1000.0 * static_cast<double>(m_field) + 100.0 * m_item + static_cast<double>(k);
    }
    ++m_field;
    return v;
  }
  std::size_t m_width, m_records;
  bool m_node_data;
  double m_item;
  std::size_t m_field = 0;
};

PointResult filled_point(std::size_t width, bool node_data, double item) {
  PointResult p;
  Filler filler(width, 0, node_data, item);
  visit_point_fields(filler, p);
  return p;
}

TimeSeries filled_series(std::size_t width, std::size_t records) {
  TimeSeries s;
  Filler filler(width, records, false, 0.0);
  visit_series_fields(filler, s);
  return s;
}

// Requires two results equal field by field, naming the field that differs.
struct Equal {
  template <class T>
  void check(const char* name, const T& a, const T& b) const {
    INFO("field " << name);
    REQUIRE(a == b);
  }
  template <class T>
  void scalar(const char* n, const T& a, const T& b) const {
    check(n, a, b);
  }
  template <class T>
  void text(const char* n, const T& a, const T& b) const {
    check(n, a, b);
  }
  template <class T>
  void per_replica(const char* n, const T& a, const T& b) const {
    check(n, a, b);
  }
  template <class T>
  void per_node_replica(const char* n, const T& a, const T& b) const {
    check(n, a, b);
  }
  template <class T>
  void node_vector(const char* n, const T& a, const T& b) const {
    check(n, a, b);
  }
  template <class T>
  void per_record(const char* n, const T& a, const T& b) const {
    check(n, a, b);
  }
  template <class T>
  void per_record_replica(const char* n, const T& a, const T& b) const {
    check(n, a, b);
  }
};

// Changes the value of field `target` (in list order) and nothing else.
class Perturb {
 public:
  explicit Perturb(std::size_t target) : m_target(target) {}
  void scalar(const char*, double& x) {
    if (hit()) x += 0.5;
  }
  void text(const char*, std::string& s) {
    if (hit()) s += "!";
  }
  void per_replica(const char*, std::vector<double>& v) { change(v); }
  void per_node_replica(const char*, std::vector<double>& v) { change(v); }
  void node_vector(const char*, std::vector<double>& v) { change(v); }
  void per_record(const char*, std::vector<double>& v) { change(v); }
  void per_record_replica(const char*, std::vector<double>& v) { change(v); }

 private:
  bool hit() { return m_field++ == m_target; }
  void change(std::vector<double>& v) {
    if (hit()) v.back() += 0.5;
  }
  std::size_t m_target;
  std::size_t m_field = 0;
};

std::size_t point_fields() {
  PointResult p;
  FieldCounter c;
  visit_point_fields(c, p);
  return c.fields;
}

std::size_t series_fields() {
  TimeSeries s;
  FieldCounter c;
  visit_series_fields(c, s);
  return c.fields;
}

}  // namespace

TEST_CASE("Every member of PointResult and TimeSeries is in its field list", "[point_result]") {
  INFO("a member missing from visit_point_fields or visit_series_fields is lost by every consumer");
  REQUIRE(point_fields() == member_count<PointResult>());
  REQUIRE(series_fields() == member_count<TimeSeries>());
}

TEST_CASE("Every field survives the results file, with and without node data", "[point_result]") {
  for (const bool node_data : {true, false}) {
    INFO("node data " << node_data);
    const std::vector<PointResult> points{filled_point(k_replicas, node_data, 0.0),
                                          filled_point(k_replicas, node_data, 1.0)};
    const TimeSeries series = filled_series(k_replicas, 4);
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("hmfnet_test_point_result_" + std::to_string(::getpid()) + ".h5"))
                                 .string();
    {
      const Hdf5File f(path, Hdf5File::Mode::create);
      write_results(f, points, series, static_cast<int>(k_replicas));
    }
    std::vector<PointResult> read;
    TimeSeries read_series;
    {
      const Hdf5File f(path, Hdf5File::Mode::read);
      read_results(f, read, read_series, static_cast<int>(k_replicas));
    }
    std::filesystem::remove(path);
    REQUIRE(read.size() == points.size());
    const Equal equal;
    for (std::size_t k = 0; k < points.size(); ++k) visit_point_fields(equal, points[k], read[k]);
    visit_series_fields(equal, series, read_series);
  }
}

TEST_CASE("The checkpoint checksum changes with every result field", "[point_result]") {
  Checkpoint c;
  c.fingerprint = "{}";
  c.replicas = static_cast<int>(k_replicas);
  c.points = {filled_point(k_replicas, true, 0.0), filled_point(k_replicas, true, 1.0)};
  c.series = filled_series(k_replicas, 4);
  const std::string base = checkpoint_checksum(c);
  for (std::size_t field = 0; field < point_fields(); ++field) {
    INFO("point field " << field << " (in visit_point_fields order)");
    Checkpoint changed = c;
    Perturb perturb(field);
    visit_point_fields(perturb, changed.points.back());
    REQUIRE(checkpoint_checksum(changed) != base);
  }
  for (std::size_t field = 0; field < series_fields(); ++field) {
    INFO("series field " << field << " (in visit_series_fields order)");
    Checkpoint changed = c;
    Perturb perturb(field);
    visit_series_fields(perturb, changed.series);
    REQUIRE(checkpoint_checksum(changed) != base);
  }
}

TEST_CASE("The split of a run across replicas carries every field to K_m's point",
          "[point_result]") {
  SimulationParameters params;
  params.h = 0.5;
  params.duration = 2.0;
  params.transient = 0.0;
  params.K = {1.0, 2.0, 3.0};
  params.continue_state = false;
  params.K_across_replicas = true;
  params.replicas.assign(k_replicas, InitialCondition{});
  const std::size_t width = lanes(params);  // 3 K x 2 replicas
  const std::size_t records = 4;

  SimulationResult run;
  run.points = {filled_point(width, false, 0.0)};
  run.points.front().R_node = std::vector<double>(k_nodes * width);  // N x lanes, row-major
  for (std::size_t k = 0; k < run.points.front().R_node.size(); ++k) {
    run.points.front().R_node[k] = static_cast<double>(k);
  }
  run.series = filled_series(width, records);
  run.series.t = {0.5, 1.0, 1.5, 2.0};
  const SimulationResult split = split_lanes(run, params);

  REQUIRE(split.points.size() == params.K.size());
  for (std::size_t m = 0; m < params.K.size(); ++m) {
    INFO("K_" << m);
    PointResult expected = run.points.front();
    expected.K = params.K[m];
    expected.R_mean.assign(run.points.front().R_mean.begin() + long(m * k_replicas),
                           run.points.front().R_mean.begin() + long((m + 1) * k_replicas));
    for (auto* v : {&expected.R_sem, &expected.energy_rel_error_max, &expected.momentum_drift}) {
      const std::vector<double> lanes_of_run = *v;
      v->assign(lanes_of_run.begin() + long(m * k_replicas),
                lanes_of_run.begin() + long((m + 1) * k_replicas));
    }
    expected.R_node.clear();
    for (std::size_t node = 0; node < k_nodes; ++node) {
      for (std::size_t r = 0; r < k_replicas; ++r) {
        expected.R_node.push_back(static_cast<double>(node * width + m * k_replicas + r));
      }
    }
    const Equal equal;
    visit_point_fields(equal, expected, split.points[m]);
  }
  // Records: K_m's follow the m earlier segments (S = 4 steps of h = 0.5 each).
  REQUIRE(split.series.t.size() == params.K.size() * records);
  REQUIRE(split.series.t[records] == 2.0 + 0.5);
  REQUIRE(split.series.K[records] == 2.0);
  REQUIRE(split.series.R[k_replicas] == run.series.R[width]);  // record 1 of K_0
  REQUIRE(split.series.energy[0 + records * k_replicas] == run.series.energy[k_replicas]);

  // Replica 0's node data belongs to one lane: splitting it would invent data for the others.
  run.points.front().r_node = {1.0, 2.0, 3.0};
  REQUIRE_THROWS_AS(split_lanes(run, params), std::logic_error);
}
