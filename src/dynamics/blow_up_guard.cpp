#include "dynamics/blow_up_guard.hpp"

#include <cmath>

#include "core/error.hpp"

namespace hmfnet {

std::string blow_up_message(const RunRecord& r, std::size_t lane, std::size_t replicas,
                            double tolerance, double max_node_order) {
  // The fastest local libration frequency is omega_max = sqrt(K max_n R_n) (small oscillations in
  // the well K R_n cos(theta - psi_n)); the running method is stable for h omega_max below its own
  // linear bound (Integrator::stability_limit).
  const double K = (*r.K)[lane];
  const double err = (*r.energy_errors)[lane];
  const double omega = std::sqrt(K * max_node_order);
  const std::string what = std::isfinite(err)
                               ? "relative energy error " + number_text(err) +
                                     " exceeds the tolerance " + number_text(tolerance)
                               : std::string("energy is NaN or infinite");
  const auto g = [](double x, const char* format) {
    char text[32];
    std::snprintf(text, sizeof text, format, x);
    return std::string(text);
  };
  return "K = " + g(K, "%g") + ", t = " + g(static_cast<double>(r.segment_step) * r.h, "%g") +
         " (replica " + std::to_string(lane % replicas) + " of this K): " + what +
         "; the step h = " + g(r.h, "%g") + " is likely too large for this K: " + r.integrator +
         " is stable for h * omega_max < " + g(r.stability_limit, "%.4g") +
         " with omega_max = sqrt(K max_n R_n) = " + g(omega, "%.4g") + ", i.e. h < " +
         g(omega > 0 ? r.stability_limit / omega : INFINITY, "%.4g");
}

void BlowUpGuard::on_record(const RunRecord& r) {
  const std::vector<double>& errors = *r.energy_errors;
  for (std::size_t b = 0; b < errors.size(); ++b) {
    if (std::isfinite(errors[b]) && errors[b] <= m_tolerance) continue;
    throw SimulationBlowUp(blow_up_message(r, b, m_replicas, m_tolerance, r.max_node_order()));
  }
}

}  // namespace hmfnet
