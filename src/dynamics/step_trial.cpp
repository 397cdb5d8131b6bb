#include "dynamics/step_trial.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace hmfnet {

StepTrial::StepTrial(std::vector<int> candidates, std::int64_t sample_steps, int samples,
                     std::vector<std::string> labels, SampleOrder order)
    : m_candidates(std::move(candidates)),
      m_labels(std::move(labels)),
      m_sample_steps(sample_steps),
      m_samples(samples),
      m_order(order) {
  if (m_candidates.empty() || sample_steps < 1 || samples < 1) {
    throw std::invalid_argument("StepTrial: candidates, sample steps and samples must be given");
  }
  for (std::size_t i = 0; i < m_candidates.size(); ++i) {
    if (std::find(m_candidates.begin(), m_candidates.begin() + static_cast<std::ptrdiff_t>(i),
                  m_candidates[i]) != m_candidates.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw std::invalid_argument("StepTrial: candidates must be distinct");
    }
  }
  if (m_labels.empty()) {
    for (const int c : m_candidates) m_labels.push_back(std::to_string(c));
  }
  if (m_labels.size() != m_candidates.size()) {
    throw std::invalid_argument("StepTrial: one label a candidate, or none");
  }
  m_chosen = m_candidates.front();
  m_active = m_candidates.size() > 1;
  restart();
}

int StepTrial::candidate() const { return m_active ? m_candidates[m_candidate] : m_chosen; }

std::int64_t StepTrial::chunk_limit() const {
  if (!m_active) return std::numeric_limits<std::int64_t>::max();
  if (m_warm) return k_trial_warm_steps;
  const std::int64_t left = m_sample_steps - m_steps_in_sample;
  if (!may_drop() || m_sample_steps < k_trial_split_steps) return left;
  if (m_steps_in_sample == 0) return 1;
  // No slower a step so far than the limit of a drop: the rest as one chunk.
  if (m_seconds_in_sample <=
      k_trial_abandon * fastest_before() * static_cast<double>(m_steps_in_sample)) {
    return left;
  }
  return std::min(left, m_steps_in_sample);
}

double StepTrial::fastest_before() const {
  return *std::min_element(m_best.begin(),
                           m_best.begin() + static_cast<std::ptrdiff_t>(m_candidate));
}

void StepTrial::restart() {
  m_candidate = 0;
  m_round = 0;
  m_warm = true;
  m_steps_in_sample = 0;
  m_seconds_in_sample = 0.0;
  m_kind_known = false;
  m_best.assign(m_candidates.size(), std::numeric_limits<double>::infinity());
  m_dropped.assign(m_candidates.size(), false);
}

std::int64_t StepTrial::steps() const {
  const auto candidates = static_cast<std::int64_t>(m_candidates.size());
  if (m_order == SampleOrder::by_candidate)
    return candidates * (m_samples * m_sample_steps + k_trial_warm_steps);
  return candidates * m_samples * (m_sample_steps + k_trial_warm_steps);
}

void StepTrial::add(std::int64_t steps, double seconds, std::int64_t kind) {
  if (!m_active) return;
  if (steps < 1 || steps > chunk_limit()) {
    throw std::invalid_argument("StepTrial: a chunk must take 1 to chunk_limit() steps");
  }
  if (m_kind_known && kind != m_kind) {
    // The samples so far timed another kind of step: start again on this kind, from the next
    // chunk (this one ran at the count being tried, not at the first candidate's).
    if (m_restarts == k_trial_restarts) {
      m_gave_up =
          "the kind of step changed more than " + std::to_string(k_trial_restarts) + " times";
      m_active = false;
      return;
    }
    ++m_restarts;
    restart();
    m_kind = kind;
    m_kind_known = true;
    return;
  }
  m_kind = kind;
  m_kind_known = true;
  if (m_warm) {
    m_warm = false;
    return;
  }
  m_steps_in_sample += steps;
  m_seconds_in_sample += seconds;
  // Past this sum the whole sample's time a step exceeds k_trial_abandon times the fastest: the
  // candidate is dropped now, with the time a step of the steps it took.
  const bool past_abandon =
      may_drop() && m_seconds_in_sample >
                        k_trial_abandon * fastest_before() * static_cast<double>(m_sample_steps);
  if (m_steps_in_sample < m_sample_steps && !past_abandon) return;
  const double per_step = m_seconds_in_sample / static_cast<double>(m_steps_in_sample);
  m_best[m_candidate] = std::min(m_best[m_candidate], per_step);
  if (may_drop()) m_dropped[m_candidate] = past_abandon;
  m_steps_in_sample = 0;
  m_seconds_in_sample = 0.0;
  advance();
}

/// In rounds: the next candidate not dropped, in this round or the next; the first is never
/// dropped. By candidate: the same candidate's next sample, else the next candidate's first.
void StepTrial::advance() {
  if (m_order == SampleOrder::by_candidate) {
    if (++m_round < m_samples && !m_dropped[m_candidate]) return;  // the same candidate again
    m_round = 0;
    if (++m_candidate == m_candidates.size()) {
      finish();
      return;
    }
    m_warm = true;
    return;
  }
  const int last = m_candidates[m_candidate];
  do {
    if (++m_candidate == m_candidates.size()) {
      m_candidate = 0;
      if (++m_round == m_samples) {
        finish();
        return;
      }
    }
  } while (m_dropped[m_candidate]);
  m_warm = m_candidates[m_candidate] != last;
}

void StepTrial::finish() {
  m_active = false;
  std::size_t best = 0;
  for (std::size_t i = 1; i < m_candidates.size(); ++i) {
    if (m_best[i] < m_best[best]) best = i;
  }
  // The rule's count stays unless another is faster by more than the margin.
  if (best != 0 && m_best[best] < (1.0 - k_trial_margin) * m_best[0]) m_chosen = m_candidates[best];
}

std::string StepTrial::summary() const {
  if (m_candidates.size() < 2) return "";
  if (!m_gave_up.empty()) return "no choice: " + m_gave_up;
  if (m_active || m_best.back() == std::numeric_limits<double>::infinity()) {
    return "no choice: the run ended during the trial";
  }
  std::string s;
  char buffer[64];
  for (std::size_t i = 0; i < m_candidates.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, ": %.4g us", m_best[i] * 1e6);
    s += (i > 0 ? ", " : "") + m_labels[i] + buffer;
  }
  const auto chosen = std::find(m_candidates.begin(), m_candidates.end(), m_chosen);
  return s + " -> " + m_labels[static_cast<std::size_t>(chosen - m_candidates.begin())];
}

}  // namespace hmfnet
