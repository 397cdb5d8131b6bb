#include "dynamics/checkpoint_timer.hpp"

#include "parallel/parallel_session.hpp"

namespace hmfnet {

void CheckpointTimer::on_record(const RunRecord& r) {
  if (!m_write || r.last_of_segment()) return;
  const double since =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_last).count();
  const bool root_due = ParallelSession::rank() == 0 && since >= m_seconds;
  if (ParallelSession::max(root_due ? 1.0 : 0.0) > 0.0) write_now();
}

void CheckpointTimer::write_now() {
  if (!m_write) return;
  m_write();
  m_last = std::chrono::steady_clock::now();
}

}  // namespace hmfnet
