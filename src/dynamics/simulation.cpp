#include "dynamics/simulation.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>

#include "core/error.hpp"
#include "dynamics/checkpoint.hpp"
#include "dynamics/interrupt.hpp"
#include "dynamics/node_statistics.hpp"
#include "dynamics/ordered_sum.hpp"
#include "dynamics/time_average.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

using Clock = std::chrono::steady_clock;

std::int64_t steps_for(double time, double h) { return std::llround(time / h); }

/// Where the recorded time is measured from at segment k: the time and step count at the start
/// of the last segment whose step differs from its predecessor's. With one step throughout it
/// stays (0, 0), so t = steps * h exactly as with a single h.
struct TimeOrigin {
  double t = 0.0;
  std::int64_t steps = 0;
};

TimeOrigin time_origin(const SimulationParameters& p, std::size_t k) {
  TimeOrigin origin;
  double t = 0.0;
  std::int64_t steps = 0;
  for (std::size_t j = 0; j <= k; ++j) {
    const double h = step_at(p, j).h;
    if (j > 0 && h != step_at(p, j - 1).h) origin = {t, steps};
    if (j == k) break;
    const std::int64_t n = steps_for(p.duration, h);
    t = origin.t + static_cast<double>(steps + n - origin.steps) * h;
    steps += n;
  }
  return origin;
}

// Accumulators of the K being integrated.
struct Segment {
  std::int64_t step = 0;
  BatchMeans R;
  std::vector<double> energy0, momentum0, momentum_scale, energy_err_max, momentum_drift_max;
  std::vector<double> theta_T1, R_node_sum;
  NodeStatistics stats;
};

struct Observables {
  std::vector<double> R, energy, momentum, momentum_scale;
};

class Run {
 public:
  Run(const DistributedNetwork& network, const std::vector<double>& degrees, CouplingForce& force,
      const SimulationParameters& params)
      : m_network(network),
        m_force(force),
        m_params(params),
        m_integrator(make_integrator(step_at(params, 0).integrator)),
        m_h(step_at(params, 0).h),
        m_f(force),
        m_width(static_cast<int>(params.replicas.size())),
        m_total_degree(std::accumulate(degrees.begin(), degrees.end(), 0.0)),
        m_n(static_cast<double>(network.global_size())) {}

  SimulationResult execute();

 private:
  std::vector<double> K_per_replica(double K) const {
    return std::vector<double>(static_cast<std::size_t>(m_width), K);
  }
  std::vector<double> order_parameter() const;
  Observables observe(double K) const;
  void use_step(int k_index);
  std::int64_t segment_steps() const { return steps_for(m_params.duration, m_h); }
  std::int64_t transient_steps() const { return steps_for(m_params.transient, m_h); }
  void start_segment(int k_index);
  void finish_segment(int k_index);
  void record(int k_index);
  void sample();
  void guard(double K, const Observables& o);
  void maybe_checkpoint(int k_index, bool force_now);
  void finish_interrupted();
  void restore(const Checkpoint& c);
  std::vector<double> gather(const std::vector<double>& local, int width = 0) const;
  std::vector<double> scatter(const std::vector<double>& global, int width = 0) const;
  std::int64_t rotor_samples() const;
  void progress(int k_index, bool final_line) const;

  const DistributedNetwork& m_network;
  CouplingForce& m_force;
  const SimulationParameters& m_params;
  std::unique_ptr<Integrator> m_integrator;  // of the current segment (step_at)
  double m_h;                                // of the current segment
  TimeOrigin m_origin;                       // of the current segment (time_origin)
  ForceEvaluation m_f;
  int m_width;
  double m_total_degree;
  double m_n;
  RotorState m_state;
  Segment m_seg;
  SimulationResult m_result;
  int m_k_start = 0;
  double m_seconds_before = 0.0;  // integration seconds of earlier sessions (resume)
  Clock::time_point m_loop_start{};
  Clock::time_point m_last_checkpoint{};
};

std::vector<double> Run::order_parameter() const {
  // eq:globalOrderParam: R = sum_n R_n / ||d|| = sum_n |y_n| / sum_n d_n.
  std::vector<double> R = m_f.sums().order;
  ParallelSession::sum_in_place(R);
  for (double& x : R) x /= m_total_degree;
  return R;
}

Observables Run::observe(double K) const {
  const auto rows = static_cast<std::size_t>(m_state.rows);
  std::vector<double> p2(m_state.p.size()), absp(m_state.p.size());
  for (std::size_t k = 0; k < p2.size(); ++k) {
    p2[k] = 0.5 * m_state.p[k] * m_state.p[k];
    absp[k] = std::abs(m_state.p[k]);
  }
  Observables o;
  std::vector<double> kinetic, momentum, scale;
  ordered_column_sums(p2, rows, m_width, kinetic);
  ordered_column_sums(m_state.p, rows, m_width, momentum);
  ordered_column_sums(absp, rows, m_width, scale);
  std::vector<double> coupling = m_f.sums().coupling;
  // One reduction for all four sums.
  std::vector<double> all;
  for (const auto* v : {&kinetic, &momentum, &scale, &coupling})
    all.insert(all.end(), v->begin(), v->end());
  ParallelSession::sum_in_place(all);
  const auto w = static_cast<std::size_t>(m_width);
  o.R = order_parameter();
  for (std::size_t b = 0; b < w; ++b) {
    // eq:hamiltonianNetworkCase: H = sum p^2/2 - (K/2N) sum_nm A_nm cos(theta_m - theta_n).
    o.energy.push_back(all[b] - K / (2.0 * m_n) * all[3 * w + b]);
    o.momentum.push_back(all[w + b]);
    o.momentum_scale.push_back(all[2 * w + b]);
  }
  return o;
}

void Run::use_step(int k_index) {
  const StepChoice choice = step_at(m_params, static_cast<std::size_t>(k_index));
  if (choice.integrator != m_integrator->name()) m_integrator = make_integrator(choice.integrator);
  m_h = choice.h;
  m_origin = time_origin(m_params, static_cast<std::size_t>(k_index));
}

void Run::start_segment(int k_index) {
  const double K = m_params.K[static_cast<std::size_t>(k_index)];
  use_step(k_index);
  if (!m_params.continue_state && k_index > 0) {
    m_state = initial_state(m_network.first_row(), m_network.local_size(), m_params.replicas);
    m_f.update(m_state);
  }
  const std::int64_t steps = segment_steps();
  const std::int64_t transient = transient_steps();
  m_seg = Segment{};
  m_seg.R = BatchMeans(steps - transient, m_params.batches, m_width);
  const Observables o = observe(K);
  m_seg.energy0 = o.energy;
  m_seg.momentum0 = o.momentum;
  m_seg.momentum_scale = o.momentum_scale;
  m_seg.energy_err_max.assign(static_cast<std::size_t>(m_width), 0.0);
  m_seg.momentum_drift_max.assign(static_cast<std::size_t>(m_width), 0.0);
  if (m_params.node_data) {
    m_seg.R_node_sum.assign(m_state.p.size(), 0.0);
    if (transient == 0) m_seg.theta_T1 = m_state.theta;
    m_seg.stats = NodeStatistics(m_state.first_row, m_state.rows, m_params.rotor_node,
                                 rotor_samples(), m_params.phase_bins, o.momentum[0] / m_n);
  }
}

std::int64_t Run::rotor_samples() const {
  // Records fall on multiples of the stride and on the last step.
  const std::int64_t steps = segment_steps();
  const std::int64_t transient = transient_steps();
  const std::int64_t stride = m_params.record_stride;
  return steps / stride - transient / stride + (steps % stride != 0 ? 1 : 0);
}

void Run::sample() {
  m_seg.R.add(order_parameter());
  if (!m_params.node_data) return;
  const auto& y = m_force.local_fields();
  for (std::size_t k = 0; k < m_seg.R_node_sum.size(); ++k) {
    m_seg.R_node_sum[k] += std::sqrt(y[2 * k] * y[2 * k] + y[2 * k + 1] * y[2 * k + 1]) / m_n;
  }
  const double t = static_cast<double>(m_seg.step) * m_h;
  m_seg.stats.add(m_state, y, t, m_n);
  // psi_n - psi_1 once per time unit (Fig. histPsinMinusPsi1).
  const std::int64_t per_unit = std::max<std::int64_t>(1, std::llround(1.0 / m_h));
  if (m_seg.step % per_unit == 0) m_seg.stats.add_phase_sample(y, m_width);
}

void Run::guard(double K, const Observables& o) {
  for (std::size_t b = 0; b < o.energy.size(); ++b) {
    const double err = std::abs(o.energy[b] - m_seg.energy0[b]) / std::abs(m_seg.energy0[b]);
    if (std::isfinite(err) && err <= m_params.energy_tolerance) continue;
    // Leap-frog is stable for h omega < 2; the fastest local libration frequency is
    // omega_max = sqrt(K max_n R_n) (small oscillations in the well K R_n cos(theta - psi_n)).
    const auto& y = m_force.local_fields();
    double max_r = 0.0;
    for (std::size_t k = 0; 2 * k + 1 < y.size(); ++k) {
      max_r = std::max(max_r, std::hypot(y[2 * k], y[2 * k + 1]) / m_n);
    }
    max_r = ParallelSession::max(max_r);
    const double omega = std::sqrt(K * max_r);
    char message[512];
    std::snprintf(message, sizeof message,
                  "K = %g, t = %g (replica %zu): %s; the step h = %g is likely too large for "
                  "this K: leap-frog needs h * omega_max < 2 with omega_max = sqrt(K max_n R_n) "
                  "= %.4g, i.e. h < %.4g",
                  K, static_cast<double>(m_seg.step) * m_h, b,
                  std::isfinite(err)
                      ? ("relative energy error " + std::to_string(err) +
                         " exceeds the tolerance " + std::to_string(m_params.energy_tolerance))
                            .c_str()
                      : "energy is NaN or infinite",
                  m_h, omega, omega > 0 ? 2.0 / omega : INFINITY);
    throw SimulationBlowUp(message);
  }
}

void Run::record(int k_index) {
  const double K = m_params.K[static_cast<std::size_t>(k_index)];
  const Observables o = observe(K);
  if (m_params.node_data && m_seg.step > transient_steps()) {
    m_seg.stats.add_rotor_sample(m_state, static_cast<double>(m_seg.step) * m_h);
  }
  for (std::size_t b = 0; b < o.energy.size(); ++b) {
    const double err = std::abs(o.energy[b] - m_seg.energy0[b]) / std::abs(m_seg.energy0[b]);
    m_seg.energy_err_max[b] = std::max(m_seg.energy_err_max[b], err);
    const double drift = std::abs(o.momentum[b] - m_seg.momentum0[b]) / m_seg.momentum_scale[b];
    m_seg.momentum_drift_max[b] = std::max(m_seg.momentum_drift_max[b], drift);
  }
  auto& ts = m_result.series;
  ts.t.push_back(m_origin.t + static_cast<double>(m_result.steps - m_origin.steps) * m_h);
  ts.K.push_back(K);
  ts.R.insert(ts.R.end(), o.R.begin(), o.R.end());
  ts.energy.insert(ts.energy.end(), o.energy.begin(), o.energy.end());
  ts.momentum.insert(ts.momentum.end(), o.momentum.begin(), o.momentum.end());
  guard(K, o);
}

std::vector<double> Run::gather(const std::vector<double>& local, int width) const {
  // Rows x width (default: replicas): one gather per column (checkpoints and results only).
  const auto w = static_cast<std::size_t>(width > 0 ? width : m_width);
  const auto rows = static_cast<std::size_t>(m_state.rows);
  const auto n = static_cast<std::size_t>(m_network.global_size());
  std::vector<double> global(n * w), column(rows);
  for (std::size_t b = 0; b < w; ++b) {
    for (std::size_t r = 0; r < rows; ++r) column[r] = local[r * w + b];
    const std::vector<double> all = m_network.gather(column);
    for (std::size_t i = 0; i < n; ++i) global[i * w + b] = all[i];
  }
  return global;
}

std::vector<double> Run::scatter(const std::vector<double>& global, int width) const {
  const auto w = static_cast<std::size_t>(width > 0 ? width : m_width);
  const auto first =
      static_cast<std::ptrdiff_t>(m_state.first_row) * static_cast<std::ptrdiff_t>(w);
  const auto count = static_cast<std::ptrdiff_t>(m_state.rows) * static_cast<std::ptrdiff_t>(w);
  if (global.size() < static_cast<std::size_t>(first + count)) {
    throw InputError(m_params.checkpoint_path, 0,
                     "checkpoint arrays are too short for this network");
  }
  return std::vector<double>(global.begin() + first, global.begin() + first + count);
}

void Run::maybe_checkpoint(int k_index, bool force_now) {
  if (m_params.checkpoint_path.empty()) return;
  const double since = std::chrono::duration<double>(Clock::now() - m_last_checkpoint).count();
  // Wall clocks differ between ranks: the root decides for everyone.
  const bool due =
      force_now ||
      ParallelSession::max(
          ParallelSession::rank() == 0 && since >= m_params.checkpoint_seconds ? 1.0 : 0.0) > 0.0;
  if (!due) return;
  Checkpoint c;
  c.fingerprint = fingerprint(m_params, m_network);
  c.k_index = k_index;
  c.segment_step = m_seg.step;
  c.steps_total = m_result.steps;
  c.evaluations = m_f.count() + m_result.force_evaluations;
  c.integration_seconds =
      m_seconds_before + std::chrono::duration<double>(Clock::now() - m_loop_start).count();
  c.replicas = m_width;
  c.theta = gather(m_state.theta);
  c.p = gather(m_state.p);
  c.batch_count = m_seg.R.count();
  c.batch_sums = m_seg.R.sums();
  c.energy0 = m_seg.energy0;
  c.momentum0 = m_seg.momentum0;
  c.momentum_scale = m_seg.momentum_scale;
  c.energy_err_max = m_seg.energy_err_max;
  c.momentum_drift_max = m_seg.momentum_drift_max;
  if (!m_seg.theta_T1.empty()) c.theta_T1 = gather(m_seg.theta_T1);
  if (!m_seg.R_node_sum.empty()) c.R_node_sum = gather(m_seg.R_node_sum);
  if (m_params.node_data) {
    c.node_rows = gather(m_seg.stats.row_state(), NodeStatistics::k_row_width);
    c.node_globals = m_seg.stats.global_state();
    // Counts are per rank and additive; the leading shared values are equal on every rank.
    const auto shared = static_cast<std::ptrdiff_t>(NodeStatistics::k_shared_globals);
    std::vector<double> additive(c.node_globals.begin() + shared, c.node_globals.end());
    ParallelSession::sum_in_place(additive);
    std::copy(additive.begin(), additive.end(), c.node_globals.begin() + shared);
  }
  c.points = m_result.points;
  c.series = m_result.series;
  if (ParallelSession::rank() == 0) write_checkpoint(m_params.checkpoint_path, c);
  ParallelSession::max(0.0);  // barrier: no rank moves on before the checkpoint is in place
  m_last_checkpoint = Clock::now();
}

void Run::finish_interrupted() {
  m_result.interrupted = true;
  m_result.integration_seconds =
      m_seconds_before + std::chrono::duration<double>(Clock::now() - m_loop_start).count();
  m_result.force_evaluations += m_f.count();
}

void Run::restore(const Checkpoint& c) {
  if (c.fingerprint != fingerprint(m_params, m_network)) {
    throw InputError(m_params.checkpoint_path, 0,
                     "checkpoint belongs to a run with other parameters or another network "
                     "(fingerprints differ); remove it or drop --resume");
  }
  if (c.replicas != m_width || c.k_index < 0 || c.k_index >= static_cast<int>(m_params.K.size())) {
    throw InputError(m_params.checkpoint_path, 0, "checkpoint does not fit this run");
  }
  m_state.theta = scatter(c.theta);
  m_state.p = scatter(c.p);
  m_f.update(m_state);
  m_k_start = c.k_index;
  use_step(c.k_index);
  m_seg = Segment{};
  m_seg.R = BatchMeans(segment_steps() - transient_steps(), m_params.batches, m_width);
  m_seg.step = c.segment_step;
  m_seg.R.restore(c.batch_count, c.batch_sums);
  m_seg.energy0 = c.energy0;
  m_seg.momentum0 = c.momentum0;
  m_seg.momentum_scale = c.momentum_scale;
  m_seg.energy_err_max = c.energy_err_max;
  m_seg.momentum_drift_max = c.momentum_drift_max;
  m_seg.theta_T1 = c.theta_T1.empty() ? std::vector<double>{} : scatter(c.theta_T1);
  if (!c.R_node_sum.empty()) m_seg.R_node_sum = scatter(c.R_node_sum);
  if (m_params.node_data) {
    m_seg.stats = NodeStatistics(m_state.first_row, m_state.rows, m_params.rotor_node,
                                 rotor_samples(), m_params.phase_bins, c.momentum0[0] / m_n);
    m_seg.stats.restore(scatter(c.node_rows, NodeStatistics::k_row_width), c.node_globals,
                        ParallelSession::rank() == 0);
  }
  m_result.points = c.points;
  m_result.series = c.series;
  m_result.steps = c.steps_total;
  m_result.force_evaluations = c.evaluations - m_f.count();
  m_seconds_before = c.integration_seconds;
  m_result.resumed = true;
}

void Run::finish_segment(int k_index) {
  PointResult point;
  point.K = m_params.K[static_cast<std::size_t>(k_index)];
  point.R_mean = m_seg.R.mean();
  point.R_sem = m_seg.R.standard_error();
  point.energy_rel_error_max = m_seg.energy_err_max;
  point.momentum_drift = m_seg.momentum_drift_max;
  if (m_params.node_data) {
    const double span = m_params.duration - m_params.transient;
    std::vector<double> omega(m_state.theta.size()), r_node(m_seg.R_node_sum.size());
    for (std::size_t k = 0; k < omega.size(); ++k) {
      omega[k] = (m_state.theta[k] - m_seg.theta_T1[k]) / span;
      r_node[k] = m_seg.R_node_sum[k] / static_cast<double>(m_seg.R.count());
    }
    point.omega_node = gather(omega);
    point.R_node = gather(r_node);
    NodeStatisticsResult stats = m_seg.stats.finish(m_network);
    point.r_node = std::move(stats.r);
    point.fluctuation = std::move(stats.fluctuation);
    point.synchronised = std::move(stats.synchronised);
    point.phase_histogram = std::move(stats.phase_histogram);
    point.rotor_theta_bar = std::move(stats.rotor_theta_bar);
    point.rotor_p_bar = std::move(stats.rotor_p_bar);
    point.psi_frequency = std::move(stats.psi_frequency);
    point.frame = {stats.omega, stats.phi, stats.omega_momentum};
  }
  m_result.points.push_back(std::move(point));
}

void Run::progress(int k_index, bool final_line) const {
  if (!m_params.progress || ParallelSession::rank() != 0) return;
  const double seconds = std::chrono::duration<double>(Clock::now() - m_loop_start).count();
  const double done = static_cast<double>(m_result.steps);
  double total = 0.0;
  for (std::size_t k = 0; k < m_params.K.size(); ++k)
    total += static_cast<double>(steps_for(m_params.duration, step_at(m_params, k).h));
  const double rate = seconds > 0 ? done / seconds : 0.0;
  std::fprintf(stderr, "\rK = %-10g t = %-9.1f %8.0f steps/s  %6.1f s left   %s",
               m_params.K[static_cast<std::size_t>(k_index)], static_cast<double>(m_seg.step) * m_h,
               rate, rate > 0 ? (total - done) / rate : 0.0, final_line ? "\n" : "");
}

SimulationResult Run::execute() {
  m_state = initial_state(m_network.first_row(), m_network.local_size(), m_params.replicas);
  m_f.update(m_state);
  const bool resuming = m_params.resume && !m_params.checkpoint_path.empty() &&
                        std::filesystem::exists(m_params.checkpoint_path);
  if (resuming) {
    restore(read_checkpoint(m_params.checkpoint_path));
  } else {
    start_segment(0);
  }
  m_loop_start = Clock::now();
  m_last_checkpoint = m_loop_start;
  std::int64_t session_steps = 0;
  for (int k = m_k_start; k < static_cast<int>(m_params.K.size()); ++k) {
    if (k != m_k_start) {
      start_segment(k);
      maybe_checkpoint(k, true);  // at every K: a resume restarts here at worst
    }
    const std::vector<double> K = K_per_replica(m_params.K[static_cast<std::size_t>(k)]);
    const std::int64_t steps = segment_steps(), transient = transient_steps();
    while (m_seg.step < steps) {
      if (m_params.stop_after_steps > 0 && ++session_steps > m_params.stop_after_steps) {
        m_result.interrupted = true;
        return m_result;
      }
      m_integrator->step(m_state, m_h, K, m_f);
      ++m_seg.step;
      ++m_result.steps;
      if (m_seg.step > transient) sample();
      if (m_seg.step == transient && m_params.node_data) m_seg.theta_T1 = m_state.theta;
      if (m_seg.step % m_params.record_stride == 0 || m_seg.step == steps) {
        record(k);
        progress(k, false);
        // SIGINT/SIGTERM (interrupt.hpp): every rank stops at the same record, after a final
        // checkpoint, so --resume continues from here.
        if (ParallelSession::max(static_cast<double>(interrupt_signal())) > 0.0) {
          maybe_checkpoint(k, true);
          finish_interrupted();
          return m_result;
        }
        if (m_seg.step < steps) maybe_checkpoint(k, false);
      }
    }
    finish_segment(k);
  }
  progress(static_cast<int>(m_params.K.size()) - 1, true);
  m_result.integration_seconds =
      m_seconds_before + std::chrono::duration<double>(Clock::now() - m_loop_start).count();
  m_result.force_evaluations += m_f.count();
  m_result.nnz_per_evaluation = static_cast<EdgeOffset>(
      ParallelSession::sum(static_cast<double>(m_force.work_per_evaluation())));
  m_result.force_name = m_force.name();
  return m_result;
}

}  // namespace

StepChoice step_at(const SimulationParameters& p, std::size_t k) {
  return p.steps.empty() ? StepChoice{p.integrator, p.h} : p.steps.at(k);
}

void validate(const SimulationParameters& p) {
  const auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (!positive(p.h)) throw ParameterError("h", std::to_string(p.h), "h > 0");
  if (!(p.transient >= 0.0) || !std::isfinite(p.transient)) {
    throw ParameterError("transient", std::to_string(p.transient), "transient >= 0");
  }
  if (!positive(p.duration) || !(p.duration > p.transient)) {
    throw ParameterError("T", std::to_string(p.duration), "T > transient >= 0");
  }
  if (p.K.empty()) throw ParameterError("K", "empty schedule", "at least one K >= 0");
  if (!p.steps.empty() && p.steps.size() != p.K.size()) {
    throw ParameterError("steps", std::to_string(p.steps.size()) + " entries",
                         "none, or one per K (" + std::to_string(p.K.size()) + ")");
  }
  for (std::size_t k = 0; k < p.steps.size(); ++k) {
    if (!positive(p.steps[k].h)) {
      throw ParameterError("steps[" + std::to_string(k) + "].h", std::to_string(p.steps[k].h),
                           "h > 0");
    }
    make_integrator(p.steps[k].integrator);  // unknown names fail here, before any work
  }
  for (std::size_t k = 0; k < std::max<std::size_t>(p.steps.size(), 1); ++k) {
    const double h = step_at(p, k).h;
    const std::int64_t samples = steps_for(p.duration, h) - steps_for(p.transient, h);
    if (samples < p.batches) {
      throw ParameterError("T - transient", std::to_string(p.duration - p.transient),
                           "at least " + std::to_string(p.batches) +
                               " steps of h = " + std::to_string(h) + " to average over");
    }
  }
  for (const double K : p.K) {
    if (!(K >= 0.0) || !std::isfinite(K)) throw ParameterError("K", std::to_string(K), "K >= 0");
  }
  if (p.replicas.empty() || p.replicas.size() > 64) {
    throw ParameterError("replicas", std::to_string(p.replicas.size()), "1 to 64");
  }
  for (const auto& r : p.replicas) {
    if (!positive(r.sigma0)) throw ParameterError("sigma0", std::to_string(r.sigma0), "sigma0 > 0");
  }
  if (p.record_stride < 1)
    throw ParameterError("record stride", std::to_string(p.record_stride), ">= 1");
  if (p.phase_bins < 1) throw ParameterError("phase bins", std::to_string(p.phase_bins), ">= 1");
  if (p.rotor_node < 0) throw ParameterError("rotor node", std::to_string(p.rotor_node), ">= 0");
  if (p.batches < 2) throw ParameterError("batches", std::to_string(p.batches), ">= 2");
  if (!positive(p.energy_tolerance)) {
    throw ParameterError("energy tolerance", std::to_string(p.energy_tolerance), "> 0");
  }
}

std::string fingerprint(const SimulationParameters& p, const DistributedNetwork& network) {
  nlohmann::json j;
  j["h"] = p.h;
  j["T"] = p.duration;
  j["transient"] = p.transient;
  j["K"] = p.K;
  j["continue_state"] = p.continue_state;
  for (const auto& r : p.replicas) {
    j["replicas"].push_back({{"omega", r.omega}, {"sigma0", r.sigma0}, {"seed", r.seed}});
  }
  j["record_stride"] = p.record_stride;
  j["batches"] = p.batches;
  j["node_data"] = p.node_data;
  j["rotor_node"] = p.rotor_node;
  j["phase_bins"] = p.phase_bins;
  j["integrator"] = p.integrator;
  // Only when set, so the fingerprints (and checkpoints) of single-step runs are unchanged.
  for (const auto& s : p.steps) j["steps"].push_back({{"integrator", s.integrator}, {"h", s.h}});
  j["n"] = network.global_size();
  j["nnz"] = network.global_nnz();
  return j.dump();
}

SimulationResult simulate(const DistributedNetwork& network, const std::vector<double>& degrees,
                          CouplingForce& force, const SimulationParameters& params) {
  validate(params);
  if (params.rotor_node >= network.global_size()) {
    throw ParameterError("rotor node", std::to_string(params.rotor_node),
                         "0 <= node < N = " + std::to_string(network.global_size()));
  }
  Run run(network, degrees, force, params);
  return run.execute();
}

}  // namespace hmfnet
