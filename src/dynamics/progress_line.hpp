#pragma once
// The observer that shows a run's progress on stderr (root rank, when asked): K, t, the stepping
// rate and the time left, overwritten at each record, and a final line at the end.
#include <chrono>
#include <cstdint>

#include "dynamics/run_record.hpp"

namespace hmfnet {

class ProgressLine : public RunObserver {
 public:
  /// `enabled`: params.progress on the root rank; `total_steps`: every K's steps.
  ProgressLine(bool enabled, double total_steps) : m_enabled(enabled), m_total(total_steps) {}
  /// The stepping loop starts now at coupling K (a resumed run counts its rate from here).
  void start(std::int64_t steps_done, double K);
  void on_record(const RunRecord& r) override;
  /// The last record's line again, ending with a newline.
  void finish() const { show(true); }

 private:
  void show(bool final_line) const;
  bool m_enabled;
  double m_K = 0.0, m_t = 0.0, m_done = 0.0;  // of the last record
  double m_total;
  std::int64_t m_steps_at_start = 0;
  std::chrono::steady_clock::time_point m_start{};
};

}  // namespace hmfnet
