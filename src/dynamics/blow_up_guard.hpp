#pragma once
// The observer that stops a run whose energy error leaves the tolerance or becomes NaN, with the
// likely cause: the step is too large for the coupling (SimulationBlowUp says by how much).
#include <stdexcept>
#include <string>

#include "dynamics/run_record.hpp"

namespace hmfnet {

/// NaN/Inf or an energy error beyond the tolerance.
class SimulationBlowUp : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class BlowUpGuard : public RunObserver {
 public:
  /// `replicas`: the run's own replicas per K (a run across replicas has K.size() times more
  /// lanes).
  BlowUpGuard(double energy_tolerance, std::size_t replicas)
      : m_tolerance(energy_tolerance), m_replicas(replicas) {}
  /// Throws SimulationBlowUp at the first replica out of tolerance. Every rank holds the same
  /// (reduced) errors, so every rank throws alike.
  void on_record(const RunRecord& r) override;

 private:
  double m_tolerance;
  std::size_t m_replicas;
};

/// The message for replica `lane` of the record: its error, the step, and the largest stable step
/// h < limit / omega_max with omega_max = sqrt(K max_n R_n).
std::string blow_up_message(const RunRecord& r, std::size_t lane, std::size_t replicas,
                            double tolerance, double max_node_order);

}  // namespace hmfnet
