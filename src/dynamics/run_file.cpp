#include "dynamics/run_file.hpp"

#include <algorithm>
#include <cmath>

#include "core/atomic_file.hpp"
#include "core/version.hpp"

namespace hmfnet {

namespace {

std::vector<double> stack(const std::vector<PointResult>& points,
                          std::vector<double> PointResult::*field) {
  std::vector<double> out;
  for (const auto& p : points) out.insert(out.end(), (p.*field).begin(), (p.*field).end());
  return out;
}

void unstack(std::vector<PointResult>& points, std::vector<double> PointResult::*field,
             const std::vector<double>& data, std::size_t per_point) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto first = data.begin() + static_cast<std::ptrdiff_t>(k * per_point);
    (points[k].*field).assign(first, first + static_cast<std::ptrdiff_t>(per_point));
  }
}

const std::pair<const char*, std::vector<double> PointResult::*> k_per_replica[] = {
    {"R_mean", &PointResult::R_mean},
    {"R_sem", &PointResult::R_sem},
    {"energy_rel_error_max", &PointResult::energy_rel_error_max},
    {"momentum_drift", &PointResult::momentum_drift}};

const std::pair<const char*, std::vector<double> PointResult::*> k_per_node[] = {
    {"R_node", &PointResult::R_node}, {"omega_node", &PointResult::omega_node}};

// Replica-0 vectors of the same length at every point: stored [points x length].
const std::pair<const char*, std::vector<double> PointResult::*> k_per_point_vector[] = {
    {"r_node", &PointResult::r_node},
    {"fluctuation", &PointResult::fluctuation},
    {"synchronised", &PointResult::synchronised},
    {"phase_histogram", &PointResult::phase_histogram},
    {"rotor_theta_bar", &PointResult::rotor_theta_bar},
    {"rotor_p_bar", &PointResult::rotor_p_bar},
    {"psi_frequency", &PointResult::psi_frequency},
    {"frame", &PointResult::frame}};

// Per-point arrays present only with node data: [points * rows x cols], split evenly by point.
template <class Table>
void read_optional(const Hdf5File& f, hid_t group, std::vector<PointResult>& points,
                   const Table& table) {
  for (const auto& [name, field] : table) {
    if (!f.exists(std::string("points/") + name) || points.empty()) continue;
    std::size_t rows = 0, cols = 0;
    const auto data = f.read_matrix(group, name, rows, cols);
    unstack(points, field, data, data.size() / points.size());
  }
}

}  // namespace

void write_results(const Hdf5File& f, const std::vector<PointResult>& points,
                   const TimeSeries& series, int replicas) {
  const auto w = static_cast<std::size_t>(replicas);
  const H5Id pg = f.create_group("points");
  std::vector<double> K, h;
  std::vector<std::string> integrator;
  for (const auto& p : points) {
    K.push_back(p.K);
    h.push_back(p.h);
    integrator.push_back(p.integrator);
  }
  f.write(pg.get(), "K", K);
  f.write(pg.get(), "h", h);
  f.write_strings(pg.get(), "integrator", integrator);
  for (const auto& [name, field] : k_per_replica) {
    f.write_matrix(pg.get(), name, stack(points, field), points.size(), w);
  }
  for (const auto& [name, field] : k_per_node) {
    const auto data = stack(points, field);
    if (!data.empty()) f.write_matrix(pg.get(), name, data, data.size() / w, w);
  }
  for (const auto& [name, field] : k_per_point_vector) {
    const auto data = stack(points, field);
    if (!data.empty())
      f.write_matrix(pg.get(), name, data, points.size(), data.size() / points.size());
  }
  const H5Id tg = f.create_group("timeseries");
  f.write(tg.get(), "t", series.t);
  f.write(tg.get(), "K", series.K);
  f.write_matrix(tg.get(), "R", series.R, series.t.size(), w);
  f.write_matrix(tg.get(), "energy", series.energy, series.t.size(), w);
  f.write_matrix(tg.get(), "momentum", series.momentum, series.t.size(), w);
}

void read_results(const Hdf5File& f, std::vector<PointResult>& points, TimeSeries& series,
                  int replicas) {
  const auto w = static_cast<std::size_t>(replicas);
  const H5Id pg = f.open_group("points");
  const std::vector<double> K = f.read_double(pg.get(), "K");
  const std::vector<double> h = f.read_double(pg.get(), "h");
  const std::vector<std::string> integrator = f.read_strings(pg.get(), "integrator");
  if (h.size() != K.size() || integrator.size() != K.size()) {
    f.fail("points/h and points/integrator must have one entry per K");
  }
  points.assign(K.size(), PointResult{});
  for (std::size_t k = 0; k < K.size(); ++k) {
    points[k].K = K[k];
    points[k].h = h[k];
    points[k].integrator = integrator[k];
  }
  std::size_t rows = 0, cols = 0;
  for (const auto& [name, field] : k_per_replica) {
    unstack(points, field, f.read_matrix(pg.get(), name, rows, cols), w);
  }
  read_optional(f, pg.get(), points, k_per_node);
  read_optional(f, pg.get(), points, k_per_point_vector);
  const H5Id tg = f.open_group("timeseries");
  series.t = f.read_double(tg.get(), "t");
  series.K = f.read_double(tg.get(), "K");
  series.R = f.read_matrix(tg.get(), "R", rows, cols);
  series.energy = f.read_matrix(tg.get(), "energy", rows, cols);
  series.momentum = f.read_matrix(tg.get(), "momentum", rows, cols);
}

namespace {

// Doubles stored for the results: per point and replica 4 values; per record t, K and 3 per
// replica; with node data per point 2 N per replica, 5 N (r, fluctuation, synchronised,
// psi_frequency and slack) and the histogram and rotor samples.
double result_doubles(const SimulationParameters& p, double n) {
  const double points = static_cast<double>(p.K.size());
  const double replicas = static_cast<double>(p.replicas.size());
  const double steps = std::ceil(p.duration / p.h);
  const double records = points * (steps / std::max(1, p.record_stride) + 1.0);
  double doubles = points * (4.0 * replicas + 8.0) + records * (2.0 + 3.0 * replicas);
  if (p.node_data) {
    const double rotor = (p.duration - p.transient) / p.h / std::max(1, p.record_stride) + 1.0;
    doubles += points * (n * (2.0 * replicas + 5.0) + p.phase_bins + 2.0 * rotor);
  }
  return doubles;
}

constexpr double k_metadata_bytes = 1 << 20;

}  // namespace

std::uintmax_t estimated_run_file_bytes(const SimulationParameters& params, NodeIndex n) {
  return static_cast<std::uintmax_t>(8.0 * result_doubles(params, n) + k_metadata_bytes);
}

std::uintmax_t estimated_checkpoint_bytes(const SimulationParameters& params, NodeIndex n) {
  // The results so far plus the state (theta, p), the node-data accumulators (theta_T1,
  // R_node_sum, 8 per-row sums) and the batch sums.
  const double N = static_cast<double>(n), replicas = static_cast<double>(lanes(params));
  double state = 2.0 * N * replicas + 64.0 * replicas;
  if (params.node_data) state += 2.0 * N * replicas + 8.0 * N;
  return static_cast<std::uintmax_t>(8.0 * (result_doubles(params, N) + state) + k_metadata_bytes);
}

nlohmann::json run_parameters(const SimulationParameters& params, const std::string& inputs_json) {
  nlohmann::json j = to_json(params);
  if (!inputs_json.empty()) j.update(nlohmann::json::parse(inputs_json));
  return j;
}

namespace {

// The step of the whole run when every K shares it; with per-K steps (SimulationParameters::steps)
// the top-level attributes say so and /points/integrator, /points/h hold each K's.
StepChoice common_step(const SimulationParameters& params) {
  StepChoice first = step_at(params, 0);  // not const: the return moves it
  for (std::size_t k = 1; k < params.K.size(); ++k) {
    if (!(step_at(params, k) == first)) return {"per K: see /points/integrator", std::nan("")};
  }
  return first;
}

}  // namespace

void write_run_file(const std::string& path, const SimulationResult& result,
                    const SimulationParameters& params, const RunMetadata& meta) {
  AtomicFile out(path);
  {
    const Hdf5File f(out.temp_path(), Hdf5File::Mode::create);
    const hid_t root = f.id();
    f.set_attribute(root, "hmfnet_format", std::string("simulation"));
    // 2: /points/h and /points/integrator; `parameters` is run_parameters (every field).
    f.set_attribute(root, "format_version", std::int64_t{2});
    f.set_attribute(root, "hmfnet_version", std::string(version()));
    f.set_attribute(root, "git_commit", std::string(git_commit()));
    f.set_attribute(root, "parameters", run_parameters(params, meta.inputs_json).dump());
    f.set_attribute(root, "network", meta.network_json);
    f.set_attribute(root, "provenance", meta.provenance_json);
    const StepChoice step = common_step(params);
    f.set_attribute(root, "integrator", step.integrator);
    f.set_attribute(root, "force", result.force_name);
    f.set_attribute(root, "h", step.h);
    f.set_attribute(root, "duration", params.duration);
    f.set_attribute(root, "transient", params.transient);
    f.set_attribute(root, "replicas", static_cast<std::int64_t>(params.replicas.size()));
    f.set_attribute(root, "steps", result.steps);
    f.set_attribute(root, "force_evaluations", result.force_evaluations);
    f.set_attribute(root, "integration_seconds", result.integration_seconds);
    write_results(f, result.points, result.series, static_cast<int>(params.replicas.size()));
    if (meta.Kc > 0.0) {
      const H5Id pg = f.open_group("points");
      std::vector<double> ratio;
      for (const auto& p : result.points) ratio.push_back(p.K / meta.Kc);
      f.write(pg.get(), "K_over_Kc", ratio);
      f.set_attribute(root, "Kc", meta.Kc);
    }
    f.flush();
  }
  out.commit();
}

}  // namespace hmfnet
