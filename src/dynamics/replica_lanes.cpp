#include "dynamics/replica_lanes.hpp"

#include <cmath>

namespace hmfnet {

namespace {

// Values [m R, (m + 1) R) of a per-lane vector: the replicas of K_m.
std::vector<double> slice(const std::vector<double>& v, std::size_t m, std::size_t r) {
  const auto first = v.begin() + static_cast<std::ptrdiff_t>(m * r);
  return {first, first + static_cast<std::ptrdiff_t>(r)};
}

PointResult point_of(const PointResult& run, double K, std::size_t m, std::size_t r) {
  PointResult p;
  p.K = K;
  p.integrator = run.integrator;
  p.h = run.h;
  p.R_mean = slice(run.R_mean, m, r);
  p.R_sem = slice(run.R_sem, m, r);
  p.energy_rel_error_max = slice(run.energy_rel_error_max, m, r);
  p.momentum_drift = slice(run.momentum_drift, m, r);
  return p;
}

// The sequential run's records: K_m's segment follows the m earlier ones, so its record at step
// s of the segment has t = (m S + s) h (simulation.cpp: t counts the steps of the whole run).
TimeSeries series_of(const TimeSeries& run, const SimulationParameters& params, std::size_t r) {
  const double h = step_at(params, 0).h;
  const std::int64_t S = std::llround(params.duration / h);
  const std::size_t width = lanes(params);
  TimeSeries out;
  for (std::size_t m = 0; m < params.K.size(); ++m) {
    for (std::size_t j = 0; j < run.t.size(); ++j) {
      const std::int64_t s = std::llround(run.t[j] / h);
      out.t.push_back(static_cast<double>(static_cast<std::int64_t>(m) * S + s) * h);
      out.K.push_back(params.K[m]);
      for (const auto& [from, to] : {std::pair{&run.R, &out.R}, std::pair{&run.energy, &out.energy},
                                     std::pair{&run.momentum, &out.momentum}}) {
        const auto first = from->begin() + static_cast<std::ptrdiff_t>(j * width + m * r);
        to->insert(to->end(), first, first + static_cast<std::ptrdiff_t>(r));
      }
    }
  }
  return out;
}

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
  std::vector<PointResult> points;
  if (!run.points.empty()) {
    for (std::size_t m = 0; m < params.K.size(); ++m)
      points.push_back(point_of(run.points.front(), params.K[m], m, r));
  }
  run.series = series_of(run.series, params, r);
  run.points = std::move(points);
  return run;
}

}  // namespace hmfnet
