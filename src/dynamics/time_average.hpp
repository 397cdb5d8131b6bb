#pragma once
// <X>_t of eq:timeAverage over equally spaced samples, with a standard error that accounts for
// autocorrelation by batch means (Flyvbjerg & Petersen 1989): the samples are cut into `batches`
// consecutive blocks of (nearly) equal size, and SEM = sd(block means) / sqrt(batches). Blocks
// far longer than the correlation time make the block means independent. The block of sample i
// is fixed by i and the total count, so the result does not depend on when it is read.
#include <cstdint>
#include <vector>

namespace hmfnet {

class BatchMeans {
 public:
  BatchMeans() = default;
  /// `samples`: how many samples will be added (>= batches >= 2), `width`: series side by side.
  BatchMeans(std::int64_t samples, int batches, int width);

  void add(const std::vector<double>& values);  ///< one sample of each series
  std::vector<double> mean() const;
  std::vector<double> standard_error() const;
  std::int64_t count() const { return m_count; }

  // State for checkpoints.
  const std::vector<double>& sums() const { return m_sums; }
  void restore(std::int64_t count, std::vector<double> sums);
  int batches() const { return m_batches; }
  int width() const { return m_width; }

 private:
  std::int64_t batch_size(int batch) const;
  std::int64_t m_samples = 0;
  int m_batches = 0;
  int m_width = 0;
  std::int64_t m_count = 0;
  std::vector<double> m_sums;  // batches x width
};

}  // namespace hmfnet
