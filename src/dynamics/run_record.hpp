#pragma once
// A record of a run (every record_stride steps of a K's segment and at its last step) and the
// observers that watch the records: the time series (series_recorder.hpp), the blow-up guard
// (blow_up_guard.hpp), the progress line (progress_line.hpp) and the checkpoint timer
// (checkpoint_timer.hpp). The stepping (simulation.cpp) only forms the record; what is done with
// it lives in the observers, so a stepper on another device forms the same record and reuses them.
// Every rank forms the same record (its sums are reduced over ranks) and calls the observers in
// the same order, so an observer may be collective.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace hmfnet {

/// The reduced sums of a record, per replica: R (eq:globalOrderParam), the energy
/// (eq:hamiltonianNetworkCase), the total momentum and sum |p_n| (its drift's scale).
struct Observables {
  std::vector<double> R, energy, momentum, momentum_scale;
};

struct RunRecord {
  int k_index = 0;                         ///< the schedule's K being integrated
  const std::vector<double>* K = nullptr;  ///< per replica
  std::int64_t segment_step = 0;           ///< steps into this K
  std::int64_t segment_steps = 0;          ///< steps of this K
  std::int64_t steps_total = 0;            ///< steps since the run started, all sessions
  double h = 0.0;                          ///< the step of this K's segment
  double t = 0.0;                          ///< time since the run started (the series' axis)
  const Observables* observed = nullptr;   ///< at this record
  const std::vector<double>* energy_errors = nullptr;  ///< |E - E0| / |E0| per replica
  std::string integrator;                              ///< the method of this K's segment
  double stability_limit = 0.0;                        ///< its linear bound on h omega (Integrator)
  /// max_n R_n over the network (collective): called only by an observer that reports a failure.
  std::function<double()> max_node_order;

  bool last_of_segment() const { return segment_step == segment_steps; }
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void on_record(const RunRecord& record) = 0;
};

}  // namespace hmfnet
