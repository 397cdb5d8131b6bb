#include "core/cpu_caches.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <fstream>

namespace hmfnet {

namespace {

// "2048K" or "2M" (sysfs cache size) in bytes; 0 when unreadable.
std::size_t parse_cache_size(const std::string& text) {
  std::size_t used = 0;
  unsigned long long value = 0;
  try {
    value = std::stoull(text, &used);
  } catch (...) {
    return 0;
  }
  const char unit = used < text.size() ? text[used] : ' ';
  if (unit == 'K') value <<= 10;
  if (unit == 'M') value <<= 20;
  return static_cast<std::size_t>(value);
}

constexpr const char* k_cpu0_caches = "/sys/devices/system/cpu/cpu0/cache";

// sysconf's answer for `name`, else sysfs's for `level`, else `fallback`. glibc answers from
// CPUID; it returns 0 or -1 where it cannot tell (some VMs, other libcs).
std::size_t sysconf_then_sysfs(int name, int level, std::size_t fallback) {
  const long from_sysconf = sysconf(name);
  if (from_sysconf > 0) return static_cast<std::size_t>(from_sysconf);
  const std::size_t from_sysfs = sysfs_cache(k_cpu0_caches, level).bytes;
  return from_sysfs > 0 ? from_sysfs : fallback;
}

// cpu0's L3 in sysfs, read once.
SysfsCache cpu0_l3() {
  static const SysfsCache l3 = sysfs_cache(k_cpu0_caches, 3);
  return l3;
}

}  // namespace

SysfsCache sysfs_cache(const std::string& cache_dir, int level) {
  for (int index = 0; index < 8; ++index) {
    const std::string dir = cache_dir + "/index" + std::to_string(index);
    std::ifstream level_file(dir + "/level"), type_file(dir + "/type"), size_file(dir + "/size");
    int found = 0;
    std::string type, size;
    if (!(level_file >> found) || found != level || !(size_file >> size)) continue;
    if ((type_file >> type) && type == "Instruction") continue;
    SysfsCache cache;
    cache.bytes = parse_cache_size(size);
    std::ifstream list_file(dir + "/shared_cpu_list");
    std::string list;
    if (list_file >> list) cache.sharing_cpus = cpu_list_count(list);
    return cache;
  }
  return {};
}

int cpu_list_count(const std::string& list) {
  // One CPU number at `at`: digits only (std::stoul would take signs and spaces), 0 to 2^20.
  const auto number = [&list](std::size_t& at, std::int64_t& value) {
    const std::size_t begin = at;
    value = 0;
    while (at < list.size() && list[at] >= '0' && list[at] <= '9' && at - begin < 7) {
      value = value * 10 + (list[at++] - '0');
    }
    return at > begin && value <= (std::int64_t{1} << 20);
  };
  std::int64_t count = 0;
  std::size_t at = 0;
  while (true) {
    std::int64_t first = 0, last = 0;
    if (!number(at, first)) return 0;
    last = first;
    if (at < list.size() && list[at] == '-' && !number(++at, last)) return 0;
    if (last < first) return 0;
    count += last - first + 1;
    if (at == list.size()) break;
    if (list[at++] != ',') return 0;
  }
  return static_cast<int>(std::min<std::int64_t>(count, std::int64_t{1} << 20));
}

std::size_t l1_cache_bytes() {
  static const std::size_t bytes =
      sysconf_then_sysfs(_SC_LEVEL1_DCACHE_SIZE, 1, k_default_l1_bytes);
  return bytes;
}

std::size_t l2_cache_bytes() {
  static const std::size_t bytes = sysconf_then_sysfs(_SC_LEVEL2_CACHE_SIZE, 2, k_default_l2_bytes);
  return bytes;
}

std::size_t l3_cache_bytes() {
  // sysfs first: it gives the L3 this core shares (the AMD EPYC's 8 MiB core complex), where
  // glibc's CPUID answer there is the socket's 64 MiB, no cache a core can hold a slice in.
  static const std::size_t bytes = [] {
    const std::size_t from_sysfs = cpu0_l3().bytes;
    if (from_sysfs > 0) return from_sysfs;
    const long from_sysconf = sysconf(_SC_LEVEL3_CACHE_SIZE);
    return from_sysconf > 0 ? static_cast<std::size_t>(from_sysconf) : std::size_t{0};
  }();
  return bytes;
}

bool l3_per_core_complex() {
#if defined(__x86_64__) || defined(__i386__)
  // CPUID's vendor string, through the compiler's own table (GCC and Clang); initialised here, so
  // that a caller during static initialisation reads it too.
  static const bool amd = [] {
    __builtin_cpu_init();
    return __builtin_cpu_is("amd") != 0;
  }();
  return amd;
#else
  return false;
#endif
}

CacheSizes this_cpu_caches(int threads) {
  // Threads beyond the CPUs one L3 serves run on other L3s (other core complexes).
  const int sharing = cpu0_l3().sharing_cpus;
  const int share = sharing > 0 ? std::min(threads, sharing) : threads;
  return CacheSizes{l2_cache_bytes(), l3_cache_bytes(), std::max(share, 1), l3_per_core_complex()};
}

}  // namespace hmfnet
