#include "theory/anderson_acceleration.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace hmfnet {

namespace {

using Vector = Eigen::VectorXd;
using ConstMap = Eigen::Map<const Eigen::VectorXd>;

void check(const FixedPointMap& map, const std::vector<double>& x0, const AndersonOptions& o) {
  if (!map) throw ParameterError("anderson_fixed_point: map", "empty", "a callable map");
  if (x0.empty()) {
    throw ParameterError("anderson_fixed_point: initial guess", "empty", "at least one entry");
  }
  if (o.memory < 0 || !(o.damping > 0.0 && o.damping <= 1.0) || !(o.tolerance > 0.0) ||
      o.max_iterations < 1 || !(o.restart_growth > 1.0) || !(o.max_step > 0.0) ||
      o.stagnation_window < 1) {
    throw ParameterError(
        "anderson_fixed_point: options",
        "memory " + std::to_string(o.memory) + ", damping " + std::to_string(o.damping) +
            ", tolerance " + std::to_string(o.tolerance) + ", max_iterations " +
            std::to_string(o.max_iterations) + ", restart_growth " +
            std::to_string(o.restart_growth) + ", max_step " + std::to_string(o.max_step) +
            ", stagnation_window " + std::to_string(o.stagnation_window),
        "memory >= 0, 0 < damping <= 1, tolerance > 0, max_iterations >= 1, restart_growth > 1, "
        "max_step > 0, stagnation_window >= 1");
  }
}

// The last `memory` pairs (dX_j, dF_j) as matrix columns; which column is oldest does not matter to
// the least-squares problem, so a ring buffer suffices.
class History {
 public:
  History(Eigen::Index n, int memory) : m_dx(n, memory), m_df(n, memory), m_memory(memory) {}
  void clear() { m_count = m_next = 0; }
  int count() const { return m_count; }
  void push(const Vector& dx, const Vector& df) {
    if (m_memory == 0) return;
    m_dx.col(m_next) = dx;
    m_df.col(m_next) = df;
    m_next = (m_next + 1) % m_memory;
    m_count = std::min(m_count + 1, m_memory);
  }
  // x + beta f - (dX + beta dF) c with c = argmin ||f - dF c||_2.
  Vector step(const Vector& x, const Vector& f, double beta) const {
    if (m_count == 0) return x + beta * f;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m_df.rows(), m_count);
    qr.setThreshold(1e-12);
    qr.compute(m_df.leftCols(m_count));
    const Vector c = qr.solve(f);
    return x + beta * f - (m_dx.leftCols(m_count) + beta * m_df.leftCols(m_count)) * c;
  }

 private:
  Eigen::MatrixXd m_dx, m_df;
  int m_memory;
  int m_count = 0;
  int m_next = 0;
};

struct Iterate {
  std::vector<double> x, gx;
  double residual = std::numeric_limits<double>::infinity();
};

Iterate evaluate(const FixedPointMap& map, std::vector<double> x) {
  Iterate it;
  it.gx.resize(x.size());
  const double r = map(x, it.gx);
  it.residual = std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
  it.x = std::move(x);
  return it;
}

Vector residual_vector(const Iterate& it) {
  const auto n = static_cast<Eigen::Index>(it.x.size());
  return ConstMap(it.gx.data(), n) - ConstMap(it.x.data(), n);
}

}  // namespace

FixedPointResult anderson_fixed_point(const FixedPointMap& map, std::vector<double> x0,
                                      const AndersonOptions& options) {
  check(map, x0, options);
  const auto n = static_cast<Eigen::Index>(x0.size());
  History history(n, options.memory);
  FixedPointResult result;
  Iterate current = evaluate(map, std::move(x0));
  double best = current.residual;
  result.iterations = 1;
  int damped_steps_left = 0;  // after a rejected extrapolation: damped steps before the next one
  int last_halving = 1;       // iteration at which the best residual last fell by half
  double halving_mark = best;
  while (!(current.residual <= options.tolerance) && result.iterations < options.max_iterations) {
    if (!result.damped_fallback && result.iterations - last_halving >= options.stagnation_window) {
      // Extrapolation is not helping (e.g. a component decaying to r = 0 in log variables):
      // finish with the damped iteration, which converges wherever the fixed point attracts it.
      result.damped_fallback = true;
      history.clear();
    }
    const Vector x = ConstMap(current.x.data(), n);
    const Vector f = residual_vector(current);
    const bool extrapolate =
        !result.damped_fallback && history.count() > 0 && damped_steps_left == 0;
    Vector next =
        extrapolate ? history.step(x, f, options.damping) : Vector(x + options.damping * f);
    const double length = (next - x).lpNorm<Eigen::Infinity>();
    if (extrapolate && length > options.max_step) {
      next = x + (options.max_step / length) * (next - x);
    }
    Iterate trial = evaluate(map, std::vector<double>(next.data(), next.data() + n));
    ++result.iterations;
    if (extrapolate && !(trial.residual <= options.restart_growth * best)) {
      // The extrapolation went astray (or left the domain): forget the history and take
      // damped steps from the current iterate, more of them after each such restart, so that
      // the iteration falls back to the (slow but steady) damped iteration if need be.
      history.clear();
      ++result.restarts;
      damped_steps_left = std::max(1, options.memory) * result.restarts;
      continue;
    }
    if (damped_steps_left > 0) --damped_steps_left;
    history.push(ConstMap(trial.x.data(), n) - x, residual_vector(trial) - f);
    current = std::move(trial);
    best = std::min(best, current.residual);
    if (best <= 0.5 * halving_mark) {
      halving_mark = best;
      last_halving = result.iterations;
    }
  }
  result.converged = current.residual <= options.tolerance;
  result.x = std::move(current.x);
  result.gx = std::move(current.gx);
  result.residual = current.residual;
  return result;
}

}  // namespace hmfnet
