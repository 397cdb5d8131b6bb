#include "dynamics/replica_lanes.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hmfnet {

namespace {

// Values [m R, (m + 1) R) of a per-lane vector: the replicas of K_m.
std::vector<double> slice(const std::vector<double>& v, std::size_t m, std::size_t r) {
  const auto first = v.begin() + static_cast<std::ptrdiff_t>(m * r);
  return {first, first + static_cast<std::ptrdiff_t>(r)};
}

// Columns [m R, (m + 1) R) of each row of a rows x (M R) array.
std::vector<double> column_slice(const std::vector<double>& v, std::size_t m, std::size_t r,
                                 std::size_t width) {
  std::vector<double> out;
  for (std::size_t row = 0; row * width < v.size(); ++row) {
    const auto first = v.begin() + static_cast<std::ptrdiff_t>(row * width + m * r);
    out.insert(out.end(), first, first + static_cast<std::ptrdiff_t>(r));
  }
  return out;
}

// K_m's point from the lane run's one point, field by field (point_result.hpp): what is per
// replica takes K_m's lanes; the segment's K, step and method are those of every lane.
struct PointSplit {
  std::size_t m, r, width;
  void scalar(const char*, const double& from, double& to) const { to = from; }
  void text(const char*, const std::string& from, std::string& to) const { to = from; }
  void per_replica(const char*, const std::vector<double>& from, std::vector<double>& to) const {
    to = slice(from, m, r);
  }
  void per_node_replica(const char*, const std::vector<double>& from,
                        std::vector<double>& to) const {
    to = column_slice(from, m, r, width);
  }
  // Replica 0's node data describes lane 0 only: no other K has it (validate refuses node_data
  // with K_across_replicas, so it never gets here).
  void node_vector(const char* name, const std::vector<double>& from,
                   std::vector<double>& /*to*/) const {
    if (!from.empty()) {
      throw std::logic_error(std::string("split_lanes: ") + name + " cannot be split by K");
    }
  }
};

// The sequential run's records: K_m's segment follows the m earlier ones, so its record at step
// s of the segment has t = (m S + s) h (simulation.cpp: t counts the steps of the whole run), and
// K_m's replicas are its lanes. A per-record field needs its own rule here: there is none for a
// new one until it is written.
struct SeriesSplit {
  const SimulationParameters& params;
  std::size_t r, width;
  std::int64_t S;
  double h;
  void per_record(const char* name, const std::vector<double>& from,
                  std::vector<double>& to) const {
    const std::string field = name;
    if (field != "t" && field != "K") {
      throw std::logic_error("split_lanes: no rule for the per-record field " + field);
    }
    for (std::size_t m = 0; m < params.K.size(); ++m) {
      for (const double t : from) {
        const std::int64_t s = std::llround(t / h);
        to.push_back(field == "K" ? params.K[m]
                                  : static_cast<double>(static_cast<std::int64_t>(m) * S + s) * h);
      }
    }
  }
  void per_record_replica(const char*, const std::vector<double>& from,
                          std::vector<double>& to) const {
    for (std::size_t m = 0; m < params.K.size(); ++m) {
      const std::vector<double> lanes = column_slice(from, m, r, width);
      to.insert(to.end(), lanes.begin(), lanes.end());
    }
  }
};

}  // namespace

SimulationParameters lane_parameters(const SimulationParameters& params) {
  SimulationParameters p = params;
  p.K_across_replicas = false;
  p.continue_state = true;  // one segment: nothing to continue or restart
  p.K = {params.K.front()};
  if (!params.steps.empty()) p.steps = {params.steps.front()};
  p.replicas.clear();
  for (std::size_t m = 0; m < params.K.size(); ++m)
    p.replicas.insert(p.replicas.end(), params.replicas.begin(), params.replicas.end());
  return p;
}

std::vector<double> lane_couplings(const SimulationParameters& params) {
  std::vector<double> K;
  for (const double k : params.K) K.insert(K.end(), params.replicas.size(), k);
  return K;
}

SimulationResult split_lanes(SimulationResult run, const SimulationParameters& params) {
  const std::size_t r = params.replicas.size();
  const std::size_t width = lanes(params);
  std::vector<PointResult> points;
  if (!run.points.empty()) {
    for (std::size_t m = 0; m < params.K.size(); ++m) {
      PointResult p;
      const PointSplit split{m, r, width};
      visit_point_fields(split, run.points.front(), p);
      p.K = params.K[m];
      points.push_back(std::move(p));
    }
  }
  const double h = step_at(params, 0).h;
  const SeriesSplit split{params, r, width, std::llround(params.duration / h), h};
  TimeSeries series;
  visit_series_fields(split, run.series, series);
  run.series = std::move(series);
  run.points = std::move(points);
  return run;
}

}  // namespace hmfnet
