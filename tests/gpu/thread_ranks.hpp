#pragma once
// Threads standing for MPI ranks in the gpu tests: the device check's build has no MPI, and the
// device machine no launcher. Each thread is one rank holding one device ensemble of its rows;
// the RankExchange it is given meets the other threads at a barrier over shared tables, and fills
// what DistributedNetwork::import_columns and ParallelSession::sum_in_place would: the column
// space's [cos, sin] from the owners' rows, and Z summed over the ranks in rank order. A rank
// that throws breaks the barrier, so the others stop with an error instead of waiting forever.
#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "dynamics/cuda/rank_exchange.hpp"
#include "dynamics/cuda/sparse_ensemble.hpp"

namespace hmfnet::gpu_test {

/// One rank's rows [first_row, first_row + csr.rows) of a network, over its column space as
/// DistributedNetwork lays it out (distributed_network.cpp): the own rows and every node they
/// reference, in ascending global order, so that each row keeps its global column order.
struct RankRows {
  std::int64_t first_row = 0;
  cuda::HostCsr csr;                         ///< columns index the column space
  std::vector<std::int64_t> column_globals;  ///< each column-space entry's global node
};

/// Rows [first, last) of `whole` as one rank holds them.
inline RankRows rank_rows(const cuda::HostCsr& whole, std::int64_t first, std::int64_t last) {
  RankRows r;
  r.first_row = first;
  const std::int64_t begin = whole.offsets[static_cast<std::size_t>(first)];
  const std::int64_t end = whole.offsets[static_cast<std::size_t>(last)];
  for (std::int64_t n = first; n < last; ++n) r.column_globals.push_back(n);
  r.column_globals.insert(r.column_globals.end(), whole.columns.begin() + begin,
                          whole.columns.begin() + end);
  std::sort(r.column_globals.begin(), r.column_globals.end());
  r.column_globals.erase(std::unique(r.column_globals.begin(), r.column_globals.end()),
                         r.column_globals.end());
  r.csr.rows = last - first;
  r.csr.column_count = static_cast<std::int64_t>(r.column_globals.size());
  for (std::int64_t n = first; n <= last; ++n) {
    r.csr.offsets.push_back(whole.offsets[static_cast<std::size_t>(n)] - begin);
  }
  for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
    const auto at = std::lower_bound(r.column_globals.begin(), r.column_globals.end(),
                                     static_cast<std::int64_t>(whole.columns[k]));
    r.csr.columns.push_back(static_cast<std::int32_t>(at - r.column_globals.begin()));
    if (!whole.weights.empty()) r.csr.weights.push_back(whole.weights[k]);
  }
  return r;
}

class ThreadRanks {
 public:
  /// `ranks` threads over a network of `global_rows` rows.
  ThreadRanks(int ranks, std::int64_t global_rows)
      : m_ranks(ranks), m_global_rows(global_rows), m_slots(static_cast<std::size_t>(ranks)) {}

  /// The sparse force's exchange of the rank that holds `rows` (which must outlive it).
  cuda::RankExchange sparse(const RankRows& rows) {
    cuda::RankExchange x;
    x.global_rows = m_global_rows;
    x.import_columns = [this, &rows](const double* owned, int width, double* columns) {
      import_columns(rows, owned, width, columns);
    };
    return x;
  }

  /// The rank-one force's exchange of rank `rank`.
  cuda::RankExchange rank_one(int rank) {
    cuda::RankExchange x;
    x.global_rows = m_global_rows;
    x.sum_over_ranks = [this, rank](double* values, int count) { sum(rank, values, count); };
    return x;
  }

  /// body(rank) on one thread a rank; the first exception any of them threw is rethrown here
  /// after every thread ended. Catch2's assertions are not thread-safe: bodies record, the
  /// caller checks.
  void run(const std::function<void(int)>& body) {
    std::vector<std::thread> threads;
    std::exception_ptr first;
    std::mutex failed;
    for (int r = 0; r < m_ranks; ++r) {
      threads.emplace_back([&, r] {
        try {
          body(r);
        } catch (...) {
          const std::lock_guard<std::mutex> hold(failed);
          if (!first) first = std::current_exception();
          break_barrier();
        }
      });
    }
    for (std::thread& t : threads) t.join();
    if (first) std::rethrow_exception(first);
  }

 private:
  // Every rank writes its own rows into the whole table, then reads its column space from it;
  // the last barrier keeps the next evaluation's writes from overtaking a slower rank's reads.
  void import_columns(const RankRows& rows, const double* owned, int width, double* columns) {
    const auto w = static_cast<std::size_t>(width);
    {
      const std::lock_guard<std::mutex> hold(m_mutex);
      if (m_table.size() != static_cast<std::size_t>(m_global_rows) * w)
        m_table.assign(static_cast<std::size_t>(m_global_rows) * w, 0.0);
    }
    arrive();
    std::copy(owned, owned + static_cast<std::size_t>(rows.csr.rows) * w,
              m_table.begin() + static_cast<std::ptrdiff_t>(rows.first_row) * width);
    arrive();
    for (std::size_t c = 0; c < rows.column_globals.size(); ++c) {
      const auto global = static_cast<std::size_t>(rows.column_globals[c]);
      std::copy(m_table.begin() + static_cast<std::ptrdiff_t>(global * w),
                m_table.begin() + static_cast<std::ptrdiff_t>((global + 1) * w), columns + c * w);
    }
    arrive();
  }

  // Rank 0's values plus rank 1's, and so on: at two ranks the bits of any MPI reduction.
  void sum(int rank, double* values, int count) {
    m_slots[static_cast<std::size_t>(rank)].assign(values, values + count);
    arrive();
    std::vector<double> total = m_slots[0];
    for (std::size_t r = 1; r < m_slots.size(); ++r) {
      for (std::size_t j = 0; j < total.size(); ++j) total[j] += m_slots[r][j];
    }
    std::copy(total.begin(), total.end(), values);
    arrive();
  }

  void arrive() {
    std::unique_lock<std::mutex> hold(m_mutex);
    if (m_broken) throw std::runtime_error("another rank failed");
    const long generation = m_generation;
    if (++m_arrived == m_ranks) {
      m_arrived = 0;
      ++m_generation;
      m_turn.notify_all();
      return;
    }
    m_turn.wait(hold, [&] { return m_generation != generation || m_broken; });
    if (m_broken) throw std::runtime_error("another rank failed");
  }

  void break_barrier() {
    const std::lock_guard<std::mutex> hold(m_mutex);
    m_broken = true;
    m_turn.notify_all();
  }

  int m_ranks;
  std::int64_t m_global_rows;
  std::vector<double> m_table;               // global_rows x width: the owners' [cos, sin]
  std::vector<std::vector<double>> m_slots;  // each rank's addends
  std::mutex m_mutex;
  std::condition_variable m_turn;
  int m_arrived = 0;
  long m_generation = 0;
  bool m_broken = false;
};

}  // namespace hmfnet::gpu_test
