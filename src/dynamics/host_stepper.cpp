#include "dynamics/host_stepper.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

#include "dynamics/ordered_sum.hpp"

namespace hmfnet {

void HostStepper::set_state(const RotorState& state) {
  m_state = state;
  m_f.update(m_state);
}

void HostStepper::advance(const Integrator& method, double h, const std::vector<double>& K,
                          std::int64_t steps, std::vector<double>* order) {
  // All steps in one team, each step's closing kick joined to the next step's first pass
  // (Integrator::steps); the order sums are read after each step's force evaluation.
  std::function<void()> keep_order;
  if (order != nullptr) {
    // Reserved here, so that nothing allocates (and may throw) inside the steps' team.
    order->reserve(order->size() +
                   static_cast<std::size_t>(steps) * static_cast<std::size_t>(m_state.replicas));
    keep_order = [&] {
      order->insert(order->end(), m_f.sums().order.begin(), m_f.sums().order.end());
    };
  }
  method.steps(m_state, h, K, m_f, steps, keep_order);
}

StepperSums HostStepper::sums() {
  // A record reads the sums of the last evaluation, which the integrators form there
  // (integrator.cpp); stale ones would pass for that state's silently.
  if (!m_f.sums_current())
    throw std::logic_error("HostStepper::sums: the last evaluation skipped them");
  const auto rows = static_cast<std::size_t>(m_state.rows);
  const int width = m_state.replicas;
  // The terms live in members: fresh vectors each record were zeroed and, past glibc's mmap
  // threshold, page-faulted in again (the water-bag threshold driver on K_100000 spent 9% of its
  // time there, perf). resize keeps the storage when the size is unchanged.
  const std::size_t size = m_state.p.size();
  m_kinetic_terms.resize(size);
  m_abs_p.resize(size);
  const double* p = m_state.p.data();
  double* kinetic = m_kinetic_terms.data();
  double* abs_p = m_abs_p.data();
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < size; ++k) {
    kinetic[k] = 0.5 * p[k] * p[k];
    abs_p[k] = std::abs(p[k]);
  }
  StepperSums s;
  s.order = m_f.sums().order;
  s.coupling = m_f.sums().coupling;
  ordered_column_sums(m_kinetic_terms, rows, width, s.kinetic);
  ordered_column_sums(m_state.p, rows, width, s.momentum);
  ordered_column_sums(m_abs_p, rows, width, s.momentum_scale);
  return s;
}

}  // namespace hmfnet
