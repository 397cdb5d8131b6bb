#pragma once
// The QSS campaign's resume file (qss_lifetime_gpu.cpp): what a run stopped at its sizes'
// record ends needs to go on with the bits it would have had uninterrupted
// (CompleteGraphEnsembles::resume): per size its state, steps and records.
//
// Layout, little-endian: the 16 bytes "hmfnet-qss-res-1", the size count (int64), then per size
// six int64 (N, replicas, record_every, records, steps_planned, steps_done) and four double
// arrays: R_mean and energy (replicas x records, replica-major as CompleteGraphRecords holds
// them), theta and p (N x replicas, node-major as set_state takes them). Written to a
// temporary file beside the target and renamed, so a stopped writer leaves the old file whole.
#include <cstdint>
#include <string>
#include <vector>

namespace hmfnet::verification {

struct QssResumeSize {
  std::int64_t n = 0;
  std::int64_t replicas = 0;
  std::int64_t record_every = 1;
  std::int64_t records = 0;
  std::int64_t steps_planned = 0;
  std::int64_t steps_done = 0;
  std::vector<double> R_mean, energy;  ///< replicas x records
  std::vector<double> theta, p;        ///< N x replicas
};

/// Throws std::runtime_error naming the file when it cannot be written.
void write_qss_resume(const std::string& path, const std::vector<QssResumeSize>& sizes);

/// Throws std::runtime_error naming the file and what is wrong with it (not one, truncated,
/// sizes that contradict each other, bytes left over).
std::vector<QssResumeSize> read_qss_resume(const std::string& path);

}  // namespace hmfnet::verification
