#pragma once
// Arrays that start on a cache line. The sparse force gathers whole records of 2B values from
// its [cos, sin] table; a std::vector of that size starts 16 bytes past a page (glibc's chunk
// header), so a record of 64 bytes (float64 with 4 replicas, float32 with 8) lay across two
// lines and one of 128 bytes across three. On a line, each record takes ceil(bytes / 64) lines,
// as the step's bound counts them (bench/bench_access_lines.cpp). Measured on the Intel Xeon
// (docs/performance.md, "Cache lines in the bound"): the step's speed unchanged within the
// noise; the carried partial sums, aligned too, ran 3-8% slower at N = 10^6 and stay unaligned.
// Tables of k_huge_table_bytes and more (from 262,144 nodes with one float64 replica) also start
// on a huge page, in huge pages (huge_pages.hpp): measured on the AMD EPYC family 25 model 17
// (docs/performance.md, "The gathered table in huge pages"). Smaller ones stay in 4 KiB pages:
// a table of N = 10^4 in one huge page ran 0.80-1.02x there.
#include <cstddef>
#include <vector>

#include "core/huge_pages.hpp"

namespace hmfnet {

inline constexpr std::size_t k_cache_line_bytes = 64;
inline constexpr std::size_t k_huge_table_bytes = 2 * k_huge_page_bytes;

/// std::allocator's interface, every block aligned to k_cache_line_bytes, and blocks of at least
/// k_huge_table_bytes to k_huge_page_bytes in huge pages where the kernel gives them.
template <typename T>
struct CacheAlignedAllocator {
  using value_type = T;

  CacheAlignedAllocator() = default;
  // Implicit, as std::allocator's: a container may copy-initialise its rebound allocator.
  template <typename U>
  CacheAlignedAllocator(const CacheAlignedAllocator<U>& /*other*/) {}

  T* allocate(std::size_t n) {
    return static_cast<T*>(allocate_table(n * sizeof(T), k_cache_line_bytes, k_huge_table_bytes));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    deallocate_table(p, n * sizeof(T), k_cache_line_bytes, k_huge_table_bytes);
  }

  template <typename U>
  bool operator==(const CacheAlignedAllocator<U>& /*other*/) const {
    return true;
  }
  template <typename U>
  bool operator!=(const CacheAlignedAllocator<U>& /*other*/) const {
    return false;
  }
};

/// A std::vector whose data() starts on a cache line.
template <typename T>
using CacheAlignedVector = std::vector<T, CacheAlignedAllocator<T>>;

}  // namespace hmfnet
