#pragma once
// The caches of the CPU this process runs on, read once at run time: glibc's sysconf (from
// CPUID) and Linux's /sys/devices/system/cpu/cpu0/cache. The kernels size their blocks by them
// (dynamics/column_segments.hpp); the benchmarks' line counts too.
#include <cstddef>
#include <string>

namespace hmfnet {

/// Used where neither source answers: the smallest per-core L2 of the machines measured so far
/// (AMD EPYC: 512 KiB; Intel Xeon: 2 MiB), so a slice sized by it fits on both.
inline constexpr std::size_t k_default_l2_bytes = std::size_t{512} << 10;

/// Used where neither source answers: the Intel Xeon's 48 KiB (the AMD EPYC has 32 KiB).
inline constexpr std::size_t k_default_l1_bytes = std::size_t{48} << 10;

/// The L1 data cache, in bytes: sysconf(_SC_LEVEL1_DCACHE_SIZE), else the level-1 data entry of
/// sysfs, else k_default_l1_bytes. Read once.
std::size_t l1_cache_bytes();

/// The L2 cache, in bytes: sysconf(_SC_LEVEL2_CACHE_SIZE), else the level-2 entry of sysfs, else
/// k_default_l2_bytes. Read once.
std::size_t l2_cache_bytes();

/// The L3 cache that cpu0 shares, in bytes: the level-3 entry of sysfs, else
/// sysconf(_SC_LEVEL3_CACHE_SIZE), else 0. Read once.
std::size_t l3_cache_bytes();

/// The caches a kernel's block of data can live in, in bytes (l3 0: none known), the threads
/// that share the L3 (each may hold a block of its own there), and whether the L3 is a core
/// complex's own (l3_per_core_complex()).
struct CacheSizes {
  std::size_t l2 = k_default_l2_bytes;
  std::size_t l3 = 0;
  int l3_threads = 1;
  bool l3_core_complex = false;
};

/// Whether this CPU's L3 serves one core complex, close to its few cores, rather than a whole
/// die: true on AMD (an L3 per core complex since Zen; the earlier AMD parts, whose L3 a die
/// shares, and Hygon's Zen parts are not told apart), false elsewhere. The Intel Xeons measured
/// (a 260 MiB and a 48 MiB L3, a whole socket's on a mesh) served slices of their L3 slower than
/// slices of the L2 (docs/performance.md, "Segment slices in a core complex's L3" and "An
/// Intel Xeon's L3 is no core complex's").
bool l3_per_core_complex();

/// The CPUs of a sysfs CPU list ("0-7,64-71": 16, at most 2^20); 0 where it does not parse.
int cpu_list_count(const std::string& list);

/// One cache as sysfs describes it; zeros where unreadable.
struct SysfsCache {
  std::size_t bytes = 0;
  int sharing_cpus = 0;  ///< the CPUs of its shared_cpu_list
};

/// The data or unified cache of `level` among `cache_dir`/index0 .. index7 (a CPU's cache folder
/// in sysfs: level, type, size, shared_cpu_list), the first whose level and size read; a level-1
/// instruction cache is skipped. Zeros where there is none.
SysfsCache sysfs_cache(const std::string& cache_dir, int level);

/// This CPU's (l2_cache_bytes(), l3_cache_bytes()) for a team of `threads`: at least one, at
/// most the CPUs that share cpu0's L3 (sysfs shared_cpu_list), as threads beyond those run on
/// other L3s; and l3_per_core_complex().
CacheSizes this_cpu_caches(int threads);

}  // namespace hmfnet
