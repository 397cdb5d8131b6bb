#include "dynamics/time_average.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"

namespace hmfnet {

BatchMeans::BatchMeans(std::int64_t samples, int batches, int width)
    : m_samples(samples), m_batches(batches), m_width(width) {
  if (batches < 2 || samples < batches || width < 1) {
    throw ParameterError("batch means",
                         std::to_string(samples) + " samples, " + std::to_string(batches) +
                             " batches, width " + std::to_string(width),
                         "samples >= batches >= 2, width >= 1");
  }
  m_sums.assign(static_cast<std::size_t>(batches) * static_cast<std::size_t>(width), 0.0);
}

std::int64_t BatchMeans::batch_size(int batch) const {
  // Sample i belongs to batch floor(i B / S); count the samples of `batch` added so far.
  const std::int64_t first =
      (static_cast<std::int64_t>(batch) * m_samples + m_batches - 1) / m_batches;
  const std::int64_t end =
      (static_cast<std::int64_t>(batch + 1) * m_samples + m_batches - 1) / m_batches;
  return std::max<std::int64_t>(0, std::min(end, m_count) - first);
}

void BatchMeans::add(const std::vector<double>& values) {
  if (m_count >= m_samples) throw std::logic_error("more samples than planned in BatchMeans");
  const auto batch = static_cast<std::size_t>(m_count * m_batches / m_samples);
  const auto w = static_cast<std::size_t>(m_width);
  for (std::size_t k = 0; k < w; ++k) m_sums[batch * w + k] += values[k];
  ++m_count;
}

std::vector<double> BatchMeans::mean() const {
  const auto w = static_cast<std::size_t>(m_width);
  std::vector<double> m(w, 0.0);
  for (std::size_t b = 0; b < static_cast<std::size_t>(m_batches); ++b)
    for (std::size_t k = 0; k < w; ++k) m[k] += m_sums[b * w + k];
  for (double& x : m) x /= static_cast<double>(m_count);
  return m;
}

std::vector<double> BatchMeans::standard_error() const {
  const auto w = static_cast<std::size_t>(m_width);
  const std::vector<double> overall = mean();
  std::vector<double> var(w, 0.0);
  for (int b = 0; b < m_batches; ++b) {
    const double size = static_cast<double>(batch_size(b));
    for (std::size_t k = 0; k < w; ++k) {
      const double d = m_sums[static_cast<std::size_t>(b) * w + k] / size - overall[k];
      var[k] += d * d;
    }
  }
  for (double& v : var) v = std::sqrt(v / (m_batches - 1) / m_batches);
  return var;
}

void BatchMeans::restore(std::int64_t count, std::vector<double> sums) {
  // A caller's bug, not bad input: checkpoint.cpp checks the stored size before restoring.
  if (sums.size() != m_sums.size()) throw std::logic_error("batch means: wrong state size");
  m_count = count;
  m_sums = std::move(sums);
}

}  // namespace hmfnet
