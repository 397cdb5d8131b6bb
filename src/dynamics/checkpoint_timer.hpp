#pragma once
// The observer that writes a checkpoint every checkpoint_seconds of wall time, at a record inside
// a segment (a segment's end is checkpointed when the next K starts). Wall clocks differ between
// ranks: the root's decides for everyone (one collective per record).
#include <chrono>
#include <functional>

#include "dynamics/run_record.hpp"

namespace hmfnet {

class CheckpointTimer : public RunObserver {
 public:
  /// `write`: the run's collective checkpoint; `seconds`: the interval. An empty `write` never
  /// fires (a run without --checkpoint).
  CheckpointTimer(std::function<void()> write, double seconds)
      : m_write(std::move(write)), m_seconds(seconds) {}
  void restart() { m_last = std::chrono::steady_clock::now(); }
  void on_record(const RunRecord& r) override;
  /// Collective: a checkpoint now (a new K, a signal).
  void write_now();

 private:
  std::function<void()> m_write;
  double m_seconds;
  std::chrono::steady_clock::time_point m_last{};
};

}  // namespace hmfnet
