#include "dynamics/progress_line.hpp"

#include <cstdio>

namespace hmfnet {

void ProgressLine::start(std::int64_t steps_done, double K) {
  m_steps_at_start = steps_done;
  // What the last line shows when no record follows (a run resumed at its very end).
  m_done = static_cast<double>(steps_done);
  m_K = K;
  m_start = std::chrono::steady_clock::now();
}

void ProgressLine::on_record(const RunRecord& r) {
  m_K = r.K->front();
  m_t = static_cast<double>(r.segment_step) * r.h;
  m_done = static_cast<double>(r.steps_total);
  show(false);
}

void ProgressLine::show(bool final_line) const {
  if (!m_enabled) return;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  // The rate of this session (a resumed run's earlier steps took no time here).
  const double rate =
      seconds > 0 ? (m_done - static_cast<double>(m_steps_at_start)) / seconds : 0.0;
  std::fprintf(stderr, "\rK = %-10g t = %-9.1f %8.0f steps/s  %6.1f s left   %s", m_K, m_t, rate,
               rate > 0 ? (m_total - m_done) / rate : 0.0, final_line ? "\n" : "");
}

}  // namespace hmfnet
