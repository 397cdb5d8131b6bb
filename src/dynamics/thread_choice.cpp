#include "dynamics/thread_choice.hpp"

#include <omp.h>

#include <algorithm>

namespace hmfnet {

int default_threads(std::int64_t work, int available) {
  const std::int64_t by_work = std::max<std::int64_t>(1, work / k_work_per_thread);
  return static_cast<int>(std::min<std::int64_t>(std::max(1, available), by_work));
}

ThreadCountScope::ThreadCountScope(int threads) : m_previous(omp_get_max_threads()) {
  omp_set_num_threads(std::max(1, threads));
}

ThreadCountScope::~ThreadCountScope() { omp_set_num_threads(m_previous); }

}  // namespace hmfnet
