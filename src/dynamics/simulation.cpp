#include "dynamics/simulation.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>

#include "core/error.hpp"
#include "dynamics/blow_up_guard.hpp"
#include "dynamics/checkpoint.hpp"
#include "dynamics/checkpoint_timer.hpp"
#include "dynamics/interrupt.hpp"
#include "dynamics/node_statistics.hpp"
#include "dynamics/progress_line.hpp"
#include "dynamics/replica_lanes.hpp"
#include "dynamics/segment_state.hpp"
#include "dynamics/series_recorder.hpp"
#include "dynamics/step_trial.hpp"
#include "dynamics/stepper_choice.hpp"
#include "dynamics/thread_choice.hpp"
#include "dynamics/time_average.hpp"
#include "parallel/network_content_hash.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

using Clock = std::chrono::steady_clock;

std::int64_t steps_for(double time, double h) { return std::llround(time / h); }

// The default count's trial (step_trial.hpp; simulate: thread_trial). A sample is
// k_trial_sample_work units of the rule's work (1-6 ms at 0.25-1.5 ns a unit); a step of more
// keeps the rule's count, 2 threads or more there under either wait policy (every measured
// network of 4 10^6 units and more ran 1.6-2.0x faster on 2 threads than on 1 on both machines:
// docs/performance.md), and on a network large enough that a switch of the team, which makes the
// sparse force cut its segments again (NetworkForce::prepare_segments), would cost a copy of its
// column indices. The trial's steps are at most 1 / k_trial_share of the run's steps left.
constexpr std::int64_t k_trial_sample_work = 4'000'000;
constexpr int k_trial_samples = 3;
constexpr double k_trial_share = 40.0;

/// Whether a whole `trial` takes at most 1 / k_trial_share of `steps_left`.
bool trial_fits(const StepTrial& trial, double steps_left) {
  return static_cast<double>(trial.steps()) * k_trial_share <= steps_left;
}

/// Steps of the whole schedule, every segment.
double total_steps(const SimulationParameters& p) {
  double total = 0.0;
  for (std::size_t k = 0; k < p.K.size(); ++k)
    total += static_cast<double>(steps_for(p.duration, step_at(p, k).h));
  return total;
}

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

// One run of the schedule on this rank's rows. The rules that keep it correct:
//  - m_stepper and m_seg travel together: the stepper holds the state and the force at it (the
//    state changes only by its advance and set_state), and m_seg holds the accumulators of the
//    current K, m_seg.step steps into it. The stepper runs chunks of steps alone (chunk_end: up
//    to the next record, the transient's end, the session's limit); the loop then takes each
//    step's samples in order, so the chunks change no result. What a resume needs is exactly
//    RunPosition + SegmentState (segment_state.hpp) + the results so far: a new accumulator goes
//    into SegmentState and its field list, never into a member of Run.
//  - m_integrator, m_h and m_origin belong to the current K (step_at); only use_step sets them.
//  - m_result.steps and m_result.force_evaluations + m_stepper->evaluations() count every session
//  of the run
//    (a resume starts from the checkpoint's counts); every exit from the stepping loop goes
//    through finish(), which sets the counts and the integration time.
//  - Collective (every rank calls them at the same step, in the same order): order_parameter,
//    observe, sample, record (and its observers), start_segment, finish_segment, restore,
//    and m_exchange's gather and scatter. A decision that ends or branches the loop is agreed over
//    ranks first (the root's clock decides a timed checkpoint, the maximum over ranks a signal or a
//    blow-up), so no rank waits in a collective that another has skipped.
class Run {
 public:
  /// `lane_K`: each replica's K for a run across replicas (replica_lanes.hpp), or empty: every
  /// replica at the schedule's K. `identity`: the parameters the checkpoint's fingerprint names.
  Run(const DistributedNetwork& network, const std::vector<double>& degrees, CouplingForce& force,
      std::unique_ptr<EnsembleStepper> stepper, const SimulationParameters& params,
      std::vector<double> lane_K, const SimulationParameters& identity, StepTrial trial)
      : m_network(network),
        m_force(force),
        m_stepper(std::move(stepper)),
        m_params(params),
        m_identity(identity),
        m_lane_K(std::move(lane_K)),
        m_integrator(make_integrator(step_at(params, 0).integrator)),
        m_h(step_at(params, 0).h),
        m_width(static_cast<int>(params.replicas.size())),
        m_total_degree(std::accumulate(degrees.begin(), degrees.end(), 0.0)),
        m_n(static_cast<double>(network.global_size())),
        m_exchange(row_exchange(network, params.checkpoint_path)),
        m_series(m_result.series),
        m_guard(params.energy_tolerance, identity.replicas.size()),
        m_progress(params.progress && ParallelSession::rank() == 0, total_steps(params)),
        m_checkpoints(
            params.checkpoint_path.empty() ? std::function<void()>{}
                                           : [this] { write_checkpoint_now(); },
            params.checkpoint_seconds),
        m_trial(std::move(trial)) {}

  SimulationResult execute();

 private:
  /// K of every replica in segment k.
  std::vector<double> segment_K(int k) const {
    if (!m_lane_K.empty()) return m_lane_K;
    return std::vector<double>(static_cast<std::size_t>(m_width),
                               m_params.K[static_cast<std::size_t>(k)]);
  }
  std::vector<double> order_parameter(std::vector<double> order_sums) const;
  Observables observe(const std::vector<double>& K) const;
  std::vector<double> energy_errors(const Observables& o) const;
  void use_step(int k_index);
  std::int64_t segment_steps() const { return steps_for(m_params.duration, m_h); }
  std::int64_t transient_steps() const { return steps_for(m_params.transient, m_h); }
  SegmentState fresh_segment(double omega) const;
  void start_segment(int k_index);
  void finish_segment(int k_index);
  bool record(int k_index);
  void sample(const std::vector<double>& order_sums);
  std::int64_t chunk_end(std::int64_t session_steps_left) const;
  void write_checkpoint_now();
  void finish(bool interrupted);
  void restore(const Checkpoint& c);
  std::int64_t rotor_samples() const;
  /// `done`: steps of the chunk just run, not yet counted in m_result.steps.
  void consider_segment_trial(std::int64_t done);
  /// The steps the next chunk may take for the trials: the active one's chunk_limit(); one step
  /// where the segments' trial is still to be considered (the force is prepared by that step, and
  /// the trial has the rest of the run); no limit otherwise.
  std::int64_t trial_chunk_limit() const {
    if (m_trial.active()) return m_trial.chunk_limit();
    if (!m_segments_considered) return 1;
    return m_segment_trial.chunk_limit();
  }
  /// Every chunk of a trial: runs it at the candidate being tried, tells the trial its time.
  void advance_in_trials(std::int64_t n, const std::vector<double>& K, std::int64_t kind,
                         std::vector<double>* order);
  double max_node_order() const;
  /// Collective the first time (the network's content hash): called by every rank alike.
  std::string run_fingerprint() {
    if (m_fingerprint.empty()) {
      const RunIdentity identity{m_network.global_size(), m_network.global_nnz(),
                                 network_content_hash(m_network), m_force.name()};
      m_fingerprint = fingerprint(m_identity, identity);
    }
    return m_fingerprint;
  }

  const DistributedNetwork& m_network;
  CouplingForce& m_force;
  std::unique_ptr<EnsembleStepper> m_stepper;  // the state (theta, p) and the force at it
  const SimulationParameters& m_params;
  const SimulationParameters& m_identity;
  std::string m_fingerprint;  // run_fingerprint(), formed once
  std::vector<double> m_lane_K;
  std::unique_ptr<Integrator> m_integrator;  // of the current segment (step_at)
  double m_h;                                // of the current segment
  TimeOrigin m_origin;                       // of the current segment (time_origin)
  int m_width;
  double m_total_degree;
  double m_n;
  RowExchange m_exchange;  // this rank's rows <-> whole-network arrays
  SegmentState m_seg;
  SimulationResult m_result;
  // The observers of the records (run_record.hpp), in the order they see each one; the checkpoint
  // timer comes after the interrupt check (record).
  SeriesRecorder m_series;
  BlowUpGuard m_guard;
  ProgressLine m_progress;
  CheckpointTimer m_checkpoints;
  int m_k = 0;  // the K being integrated (what a checkpoint records)
  int m_k_start = 0;
  double m_seconds_before = 0.0;  // integration seconds of earlier sessions (resume)
  Clock::time_point m_loop_start{};
  StepTrial m_trial;  ///< the first steps' thread counts (step_trial.hpp), or none
  /// After the thread count's: the force's column segments (segment_candidates), or none.
  StepTrial m_segment_trial;
  std::vector<int> m_segment_counts;  ///< this rank's segments of each candidate index
  bool m_segments_considered = false;
};

std::vector<double> Run::order_parameter(std::vector<double> order_sums) const {
  // eq:globalOrderParam: R = sum_n R_n / ||d|| = sum_n |y_n| / sum_n d_n.
  std::vector<double> R = std::move(order_sums);
  ParallelSession::sum_in_place(R);
  for (double& x : R) x /= m_total_degree;
  return R;
}

Observables Run::observe(const std::vector<double>& K) const {
  StepperSums s = m_stepper->sums();
  // One reduction for all four sums.
  std::vector<double> all;
  for (const auto* v : {&s.kinetic, &s.momentum, &s.momentum_scale, &s.coupling})
    all.insert(all.end(), v->begin(), v->end());
  ParallelSession::sum_in_place(all);
  const auto w = static_cast<std::size_t>(m_width);
  Observables o;
  o.R = order_parameter(std::move(s.order));
  for (std::size_t b = 0; b < w; ++b) {
    // eq:hamiltonianNetworkCase: H = sum p^2/2 - (K/2N) sum_nm A_nm cos(theta_m - theta_n).
    o.energy.push_back(all[b] - K[b] / (2.0 * m_n) * all[3 * w + b]);
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

SegmentState Run::fresh_segment(double omega) const {
  SegmentState s;
  s.R = BatchMeans(segment_steps() - transient_steps(), m_params.batches, m_width);
  if (m_params.node_data) {
    s.stats = NodeStatistics(m_network.first_row(), m_network.local_size(), m_params.rotor_node,
                             rotor_samples(), m_params.phase_bins, omega);
  }
  return s;
}

void Run::start_segment(int k_index) {
  use_step(k_index);
  if (!m_params.continue_state && k_index > 0) {
    m_stepper->set_state(
        initial_state(m_network.first_row(), m_network.local_size(), m_params.replicas));
  }
  const Observables o = observe(segment_K(k_index));
  m_seg = fresh_segment(o.momentum[0] / m_n);
  m_seg.energy0 = o.energy;
  m_seg.momentum0 = o.momentum;
  m_seg.momentum_scale = o.momentum_scale;
  m_seg.energy_err_max.assign(static_cast<std::size_t>(m_width), 0.0);
  m_seg.momentum_drift_max.assign(static_cast<std::size_t>(m_width), 0.0);
  if (m_params.node_data) {
    m_seg.R_node_sum.assign(m_stepper->state().p.size(), 0.0);
    if (transient_steps() == 0) m_seg.theta_T1 = m_stepper->state().theta;
  }
}

std::int64_t Run::rotor_samples() const {
  // Records fall on multiples of the stride and on the last step.
  const std::int64_t steps = segment_steps();
  const std::int64_t transient = transient_steps();
  const std::int64_t stride = m_params.record_stride;
  return steps / stride - transient / stride + (steps % stride != 0 ? 1 : 0);
}

// One step's samples: R (eq:timeAverage) from the step's order sums, and the node data.
void Run::sample(const std::vector<double>& order_sums) {
  m_seg.R.add(order_parameter(order_sums));
  if (!m_params.node_data) return;
  const auto& y = m_stepper->local_fields();
  for (std::size_t k = 0; k < m_seg.R_node_sum.size(); ++k) {
    m_seg.R_node_sum[k] += std::sqrt(y[2 * k] * y[2 * k] + y[2 * k + 1] * y[2 * k + 1]) / m_n;
  }
  const double t = static_cast<double>(m_seg.step) * m_h;
  m_seg.stats.add(m_stepper->state(), y, t, m_n);
  // psi_n - psi_1 once per time unit (Fig. histPsinMinusPsi1).
  const std::int64_t per_unit = std::max<std::int64_t>(1, std::llround(1.0 / m_h));
  if (m_seg.step % per_unit == 0) m_seg.stats.add_phase_sample(y, m_width);
}

std::vector<double> Run::energy_errors(const Observables& o) const {
  std::vector<double> errors(o.energy.size());
  for (std::size_t b = 0; b < errors.size(); ++b) {
    errors[b] = std::abs(o.energy[b] - m_seg.energy0[b]) / std::abs(m_seg.energy0[b]);
  }
  return errors;
}

double Run::max_node_order() const {
  const auto& y = m_stepper->local_fields();
  double max_r = 0.0;
  for (std::size_t k = 0; 2 * k + 1 < y.size(); ++k) {
    max_r = std::max(max_r, std::hypot(y[2 * k], y[2 * k + 1]) / m_n);
  }
  return ParallelSession::max(max_r);
}

// Forms the record, updates the segment's drift maxima and hands the record to the observers.
// Returns true when a signal stops the run here (after a final checkpoint).
bool Run::record(int k_index) {
  const std::vector<double> K = segment_K(k_index);
  const Observables o = observe(K);
  if (m_params.node_data && m_seg.step > transient_steps()) {
    m_seg.stats.add_rotor_sample(m_stepper->state(), static_cast<double>(m_seg.step) * m_h);
  }
  const std::vector<double> errors = energy_errors(o);
  for (std::size_t b = 0; b < errors.size(); ++b) {
    m_seg.energy_err_max[b] = std::max(m_seg.energy_err_max[b], errors[b]);
    const double drift = std::abs(o.momentum[b] - m_seg.momentum0[b]) / m_seg.momentum_scale[b];
    m_seg.momentum_drift_max[b] = std::max(m_seg.momentum_drift_max[b], drift);
  }
  RunRecord r;
  r.k_index = k_index;
  r.K = &K;
  r.segment_step = m_seg.step;
  r.segment_steps = segment_steps();
  r.steps_total = m_result.steps;
  r.h = m_h;
  r.t = m_origin.t + static_cast<double>(m_result.steps - m_origin.steps) * m_h;
  r.observed = &o;
  r.energy_errors = &errors;
  r.integrator = m_integrator->name();
  r.stability_limit = m_integrator->stability_limit();
  r.max_node_order = [this] { return max_node_order(); };
  for (RunObserver* observer :
       std::initializer_list<RunObserver*>{&m_series, &m_guard, &m_progress})
    observer->on_record(r);
  // SIGINT/SIGTERM (interrupt.hpp): every rank stops at the same record, after a final
  // checkpoint, so --resume continues from here.
  if (ParallelSession::max(static_cast<double>(interrupt_signal())) > 0.0) {
    m_checkpoints.write_now();
    return true;
  }
  m_checkpoints.on_record(r);
  return false;
}

void Run::write_checkpoint_now() {
  RunPosition position;
  position.k_index = m_k;
  position.steps_total = m_result.steps;
  position.evaluations = m_stepper->evaluations() + m_result.force_evaluations;
  position.integration_seconds =
      m_seconds_before + std::chrono::duration<double>(Clock::now() - m_loop_start).count();
  position.theta = m_stepper->state().theta;
  position.p = m_stepper->state().p;
  Checkpoint c;
  c.fingerprint = run_fingerprint();
  c.replicas = m_width;
  c.record = capture(position, m_seg, m_width, m_exchange);
  c.points = m_result.points;
  c.series = m_result.series;
  if (ParallelSession::rank() == 0) write_checkpoint(m_params.checkpoint_path, c);
  ParallelSession::max(0.0);  // barrier: no rank moves on before the checkpoint is in place
}

void Run::finish(bool interrupted) {
  m_result.interrupted = interrupted;
  m_result.integration_seconds =
      m_seconds_before + std::chrono::duration<double>(Clock::now() - m_loop_start).count();
  m_result.force_evaluations += m_stepper->evaluations();
  m_result.nnz_per_evaluation = static_cast<EdgeOffset>(
      ParallelSession::sum(static_cast<double>(m_force.work_per_evaluation())));
  m_result.force_name = m_force.name();
  m_result.device = m_stepper->device();
  m_result.thread_trial = m_trial.summary();
  m_result.segment_trial = m_segment_trial.summary();
  // The run ended during a trial: the rule's choice again for what the caller does next.
  if (m_trial.active()) omp_set_num_threads(m_trial.chosen());
  if (m_segment_trial.active())
    m_force.use_segments(m_segment_counts[static_cast<std::size_t>(m_segment_trial.chosen())]);
}

void Run::restore(const Checkpoint& c) {
  const std::string difference = fingerprint_difference(c.fingerprint, run_fingerprint());
  if (!difference.empty()) {
    throw InputError(
        m_params.checkpoint_path, 0,
        "checkpoint belongs to another run (" + difference + "); remove it or drop --resume");
  }
  const std::int64_t k_index = c.record.count("k_index");
  if (c.replicas != m_width || k_index < 0 ||
      k_index >= static_cast<std::int64_t>(m_params.K.size())) {
    throw InputError(m_params.checkpoint_path, 0, "checkpoint does not fit this run");
  }
  m_k_start = static_cast<int>(k_index);
  use_step(m_k_start);
  m_seg = fresh_segment(0.0);  // shapes only: the frame frequency is restored with the rest
  RunPosition position;
  hmfnet::restore(c.record, position, m_seg, m_width, m_exchange);
  RotorState state = m_stepper->state();
  state.theta = std::move(position.theta);
  state.p = std::move(position.p);
  m_stepper->set_state(state);
  m_result.points = c.points;
  m_result.series = c.series;
  m_result.steps = position.steps_total;
  m_result.force_evaluations = position.evaluations - m_stepper->evaluations();
  m_seconds_before = position.integration_seconds;
  m_result.resumed = true;
}

void Run::finish_segment(int k_index) {
  PointResult point;
  point.K = m_params.K[static_cast<std::size_t>(k_index)];
  point.integrator = m_integrator->name();
  point.h = m_h;
  point.R_mean = m_seg.R.mean();
  point.R_sem = m_seg.R.standard_error();
  point.energy_rel_error_max = m_seg.energy_err_max;
  point.momentum_drift = m_seg.momentum_drift_max;
  if (m_params.node_data) {
    const double span = m_params.duration - m_params.transient;
    const std::vector<double>& theta = m_stepper->state().theta;
    std::vector<double> omega(theta.size()), r_node(m_seg.R_node_sum.size());
    for (std::size_t k = 0; k < omega.size(); ++k) {
      omega[k] = (theta[k] - m_seg.theta_T1[k]) / span;
      r_node[k] = m_seg.R_node_sum[k] / static_cast<double>(m_seg.R.count());
    }
    const auto w = static_cast<std::size_t>(m_width);
    point.omega_node = m_exchange.gather(omega, w);
    point.R_node = m_exchange.gather(r_node, w);
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

// The last step of the next chunk the stepper runs alone: the next record (a multiple of the
// stride, or the segment's end), the end of the transient (the samples start after it, and node
// data take theta_T1 there), one step while node data are sampled (they read every step's y_n),
// the steps this session may still take (`left`, -1: no limit), and k_chunk_values order sums
// (a record stride of 10^8 steps must not hold 10^8 x replicas of them: the memory stays that
// of a per-step loop). Where a chunk ends changes no result.
std::int64_t Run::chunk_end(std::int64_t left) const {
  constexpr std::int64_t k_chunk_values = std::int64_t{1} << 20;  // 8 MB of order sums
  const std::int64_t step = m_seg.step;
  const std::int64_t stride = m_params.record_stride;
  std::int64_t end = std::min(segment_steps(), (step / stride + 1) * stride);
  end = std::min(end, step + std::max<std::int64_t>(1, k_chunk_values / m_width));
  if (step < transient_steps()) {
    end = std::min(end, transient_steps());
  } else if (m_params.node_data) {
    end = step + 1;
  }
  if (left >= 0) end = std::min(end, step + left);
  return end;
}

SimulationResult Run::execute() {
  // Before the force's first evaluation, which may take the network's column indices
  // (NetworkForce::take_columns) that the content hash reads.
  if (!m_params.checkpoint_path.empty()) run_fingerprint();
  // The force's rule again: an earlier run's trial on this force chose for that run, and this one
  // makes its own or none.
  m_force.use_segments(1);
  m_stepper->set_state(
      initial_state(m_network.first_row(), m_network.local_size(), m_params.replicas));
  const bool resuming = m_params.resume && !m_params.checkpoint_path.empty() &&
                        std::filesystem::exists(m_params.checkpoint_path);
  if (resuming) {
    restore(read_checkpoint(m_params.checkpoint_path));
    // Eligible by the whole run's steps (simulate), but only the rest of them run now.
    if (!trial_fits(m_trial, total_steps(m_params) - static_cast<double>(m_result.steps)))
      m_trial = StepTrial();
  } else {
    start_segment(0);
  }
  m_loop_start = Clock::now();
  m_checkpoints.restart();
  m_progress.start(m_result.steps, segment_K(m_k_start).front());
  std::int64_t session_steps = 0;
  const auto w = static_cast<std::ptrdiff_t>(m_width);
  std::vector<double> order;  // a chunk's order sums, steps x replicas
  std::vector<double> one_step(static_cast<std::size_t>(m_width));
  for (int k = m_k_start; k < static_cast<int>(m_params.K.size()); ++k) {
    m_k = k;
    if (k != m_k_start) {
      start_segment(k);
      m_checkpoints.write_now();  // at every K: a resume restarts here at worst
    }
    const std::vector<double> K = segment_K(k);
    const std::int64_t steps = segment_steps(), transient = transient_steps();
    while (m_seg.step < steps) {
      std::int64_t left = -1;
      if (m_params.stop_after_steps > 0) {
        left = m_params.stop_after_steps - session_steps;
        if (left == 0) {
          finish(true);
          return m_result;
        }
      }
      const std::int64_t n = std::min(chunk_end(left) - m_seg.step, trial_chunk_limit());
      const bool sampled = m_seg.step >= transient;  // every step of the chunk, or none
      order.clear();
      // Steps of one kind cost the same: one segment's integrator and step, sampled or not.
      advance_in_trials(n, K, 2 * static_cast<std::int64_t>(k) + (sampled ? 1 : 0),
                        sampled ? &order : nullptr);
      session_steps += n;
      m_result.steps += n;
      for (std::int64_t i = 0; i < n; ++i) {
        ++m_seg.step;
        if (sampled) {
          std::copy(order.begin() + i * w, order.begin() + (i + 1) * w, one_step.begin());
          sample(one_step);
        }
      }
      if (m_seg.step == transient && m_params.node_data) m_seg.theta_T1 = m_stepper->state().theta;
      if ((m_seg.step % m_params.record_stride == 0 || m_seg.step == steps) && record(k)) {
        finish(true);
        return m_result;
      }
    }
    finish_segment(k);
  }
  m_progress.finish();
  finish(false);
  return m_result;
}

void Run::advance_in_trials(std::int64_t n, const std::vector<double>& K, std::int64_t kind,
                            std::vector<double>* order) {
  // At most one trial at a time: the segments' starts once the thread count's has ended.
  StepTrial* trial = m_trial.active()           ? &m_trial
                     : m_segment_trial.active() ? &m_segment_trial
                                                : nullptr;
  const auto use = [&](int candidate) {
    if (trial == &m_trial) {
      omp_set_num_threads(candidate);
    } else {
      m_force.use_segments(m_segment_counts[static_cast<std::size_t>(candidate)]);
    }
  };
  if (trial != nullptr) use(trial->candidate());
  const Clock::time_point chunk_start = Clock::now();
  m_stepper->advance(*m_integrator, m_h, K, n, order);
  if (trial != nullptr) {
    // Over several ranks, the slowest rank's time (the others wait for it at every step's halo
    // exchange): every rank's trial is told the same and takes the same decisions.
    const double seconds =
        ParallelSession::max(std::chrono::duration<double>(Clock::now() - chunk_start).count());
    trial->add(n, seconds, kind);
    if (!trial->active()) use(trial->chosen());
  }
  // Not after the thread trial's last chunk: the force is prepared at the chosen count only by
  // the next one.
  if (trial != &m_trial) consider_segment_trial(n);
}

// Once, after the first chunk run outside the thread trial (the force has been prepared at the
// team that goes on): a trial of the force's segment candidates where every rank's force has them
// (agreed over ranks, so every rank takes the same chunks; each rank runs its own counts) and the
// trial fits the steps left. Collective. A sample is k_trial_sample_work stored entries x lanes,
// at least one step: where there is a choice on the AMD EPYC guests a step gathers ~10^6 lines
// and more (a table beyond two 4 MiB slices of 64-byte records, 12 entries a row and more), so
// its samples are one or a few steps, up to a second each at ER N = 10^6, degree 100, and the
// untimed step before a candidate's samples holds the force's new cut of its columns (there a
// copy of 10^8 indices). The labels name the count the trial width would cut; where the cut is
// refused (rows not sorted by column: column_segments.hpp) both candidates run unblocked, the
// same bits, and the margin keeps the first.
void Run::consider_segment_trial(std::int64_t done) {
  if (m_segments_considered) return;
  m_segments_considered = true;
  m_segment_counts =
      m_stepper->device() == "cpu" ? m_force.segment_candidates() : std::vector<int>{};
  if (ParallelSession::max(m_segment_counts.size() == 2 ? 0.0 : 1.0) > 0.0) return;
  const double work = ParallelSession::max(static_cast<double>(m_force.work_per_evaluation()) *
                                           static_cast<double>(m_width));
  const auto sample_steps = static_cast<std::int64_t>(
      std::max(1.0, std::ceil(static_cast<double>(k_trial_sample_work) / work)));
  std::vector<std::string> labels;
  for (const int count : m_segment_counts)
    labels.push_back(count == 1 ? "unsegmented" : std::to_string(count) + " segments");
  // By candidate: the unblocked rows' samples, then the slices' (one cut of the columns, no
  // rebuild of them unless the unblocked rows win).
  StepTrial trial({0, 1}, sample_steps, k_trial_samples, std::move(labels),
                  SampleOrder::by_candidate);
  if (trial_fits(trial, total_steps(m_params) - static_cast<double>(m_result.steps + done)))
    m_segment_trial = std::move(trial);
}

/// What every rank's trial is made from, the same on all of them: whether every rank leaves the
/// count to the run, the heaviest rank's work a step (the step takes as long as that rank's part)
/// and the fewest threads a rank is offered.
struct TrialInputs {
  bool every_rank_asks;
  std::int64_t work;
  int available;
};

/// `asks`: this rank's run takes the default count on the CPU. Collective. A count can differ
/// between ranks (OMP_NUM_THREADS set for some only: simulate_request.cpp), and a trial on some
/// ranks only would call its reduction on those alone: then none makes one.
TrialInputs trial_inputs(bool asks, std::int64_t work, int available) {
  // One reduction: the mins are maxes of the negated values. Work a step and thread counts are
  // far below 2^53: exact in a double.
  std::vector<double> v{asks ? -1.0 : 0.0, static_cast<double>(work),
                        -static_cast<double>(available)};
  ParallelSession::max_in_place(v);
  return {v[0] < 0.0, static_cast<std::int64_t>(v[1]), static_cast<int>(-v[2])};
}

/// The trial of the default thread count (step_trial.hpp): the rule's count for the inputs, 1
/// and all the threads offered (not the counts in between), each timed over samples of
/// k_trial_sample_work units of the rule's work. Every rank makes the same trial from the same
/// inputs and is told the same times (Run::execute), so the ranks switch counts at the same steps.
/// None where a rank was given a count or runs on a GPU, where one thread is offered, where a step
/// is more than a sample's work, or where the trial's steps would exceed 1 / k_trial_share of the
/// run's (docs/performance.md "The thread rule measured at run time").
StepTrial thread_trial(const SimulationParameters& params, TrialInputs in) {
  const std::int64_t work = in.work;
  const int available = in.available;
  if (!in.every_rank_asks || available < 2) return {};
  if (work > k_trial_sample_work) return {};
  std::vector<int> candidates{default_threads(work, available)};
  for (const int c : {1, available}) {
    if (std::find(candidates.begin(), candidates.end(), c) == candidates.end())
      candidates.push_back(c);
  }
  const std::int64_t sample_steps =
      std::max<std::int64_t>(1, (k_trial_sample_work + work - 1) / std::max<std::int64_t>(work, 1));
  StepTrial trial(std::move(candidates), sample_steps, k_trial_samples);
  if (!trial_fits(trial, total_steps(params))) return {};
  return trial;
}

}  // namespace

SimulationResult simulate(const DistributedNetwork& network, const std::vector<double>& degrees,
                          CouplingForce& force, const SimulationParameters& params) {
  validate(params);
  if (params.rotor_node >= network.global_size()) {
    throw ParameterError("rotor node", std::to_string(params.rotor_node),
                         "0 <= node < N = " + std::to_string(network.global_size()));
  }
  const auto pass_lanes = static_cast<int>(lanes(params));
  const auto gathers = static_cast<std::int64_t>(std::llround(
      static_cast<double>(force.gathers_per_evaluation()) * force.lane_gather_cost(pass_lanes)));
  const std::int64_t work = step_work(gathers, static_cast<std::int64_t>(network.local_size()),
                                      static_cast<std::int64_t>(pass_lanes), force.row_work());
  const int available = omp_get_max_threads();
  const int by_rule = params.threads > 0 ? params.threads : default_threads(work, available);
  const TrialInputs shared =
      trial_inputs(params.threads == 0 && params.device == "cpu", work, available);
  const auto trial = [&](const SimulationParameters& run) { return thread_trial(run, shared); };
  const ThreadCountScope threads(by_rule);
  SimulationResult result;
  if (params.K_across_replicas) {
    const SimulationParameters one_pass = lane_parameters(params);
    Run run(network, degrees, force, make_stepper(network, force, one_pass), one_pass,
            lane_couplings(params), params, trial(one_pass));
    result = split_lanes(run.execute(), params);
  } else {
    Run run(network, degrees, force, make_stepper(network, force, params), params, {}, params,
            trial(params));
    result = run.execute();
  }
  result.threads = omp_get_max_threads();
  result.thread_rule_work = work;
  result.lanes = static_cast<int>(lanes(params));
  return result;
}

}  // namespace hmfnet
