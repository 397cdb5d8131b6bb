// The caches read at run time (core/cpu_caches.hpp): sysfs CPU lists parsed or refused whole, a
// cache folder laid out as Linux lays out cpu0's read by level (the instruction cache skipped),
// and the sizes this machine reports usable (non-zero, a team of at least one).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/cpu_caches.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;
using hmfnet::test::TempDirectory;
using hmfnet::test::write_text;

namespace {

// One index folder of a sysfs cache folder.
void write_index(const std::string& dir, int index, const std::string& level,
                 const std::string& type, const std::string& size, const std::string& cpus) {
  const std::string at = dir + "/index" + std::to_string(index);
  std::filesystem::create_directories(at);
  write_text(at + "/level", level + "\n");
  write_text(at + "/type", type + "\n");
  if (!size.empty()) write_text(at + "/size", size + "\n");
  write_text(at + "/shared_cpu_list", cpus + "\n");
}

}  // namespace

TEST_CASE("sysfs CPU lists: ranges and singles counted, anything else refused", "[cpu_caches]") {
  CHECK(cpu_list_count("0-1") == 2);
  CHECK(cpu_list_count("0-7,64-71") == 16);
  CHECK(cpu_list_count("3") == 1);
  CHECK(cpu_list_count("5-2") == 0);
  CHECK(cpu_list_count("0-1;4") == 0);
  CHECK(cpu_list_count("x") == 0);
  CHECK(cpu_list_count("") == 0);
  CHECK(cpu_list_count("0-1,") == 0);
  CHECK(cpu_list_count("-5") == 0);
  CHECK(cpu_list_count("0, 1") == 0);
  CHECK(cpu_list_count("0-2147483647") == 0);
}

TEST_CASE("This CPU's caches: non-zero L1 and L2, a team of at least one on the L3",
          "[cpu_caches]") {
  // Each size falls back to a default where neither sysconf nor sysfs answers: never 0.
  CHECK(l1_cache_bytes() > 0);
  CHECK(l2_cache_bytes() > 0);
  CHECK(this_cpu_caches(2).l2 == l2_cache_bytes());
  CHECK(this_cpu_caches(2).l3 == l3_cache_bytes());
  CHECK(this_cpu_caches(0).l3_threads == 1);
  CHECK(this_cpu_caches(1).l3_threads == 1);
  CHECK(this_cpu_caches(2).l3_threads >= 1);
  CHECK(this_cpu_caches(2).l3_threads <= 2);
  CHECK(this_cpu_caches(2).l3_core_complex == l3_per_core_complex());
}

TEST_CASE("This CPU's L3 is a core complex's exactly where /proc/cpuinfo names AMD",
          "[cpu_caches]") {
  // Linux's own reading of CPUID's vendor string, apart from the compiler's.
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, vendor;
  while (vendor.empty() && std::getline(cpuinfo, line)) {
    const std::size_t colon = line.find(": ");
    if (line.rfind("vendor_id", 0) == 0 && colon != std::string::npos) {
      vendor = line.substr(colon + 2);
    }
  }
  // No vendor_id (not x86): no AMD L3 either.
  INFO("vendor_id " << (vendor.empty() ? "(none)" : vendor));
  CHECK(l3_per_core_complex() == (vendor == "AuthenticAMD"));
}

TEST_CASE("sysfs cache folders: the data or unified cache of a level, its size and sharers",
          "[cpu_caches]") {
  const TempDirectory tmp;
  const std::string dir = tmp.path().string();
  // The AMD EPYC's layout (its L1 instruction cache listed between the others here, so that a
  // walker taking the first level-1 entry would read it) and an L3 shared by 8 CPUs.
  write_index(dir, 0, "1", "Instruction", "64K", "0");
  write_index(dir, 1, "1", "Data", "32K", "0");
  write_index(dir, 2, "2", "Unified", "512K", "0");
  write_index(dir, 3, "3", "Unified", "8192K", "0-7");
  CHECK(sysfs_cache(dir, 1).bytes == std::size_t{32} << 10);
  CHECK(sysfs_cache(dir, 1).sharing_cpus == 1);
  CHECK(sysfs_cache(dir, 2).bytes == std::size_t{512} << 10);
  CHECK(sysfs_cache(dir, 3).bytes == std::size_t{8} << 20);
  CHECK(sysfs_cache(dir, 3).sharing_cpus == 8);
  CHECK(sysfs_cache(dir, 4).bytes == 0);
  CHECK(sysfs_cache(dir + "/none", 2).bytes == 0);
  // An entry whose size does not read is passed over for the next of its level; "M" sizes read.
  const TempDirectory other;
  const std::string odir = other.path().string();
  write_index(odir, 0, "2", "Unified", "", "0");
  write_index(odir, 1, "2", "Unified", "2M", "0-1");
  CHECK(sysfs_cache(odir, 2).bytes == std::size_t{2} << 20);
  CHECK(sysfs_cache(odir, 2).sharing_cpus == 2);
}
