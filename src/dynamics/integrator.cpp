#include "dynamics/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <utility>

#include "core/error.hpp"
#include "dynamics/kick_drift_lanes.hpp"
#include "dynamics/splitting_coefficients.hpp"
#include "dynamics/team.hpp"

namespace hmfnet {

namespace {

// One pass over all rows in blocks of ~1024 cells, shared out over the team: long enough for the
// vector loops of kick_drift_lanes.cpp, short enough to share out. theta drifts where `drift`.
void kick_drift_pass(RotorState& state, const std::vector<double>& K, const std::vector<double>& g,
                     const KickDriftCoefficients& c, bool drift) {
  const auto w = static_cast<std::size_t>(state.replicas);
  const auto rows = static_cast<std::size_t>(state.rows);
  if (w == 0 || rows == 0) return;  // every thread alike: no worksharing loop is skipped by some
  const KickDriftCells cells{state.p.data(), drift ? state.theta.data() : nullptr, g.data(),
                             K.data(), w};
  const std::size_t block = std::max<std::size_t>(1, 1024 / w);
  const std::size_t blocks = (rows + block - 1) / block;
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < blocks; ++i)
    kick_drift_rows(cells, c, i * block, std::min(rows, (i + 1) * block));
}

// `steps` steps of the splitting kicks[0] drifts[0] kicks[1] ... drifts[s-1] kicks[s] (times h):
// each step's closing kick joins the next step's opening kick and drift in one pass (the same
// operations on every cell in the same order: the same bits as step after step), the last
// step's closing kick at the end. after_step runs on the master after each step's last force
// evaluation, when f.sums() is that step's. The sums are formed only where they are read: at a
// step's last evaluation when after_step may read them, and at the last step's. Where the force
// fuses its passes, a sampled step's sums come with the next step's first pass, whose kick forms
// the force at those phases again anyway (ForceOutputs::start_sums_and_force), and its
// after_step runs after that pass: one pass over the cells a step instead of two (the rank-one
// force's field pass; docs/performance.md "A sampled step's sums in the next pass"). The last
// step's sums come from its closing evaluation, or, where that pass formed the step before's,
// from form_sums after that step's after_step.
void advance_splitting(RotorState& state, double h, const std::vector<double>& K,
                       ForceEvaluation& f, const std::vector<double>& kicks,
                       const std::vector<double>& drifts, std::int64_t steps,
                       const std::function<void()>& after_step) {
  bool pending = false;  // the last step's sums and after_step wait for this step's first pass
  for (std::int64_t n = 0; n < steps; ++n) {
    const bool last = n + 1 == steps;
    const bool read = after_step || last;
    const bool defer = after_step && !last && f.force().fuses_kick_drift(state);
    for (std::size_t i = 0; i < drifts.size(); ++i) {
      KickDriftCoefficients c{{kicks[i] * h, 0.0}, 1, drifts[i] * h};
      if (i == 0 && n > 0) c = {{kicks.back() * h, kicks[0] * h}, 2, drifts[0] * h};
      const bool closing_sums = read && !defer && i + 1 == drifts.size();
      const bool start_sums = pending && i == 0;
      ForceOutputs outputs = ForceOutputs::force_only;
      if (start_sums) {
        outputs = ForceOutputs::start_sums_and_force;
      } else if (closing_sums) {
        outputs = ForceOutputs::force_and_sums;
      }
      f.kick_drift_update(state, K, c, outputs);
      if (!start_sums) continue;
      master_only(after_step);
      pending = false;
      // The sums of this pass's phases too: after the record above read the start's.
      if (closing_sums) f.form_sums(state);
    }
    if (defer) {
      pending = true;
    } else if (after_step) {
      master_only(after_step);
    }
  }
  if (steps > 0) kick_drift_pass(state, K, f.g(), {{kicks.back() * h, 0.0}, 1, 0.0}, false);
}

// Leap-frog as a splitting: c = h / 2 and h, as the kicks and the drift have always been formed.
const std::vector<double>& leapfrog_kicks() {
  static const std::vector<double> kicks{0.5, 0.5};
  return kicks;
}
const std::vector<double>& leapfrog_drifts() {
  static const std::vector<double> drifts{1.0};
  return drifts;
}

}  // namespace

void ForceEvaluation::kick_drift_update(RotorState& state, const std::vector<double>& K,
                                        const KickDriftCoefficients& c, ForceOutputs outputs) {
  if (!m_force->fuses_kick_drift(state)) {
    // The start's sums before the kick moves the phases (an evaluation there again).
    if (outputs == ForceOutputs::start_sums_and_force) m_force->form_sums(state, m_g, m_sums);
    kick_drift_pass(state, K, m_g, c, true);
    update(state, outputs == ForceOutputs::force_and_sums ? outputs : ForceOutputs::force_only);
    return;
  }
  if (outside_team()) prepare(state);
  m_force->kick_drift_evaluate(state, K, c, m_g, m_sums, outputs);
#pragma omp master
  {
    ++m_count;
    m_sums_current = outputs == ForceOutputs::force_and_sums;
  }
}

void kick(RotorState& state, double c, const std::vector<double>& K, const std::vector<double>& g) {
  kick_drift_pass(state, K, g, {{c, 0.0}, 1, 0.0}, false);
}

void kick_drift(RotorState& state, double c_kick, const std::vector<double>& K,
                const std::vector<double>& g, double c_drift) {
  kick_drift_pass(state, K, g, {{c_kick, 0.0}, 1, c_drift}, true);
}

void Integrator::step(RotorState& state, double h, const std::vector<double>& K,
                      ForceEvaluation& f) const {
  f.prepare(state);
  prepare(state);
  in_team([&] { advance(state, h, K, f); });
}

void Integrator::steps(RotorState& state, double h, const std::vector<double>& K,
                       ForceEvaluation& f, std::int64_t n,
                       const std::function<void()>& after_step) const {
  if (n <= 0) return;
  f.prepare(state);
  prepare(state);
  in_team([&] { advance_steps(state, h, K, f, n, after_step); });
}

void Integrator::advance_steps(RotorState& state, double h, const std::vector<double>& K,
                               ForceEvaluation& f, std::int64_t n,
                               const std::function<void()>& after_step) const {
  for (std::int64_t i = 0; i < n; ++i) {
    advance(state, h, K, f);
    if (after_step) master_only(after_step);
  }
}

void LeapFrog::advance(RotorState& state, double h, const std::vector<double>& K,
                       ForceEvaluation& f) const {
  advance_splitting(state, h, K, f, leapfrog_kicks(), leapfrog_drifts(), 1, {});
}

void LeapFrog::advance_steps(RotorState& state, double h, const std::vector<double>& K,
                             ForceEvaluation& f, std::int64_t n,
                             const std::function<void()>& after_step) const {
  advance_splitting(state, h, K, f, leapfrog_kicks(), leapfrog_drifts(), n, after_step);
}

KickDriftSplitting::KickDriftSplitting(std::string name, int order, std::vector<double> kicks,
                                       std::vector<double> drifts)
    : m_name(std::move(name)),
      m_order(order),
      m_kicks(std::move(kicks)),
      m_drifts(std::move(drifts)),
      m_stability_limit(0.0) {
  // The coefficients are tabulated to ~15 digits and the middle ones are derived from the
  // others, so a consistent method sums to 1 within a few ulps; 1e-12 only rejects typos.
  constexpr double consistency = 1e-12;
  const double kick_sum = std::accumulate(m_kicks.begin(), m_kicks.end(), 0.0);
  const double drift_sum = std::accumulate(m_drifts.begin(), m_drifts.end(), 0.0);
  if (m_drifts.empty() || m_kicks.size() != m_drifts.size() + 1 ||
      std::abs(kick_sum - 1.0) > consistency || std::abs(drift_sum - 1.0) > consistency) {
    throw ParameterError("splitting " + m_name, "inconsistent coefficients",
                         "one more kick than drifts and each set summing to 1");
  }
  m_stability_limit = splitting_stability_limit(m_kicks, m_drifts);
}

namespace {

// Trace of the one-step map of q' = p, p' = -q at step x (omega = 1, h = x).
double splitting_trace(const std::vector<double>& kicks, const std::vector<double>& drifts,
                       double x) {
  double m00 = 1.0, m01 = 0.0, m10 = 0.0, m11 = 1.0;  // M = identity; M <- step * M
  const auto apply_kick = [&](double b) {
    m10 -= b * x * m00;
    m11 -= b * x * m01;
  };
  for (std::size_t i = 0; i < drifts.size(); ++i) {
    apply_kick(kicks[i]);
    m00 += drifts[i] * x * m10;
    m01 += drifts[i] * x * m11;
  }
  apply_kick(kicks.back());
  return m00 + m11;
}

}  // namespace

double splitting_stability_limit(const std::vector<double>& kicks,
                                 const std::vector<double>& drifts) {
  constexpr double grid = 1e-3, last = 8.0, resolution = 1e-12;
  const auto unstable = [&](double x) {
    return std::abs(splitting_trace(kicks, drifts, x)) >= 2.0;
  };
  // x accumulates the grid step rather than being k * grid: the grid only brackets the first
  // unstable point, which the bisection then refines to `resolution`, and the accumulated
  // rounding (a few 1e-12 over 8000 steps) is far below the grid; kept so results stay the same.
  // NOLINTNEXTLINE(clang-analyzer-security.FloatLoopCounter)
  for (double x = grid; x <= last; x += grid) {
    if (!unstable(x)) continue;
    double lo = x - grid, hi = x;
    while (hi - lo > resolution) {
      const double mid = 0.5 * (lo + hi);
      (unstable(mid) ? hi : lo) = mid;
    }
    return lo;
  }
  return last;
}

void KickDriftSplitting::advance(RotorState& state, double h, const std::vector<double>& K,
                                 ForceEvaluation& f) const {
  advance_splitting(state, h, K, f, m_kicks, m_drifts, 1, {});
}

void KickDriftSplitting::advance_steps(RotorState& state, double h, const std::vector<double>& K,
                                       ForceEvaluation& f, std::int64_t n,
                                       const std::function<void()>& after_step) const {
  advance_splitting(state, h, K, f, m_kicks, m_drifts, n, after_step);
}

KickDriftSplitting yoshida4() {
  SplittingCoefficients c = yoshida4_coefficients();
  return {"yoshida4", 4, std::move(c.kicks), std::move(c.drifts)};
}

KickDriftSplitting blanes_moan4() {
  SplittingCoefficients c = blanes_moan4_coefficients();
  return {"blanes_moan", 4, std::move(c.kicks), std::move(c.drifts)};
}

namespace {

// One Runge-Kutta stage for theta' = p, p' = K g: from the previous stage's momenta P (held in
// stage.p) and its force g, the next stage is Theta = theta0 + c P, P' = p0 + c K g; the
// momentum weight w of the final combination is accumulated into theta_rate.
void runge_kutta_stage(RotorState& stage, const RotorState& start, double c,
                       const std::vector<double>& K, const std::vector<double>& g, double w,
                       std::vector<double>& theta_rate) {
  const auto width = static_cast<std::size_t>(start.replicas);
  const auto rows = static_cast<std::size_t>(start.rows);
#pragma omp for schedule(static)
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t b = 0; b < width; ++b) {
      const std::size_t k = r * width + b;
      stage.theta[k] = start.theta[k] + c * stage.p[k];
      stage.p[k] = start.p[k] + c * K[b] * g[k];
      theta_rate[k] += w * stage.p[k];
    }
  }
}

void accumulate(std::vector<double>& sum, double w, const std::vector<double>& g) {
  const std::size_t cells = sum.size();
#pragma omp for schedule(static)
  for (std::size_t k = 0; k < cells; ++k) sum[k] += w * g[k];
}

}  // namespace

void RungeKutta4::prepare(const RotorState& state) const {
  m_stage.replicas = state.replicas;
  m_stage.rows = state.rows;
  m_stage.first_row = state.first_row;
  m_stage.theta.resize(state.theta.size());
  m_stage.p.resize(state.p.size());
  m_theta_rate.resize(state.p.size());
  m_force_sum.resize(state.p.size());
}

void RungeKutta4::advance(RotorState& state, double h, const std::vector<double>& K,
                          ForceEvaluation& f) const {
  advance_one(state, h, K, f, ForceOutputs::force_and_sums);
}

// As advance_splitting: the sums at a step's closing evaluation where after_step may read them,
// and at the last step's.
void RungeKutta4::advance_steps(RotorState& state, double h, const std::vector<double>& K,
                                ForceEvaluation& f, std::int64_t n,
                                const std::function<void()>& after_step) const {
  for (std::int64_t i = 0; i < n; ++i) {
    const bool read = after_step || i + 1 == n;
    advance_one(state, h, K, f, read ? ForceOutputs::force_and_sums : ForceOutputs::force_only);
    if (after_step) master_only(after_step);
  }
}

void RungeKutta4::advance_one(RotorState& state, double h, const std::vector<double>& K,
                              ForceEvaluation& f, ForceOutputs last) const {
  // Butcher tableau of classical RK4 (Hairer, Norsett & Wanner I, Table II.1.2):
  // y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4), stages at c = 0, 1/2, 1/2, 1.
  // The scratch holds the start of the step (sized by prepare, outside the team; the loop's
  // barrier publishes the copies).
  const std::size_t cells = state.p.size();
#pragma omp for schedule(static)
  for (std::size_t k = 0; k < cells; ++k) {
    m_stage.theta[k] = state.theta[k];
    m_stage.p[k] = state.p[k];
    m_theta_rate[k] = state.p[k];
    m_force_sum[k] = f.g()[k];
  }
  // The stages' sums are never read: g alone (coupling_force.hpp).
  runge_kutta_stage(m_stage, state, 0.5 * h, K, f.g(), 2.0, m_theta_rate);
  f.update(m_stage, ForceOutputs::force_only);
  accumulate(m_force_sum, 2.0, f.g());
  runge_kutta_stage(m_stage, state, 0.5 * h, K, f.g(), 2.0, m_theta_rate);
  f.update(m_stage, ForceOutputs::force_only);
  accumulate(m_force_sum, 2.0, f.g());
  runge_kutta_stage(m_stage, state, h, K, f.g(), 1.0, m_theta_rate);
  f.update(m_stage, ForceOutputs::force_only);
  accumulate(m_force_sum, 1.0, f.g());
  const auto width = static_cast<std::size_t>(state.replicas);
  const auto rows = static_cast<std::size_t>(state.rows);
#pragma omp for schedule(static)
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t b = 0; b < width; ++b) {
      const std::size_t k = r * width + b;
      state.theta[k] += h / 6.0 * m_theta_rate[k];
      state.p[k] += h / 6.0 * K[b] * m_force_sum[k];
    }
  }
  // The new phases are not one of the stages: a fourth evaluation leaves f at the new state.
  f.update(state, last);
}

std::string integrator_names() { return "leapfrog, yoshida4, blanes_moan, rk4"; }

std::unique_ptr<Integrator> make_integrator(const std::string& name) {
  if (name == "leapfrog") return std::make_unique<LeapFrog>();
  if (name == "yoshida4") return std::make_unique<KickDriftSplitting>(yoshida4());
  if (name == "blanes_moan") return std::make_unique<KickDriftSplitting>(blanes_moan4());
  if (name == "rk4") return std::make_unique<RungeKutta4>();
  throw ParameterError("integrator", name, integrator_names());
}

}  // namespace hmfnet
