#include "dynamics/thread_choice.hpp"

#include <omp.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>

namespace hmfnet {

WaitPolicy wait_policy_from_environment() {
  const char* value = std::getenv("OMP_WAIT_POLICY");
  if (value == nullptr) return WaitPolicy::spinning;
  std::string policy(value);
  std::transform(policy.begin(), policy.end(), policy.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return policy == "PASSIVE" ? WaitPolicy::passive : WaitPolicy::spinning;
}

double wide_lane_gather_cost(bool float32, int lanes) {
  switch (lanes) {
    case 2:
      return float32 ? 1.0 : 0.64;  // float32 B = 2: the baseline loop
    case 4:
      return float32 ? 0.40 : 0.44;
    case 8:
      return float32 ? 0.32 : 0.44;
    default:
      return 1.0;
  }
}

double grouped_lane_gather_cost(bool float32, int lanes) {
  if (lanes <= 0) return 1.0;
  double total = 0.0;
  int left = lanes;
  for (const int group : {8, 4, 2}) {
    if (group == 2 && float32) break;  // float32 pairs: 16-byte records, single replicas
    const int whole = group == 8 ? left / 8 : static_cast<int>(left >= group);
    total += whole * group * wide_lane_gather_cost(float32, group);
    left -= whole * group;
  }
  return (total + left) / lanes;
}

std::int64_t step_work(std::int64_t gathers, std::int64_t rows, std::int64_t lanes,
                       std::int64_t row_work) {
  return (gathers + row_work * rows) * lanes;
}

int default_threads(std::int64_t work, int available, WaitPolicy policy) {
  const std::int64_t per_thread =
      policy == WaitPolicy::passive ? k_work_per_thread_passive : k_work_per_thread_spinning;
  const std::int64_t by_work = std::max<std::int64_t>(1, work / per_thread);
  return static_cast<int>(std::min<std::int64_t>(std::max(1, available), by_work));
}

ThreadCountScope::ThreadCountScope(int threads) : m_previous(omp_get_max_threads()) {
  omp_set_num_threads(std::max(1, threads));
}

ThreadCountScope::~ThreadCountScope() { omp_set_num_threads(m_previous); }

}  // namespace hmfnet
